// What "covered" means, shared by the binner (front/) and the rasterizer (raster/): exact
// integer edge functions over fixed-point vertices, pixel centres at +0.5, top-left rule.
#pragma once
#include <cstdint>

#include "core/force_inline.h"
#include "frame/frame.h"

namespace fastshade {

// E(X, Y) = a*X + b*Y + c in fixed-point units for the edge opposite one vertex; positive on
// the inside. The pixel (px, py) is covered by the edge when E(centre) >= threshold, where
// threshold is 0 on a top or left edge and 1 otherwise (the top-left rule: a centre exactly on
// a shared edge belongs to exactly one of the two triangles).
struct Edge {
  int64_t a, b, c;
  int64_t threshold;
  FASTSHADE_FORCE_INLINE int64_t at(int64_t x_fx, int64_t y_fx) const { return a * x_fx + b * y_fx + c; }
  bool covers(int64_t x_fx, int64_t y_fx) const { return at(x_fx, y_fx) >= threshold; }
};

// Edge functions run on doubled fixed-point coordinates, one fractional bit more than the
// vertices have (9), so that the edge midpoints of Sierpinski subtriangles are exact points
// too (docs/PAPER.md, "Sierpinski subtriangles and the ninth bit": midpoints of 8-bit vertices
// need a ninth bit). A doubled coordinate is below
// 2^25, an edge value below 2^51: exact in int64 and in a double.
inline constexpr int64_t kEdgeUnitsPerPixel = 2 * limits::kSubpixelOne;

inline constexpr int64_t pixel_centre_fx(int64_t px) {
  return px * kEdgeUnitsPerPixel + kEdgeUnitsPerPixel / 2;
}

// The edge from a to b, in doubled coordinates. Triangles are wound so that their area is
// positive: clockwise on the y-down screen.
FASTSHADE_FORCE_INLINE Edge make_edge(int64_t xa, int64_t ya, int64_t xb, int64_t yb) {
  const int64_t dx = xb - xa, dy = yb - ya;
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

// Edge k runs from corner k+1 to corner k+2 (mod 3), so E_k(corner k) is the area.
FASTSHADE_FORCE_INLINE TriangleEdges edges_of(const int64_t x[3], const int64_t y[3]) {
  TriangleEdges te;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    te.e[k] = make_edge(x[i], y[i], x[j], y[j]);
  }
  return te;
}

// The whole triangle's edges: what attributes are interpolated over.
FASTSHADE_FORCE_INLINE TriangleEdges shape_edges(const SetupTriangle& t) {
  const int64_t x[3] = {2 * int64_t(t.x_fx[0]), 2 * int64_t(t.x_fx[1]), 2 * int64_t(t.x_fx[2])};
  const int64_t y[3] = {2 * int64_t(t.y_fx[0]), 2 * int64_t(t.y_fx[1]), 2 * int64_t(t.y_fx[2])};
  return edges_of(x, y);
}

// The corners of Sierpinski part p (1-3: the subtriangle at vertex p - 1; 4: the middle one,
// the parent turned half a turn about its centroid, so wound the same way), doubled.
inline void sierpinski_corners(const SetupTriangle& t, int part, int64_t x[3], int64_t y[3]) {
  int64_t vx[3], vy[3], mx[3], my[3];  // mx[k]: midpoint of the edge opposite vertex k
  for (int k = 0; k < 3; ++k) vx[k] = 2 * int64_t(t.x_fx[k]), vy[k] = 2 * int64_t(t.y_fx[k]);
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    mx[k] = int64_t(t.x_fx[i]) + t.x_fx[j];
    my[k] = int64_t(t.y_fx[i]) + t.y_fx[j];
  }
  if (part == 4) {  // (m2, m0, m1): midpoints of AB, BC, CA, in the parent's order
    x[0] = mx[2], y[0] = my[2], x[1] = mx[0], y[1] = my[0], x[2] = mx[1], y[2] = my[1];
    return;
  }
  const int v = part - 1;  // corner v with the midpoints of its two edges, in winding order
  const int next = (v + 1) % 3, prev = (v + 2) % 3;
  x[v] = vx[v], y[v] = vy[v];
  x[next] = mx[prev], y[next] = my[prev];  // midpoint of edge v -> next (opposite prev)
  x[prev] = mx[next], y[prev] = my[next];  // midpoint of edge prev -> v (opposite next)
}

inline int sierpinski_part(const SetupTriangle& t) { return (t.flags >> kSierpinskiShift) & 7; }

// What coverage is tested against: the triangle, or its Sierpinski part.
FASTSHADE_FORCE_INLINE TriangleEdges triangle_edges(const SetupTriangle& t) {
  const int part = sierpinski_part(t);
  if (part == 0) return shape_edges(t);
  int64_t x[3], y[3];
  sierpinski_corners(t, part, x, y);
  return edges_of(x, y);
}

// Twice the area in vertex fixed point; edge values (doubled coordinates) are 4x larger.
FASTSHADE_FORCE_INLINE int64_t doubled_area(const SetupTriangle& t) {
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
