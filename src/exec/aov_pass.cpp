#include "exec/aov_pass.h"

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "exec/tile_io.h"
#include "raster/planes.h"
#include "raster/triangle_in_tile.h"

namespace fastshade {

namespace {

constexpr float kClearedDepth = 1.0f;  // exec/tile_io.h clear_tile
constexpr int kSmallBoxPx = 64;         // shows_nothing(): boxes up to 8x8 are scanned

// Whether no pixel of a small triangle's box can show it: each is taken, or holds a depth
// nearer than the triangle's nearest vertex (its depth plane is clamped to the vertex depths,
// raster/planes.h). A dense mesh's tiles hold many triangles the depth test rejected, and this
// costs a few loads where edges and planes cost a few hundred cycles. Larger boxes go on: a
// scan would cost what the span walk does.
bool shows_nothing(const SetupTriangle& t, const PixelRect& box, const PixelRect& tile, const float* depth, int stride,
                   const uint32_t* entries) {
  if ((box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1) > kSmallBoxPx) return false;
  const float nearest = std::min({t.depth[0], t.depth[1], t.depth[2]});
  for (int py = box.y0; py <= box.y1; ++py) {
    const std::size_t row = std::size_t(py - tile.y0) * stride - tile.x0;
    for (int px = box.x0; px <= box.x1; ++px)
      if (entries[row + px] == kAovNoEntry && depth[row + px] >= nearest) return false;
  }
  return true;
}

// Which of the tile's triangles (its index from `begin`) each pixel shows. The depth test keeps a pixel's first triangle
// in draw order at the least depth (strict less, shade/span_loop-inl.h), and depth comes from
// raster/triangle_in_tile.h for every method: so the shown triangle is the first, in the same
// order, over the same coverage, whose depth at the pixel equals the tile's final depth,
// evaluated by the same float sequence (plane_at). No second depth buffer, and the ids are
// those of the colour by construction.
void resolve_entries(const Frame& frame, uint32_t begin, uint32_t end, const PixelRect& rect, const float* depth,
                     int stride, uint32_t* entries) {
  const int w = rect.x1 - rect.x0 + 1;
  for (int y = 0; y <= rect.y1 - rect.y0; ++y) std::fill_n(entries + y * stride, w, kAovNoEntry);
  for (uint32_t i = begin; i < end; ++i) {
    const SetupTriangle& t = frame.triangle(frame.bin_entries[i]);
    TriangleInTile tri;
    if (!place_in_tile(t, rect, tri) || shows_nothing(t, tri.rect, rect, depth, stride, entries)) continue;
    tri.edges = triangle_edges(t);
    tri.set_up_planes();
    for_each_span(tri.edges, tri.rect, [&](int py, int x0, int x1) {
      const std::size_t row = std::size_t(py - rect.y0) * stride - rect.x0;
      for (int px = x0; px <= x1; ++px) {
        const float z = depth[row + px];
        if (entries[row + px] == kAovNoEntry && z < kClearedDepth &&
            plane_at(tri.depth, pixel_offsets(tri.bary, px, py)) == z)
          entries[row + px] = i - begin;
      }
    });
  }
}

void set_shown(const Frame& frame, const AovFrame& aov, uint32_t entry, AovTriangle& s) {
  s.set_up = true;
  const SetupTriangle& t = frame.triangle(entry);
  // The whole triangle's barycentrics (a Sierpinski part's parent): its vertices' attributes.
  Barycentrics b;
  set_barycentrics(t, shape_edges(t), b);
  s.ax = b.ax;
  s.ay = b.ay;
  const double* lambda[3] = {b.at_anchor, b.d_dx, b.d_dy};
  for (int p = 0; p < 3; ++p) s.inv_w[p] = lambda[p][0] * t.inv_w[0] + lambda[p][1] * t.inv_w[1] + lambda[p][2] * t.inv_w[2];
  if (aov.which.normal) {
    // Two-sided lighting shades a back face with its normal flipped (shade/phong-inl.h).
    const double flip = (frame.shade.two_sided && (t.flags & kBackFacing)) ? -1.0 : 1.0;
    glm::dvec3 n[3];
    for (int k = 0; k < 3; ++k)
      n[k] = flip * double(t.inv_w[k]) * (aov.view_to_world * glm::dvec3(frame.vertex(entry, t.attr[k], &AttrArrays::n_view)));
    for (int p = 0; p < 3; ++p) s.n_world[p] = lambda[p][0] * n[0] + lambda[p][1] * n[1] + lambda[p][2] * n[2];
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

// What empty pixels hold, a widest tile's row of each: streamed into empty tiles.
struct EmptyRows {
  std::vector<float> zeros = std::vector<float>(std::size_t(limits::kMaxTilePx) * 3, 0.0f);
  std::vector<int32_t> no_id = std::vector<int32_t>(limits::kMaxTilePx, -1);
};
const EmptyRows kEmptyRows;

// Rows of `count` values a pixel from the tile's scratch (stride `stride_px` pixels) to the
// frame array `out` (width `width` pixels), at `rect`.
template <typename T>
void stream_out(SimdTarget simd, const T* tile, int stride_px, std::vector<T>& out, int width, const PixelRect& rect,
                int count) {
  const int row_bytes = (rect.x1 - rect.x0 + 1) * count * int(sizeof(T));
  stream_rows(simd, reinterpret_cast<const uint8_t*>(tile), stride_px * count * int(sizeof(T)),
              reinterpret_cast<uint8_t*>(out.data() + (std::size_t(rect.y0) * width + rect.x0) * count),
              width * count * int(sizeof(T)), row_bytes, rect.y1 - rect.y0 + 1);
}

}  // namespace

void AovTileScratch::size_for(int tile_px) {
  const std::size_t n = std::size_t(tile_px) * tile_px;
  if (entries.size() >= n) return;
  entries.resize(n);
  depth.resize(n);
  normal.resize(n * 3);
  triangle_id.resize(n);
  object_id.resize(n);
}

void write_tile_aovs(const Frame& frame, const AovFrame& aov, uint32_t begin, uint32_t end, const PixelRect& rect,
                     const float* tile_depth, int stride_px, AovTileScratch& scratch) {
  scratch.size_for(stride_px);
  resolve_entries(frame, begin, end, rect, tile_depth, stride_px, scratch.entries.data());
  // Each shown triangle's planes once per tile: small triangles take turns along a row.
  scratch.shown.assign(end - begin, AovTriangle{});
  for (int py = rect.y0; py <= rect.y1; ++py) {
    const std::size_t row = std::size_t(py - rect.y0) * stride_px - rect.x0;
    for (int px = rect.x0; px <= rect.x1; ++px) {
      const std::size_t at = row + px;
      const uint32_t local = scratch.entries[at];
      if (local == kAovNoEntry) {
        if (aov.which.depth) scratch.depth[at] = 0.0f;
        if (aov.which.normal) std::fill_n(&scratch.normal[at * 3], 3, 0.0f);
        if (aov.which.triangle_id) scratch.triangle_id[at] = -1;
        if (aov.which.object_id) scratch.object_id[at] = -1;
        continue;
      }
      AovTriangle& shown = scratch.shown[local];
      if (!shown.set_up) set_shown(frame, aov, frame.bin_entries[begin + local], shown);
      const double dx = px - shown.ax, dy = py - shown.ay;
      // 1/w is linear in screen space; w is the view depth.
      if (aov.which.depth)
        scratch.depth[at] = static_cast<float>(1.0 / (shown.inv_w[0] + shown.inv_w[1] * dx + shown.inv_w[2] * dy));
      if (aov.which.normal) {
        const glm::dvec3 n = shown.n_world[0] + shown.n_world[1] * dx + shown.n_world[2] * dy;
        const double len = glm::length(n);
        const glm::dvec3 unit = len > 0.0 ? n * (1.0 / len) : glm::dvec3(0.0);  // one division, not three
        for (int c = 0; c < 3; ++c) scratch.normal[at * 3 + c] = static_cast<float>(unit[c]);
      }
      if (aov.which.triangle_id) scratch.triangle_id[at] = shown.triangle;
      if (aov.which.object_id) scratch.object_id[at] = shown.object;
    }
  }
  AovImages& out = *aov.out;
  if (aov.which.depth) stream_out(frame.simd, scratch.depth.data(), stride_px, out.depth, out.width, rect, 1);
  if (aov.which.normal) stream_out(frame.simd, scratch.normal.data(), stride_px, out.normal, out.width, rect, 3);
  if (aov.which.triangle_id) stream_out(frame.simd, scratch.triangle_id.data(), stride_px, out.triangle_id, out.width, rect, 1);
  if (aov.which.object_id) stream_out(frame.simd, scratch.object_id.data(), stride_px, out.object_id, out.width, rect, 1);
}

void write_empty_aovs(const Frame& frame, const AovFrame& aov, const PixelRect& rect) {
  AovImages& out = *aov.out;
  // Stride 0: the same row every time.
  if (aov.which.depth) stream_out(frame.simd, kEmptyRows.zeros.data(), 0, out.depth, out.width, rect, 1);
  if (aov.which.normal) stream_out(frame.simd, kEmptyRows.zeros.data(), 0, out.normal, out.width, rect, 3);
  if (aov.which.triangle_id) stream_out(frame.simd, kEmptyRows.no_id.data(), 0, out.triangle_id, out.width, rect, 1);
  if (aov.which.object_id) stream_out(frame.simd, kEmptyRows.no_id.data(), 0, out.object_id, out.width, rect, 1);
}

}  // namespace fastshade
