// The frame loop: front end (vertex stage, triangle setup), binning, back end, with stage
// times. Implements include/fastshade/render.h.
#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>

#include <tbb/parallel_for.h>

#include "classify/segment_step.h"
#include "exec/frame_profile.h"
#include "exec/isa.h"
#include "exec/left_out.h"
#include "exec/tile_executor.h"
#include "exec/tile_size.h"
#include "exec/worker_arena.h"
#include "fastshade/error.h"
#include "fastshade/render.h"
#include "front/binning.h"
#include "front/scene_geometry.h"
#include "front/segment_steps.h"
#include "front/self_occlusion.h"
#include "front/triangle_setup.h"
#include "front/vertex_stage.h"
#include "light/brdf.h"
#include "shade/method.h"
#include "shade/normal_blocks.h"

namespace fastshade {

std::string RenderOptions::to_string() const {
  std::ostringstream s;
  s << "method=" << method << " threads=" << threads << " tile=" << (tile_px ? std::to_string(tile_px) : "auto")
    << " isa=" << isa
    << " srgb=" << (srgb ? "on" : "off") << " brdf=" << brdf << " max_error=" << max_error
    << " normals=" << normals << " gouraud=" << gouraud << " hidden_faces=" << hidden_faces;
  if (method == "auto")
    s << " spec_threshold=" << spec_threshold << " spec_method=" << spec_method
      << " classifier=" << classifier << " classify_min_px=" << classify_min_px;
  return s.str();
}

void validate(const RenderOptions& o) {
  if (o.threads < 0 || o.threads > 1024)
    throw InputError("--threads", "expected 0 (all) to 1024, got " + std::to_string(o.threads));
  if (o.tile_px != 0 && (o.tile_px < limits::kMinTilePx || o.tile_px > limits::kMaxTilePx ||
                         (o.tile_px & (o.tile_px - 1)) != 0))
    throw InputError("--tile", "expected a power of two from " + std::to_string(limits::kMinTilePx) + " to " +
                                   std::to_string(limits::kMaxTilePx) +
                                   ", or 0 (sized from the image and threads), got " + std::to_string(o.tile_px));
  const Method* method = find_method(o.method);
  if (!method) {
    std::string names;
    for (const Method& m : all_methods()) names += (names.empty() ? "" : ", ") + std::string(m.name);
    throw InputError("--method", "unknown method '" + o.method + "' (expected one of: " + names + ")");
  }
  parse_brdf(o.brdf, "--brdf");
  parse_normals(o.normals, "--normals");
  if (o.gouraud != "increments" && o.gouraud != "sierpinski")
    throw InputError("--gouraud", "expected increments or sierpinski, got '" + o.gouraud + "'");
  if (o.hidden_faces != "skip" && o.hidden_faces != "draw")
    throw InputError("--hidden-faces", "expected skip or draw, got '" + o.hidden_faces + "'");
  if (o.gouraud == "sierpinski" && o.method != "gouraud")
    throw InputError("--gouraud", "sierpinski subtriangles apply to --method gouraud only");
  if (!(o.max_error >= 0 && o.max_error <= 255))
    throw InputError("--max-error", "expected 0 to 255 (8-bit steps), got " + std::to_string(o.max_error));
  if (!method->classifies) {
    const RenderOptions defaults;
    for (const auto& [set, flag] : {std::pair{o.spec_threshold != defaults.spec_threshold, "--spec-threshold"},
                                    std::pair{o.spec_method != defaults.spec_method, "--spec-method"},
                                    std::pair{o.classifier != defaults.classifier, "--classifier"},
                                    std::pair{o.classify_min_px != defaults.classify_min_px, "--classify-min-px"}})
      if (set) throw InputError(flag, "applies to --method auto only");
  }
  if (const std::string why = method->refuse(o); !why.empty()) {
    const std::size_t colon = why.find(": ");  // "--option: reason"
    throw InputError(why.substr(0, colon), why.substr(colon + 2));
  }
}

std::vector<MethodDescription> list_methods() {
  std::vector<MethodDescription> out;
  for (const Method& m : all_methods()) out.push_back({std::string(m.name), std::string(m.summary)});
  return out;
}

double RenderStats::mpix_per_s() const {
  return median.total > 0 ? covered_pixels / (median.total * 1e3) : 0.0;
}
double RenderStats::mtri_per_s() const {
  return median.total > 0 ? triangles_in / (median.total * 1e3) : 0.0;
}

namespace {

using Clock = std::chrono::steady_clock;

// Triangles per task of the segment-length pass: about 50-100 us of work at 0.2-0.4 us a triangle,
// far above a task's cost, and 16 tasks for a chunk of 4096.
constexpr uint32_t kStepBlock = 256;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

TileGrid make_grid(int width, int height, int tile_px) {
  TileGrid g;
  g.width = width;
  g.height = height;
  g.tile_px = tile_px;
  g.tile_shift = std::countr_zero(static_cast<unsigned>(tile_px));
  g.tiles_x = (width + tile_px - 1) / tile_px;
  g.tiles_y = (height + tile_px - 1) / tile_px;
  return g;
}

}  // namespace

struct Renderer::Impl {
  RenderOptions options;
  SceneGeometry geometry;
  const Method* method;
  ViewTransform xf;
  AttrNeeds needs;
  TileDraw draw;
  bool classified = false;
  std::optional<Classifier> classifier;
  std::vector<MeshClosure> closures;  // per object, when hidden faces are skipped
  SelfOcclusionPlan occlusion;
  WorkerArena arena;
  Frame frame;
  ProjectedVertices vertices;
  SetupParams setup;
  TileExecutor executor;
  RenderStats stats;

