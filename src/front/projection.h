// Clip space to the fixed-point screen: one definition, used per vertex by the vertex stage
// and per new vertex by the clipping path, so a shared vertex always snaps to the same point.
#pragma once
#include <cmath>
#include <cstdint>

#include <glm/vec4.hpp>

#include "core/limits.h"
#include "front/clip.h"

namespace fastshade {

struct ScreenVertex {
  int32_t x_fx, y_fx;  // kSubpixelBits fixed point, y down
  float depth;         // window depth in [0, 1]
  float inv_w;
};

struct Viewport {
  int width = 0, height = 0;
  float guard_x = 1, guard_y = 1;  // |x/w|, |y/w| a vertex may reach without clipping
  ClipPlanes planes;               // near, far and the guard band
};

// |x_ndc| <= guard maps to screen x in [W/2 - G/2, W/2 + G/2]; with W <= G/2 that stays inside
// (-G, G), the fixed-point range limits.h budgets for.
Viewport make_viewport(int width, int height);

// Vertex flags: the frustum outcode (a triangle whose vertices share a bit is invisible),
// whether the vertex lies outside near/far or the guard band (its triangles go through the
// clipper), and whether its position is not finite (its triangles are dropped).
inline constexpr uint8_t kOutcodeMask = 0x3F;
inline constexpr uint8_t kNeedsClip = 0x40;
inline constexpr uint8_t kNonFinite = 0x80;

// Bit i: outside clip plane i (left, right, bottom, top, near, far).
inline uint8_t frustum_outcode(const glm::vec4& v) {
  return static_cast<uint8_t>((v.x < -v.w) | (v.x > v.w) << 1 | (v.y < -v.w) << 2 | (v.y > v.w) << 3 |
                              (v.z < -v.w) << 4 | (v.z > v.w) << 5);
}

inline uint8_t vertex_flags(const glm::vec4& v, const Viewport& vp) {
  if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w)))
    return kNonFinite;
  const uint8_t outcode = frustum_outcode(v);
  const bool inside = v.z >= -v.w && v.z <= v.w && std::fabs(v.x) <= vp.guard_x * v.w &&
                      std::fabs(v.y) <= vp.guard_y * v.w;
  return outcode | (inside ? 0 : kNeedsClip);
}

// Window pixels (y down) of a clip-space point with 1/w = inv_w, before snapping.
struct WindowPx {
  double x, y;
};
inline WindowPx window_px(const glm::vec4& v, double inv_w, const Viewport& vp) {
  return {(v.x * inv_w + 1.0) * 0.5 * vp.width, (1.0 - v.y * inv_w) * 0.5 * vp.height};
}

// Only for vertices inside near/far and the guard band (w > 0).
inline ScreenVertex project(const glm::vec4& v, const Viewport& vp) {
  const double inv_w = 1.0 / static_cast<double>(v.w);
  const auto [x_px, y_px] = window_px(v, inv_w, vp);
  return {static_cast<int32_t>(std::lrint(x_px * limits::kSubpixelOne)),
          static_cast<int32_t>(std::lrint(y_px * limits::kSubpixelOne)),
          static_cast<float>(v.z * inv_w * 0.5 + 0.5), static_cast<float>(inv_w)};
}

}  // namespace fastshade
