#include "app/report_metrics.h"

#include <cmath>

#include "fastshade/compare.h"

namespace fastshade {

namespace {
// A reference channel a NaN-zeroed channel would visibly differ from: more than the 1 LSB that
// rounding alone may account for.
constexpr int kVisibleChannelLsb = 2;
}  // namespace

long long nan_suspect_channels(const Image& image, const Image& reference) {
  long long count = 0;
  for (std::size_t i = 0; i < image.rgb.size() && i < reference.rgb.size(); ++i)
    count += image.rgb[i] == 0 && reference.rgb[i] >= kVisibleChannelLsb;
  return count;
}

ErrorMetrics measure_error(const Image& image, const Image& reference, long long covered_pixels) {
  const ImageDiff diff = compare_images(to_float(image), to_float(reference));
  ErrorMetrics m;
  // 8-bit codes differ by whole steps; compare's float path may add a few 1e-6 LSB.
  m.max_abs_lsb = std::round(diff.max_abs_lsb);
  m.rmse_lsb = diff.rmse_lsb;
  m.psnr_db = diff.psnr_db;
  const double image_px = double(image.width) * image.height;
  m.pct_covered_over_1lsb =
      covered_pixels > 0 ? diff.pct_over_1lsb * image_px / double(covered_pixels) : 0.0;
  m.nan_suspect_channels = nan_suspect_channels(image, reference);
  return m;
}

}  // namespace fastshade
