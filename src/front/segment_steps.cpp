#include "front/segment_steps.h"

#include <bit>
#include <vector>

#include "classify/segment_step.h"
#include "core/limits.h"
#include "frame/edge_function.h"
#include "raster/planes.h"

namespace fastshade {

bool draws_segments(const SetupTriangle& t, SegmentSteps which) {
  if (which == SegmentSteps::None || t.px_max[0] - t.px_min[0] + 1 < limits::kHybridMinWidthPx) return false;
  return which == SegmentSteps::All || Frame::path_of(t) == ShadePath::Specular;
}

void decide_segment_steps(Frame& frame, uint32_t chunk, uint32_t first, uint32_t last) {
  const ShadeConstants& k = frame.shade;
  Chunk& c = frame.chunks[chunk];
  for (uint32_t p = first; p < last; ++p) {
    const uint32_t i = c.segment_pending[p];
    SetupTriangle& t = c.triangles[i];
    const uint32_t entry = bin_entry(chunk, i);
    // The kernel's planes interpolate flip * n / w and p / w (shade/phong-inl.h
    // set_up_phong_planes); their x gradients, in double, from the barycentrics' exact ones.
    const float flip = (k.two_sided && (t.flags & kBackFacing)) ? -1.0f : 1.0f;
    const Barycentrics b = barycentrics(t, triangle_edges(t));
    SegmentStepInput in;
    in.material = &k.materials[t.material];
    in.shade = &k;
    for (int v = 0; v < 3; ++v) {
      in.n[v] = flip * frame.vertex(entry, t.attr[v], &AttrArrays::n_view);
      in.inv_w[v] = t.inv_w[v];
      in.n_over_w_dx += (dvec3(in.n[v]) * double(t.inv_w[v])) * b.d_dx[v];
      if (k.local_viewer) {
        in.pos_view[v] = frame.vertex(entry, t.attr[v], &AttrArrays::pos_view);
        in.pos_over_w_dx += (dvec3(in.pos_view[v]) * double(t.inv_w[v])) * b.d_dx[v];
      } else {
        in.pos_view[v] = glm::vec3(0.0f);
      }
    }
    const SegmentPlan plan = hybrid_triangle_step(in, k.hybrid_tolerance);
    t.flags = static_cast<uint16_t>((t.flags & ~(kSegmentStepMask | kSplitLightMask | kSegmentNoSpecular)) |
                                    (std::countr_zero(unsigned(plan.step_px)) << kSegmentStepShift) |
                                    ((plan.split_light + 1) << kSplitLightShift) |
                                    (plan.specular ? 0 : kSegmentNoSpecular));
  }
}

SegmentTally tally_segment_plans(const Frame& frame) {
  SegmentTally tally;  // left empty where no triangle reached hybrid (auto without a highlight)
  for (const Chunk& c : frame.chunks)
    for (const uint32_t i : c.segment_pending) {
      if (tally.by_log2_px.empty()) tally.by_log2_px.assign(std::countr_zero(unsigned(limits::kSeedBlockPx)) + 1, 0);
      const SetupTriangle& t = c.triangles[i];
      ++tally.by_log2_px[std::countr_zero(unsigned(Frame::segment_step_px(t)))];
      tally.split += Frame::split_light(t) >= 0;
      tally.no_specular += Frame::segment_step_px(t) > 1 && !Frame::segment_specular(t);
    }
  return tally;
}

}  // namespace fastshade
