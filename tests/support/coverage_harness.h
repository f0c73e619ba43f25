// Drives the front end and back end on clip-space triangles and reads back, per pixel, how
// many triangles covered it: the raster tests' view of the pipeline, shading left out.
#pragma once
#include <array>
#include <vector>

#include <glm/vec4.hpp>

#include "exec/tile_executor.h"
#include "front/binning.h"
#include "front/triangle_setup.h"

namespace fastshade::test {

struct CoverageResult {
  int width = 0, height = 0;
  std::vector<int> hits;  // per pixel
  long long dropped = 0, culled = 0, drawn = 0;
  int at(int x, int y) const { return hits[std::size_t(y) * width + x]; }
};

// Adds 1 to the red channel of every covered pixel: no depth test, so overlaps show as 2+.
inline void count_hits(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  const SetupTriangle& t = frame.triangle(entry);
  const TriangleEdges edges = triangle_edges(t);
  const PixelRect r{std::max<int>(t.px_min[0], tt.rect.x0), std::max<int>(t.px_min[1], tt.rect.y0),
                    std::min<int>(t.px_max[0], tt.rect.x1), std::min<int>(t.px_max[1], tt.rect.y1)};
  if (r.x0 > r.x1 || r.y0 > r.y1) return;
  for_each_span(edges, r, [&](int py, int x0, int x1) {
    uint32_t* row = tt.color + (py - tt.y_origin) * tt.stride - tt.x_origin;
    for (int x = x0; x <= x1; ++x) row[x] += 1;
  });
}

// Each triangle is three clip-space positions; chunks of `per_chunk` triangles.
inline CoverageResult rasterize_clip_triangles(const std::vector<std::array<glm::vec4, 3>>& tris,
                                               int width, int height, int tile_px,
                                               int per_chunk = 64, Cull cull = Cull::None,
                                               bool sierpinski = false) {
  SceneGeometry g;
  for (std::size_t n = 0; n < tris.size(); ++n) {
    const uint32_t base = static_cast<uint32_t>(g.positions.size());
    g.positions.resize(base + 3, glm::vec3(0));
    g.triangles.push_back({base, base + 1, base + 2});
    g.triangle_material.push_back(0);
  }
  const Viewport viewport = make_viewport(width, height);
  ProjectedVertices vertices;
  vertices.resize(g.positions.size());
  for (std::size_t n = 0; n < tris.size(); ++n)
    for (int i = 0; i < 3; ++i) {  // given clip positions: the vertex stage's flags and snapping
      const std::size_t v = n * 3 + i;
      vertices.clip[v] = tris[n][i];
      vertices.flags[v] = vertex_flags(tris[n][i], viewport);
      if (!(vertices.flags[v] & (kNeedsClip | kNonFinite))) vertices.screen[v] = project(tris[n][i], viewport);
    }

  Frame frame;
  frame.grid.width = width;
  frame.grid.height = height;
  frame.grid.tile_px = tile_px;
  frame.grid.tile_shift = __builtin_ctz(tile_px);
  frame.grid.tiles_x = (width + tile_px - 1) / tile_px;
  frame.grid.tiles_y = (height + tile_px - 1) / tile_px;
  frame.shade.background = glm::vec3(0);
  const SetupParams params{.viewport = viewport, .cull = cull, .sierpinski = sierpinski};
  const uint32_t n = static_cast<uint32_t>(tris.size());
  frame.chunks.resize((n + per_chunk - 1) / per_chunk);
  CoverageResult out;
  for (uint32_t c = 0; c < frame.chunks.size(); ++c) {
    setup_chunk(g, vertices, frame.attrs, c * per_chunk, std::min<uint32_t>((c + 1) * per_chunk, n), params,
                frame.chunks[c]);
    count_chunk_bins(frame.grid, false, frame.chunks[c]);
    out.dropped += frame.chunks[c].dropped;
    out.culled += frame.chunks[c].culled;
    out.drawn += static_cast<long long>(frame.chunks[c].triangles.size());
  }
  plan_bins(frame);
  for (uint32_t c = 0; c < frame.chunks.size(); ++c) fill_chunk_bins(frame, c);
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.resize(std::size_t(width) * height * 3);
  TileExecutor executor;
  executor.run(frame, TileDraw{count_hits}, image);
  out.width = width;
  out.height = height;
  out.hits.resize(std::size_t(width) * height);
  for (std::size_t i = 0; i < out.hits.size(); ++i) out.hits[i] = image.rgb[i * 3];
  return out;
}

// Clip-space position of a screen point (pixels, y down) at w = 1, z = 0: setup maps it back.
inline glm::vec4 screen_to_clip(double x_px, double y_px, int width, int height, double w = 1.0) {
  const double x_ndc = x_px / width * 2.0 - 1.0, y_ndc = 1.0 - y_px / height * 2.0;
  return glm::vec4(float(x_ndc * w), float(y_ndc * w), 0.0f, float(w));
}

}  // namespace fastshade::test
