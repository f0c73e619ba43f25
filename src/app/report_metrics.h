// The error figures of one report row: a method's 8-bit image against the reference's.
#pragma once
#include "fastshade/image.h"

namespace fastshade {

struct ErrorMetrics {
  double max_abs_lsb = 0;            // largest channel difference, in 8-bit steps
  double rmse_lsb = 0;               // over every channel of every pixel (as `fastshade compare`)
  double psnr_db = 0;                // +inf for identical images
  double pct_covered_over_1lsb = 0;  // pixels off by more than 1 LSB, % of covered pixels
  long long nan_suspect_channels = 0;  // see nan_suspect_channels()
};

// The renderer writes 8 bits and its quantiser turns a NaN into 0 (light/lighting.h,
// shade/span_loop-inl.h), so a NaN cannot be counted in the image itself. What can be counted
// is every place one could have gone: channels that are 0 in `image` where `reference` is at
// least 2 LSB (a zeroed channel of 0 or 1 LSB is within rounding and invisible). The count is
// an upper bound on NaN channels; 0 means no NaN changed any channel by more than 1 LSB.
long long nan_suspect_channels(const Image& image, const Image& reference);

// `covered_pixels`: pixels any triangle covers (RenderStats); the same for every method.
ErrorMetrics measure_error(const Image& image, const Image& reference, long long covered_pixels);

}  // namespace fastshade