  Impl(const Scene& scene, const RenderOptions& o)
      : options(o),
        geometry(flatten_scene(scene)),
        method(find_method(o.method)),
        xf(view_transform(scene)),
        arena(o.threads) {
    select_isa(o.isa);
    frame.grid = make_grid(scene.width, scene.height,
                           resolve_tile_px(o.tile_px, scene.width, scene.height, arena.threads()));
    frame.shade = shade_constants(scene, xf, o.srgb, parse_brdf(o.brdf, "--brdf"));
    frame.shade.hybrid_tolerance = hybrid_tolerance(o.max_error);
    frame.shade.normals = parse_normals(o.normals, "--normals");
    needs = method->needs(frame.shade);
    draw = method->select(frame.shade, o);
    // Without lights `auto` has nothing to classify (every colour is the ambient one).
    classified = method->classifies && !frame.shade.lights.empty();
    if (classified) {
      classifier.emplace(frame.shade, ClassifierParams{o.spec_threshold, auto_gouraud_budget(o.max_error),
                                                       o.classifier == "paper"});
      setup.classifier = &*classifier;
      // The literal rule is there to measure the paper's classifier: it classifies everything.
      setup.classify_min_box_px = o.classifier == "paper" ? 0.0 : o.classify_min_px;
    }
    setup.viewport = make_viewport(scene.width, scene.height);
    setup.cull = scene.cull;
    // Culling back faces would remove an inward-wound mesh's occluders.
    if (o.hidden_faces == "skip" && scene.cull == Cull::None) {
      closures = analyze_closures(geometry);
      setup.occlusion = &occlusion;
    }
    setup.with_attrs = needs.normal || needs.color || needs.position;
    setup.sierpinski = o.gouraud == "sierpinski";
    setup.segment_steps = method->segment_steps(o);
    const std::size_t chunks =
        (geometry.triangles.size() + limits::kTrianglesPerChunk - 1) / limits::kTrianglesPerChunk;
    frame.chunks.resize(chunks);
    stats.triangles_in = static_cast<long long>(geometry.triangles.size());
    stats.tiles_total = frame.grid.tile_count();
    stats.threads = arena.threads();
    stats.tile = frame.grid.tile_px;
    stats.method = o.method;
    stats.isa = active_isa();
  }

