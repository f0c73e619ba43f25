#include "front/triangle_setup.h"

#include <algorithm>
#include <bit>

#include <glm/geometric.hpp>

#include "frame/edge_function.h"
#include "front/clip.h"
#include "front/front_limits.h"
#include "front/triangle_fate.h"

namespace fastshade {

namespace {

class ChunkBuilder {
 public:
  ChunkBuilder(const SetupParams& p, const AttrArrays& attrs, Chunk& chunk, uint32_t first)
      : p_(p), attrs_(attrs), chunk_(chunk), occlusion_(p.occlusion, first) {}

  // The input triangle the next emits come from (its pieces after clipping share its path).
  void begin_source(uint32_t triangle, const uint32_t* idx, uint16_t material, ShadePath planned,
                    uint64_t planned_lights) {
    source_triangle_ = triangle;
    source_ = idx;
    material_ = material;
    planned_ = planned;
    planned_lights_ = planned_lights;
    path_[0] = path_[1] = ShadePath::Unclassified;
  }

  // Decides in SIMD lanes the paths of source triangles sources[0, count) (classify/
  // cone_batch.h): planned[i] (and for Specular the lights reported), Unclassified where
  // classify() must look. Only triangles setup keeps are planned: a dense mesh culls half.
  // In a dense block, triangles of materials with a specular term take the specular path
  // without a look, and the lights reported are all whose term alone may reach the threshold.
  void plan_paths(const SceneGeometry& g, const uint32_t* sources, int count, bool dense, ShadePath* planned,
                  uint64_t* planned_lights) {
    std::fill(planned, planned + count, ShadePath::Unclassified);
    if (!p_.classifier) return;
    alignas(64) double normals[9][kFateBlock];
    NormalsSoA soa;
    for (int k = 0; k < 9; ++k) soa.n[k] = normals[k];
    for (int run = 0; run < count;) {  // runs of one material
      const uint16_t material = g.triangle_material[sources[run]];
      int end = run + 1;
      while (end < count && g.triangle_material[sources[end]] == material) ++end;
      if (dense && p_.classifier->can_highlight(material)) {
        std::fill(planned + run, planned + end, ShadePath::Specular);
        std::fill(planned_lights + run, planned_lights + end, p_.classifier->highlight_lights(material));
        chunk_.paths.unclassified += end - run;
      } else if (const ConeBatchTerms* terms = p_.classifier->cone_batch_terms(material)) {
        for (int i = run; i < end; ++i)
          for (int v = 0; v < 3; ++v) {
            const glm::vec3& n = attrs_.n_view[g.triangles[sources[i]][v]];
            for (int c = 0; c < 3; ++c) normals[3 * v + c][i - run] = n[c];
          }
        decide_paths_batch(p_.simd, *terms, soa, end - run, planned + run, planned_lights + run);
      }
      run = end;
    }
  }

  // Whether the triangles that culling keeps are so small on screen (mean pixel box below
  // classify_min_box_px) that classifying them would cost more than the specular path saves:
  // there per-pixel Phong, lit through the tile's pixel queue, costs about what Gouraud does.
  // A block is a fixed range of input triangles, and the mean is taken before hidden back
  // faces are left out, so the answer is the same for any thread count, tile size or
  // --hidden-faces.
  bool dense(int64_t box_area_px, int count) const {
    return p_.classify_min_box_px > 0.0 && count > 0 &&
           static_cast<double>(box_area_px) < p_.classify_min_box_px * count;
  }

  // Culls, winds and bounds one triangle of snapped vertices (a clipped piece).
  void emit(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, uint32_t attr_a,
            uint32_t attr_b, uint32_t attr_c, uint16_t material) {
    const TriangleDecision t = decide_triangle(a, b, c, p_.viewport.width, p_.viewport.height, p_.cull == Cull::Back);
    if (t.fate == TriangleFate::kDropped) ++chunk_.dropped;
    else if (t.fate == TriangleFate::kCulled) ++chunk_.culled;
    else append(a, b, c, attr_a, attr_b, attr_c, material, t.fate == TriangleFate::kBack, t.box);
  }

