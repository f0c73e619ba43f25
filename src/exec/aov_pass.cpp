#include "exec/aov_pass.h"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "raster/planes.h"
#include "raster/triangle_in_tile.h"

namespace fastshade {

namespace {

constexpr uint32_t kNoEntry = std::numeric_limits<uint32_t>::max();
constexpr float kClearedDepth = 1.0f;  // exec/tile_io.h clear_tile

// Which bin entry each pixel of the tile shows. The depth test keeps a pixel's first triangle
// in draw order at the least depth (strict less, shade/span_loop-inl.h), and depth comes from
// raster/triangle_in_tile.h for every method: so the shown triangle is the first, in the same
// order, over the same coverage, whose depth at the pixel equals the tile's final depth,
// evaluated by the same float sequence (plane_at). No second depth buffer, and the ids are
// those of the colour by construction.
void resolve_entries(const Frame& frame, uint32_t begin, uint32_t end, const PixelRect& rect, const float* depth,
                     int stride, uint32_t* entries) {
  const int w = rect.x1 - rect.x0 + 1;
  for (int y = 0; y <= rect.y1 - rect.y0; ++y) std::fill_n(entries + y * stride, w, kNoEntry);
  for (uint32_t i = begin; i < end; ++i) {
    const uint32_t entry = frame.bin_entries[i];
    TriangleInTile tri;
    if (!prepare_triangle(frame.triangle(entry), rect, tri)) continue;
    tri.set_up_planes();
    for_each_span(tri.edges, tri.rect, [&](int py, int x0, int x1) {
      const std::size_t row = std::size_t(py - rect.y0) * stride - rect.x0;
      for (int px = x0; px <= x1; ++px) {
        const float z = depth[row + px];
        if (entries[row + px] == kNoEntry && z < kClearedDepth &&
            plane_at(tri.depth, pixel_offsets(tri.bary, px, py)) == z)
          entries[row + px] = entry;
      }
    });
  }
}

// What the pass derives once per shown triangle, reused across its pixels.
struct ShownTriangle {
  uint32_t entry = kNoEntry;
  Barycentrics bary;
  double inv_w[3];
  glm::dvec3 n_view[3];  // weighted by the vertex's 1/w: perspective-correct interpolation
  int32_t object = -1, triangle = -1;
};

void set_shown(const Frame& frame, const AovFrame& aov, uint32_t entry, ShownTriangle& s) {
  s.entry = entry;
  const SetupTriangle& t = frame.triangle(entry);
  // The whole triangle's barycentrics (a Sierpinski part's parent): its vertices' attributes.
  set_barycentrics(t, shape_edges(t), s.bary);
  // Two-sided lighting shades a back face with its normal flipped (shade/phong-inl.h).
  const double flip = (frame.shade.two_sided && (t.flags & kBackFacing)) ? -1.0 : 1.0;
  for (int k = 0; k < 3; ++k) {
    s.inv_w[k] = t.inv_w[k];
    if (aov.which.normal) s.n_view[k] = flip * s.inv_w[k] * glm::dvec3(frame.vertex(entry, t.attr[k], &AttrArrays::n_view));
  }
  if (aov.which.ids()) {
    const uint32_t chunk = entry >> kBinIndexBits, index = entry & ((1u << kBinIndexBits) - 1);
    const uint32_t source = frame.chunks[chunk].sources[index];
    const auto& firsts = aov.object_first_triangle;
    const auto object = std::upper_bound(firsts.begin(), firsts.end(), source) - firsts.begin() - 1;
    s.object = static_cast<int32_t>(object);
    s.triangle = static_cast<int32_t>(source - firsts[object]);
  }
}

}  // namespace

void write_tile_aovs(const Frame& frame, const AovFrame& aov, uint32_t begin, uint32_t end, const PixelRect& rect,
                     const float* tile_depth, int stride_px, uint32_t* entry_scratch) {
  resolve_entries(frame, begin, end, rect, tile_depth, stride_px, entry_scratch);
  AovImages& out = *aov.out;
  ShownTriangle shown;
  for (int py = rect.y0; py <= rect.y1; ++py) {
    const uint32_t* entries = entry_scratch + std::size_t(py - rect.y0) * stride_px - rect.x0;
    for (int px = rect.x0; px <= rect.x1; ++px) {
      const std::size_t at = std::size_t(py) * out.width + px;
      const uint32_t entry = entries[px];
      if (entry == kNoEntry) {
        if (aov.which.depth) out.depth[at] = 0.0f;
        if (aov.which.normal) std::fill_n(&out.normal[at * 3], 3, 0.0f);
        if (aov.which.triangle_id) out.triangle_id[at] = -1;
        if (aov.which.object_id) out.object_id[at] = -1;
        continue;
      }
      if (entry != shown.entry) set_shown(frame, aov, entry, shown);
      // Screen-space barycentrics at the pixel centre, in double from the exact edge
      // functions (raster/planes.h); 1/w is linear in screen space, w the view depth.
      const Barycentrics& b = shown.bary;
      const double dx = px - b.ax, dy = py - b.ay;
      double lambda[3];
      for (int k = 0; k < 3; ++k) lambda[k] = b.at_anchor[k] + b.d_dx[k] * dx + b.d_dy[k] * dy;
      if (aov.which.depth) {
        const double inv_w = lambda[0] * shown.inv_w[0] + lambda[1] * shown.inv_w[1] + lambda[2] * shown.inv_w[2];
        out.depth[at] = static_cast<float>(1.0 / inv_w);
      }
      if (aov.which.normal) {
        const glm::dvec3 n = lambda[0] * shown.n_view[0] + lambda[1] * shown.n_view[1] + lambda[2] * shown.n_view[2];
        const double len = glm::length(n);
        const glm::dvec3 n_world = len > 0.0 ? aov.view_to_world * (n / len) : glm::dvec3(0.0);
        for (int c = 0; c < 3; ++c) out.normal[at * 3 + c] = static_cast<float>(n_world[c]);
      }
      if (aov.which.triangle_id) out.triangle_id[at] = shown.triangle;
      if (aov.which.object_id) out.object_id[at] = shown.object;
    }
  }
}

void write_empty_aovs(const AovFrame& aov, const PixelRect& rect) {
  AovImages& out = *aov.out;
  const int w = rect.x1 - rect.x0 + 1;
  for (int py = rect.y0; py <= rect.y1; ++py) {
    const std::size_t at = std::size_t(py) * out.width + rect.x0;
    if (aov.which.depth) std::fill_n(&out.depth[at], w, 0.0f);
    if (aov.which.normal) std::fill_n(&out.normal[at * 3], std::size_t(w) * 3, 0.0f);
    if (aov.which.triangle_id) std::fill_n(&out.triangle_id[at], w, -1);
    if (aov.which.object_id) std::fill_n(&out.object_id[at], w, -1);
  }
}

}  // namespace fastshade
