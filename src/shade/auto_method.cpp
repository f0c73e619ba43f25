// `auto`: the classifier's plan (classify/classifier.h) carried out. The front end marks each
// triangle's shading path; here each path gets its kernel, chosen once per frame, and a tile
// whose triangles share one path runs that kernel alone (exec/tile_executor.cpp).
#include "shade/methods.h"
#include "shade/pixel_queue.h"

namespace fastshade {

namespace {

// A tile with several paths: each triangle goes to its path's kernel, and its pixels carry
// the path in their alpha byte (the per-path pixel counts of RenderStats). Only the specular
// path queues small triangles' lanes (shade/pixel_queue.h); the queue is lit, with the tag its
// entries came with, before a triangle of another path draws, so colours land in draw order.
void draw_by_path(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  const ShadePath path = Frame::path_of(frame.triangle(entry));
  TileTarget tagged = tt;
  tagged.alpha_xor = path_alpha_xor(path);
  if (path != ShadePath::Specular) {
    if (tt.pending) light_pending(*tt.pending, tt);
    tagged.pending = nullptr;
  }
  tt.path_draw[static_cast<int>(path)](frame, entry, tagged);
}

}  // namespace

AttrNeeds auto_needs(const ShadeConstants& k) {
  // Without lights every colour is the ambient one: no normals, no classification.
  const bool lit = !k.lights.empty();
  return {.normal = lit || k.two_sided,
          .color = true,
          .position = lit && k.local_viewer,
          .diffuse_color = true};
}

TileDraw select_auto(SimdTarget simd, const ShadeConstants& k, const RenderOptions& c) {
  if (k.lights.empty()) return {select_gouraud_diffuse(simd, k)};
  TileDraw draw;
  draw.any = draw_by_path;
  draw.path[static_cast<int>(ShadePath::GouraudDiffuse)] = select_gouraud_diffuse(simd, k);
  draw.path[static_cast<int>(ShadePath::PixelDiffuse)] =
      k.normals == PhongNormals::Normalize ? select_phong_diffuse(simd, k) : select_phong_normals_diffuse(simd, k);
  draw.path[static_cast<int>(ShadePath::Specular)] =
      c.spec_method == SpecMethod::Phong ? select_phong(simd, k) : select_hybrid(simd, k);
  return draw;
}

SegmentSteps auto_segment_steps(const RenderOptions& c) {
  return c.spec_method == SpecMethod::Hybrid ? SegmentSteps::SpecularPath : SegmentSteps::None;
}

}  // namespace fastshade