  // The kept triangles of unclipped source triangles decided in lanes, in order: source[i] is
  // the input triangle in column i. Their paths are planned once the survivors are known.
  void emit_columns(const SceneGeometry& g, const ScreenVertex* screen, const TriangleColumns& columns,
                    const uint32_t* source, int count) {
    TriangleFates fates;
    decide_triangles(p_.simd, columns, count, p_.viewport.width, p_.viewport.height, p_.cull == Cull::Back, fates);
    chunk_.dropped += fates.dropped;
    chunk_.culled += fates.culled;
    int kept = 0, hidden = 0;  // counted here: the chunk's counters in the loop made a chain of stores and loads
    int64_t box_area_px = 0;
    uint32_t kept_source[kFateBlock];
    uint16_t kept_column[kFateBlock];
    for (int word = 0; word * 64 < count; ++word)
      for (uint64_t bits = fates.kept[word]; bits; bits &= bits - 1) {
        const int i = word * 64 + std::countr_zero(bits);
        box_area_px += int64_t(fates.x1[i] - fates.x0[i] + 1) * (fates.y1[i] - fates.y0[i] + 1);
        const bool back_facing = (fates.back[word] >> (i % 64)) & 1;
        if (occlusion_.hidden(source[i], back_facing, {fates.x0[i], fates.y0[i], fates.x1[i], fates.y1[i]})) {
          ++hidden;
          continue;
        }
        kept_source[kept] = source[i];
        kept_column[kept++] = static_cast<uint16_t>(i);
      }
    chunk_.culled += hidden;
    chunk_.hidden += hidden;
    ShadePath planned[kFateBlock];
    uint64_t planned_lights[kFateBlock];
    plan_paths(g, kept_source, kept, dense(box_area_px, kept + hidden), planned, planned_lights);
    for (int k = 0; k < kept; ++k) {
      const int i = kept_column[k];
      const auto& idx = g.triangles[kept_source[k]];
      const uint16_t material = g.triangle_material[kept_source[k]];
      begin_source(kept_source[k], idx.data(), material, planned[k], planned_lights[k]);
      const bool back_facing = (fates.back[i / 64] >> (i % 64)) & 1;
      append(screen[idx[0]], screen[idx[1]], screen[idx[2]], idx[0], idx[1], idx[2], material, back_facing,
             {fates.x0[i], fates.y0[i], fates.x1[i], fates.y1[i]});
    }
  }

  // Appends a kept triangle's record (and replaces it by its Sierpinski parts if asked).
  void append(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, uint32_t attr_a,
              uint32_t attr_b, uint32_t attr_c, uint16_t material, bool back_facing, const PixelBox& box) {
    // The rasterizer wants positive area: front faces swap their last two vertices.
    const ScreenVertex& v1 = back_facing ? b : c;
    const ScreenVertex& v2 = back_facing ? c : b;
    SetupTriangle t;  // built whole, then appended: emplace_back() would zero the record first
    t.x_fx[0] = a.x_fx, t.x_fx[1] = v1.x_fx, t.x_fx[2] = v2.x_fx;
    t.y_fx[0] = a.y_fx, t.y_fx[1] = v1.y_fx, t.y_fx[2] = v2.y_fx;
    t.depth[0] = a.depth, t.depth[1] = v1.depth, t.depth[2] = v2.depth;
    t.inv_w[0] = a.inv_w, t.inv_w[1] = v1.inv_w, t.inv_w[2] = v2.inv_w;
    t.attr[0] = attr_a, t.attr[1] = back_facing ? attr_b : attr_c, t.attr[2] = back_facing ? attr_c : attr_b;
    t.px_min[0] = static_cast<int16_t>(box.x0);
    t.px_min[1] = static_cast<int16_t>(box.y0);
    t.px_max[0] = static_cast<int16_t>(box.x1);
    t.px_max[1] = static_cast<int16_t>(box.y1);
    t.material = material;
    t.flags = back_facing ? kBackFacing : 0;
    if (p_.classifier)
      t.flags |= static_cast<uint16_t>(static_cast<int>(path(back_facing)) << kShadePathShift);
    // Sierpinski parts are Gouraud's: a split frame draws no segments.
    if (!p_.sierpinski && draws_segments(t, p_.segment_steps)) chunk_.segment_pending.push_back(static_cast<uint32_t>(chunk_.triangles.size()));
    chunk_.triangles.push_back(t);
    if (p_.with_sources) chunk_.sources.push_back(source_triangle_);
    if (p_.sierpinski && std::max(box.x1 - box.x0, box.y1 - box.y0) + 1 >= limits::kSierpinskiMinPx)
      split_sierpinski();
  }