  // Every pixel is written (empty tiles get the background), so a buffer of the right size
  // is reused as it is: a fresh one cost a 4K frame 25 MB of zero-fill and page faults.
  void render(Image& image, StageTimes* times, FrameProfile* profile) {
    image.width = frame.grid.width;
    image.height = frame.grid.height;
    image.rgb.resize(std::size_t(image.width) * image.height * 3);
    StageTimes t;
    BackEndCounts back_end;
    int objects_culled = 0;
    if (profile) profile->reset(frame.chunks.size(), frame.grid.tile_count(), geometry.positions.size());
    arena.execute([&] {
      const auto t0 = Clock::now();
      {
        ItemTimer timer(profile ? &profile->vertex_stage_ns : nullptr);
        objects_culled = run_vertex_stage(geometry, xf, setup.viewport, needs, frame.shade, vertices, frame.attrs);
        if (setup.occlusion) plan_self_occlusion(geometry, closures, vertices, occlusion);
      }
      const uint32_t n_tris = static_cast<uint32_t>(geometry.triangles.size());
      // Each chunk is counted into its tiles right after its setup, while its records are in
      // cache: the count belongs to the front end's time, binning is the plan and the fill.
      tbb::parallel_for(std::size_t(0), frame.chunks.size(), [&](std::size_t c) {
        ItemTimer timer(profile_slot(profile, &FrameProfile::setup_chunk_ns, c));
        const uint32_t first = static_cast<uint32_t>(c * limits::kTrianglesPerChunk);
        const uint32_t last = std::min<uint32_t>(first + limits::kTrianglesPerChunk, n_tris);
        setup_chunk(geometry, vertices, frame.attrs, first, last, setup, frame.chunks[c]);
        count_chunk_bins(frame.grid, classified, frame.chunks[c]);
      });
      // Segment lengths after setup, in blocks across all chunks: the first chunks of a small
      // mesh hold most of its triangles, and deciding a step costs about 0.2-0.4 us.
      if (setup.segment_steps != SegmentSteps::None)
        tbb::parallel_for(std::size_t(0), frame.chunks.size(), [&](std::size_t c) {
          const uint32_t count = static_cast<uint32_t>(frame.chunks[c].segment_pending.size());
          tbb::parallel_for(uint32_t(0), (count + kStepBlock - 1) / kStepBlock, [&](uint32_t block) {
            decide_segment_steps(frame, static_cast<uint32_t>(c), block * kStepBlock,
                                 std::min(count, (block + 1) * kStepBlock));
          });
        });
      t.front_end = ms_since(t0);

      const auto t1 = Clock::now();
      {
        ItemTimer timer(profile ? &profile->plan_bins_ns : nullptr);
        plan_bins(frame);
      }
      tbb::parallel_for(std::size_t(0), frame.chunks.size(), [&](std::size_t c) {
        ItemTimer timer(profile_slot(profile, &FrameProfile::fill_chunk_ns, c));
        fill_chunk_bins(frame, static_cast<uint32_t>(c));
      });
      t.binning = ms_since(t1);

      const auto t2 = Clock::now();
      const BackEndCounts counts =
          executor.run(frame, draw, image, profile ? profile->tile_ns.data() : nullptr);
      t.raster_shade = ms_since(t2);
      t.total = ms_since(t0);
      if (profile) profile->stages = t;
      back_end = counts;
    });
    stats.threads = arena.threads_available();
    stats.tiles_nonempty = back_end.tiles_nonempty;
    stats.covered_pixels = back_end.covered_pixels;
    stats.triangles_drawn = stats.triangles_dropped = stats.triangles_culled = stats.triangles_hidden = 0;
    PathTally tally;
    for (const Chunk& c : frame.chunks) {
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
    if (setup.segment_steps != SegmentSteps::None) {
      SegmentTally segments = tally_segment_plans(frame);
      stats.segment_triangles = std::move(segments.by_log2_px);
      stats.segment_split = segments.split;
      stats.segment_no_specular = segments.no_specular;
    }
    if (classified)
      for (int p = 1; p < kShadePathCount; ++p)
        stats.paths.push_back({kShadePathNames[p], tally.triangles[p], back_end.path_pixels[p]});
    stats.left_out = left_out_report(geometry, frame.shade, options,
                                     {classified ? &tally : nullptr, back_end, stats.tiles_total, objects_culled,
                                      stats.triangles_hidden, stats.segment_no_specular});
    if (times) *times = t;
  }
};

Renderer::Renderer(const Scene& scene, const RenderOptions& options) {
  validate(options);
  impl_ = std::make_unique<Impl>(scene, options);
}
Renderer::~Renderer() = default;

Image Renderer::render_frame(StageTimes* times, FrameProfile* profile) {
  Image image;
  impl_->render(image, times, profile);
  return image;
}
void Renderer::render_frame(Image& into, StageTimes* times, FrameProfile* profile) {
  impl_->render(into, times, profile);
}
RenderStats Renderer::last_stats() const { return impl_->stats; }

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

Image render(const Scene& scene, const RenderOptions& options, int frames, RenderStats* stats) {
  Renderer renderer(scene, options);
  frames = std::max(frames, 1);
  StageTimes t;
  Image image = renderer.render_frame(&t);
  std::vector<double> front, bin, back, total;
  auto record = [&] {
    front.push_back(t.front_end);
    bin.push_back(t.binning);
    back.push_back(t.raster_shade);
    total.push_back(t.total);
  };
  // One frame is the frame asked for, timed; a benchmark's first frame is a warm-up
  // (first-touch allocation, caches) that no median includes.
  if (frames == 1) record();
  for (int i = 0; i < frames && frames > 1; ++i) {
    renderer.render_frame(image, &t);
    record();
  }
  if (stats) {
    *stats = renderer.last_stats();
    stats->frames = frames;
    stats->median = {median(front), median(bin), median(back), median(total)};
  }
  return image;
}

}  // namespace fastshade
