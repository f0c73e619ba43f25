// The frame loop: front end (vertex stage, triangle setup), binning, back end, with stage
// times: the Renderer of include/fastshade/render.h.
#include <algorithm>
#include <chrono>
#include <optional>

#include <tbb/parallel_for.h>

#include "classify/classifier.h"
#include "core/ms_between.h"
#include "core/simd_target.h"
#include "exec/aov_pass.h"
#include "exec/auto_cost.h"
#include "exec/exec_limits.h"
#include "exec/frame_profile.h"
#include "exec/frame_stats.h"
#include "exec/resolve_options.h"
#include "exec/tile_executor.h"
#include "exec/tile_size.h"
#include "exec/worker_arena.h"
#include "fastshade/error.h"
#include "fastshade/render.h"
#include "front/binning.h"
#include "front/scene_geometry.h"
#include "front/segment_steps.h"
#include "front/self_occlusion.h"
#include "front/shade_setup.h"
#include "front/triangle_setup.h"
#include "front/vertex_stage.h"
#include "shade/method.h"

namespace fastshade {

namespace {

using Clock = SteadyClock;

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

// The arrays `which` names at the frame's size, the others emptied.
void size_aovs(const AovSet& which, AovImages& out, int width, int height) {
  const std::size_t n = std::size_t(width) * height;
  out.width = width;
  out.height = height;
  out.present = which;
  out.depth.resize(which.depth ? n : 0);
  out.normal.resize(which.normal ? n * 3 : 0);
  out.triangle_id.resize(which.triangle_id ? n : 0);
  out.object_id.resize(which.object_id ? n : 0);
}

}  // namespace

struct Renderer::Impl {
  RenderOptions options;  // checked (exec/resolve_options.h)
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
  AovFrame aov;  // aov.which: what the front end was last set up for

  Impl(const Scene& scene, const RenderOptions& o, const ResolvedOptions& resolved)
      : options(resolved.options),
        geometry(flatten_scene(scene)),
        method(resolved.method),
        xf(view_transform(scene)),
        arena(o.threads) {
    const RenderOptions& c = options;
    frame.simd = resolved.simd;
    setup.simd = frame.simd;
    setup.viewport = make_viewport(scene.width, scene.height);
    frame.grid = make_grid(scene.width, scene.height,
                           resolve_tile_px(o.tile_px, scene.width, scene.height, arena.threads()));
    if (auto_cost_applies(*method, scene, c) &&
        !auto_classifies(simd_target_isa(frame.simd), sampled_triangle_px(geometry, xf, setup.viewport))) {
      method = &find_method(ShadingMethod::Phong);
      options.normals = PhongNormals::Normalize;  // auto's --normals is its diffuse path's alone
    }
    frame.shade = shade_constants(scene, xf, c);
    draw = method->select(frame.simd, frame.shade, c);
    // Without lights `auto` has nothing to classify (every colour is the ambient one).
    classified = method->classifies && !frame.shade.lights.empty();
    if (classified) {
      const bool paper_rule = c.classifier == ClassifierRule::Paper;
      classifier.emplace(frame.shade,
                         ClassifierParams{c.spec_threshold, auto_gouraud_budget(c.max_error), paper_rule});
      setup.classifier = &*classifier;
      // The literal rule is there to measure the paper's classifier: it classifies everything.
      setup.classify_min_box_px = paper_rule ? 0.0 : c.classify_min_px;
    }
    setup.cull = scene.cull;
    // Culling back faces would remove an inward-wound mesh's occluders.
    if (c.hidden_faces == HiddenFaces::Skip && scene.cull == Cull::None) {
      closures = analyze_closures(geometry);
      setup.occlusion = &occlusion;
    }
    set_needs(AovSet{});
    aov.view_to_world = glm::transpose(glm::dmat3(glm::dmat4(xf.view)));
    for (const ObjectRange& object : geometry.objects) aov.object_first_triangle.push_back(object.first_triangle);
    setup.sierpinski = c.gouraud == GouraudMode::Sierpinski;
    setup.segment_steps = method->segment_steps(c);
    const std::size_t chunks =
        (geometry.triangles.size() + limits::kTrianglesPerChunk - 1) / limits::kTrianglesPerChunk;
    frame.chunks.resize(chunks);
    stats.triangles_in = static_cast<long long>(geometry.triangles.size());
    stats.tiles_total = frame.grid.tile_count();
    stats.threads = arena.threads();
    stats.tile = frame.grid.tile_px;
    stats.method = option_name(o.method);
    stats.drawn_as = option_name(method->id);
    stats.isa = simd_target_name(frame.simd);
  }

