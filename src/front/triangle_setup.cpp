#include "front/triangle_setup.h"

#include <algorithm>
#include <cmath>

#include "frame/edge_function.h"

namespace fastshade {

SetupParams setup_params(const TileGrid& grid, Cull cull, bool with_attrs) {
  SetupParams p;
  p.grid = grid;
  p.cull = cull;
  p.with_attrs = with_attrs;
  // |x_ndc| <= g maps to screen x in [W/2 - G/2, W/2 + G/2]; with W <= G/2 that stays inside
  // (-G, G), the fixed-point range limits.h budgets for.
  p.guard_x = static_cast<float>(limits::kGuardPx) / static_cast<float>(grid.width);
  p.guard_y = static_cast<float>(limits::kGuardPx) / static_cast<float>(grid.height);
  p.planes = guard_band_planes(p.guard_x, p.guard_y);
  return p;
}

namespace {

// Frustum outcodes: a triangle all of whose vertices are outside one plane is invisible.
uint32_t outcode(const glm::vec4& v) {
  return (v.x < -v.w) | (v.x > v.w) << 1 | (v.y < -v.w) << 2 | (v.y > v.w) << 3 |
         (v.z < -v.w) << 4 | (v.z > v.w) << 5;
}

bool needs_clipping(const glm::vec4& v, const SetupParams& p) {
  return !(v.z >= -v.w && v.z <= v.w && std::fabs(v.x) <= p.guard_x * v.w &&
           std::fabs(v.y) <= p.guard_y * v.w);
}

bool finite(const glm::vec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

class ChunkBuilder {
 public:
  ChunkBuilder(const SetupParams& p, uint16_t material, Chunk& chunk)
      : p_(p), material_(material), chunk_(chunk) {}

  // Projects, snaps and emits one triangle whose vertices are inside near/far and the guard band.
  void emit(const glm::vec4* pos_clip, const uint32_t* attr) {
    SetupTriangle t;
    for (int i = 0; i < 3; ++i) {
      const double inv_w = 1.0 / static_cast<double>(pos_clip[i].w);
      const double x_px = (pos_clip[i].x * inv_w + 1.0) * 0.5 * p_.grid.width;
      const double y_px = (1.0 - pos_clip[i].y * inv_w) * 0.5 * p_.grid.height;
      t.x_fx[i] = static_cast<int32_t>(std::lrint(x_px * limits::kSubpixelOne));
      t.y_fx[i] = static_cast<int32_t>(std::lrint(y_px * limits::kSubpixelOne));
      t.depth[i] = static_cast<float>(pos_clip[i].z * inv_w * 0.5 + 0.5);
      t.inv_w[i] = static_cast<float>(inv_w);
      t.attr[i] = attr[i];
    }
    const int64_t area = doubled_area(t);
    if (area == 0) {
      ++chunk_.dropped;
      return;
    }
    // GL's front face is counter-clockwise with y up, i.e. negative area with y down.
    const bool back_facing = area > 0;
    if (back_facing && p_.cull == Cull::Back) {
      ++chunk_.culled;
      return;
    }
    if (!back_facing) {  // the rasterizer wants positive area
      std::swap(t.x_fx[1], t.x_fx[2]);
      std::swap(t.y_fx[1], t.y_fx[2]);
      std::swap(t.depth[1], t.depth[2]);
      std::swap(t.inv_w[1], t.inv_w[2]);
      std::swap(t.attr[1], t.attr[2]);
    }
    // Pixel centres px + 0.5 inside the fixed-point bounding box, clamped to the image.
    const int32_t half = limits::kSubpixelOne / 2;
    const int32_t x_lo = std::min({t.x_fx[0], t.x_fx[1], t.x_fx[2]}) - half;
    const int32_t x_hi = std::max({t.x_fx[0], t.x_fx[1], t.x_fx[2]}) - half;
    const int32_t y_lo = std::min({t.y_fx[0], t.y_fx[1], t.y_fx[2]}) - half;
    const int32_t y_hi = std::max({t.y_fx[0], t.y_fx[1], t.y_fx[2]}) - half;
    const int32_t px0 = std::max((x_lo + limits::kSubpixelOne - 1) >> limits::kSubpixelBits, 0);
    const int32_t py0 = std::max((y_lo + limits::kSubpixelOne - 1) >> limits::kSubpixelBits, 0);
    const int32_t px1 = std::min(x_hi >> limits::kSubpixelBits, p_.grid.width - 1);
    const int32_t py1 = std::min(y_hi >> limits::kSubpixelBits, p_.grid.height - 1);
    if (px0 > px1 || py0 > py1) {
      ++chunk_.culled;
      return;
    }
    t.px_min[0] = static_cast<int16_t>(px0);
    t.px_min[1] = static_cast<int16_t>(py0);
    t.px_max[0] = static_cast<int16_t>(px1);
    t.px_max[1] = static_cast<int16_t>(py1);
    t.material = material_;
    t.flags = back_facing ? kBackFacing : 0;
    chunk_.triangles.push_back(t);
  }

  void emit_clipped(ClipVertex* poly, int count) {
    uint32_t attr[kMaxClipVertices];
    glm::vec4 pos[kMaxClipVertices];
    for (int i = 0; i < count; ++i) {
      pos[i] = poly[i].pos_clip;
      if (poly[i].source != kNewVertex || !p_.with_attrs) {
        attr[i] = poly[i].source == kNewVertex ? 0 : poly[i].source;
      } else {
        attr[i] = kClippedAttr | static_cast<uint32_t>(chunk_.clipped_attrs.size());
        chunk_.clipped_attrs.push_back(poly[i].attrs);
      }
    }
    for (int i = 1; i + 1 < count; ++i) {  // a fan keeps the polygon's winding
      const glm::vec4 tri_pos[3] = {pos[0], pos[i], pos[i + 1]};
      const uint32_t tri_attr[3] = {attr[0], attr[i], attr[i + 1]};
      emit(tri_pos, tri_attr);
    }
  }

  void set_material(uint16_t m) { material_ = m; }

 private:
  const SetupParams& p_;
  uint16_t material_;
  Chunk& chunk_;
};

}  // namespace

void setup_chunk(const SceneGeometry& g, const std::vector<glm::vec4>& clip_pos,
                 const std::vector<VertexAttrs>& attrs, uint32_t first, uint32_t last,
                 const SetupParams& params, Chunk& chunk) {
  chunk.triangles.clear();
  chunk.clipped_attrs.clear();
  chunk.dropped = chunk.culled = 0;
  ChunkBuilder builder(params, 0, chunk);
  for (uint32_t t = first; t < last; ++t) {
    const auto& idx = g.triangles[t];
    const glm::vec4 v[3] = {clip_pos[idx[0]], clip_pos[idx[1]], clip_pos[idx[2]]};
    if (!finite(v[0]) || !finite(v[1]) || !finite(v[2])) {
      ++chunk.dropped;
      continue;
    }
    if (outcode(v[0]) & outcode(v[1]) & outcode(v[2])) {
      ++chunk.culled;
      continue;
    }
    builder.set_material(g.triangle_material[t]);
    if (!needs_clipping(v[0], params) && !needs_clipping(v[1], params) &&
        !needs_clipping(v[2], params)) {
      builder.emit(v, idx.data());
      continue;
    }
    ClipVertex poly[kMaxClipVertices];
    for (int i = 0; i < 3; ++i) {
      poly[i].pos_clip = v[i];
      poly[i].source = idx[i];
    }
    const int n = clip_polygon(poly, 3, params.planes, params.with_attrs,
                               attrs.empty() ? nullptr : attrs.data());
    builder.emit_clipped(poly, n);
  }
}

}  // namespace fastshade
