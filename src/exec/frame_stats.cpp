#include "exec/frame_stats.h"

#include <utility>

#include "exec/left_out.h"
#include "front/segment_steps.h"

namespace fastshade {

void count_frame(const FrameOutcome& f, RenderStats& stats) {
  stats.tiles_nonempty = f.back_end.tiles_nonempty;
  stats.covered_pixels = f.back_end.covered_pixels;
  stats.triangles_drawn = stats.triangles_dropped = stats.triangles_culled = stats.triangles_hidden = 0;
  PathTally tally;
  for (const Chunk& c : f.frame.chunks) {
    stats.triangles_drawn += static_cast<long long>(c.triangles.size());
    stats.triangles_dropped += c.dropped;
    stats.triangles_culled += c.culled;
    stats.triangles_hidden += c.hidden;
    tally.add(c.paths);
  }
  stats.paths.clear();
  stats.triangles_unclassified = tally.unclassified;
  stats.segment_triangles.clear();
  stats.segment_split = stats.segment_no_specular = 0;
  if (f.segment_steps != SegmentSteps::None) {
    SegmentTally segments = tally_segment_plans(f.frame);
    stats.segment_triangles = std::move(segments.by_log2_px);
    stats.segment_split = segments.split;
    stats.segment_no_specular = segments.no_specular;
  }
  if (f.classified)
    for (int p = 1; p < kShadePathCount; ++p)
      stats.paths.push_back({kShadePathNames[p], tally.triangles[p], f.back_end.path_pixels[p]});
  stats.left_out = left_out_report(f.geometry, f.frame.shade,
                                   {f.classified ? &tally : nullptr, f.back_end, stats.tiles_total,
                                    f.objects_culled, stats.triangles_hidden, stats.segment_no_specular,
                                    f.method_classifies, f.classify_min_px});
}

}  // namespace fastshade
