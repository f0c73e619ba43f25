// compare_images and to_float: differences in 8-bit steps (LSB = 1/255), accumulated in double.
#include "fastshade/compare.h"

#include <cmath>
#include <limits>
#include <string>

#include "fastshade/error.h"

namespace fastshade {

namespace {
std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// A pixel counts as "over 1 LSB" only past this. An 8-bit code v as float v/255 is off by up
// to half a float ulp (3e-8 below 1.0); times 255 that is up to 7.6e-6 LSB, so two codes one
// step apart can measure 1.0000076 LSB (codes 127/128). 1e-6 would count those as over;
// 1e-4 absorbs that noise with margin and is still far below any real 2-step difference.
constexpr double kOverThresholdLsb = 1.0 + 1e-4;
}  // namespace

ImageDiff compare_images(const ImageF& a, const ImageF& b) {
  if (a.width != b.width || a.height != b.height)
    throw InputError("compare", "image sizes differ: " + size_text(a.width, a.height) + " vs " +
                                    size_text(b.width, b.height));
  const size_t pixels = static_cast<size_t>(a.width < 0 ? 0 : a.width) *
                        static_cast<size_t>(a.height < 0 ? 0 : a.height);
  if (a.rgb.size() != pixels * 3 || b.rgb.size() != pixels * 3)
    throw InputError("compare", "image buffer does not hold " + size_text(a.width, a.height) +
                                    " RGB pixels");

  ImageDiff diff;
  double sum_sq = 0;
  long long counted = 0;  // channels that are not NaN in either image
  long long over = 0;
  double worst = -1;
  for (size_t p = 0; p < pixels; ++p) {
    double pixel_max = 0;
    for (int c = 0; c < 3; ++c) {
      const double va = a.rgb[3 * p + c], vb = b.rgb[3 * p + c];
      if (std::isnan(va) || std::isnan(vb)) {
        ++diff.nan_count;
        continue;
      }
      // Equal values (infinities included) differ by 0, not by inf - inf = NaN.
      const double d = va == vb ? 0.0 : std::fabs(va - vb) * 255.0;
      sum_sq += d * d;
      ++counted;
      if (d > pixel_max) pixel_max = d;
    }
    if (pixel_max > kOverThresholdLsb) ++over;
    if (pixel_max > worst) {  // strict: the first pixel in scan order wins ties
      worst = pixel_max;
      diff.worst_x = static_cast<int>(p % static_cast<size_t>(a.width));
      diff.worst_y = static_cast<int>(p / static_cast<size_t>(a.width));
    }
  }
  diff.max_abs_lsb = worst < 0 ? 0 : worst;
  diff.rmse_lsb = counted > 0 ? std::sqrt(sum_sq / static_cast<double>(counted)) : 0.0;
  diff.psnr_db = diff.rmse_lsb > 0 ? 20.0 * std::log10(255.0 / diff.rmse_lsb)
                                   : std::numeric_limits<double>::infinity();
  diff.pct_over_1lsb = pixels > 0 ? 100.0 * static_cast<double>(over) / static_cast<double>(pixels) : 0.0;
  return diff;
}

ImageF to_float(const Image& image) {
  ImageF out;
  out.width = image.width;
  out.height = image.height;
  out.rgb.resize(image.rgb.size());
  for (size_t i = 0; i < image.rgb.size(); ++i) out.rgb[i] = static_cast<float>(image.rgb[i]) / 255.0f;
  return out;
}

}  // namespace fastshade
