// The tests' brute-force rasterizer: whether a pixel centre lies in a clip-space triangle
// after the pipeline's snapping, by the top-left fill rule, written independently of
// frame/edge_function.h.
#pragma once
#include <array>
#include <cmath>
#include <utility>

#include <glm/vec4.hpp>

namespace fastshade::test {

// Fixed-point snapping and the top-left rule, written independently of frame/edge_function.h:
// a centre on an edge belongs to the triangle iff the edge is a top or a left one.
inline bool snapped_hit(const std::array<glm::vec4, 3>& t, int x, int y, int width, int height) {
  double vx[3], vy[3];
  for (int i = 0; i < 3; ++i) {
    const double inv_w = 1.0 / double(t[i].w);
    vx[i] = double(std::lrint((t[i].x * inv_w + 1.0) * 0.5 * width * 256));
    vy[i] = double(std::lrint((1.0 - t[i].y * inv_w) * 0.5 * height * 256));
  }
  const double area = (vx[1] - vx[0]) * (vy[2] - vy[0]) - (vx[2] - vx[0]) * (vy[1] - vy[0]);
  if (area == 0) return false;
  const double sign = area > 0 ? 1 : -1;  // orient clockwise on the y-down screen
  const double cx = (x + 0.5) * 256, cy = (y + 0.5) * 256;
  for (int k = 0; k < 3; ++k) {
    int i = (k + 1) % 3, j = (k + 2) % 3;
    if (sign < 0) std::swap(i, j);
    const double e = (vx[j] - vx[i]) * (cy - vy[i]) - (cx - vx[i]) * (vy[j] - vy[i]);
    if (e < 0) return false;
    if (e == 0) {
      const double dx = vx[j] - vx[i], dy = vy[j] - vy[i];
      const bool top = dy == 0 && dx > 0, left = dy < 0;
      if (!top && !left) return false;
    }
  }
  return true;
}

}  // namespace fastshade::test