  // The source triangle's path for this facing, classified on first use.
  ShadePath path(bool back_facing) {
    ShadePath& cached = path_[back_facing];
    if (cached != ShadePath::Unclassified) return cached;
    if (planned_ != ShadePath::Unclassified) {  // settled in lanes
      ++chunk_.paths.triangles[static_cast<int>(planned_)];
      if (planned_ == ShadePath::Specular) chunk_.paths.lights_with_highlight |= planned_lights_;
      return cached = planned_;
    }
    const ShadeConstants& k = p_.classifier->shade();
    // Two-sided lighting shades a back face with its normals flipped (shade/phong-inl.h).
    const double flip = (k.two_sided && back_facing) ? -1.0 : 1.0;
    ClassifyInput in;
    in.local_viewer = k.local_viewer;
    for (int i = 0; i < 3; ++i) {
      in.n[i] = flip * dvec3(attrs_.n_view[source_[i]]);
      if (k.local_viewer) in.v[i] = glm::normalize(-dvec3(attrs_.pos_view[source_[i]]));
    }
    const Classification c = p_.classifier->classify(in, material_);
    ++chunk_.paths.triangles[static_cast<int>(c.path)];
    chunk_.paths.lights_with_highlight |= c.lights_with_highlight;
    return cached = c.path;
  }

  // Replaces the triangle just emitted by its four Sierpinski parts (frame/edge_function.h):
  // each part is its own bin entry, so the parts of a large triangle are drawn as separate
  // tasks, possibly by different workers. Their coverage is exactly the parent's.
  void split_sierpinski() {
    const SetupTriangle parent = chunk_.triangles.back();
    chunk_.triangles.pop_back();
    if (p_.with_sources) chunk_.sources.pop_back();
    const int64_t unit = kEdgeUnitsPerPixel, half = unit / 2;
    for (int part = 1; part <= 4; ++part) {
      int64_t x[3], y[3];
      SetupTriangle t = parent;
      t.flags = static_cast<uint16_t>(parent.flags | (part << kSierpinskiShift));
      sierpinski_corners(parent, part, x, y);
      // Pixel centres inside the part's box (doubled coordinates), within the parent's box.
      const int64_t x_lo = std::min({x[0], x[1], x[2]}) - half, x_hi = std::max({x[0], x[1], x[2]}) - half;
      const int64_t y_lo = std::min({y[0], y[1], y[2]}) - half, y_hi = std::max({y[0], y[1], y[2]}) - half;
      const int px0 = std::max<int>(static_cast<int>((x_lo + unit - 1) >> (limits::kSubpixelBits + 1)), parent.px_min[0]);
      const int py0 = std::max<int>(static_cast<int>((y_lo + unit - 1) >> (limits::kSubpixelBits + 1)), parent.px_min[1]);
      const int px1 = std::min<int>(static_cast<int>(x_hi >> (limits::kSubpixelBits + 1)), parent.px_max[0]);
      const int py1 = std::min<int>(static_cast<int>(y_hi >> (limits::kSubpixelBits + 1)), parent.px_max[1]);
      if (px0 > px1 || py0 > py1) continue;
      t.px_min[0] = static_cast<int16_t>(px0), t.px_min[1] = static_cast<int16_t>(py0);
      t.px_max[0] = static_cast<int16_t>(px1), t.px_max[1] = static_cast<int16_t>(py1);
      chunk_.triangles.push_back(t);
      if (p_.with_sources) chunk_.sources.push_back(source_triangle_);
    }
  }

