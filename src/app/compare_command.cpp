#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "fastshade/compare.h"

namespace fastshade {

int run_compare(const std::string& a, const std::string& b, bool json) {
  const ImageDiff diff = compare_images(read_image(a), read_image(b));
  if (json) {
    const nlohmann::json j = {
        {"max_abs_lsb", diff.max_abs_lsb}, {"rmse_lsb", diff.rmse_lsb},
        // JSON has no infinity: identical images report psnr_db null.
        {"psnr_db", std::isfinite(diff.psnr_db) ? nlohmann::json(diff.psnr_db) : nlohmann::json()},
        {"pct_over_1lsb", diff.pct_over_1lsb}, {"worst_x", diff.worst_x}, {"worst_y", diff.worst_y},
        {"nan_count", diff.nan_count}};
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf(
        "max abs error %.3f LSB, RMSE %.4f LSB, PSNR %.2f dB, %.4f%% of pixels off by more than 1 "
        "LSB, worst pixel (%d, %d), NaN %lld\n",
        diff.max_abs_lsb, diff.rmse_lsb, diff.psnr_db, diff.pct_over_1lsb, diff.worst_x,
        diff.worst_y, diff.nan_count);
  }
  return 0;
}

}  // namespace fastshade
