// What every shading method derives first for a binned triangle in one tile: its edges,
// barycentric gradients, the rectangle to walk and the depth plane. Depth comes from here for
// every method, so visibility never depends on the method.
#pragma once
#include <algorithm>

#include "frame/frame.h"
#include "raster/planes.h"
#include "raster/spans.h"

namespace fastshade {

struct TriangleInTile {
  const SetupTriangle* tri;
  TriangleEdges edges;  // coverage of row spans: the triangle or its Sierpinski part
  PixelRect rect;  // bounding box ∩ tile
  // Barycentric gradients and the depth plane exist only once a span is found: a small
  // triangle's box often holds pixel centres it does not cover.
  Barycentrics bary;
  Plane depth;
  bool has_planes = false;

  // The planes span the whole triangle (a Sierpinski part's parent), from edges computed
  // afresh rather than read from `edges`: the packed and box kernels keep their coverage edges
  // in registers, and a vector load of edges just stored as scalars stalls (no forwarding).
  FASTSHADE_FORCE_INLINE void set_up_planes() {
    if (has_planes) return;
    set_barycentrics(*tri, shape_edges(*tri), bary);
    depth = make_plane(bary, tri->depth[0], tri->depth[1], tri->depth[2]);
    has_planes = true;
  }
};

// The triangle's box in this tile, without its edges (a kernel may find the triangle hidden
// before it needs them: shade/span_loop-inl.h ShadeTriangle). False if the box misses the tile.
FASTSHADE_FORCE_INLINE bool place_in_tile(const SetupTriangle& t, const PixelRect& tile, TriangleInTile& out) {
  out.rect = {std::max<int>(t.px_min[0], tile.x0), std::max<int>(t.px_min[1], tile.y0),
              std::min<int>(t.px_max[0], tile.x1), std::min<int>(t.px_max[1], tile.y1)};
  if (out.rect.x0 > out.rect.x1 || out.rect.y0 > out.rect.y1) return false;
  out.tri = &t;
  out.has_planes = false;
  return true;
}

// place_in_tile() and the coverage edges.
FASTSHADE_FORCE_INLINE bool prepare_triangle(const SetupTriangle& t, const PixelRect& tile, TriangleInTile& out) {
  if (!place_in_tile(t, tile, out)) return false;
  out.edges = triangle_edges(t);
  return true;
}

}  // namespace fastshade