  // Clips against near, far and the guard band, then fans the polygon (keeping its winding).
  void emit_clipped(const ProjectedVertices& pv, const AttrArrays& attrs, const uint32_t* idx,
                    uint16_t material) {
    ClipVertex poly[kMaxClipVertices];
    for (int i = 0; i < 3; ++i) {
      poly[i].pos_clip = pv.clip[idx[i]];
      poly[i].source = idx[i];
    }
    const int count = clip_polygon(poly, 3, p_.viewport.planes, p_.with_attrs, attrs);
    ScreenVertex screen[kMaxClipVertices];
    uint32_t attr[kMaxClipVertices];
    for (int i = 0; i < count; ++i) {
      screen[i] = project(poly[i].pos_clip, p_.viewport);
      if (poly[i].source != kNewVertex) {
        attr[i] = poly[i].source;
      } else if (p_.with_attrs) {
        attr[i] = kClippedAttr | static_cast<uint32_t>(chunk_.clipped_count++);
        // Only the arrays the method reads exist (the frame's arrays say which).
        if (!attrs.n_view.empty()) chunk_.clipped.n_view.push_back(poly[i].attrs.n_view);
        if (!attrs.color.empty()) chunk_.clipped.color.push_back(poly[i].attrs.color);
        if (!attrs.pos_view.empty()) chunk_.clipped.pos_view.push_back(poly[i].attrs.pos_view);
      } else {
        attr[i] = 0;  // the method reads no attributes
      }
    }
    for (int i = 1; i + 1 < count; ++i)
      emit(screen[0], screen[i], screen[i + 1], attr[0], attr[i], attr[i + 1], material);
  }

 private:
  const SetupParams& p_;
  const AttrArrays& attrs_;
  Chunk& chunk_;
  OcclusionCursor occlusion_;  // unclipped triangles only: an object that needs clipping culls none
  uint32_t source_triangle_ = 0;  // index in SceneGeometry::triangles
  const uint32_t* source_ = nullptr;
  uint16_t material_ = 0;
  ShadePath planned_ = ShadePath::Unclassified;
  uint64_t planned_lights_ = 0;
  ShadePath path_[2] = {};  // per facing: front, back
};

}  // namespace

void setup_chunk(const SceneGeometry& g, const ProjectedVertices& pv,
                 const AttrArrays& attrs, uint32_t first, uint32_t last,
                 const SetupParams& params, Chunk& chunk) {
  chunk.triangles.clear();
  chunk.sources.clear();
  chunk.clipped.clear();
  chunk.clipped_count = 0;
  chunk.dropped = chunk.culled = chunk.hidden = 0;
  chunk.paths = {};
  chunk.segment_pending.clear();
  ChunkBuilder builder(params, attrs, chunk, first);
  const uint8_t* flags = pv.flags.data();
  const ScreenVertex* screen = pv.screen.data();
  // The block's unclipped triangles wait as columns until the block ends or a triangle needs
  // the clipper (whose pieces must follow them: draw order).
  TriangleColumns columns{};  // zeroed once: lanes past a run's end read defined values
  uint32_t source[kFateBlock];
  for (uint32_t block = first; block < last; block += kFateBlock) {
    const uint32_t block_end = std::min(block + kFateBlock, last);
    int run = 0;
    for (uint32_t t = block; t < block_end; ++t) {
      constexpr uint32_t kAhead = limits::kSetupPrefetchTriangles;
      if (t + kAhead < last)
        for (uint32_t v : g.triangles[t + kAhead]) {
          __builtin_prefetch(flags + v);
          __builtin_prefetch(screen + v);
        }
      const auto& idx = g.triangles[t];
      const uint8_t f0 = flags[idx[0]], f1 = flags[idx[1]], f2 = flags[idx[2]];
      if ((f0 | f1 | f2) & kNonFinite) {
        ++chunk.dropped;
        continue;
      }
      if (f0 & f1 & f2 & kOutcodeMask) {  // all outside one frustum plane
        ++chunk.culled;
        continue;
      }
      if (!((f0 | f1 | f2) & kNeedsClip)) {
        for (int v = 0; v < 3; ++v) {
          columns.x_fx[v][run] = screen[idx[v]].x_fx;
          columns.y_fx[v][run] = screen[idx[v]].y_fx;
        }
        source[run++] = t;
        continue;
      }
      builder.emit_columns(g, screen, columns, source, run);
      run = 0;
      // A clipped triangle (rare) is classified by classify(), which the lanes equal exactly.
      builder.begin_source(t, idx.data(), g.triangle_material[t], ShadePath::Unclassified, 0);
      builder.emit_clipped(pv, attrs, idx.data(), g.triangle_material[t]);
    }
    builder.emit_columns(g, screen, columns, source, run);
  }
}

}  // namespace fastshade
