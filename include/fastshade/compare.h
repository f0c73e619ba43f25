// Error between two images, in 8-bit steps (LSB = 1/255).
#pragma once
#include "fastshade/image.h"

namespace fastshade {

struct ImageDiff {
  double max_abs_lsb = 0;   // largest channel difference
  double rmse_lsb = 0;      // over all channels of all pixels
  double psnr_db = 0;       // 20 log10(255 / rmse); +inf when equal
  double pct_over_1lsb = 0; // % of pixels with any channel off by more than 1 LSB
  int worst_x = 0, worst_y = 0;
  long long nan_count = 0;  // channels that are NaN in either image
};

// Throws InputError if the sizes differ.
ImageDiff compare_images(const ImageF& a, const ImageF& b);

ImageF to_float(const Image& image);

}  // namespace fastshade
