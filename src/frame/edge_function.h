// What "covered" means, shared by the binner (front/) and the rasterizer (raster/): exact
// integer edge functions over fixed-point vertices, pixel centres at +0.5, top-left rule.
#pragma once
#include <cstdint>

#include "frame/frame.h"

namespace fastshade {

// E(X, Y) = a*X + b*Y + c in fixed-point units for the edge opposite one vertex; positive on
// the inside. The pixel (px, py) is covered by the edge when E(centre) >= threshold, where
// threshold is 0 on a top or left edge and 1 otherwise (the top-left rule: a centre exactly on
// a shared edge belongs to exactly one of the two triangles).
struct Edge {
  int64_t a, b, c;
  int64_t threshold;
  int64_t at(int64_t x_fx, int64_t y_fx) const { return a * x_fx + b * y_fx + c; }
  bool covers(int64_t x_fx, int64_t y_fx) const { return at(x_fx, y_fx) >= threshold; }
};

inline constexpr int64_t pixel_centre_fx(int64_t px) {
  return px * limits::kSubpixelOne + limits::kSubpixelOne / 2;
}

// Edge k runs from vertex k+1 to vertex k+2 (mod 3), so E_k(vertex k) is the doubled area.
// Triangles are wound so that area is positive: clockwise on the y-down screen.
inline Edge make_edge(int32_t xa, int32_t ya, int32_t xb, int32_t yb) {
  const int64_t dx = int64_t(xb) - xa, dy = int64_t(yb) - ya;
  Edge e;
  e.a = -dy;
  e.b = dx;
  e.c = dy * xa - dx * ya;
  // With clockwise winding on a y-down screen, a left edge runs upward (dy < 0) and a top
  // edge runs rightward along a row (dy == 0, dx > 0).
  e.threshold = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;
  return e;
}

struct TriangleEdges {
  Edge e[3];
};

inline TriangleEdges triangle_edges(const SetupTriangle& t) {
  TriangleEdges te;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    te.e[k] = make_edge(t.x_fx[i], t.y_fx[i], t.x_fx[j], t.y_fx[j]);
  }
  return te;
}

inline int64_t doubled_area(const SetupTriangle& t) {
  return (int64_t(t.x_fx[1]) - t.x_fx[0]) * (int64_t(t.y_fx[2]) - t.y_fx[0]) -
         (int64_t(t.x_fx[2]) - t.x_fx[0]) * (int64_t(t.y_fx[1]) - t.y_fx[0]);
}

// Can the triangle cover any pixel centre of the rectangle [x0, x1] x [y0, y1] (inclusive
// pixel indices)? Conservative per edge: tests each edge at the rectangle corner where it is
// largest. Used to skip tiles that only the bounding box touches.
inline bool may_cover(const TriangleEdges& te, int x0, int y0, int x1, int y1) {
  for (const Edge& e : te.e) {
    const int64_t x = pixel_centre_fx(e.a >= 0 ? x1 : x0);
    const int64_t y = pixel_centre_fx(e.b >= 0 ? y1 : y0);
    if (e.at(x, y) < e.threshold) return false;
  }
  return true;
}

}  // namespace fastshade
