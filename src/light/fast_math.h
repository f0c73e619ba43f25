// Scalar twins of light/fast_math-inl.h: the same polynomials, constants and operation order
// (std::fma where the SIMD code uses MulAdd), for scalar references and scalar paths.
#pragma once
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace fastshade::fast_math {

// log2(1 + t) / t on t in [sqrt(1/2) - 1, sqrt(2) - 1], highest degree first (relative error
// of t P(t) against log2(1 + t): 2.7e-8; fitted in Chebyshev nodes).
inline constexpr float kLog2Poly[9] = {
    0.12615002049765003f, -0.20742355216876388f, 0.21567042774283413f,
    -0.23892004117992743f, 0.2879182434443961f,  -0.36070483806298315f,
    0.48091061233376403f,  -0.7213473332741358f, 1.4426950037552553f};
// 2^f on [0, 1), highest degree first (relative error 2.6e-9).
inline constexpr float kExp2Poly[7] = {0.00021877510622295198f, 0.001238782648402235f,
                                       0.009684578963332661f,   0.05548042773717305f,
                                       0.24023050148226868f,    0.6931469287822553f,
                                       1.000000002583028f};
inline constexpr float kExp2Min = -126.0f;

inline float log2(float x) {  // finite x > 0
  const int32_t bits = std::bit_cast<int32_t>(x);
  int32_t exponent = (bits >> 23) - 127;
  float m = std::bit_cast<float>((bits & 0x007FFFFF) | 0x3F800000);
  if (m > 1.41421356f) {
    m *= 0.5f;
    exponent += 1;
  }
  const float t = m - 1.0f;
  float p = kLog2Poly[0];
  for (int i = 1; i < 9; ++i) p = std::fma(p, t, kLog2Poly[i]);
  return std::fma(t, p, static_cast<float>(exponent));
}

inline float exp2(float y) {  // y <= 0
  y = std::max(y, kExp2Min);
  const float whole = std::floor(y);
  const float f = y - whole;
  float p = kExp2Poly[0];
  for (int i = 1; i < 7; ++i) p = std::fma(p, f, kExp2Poly[i]);
  return std::bit_cast<float>(std::bit_cast<int32_t>(p) + (static_cast<int32_t>(whole) << 23));
}

// Callers treat a vector whose squared length is below kMinInvSqrtInput (FLT_MIN: shorter than
// 1.1e-19) as zero. Its squared length is subnormal there, and has lost the precision that
// normalising would need.
inline constexpr float kMinInvSqrtInput = 0x1p-126f;

// 1/sqrt(x) as two correctly rounded operations, sqrt then a division (relative error within
// 2u): the same bits in scalar code and at every vector width, as the SIMD twin
// (light/fast_math-inl.h) needs. Not the hardware estimate, whose precision differs between
// 128-, 256- and 512-bit vectors (12 vs 14 bits).
inline float inv_sqrt(float x) { return 1.0f / std::sqrt(x); }  // finite x >= kMinInvSqrtInput

}  // namespace fastshade::fast_math