  // What the front end computes: the method's attributes, the normals a normal AOV reads, the
  // records' source triangles where ids are written. None of it changes a colour.
  void set_needs(const AovSet& which) {
    needs = method->needs(frame.shade);
    needs.normal = needs.normal || which.normal;
    setup.with_attrs = needs.normal || needs.color || needs.position;
    setup.with_sources = which.ids();
    aov.which = which;
  }

  // Every pixel is written (empty tiles get the background), so a buffer of the right size
  // is reused as it is: a fresh one cost a 4K frame 25 MB of zero-fill and page faults. The
  // same holds for the AOV arrays.
  void render(Image& image, StageTimes* times, FrameProfile* profile, const AovSet& which, AovImages* aovs) {
    image.width = frame.grid.width;
    image.height = frame.grid.height;
    image.rgb.resize(std::size_t(image.width) * image.height * 3);
    if (which != aov.which) set_needs(which);
    aov.out = aovs;
    if (aovs) size_aovs(which, *aovs, frame.grid.width, frame.grid.height);
    const AovFrame* aov_pass = which.any() ? &aov : nullptr;
    StageTimes t;
    BackEndCounts back_end;
    int objects_culled = 0;
    if (profile) profile->reset(frame.chunks.size(), frame.grid.tile_count(), geometry.positions.size());
    arena.execute([&] {
      const auto t0 = Clock::now();
      {
        ItemTimer timer(profile ? &profile->vertex_stage_ns : nullptr);
        objects_culled = run_vertex_stage(frame.simd, geometry, xf, setup.viewport, needs, frame.shade, vertices, frame.attrs);
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
          constexpr uint32_t kBlock = limits::kSegmentStepBlock;
          const uint32_t count = static_cast<uint32_t>(frame.chunks[c].segment_pending.size());
          tbb::parallel_for(uint32_t(0), (count + kBlock - 1) / kBlock, [&](uint32_t block) {
            decide_segment_steps(frame, static_cast<uint32_t>(c), block * kBlock, std::min(count, (block + 1) * kBlock));
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
          executor.run(frame, draw, image, profile ? profile->tile_ns.data() : nullptr, aov_pass);
      t.raster_shade = ms_since(t2);
      t.total = ms_since(t0);
      if (profile) profile->stages = t;
      back_end = counts;
    });
    stats.threads = arena.threads_available();
    count_frame({geometry, frame, back_end, objects_culled, method->classifies, classified,
                 options.classify_min_px, setup.segment_steps},
                stats);
    if (times) *times = t;
  }
};

Renderer::Renderer(const Scene& scene, const RenderOptions& options)
    : impl_(std::make_unique<Impl>(scene, options, resolve(options))) {}
Renderer::~Renderer() = default;

Image Renderer::render_frame(StageTimes* times, FrameProfile* profile) {
  Image image;
  impl_->render(image, times, profile, AovSet{}, nullptr);
  return image;
}
void Renderer::render_frame(Image& into, StageTimes* times, FrameProfile* profile) {
  impl_->render(into, times, profile, AovSet{}, nullptr);
}
void Renderer::render_frame(Image& into, const AovSet& which, AovImages& aovs, StageTimes* times) {
  impl_->render(into, times, nullptr, which, &aovs);
}
RenderStats Renderer::last_stats() const { return impl_->stats; }

}  // namespace fastshade
