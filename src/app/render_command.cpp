#include <cstdio>
#include <optional>

#include <nlohmann/json.hpp>

#include "fastshade/aov_list.h"
#include "app/calibration.h"
#include "app/commands.h"
#include "fastshade/error.h"
#include "fastshade/image.h"
#include "fastshade/scene.h"
#include "fastshade/atomic_file.h"

namespace fastshade {

namespace {

// --explain: the plan in a few lines, on stdout after the summary.
void print_explanation(const RenderStats& s, const RenderOptions& o) {
  std::printf("plan: method %s (%s)\n", s.method.c_str(), o.to_string().c_str());
  long long tris = 0, pixels = 0;
  for (const PathStats& p : s.paths) tris += p.triangles, pixels += p.pixels;
  for (const PathStats& p : s.paths)
    std::printf("  %-16s %9lld triangles (%5.1f %%) %10lld visible pixels (%5.1f %%)\n", p.name.c_str(),
                p.triangles, tris ? 100.0 * p.triangles / tris : 0.0, p.pixels,
                pixels ? 100.0 * p.pixels / pixels : 0.0);
  if (!s.segment_triangles.empty()) {
    std::printf("  hybrid segments (triangles wide enough for them, by length):");
    for (std::size_t m = 0; m < s.segment_triangles.size(); ++m) std::printf(" %d px %lld,", 1 << m, s.segment_triangles[m]);
    std::printf(" %lld of them interpolate a light's N.L unclamped across its terminator\n", s.segment_split);
  }
  if (!s.left_out.empty()) std::printf("left out:\n");
  for (const std::string& line : s.left_out) std::printf("  - %s\n", line.c_str());
}

}  // namespace

int run_render(const RenderCommand& cmd) {
  if (cmd.frames < 1 || cmd.frames > 100000)
    throw InputError("--frames", "expected 1 to 100000, got " + std::to_string(cmd.frames));
  validate(cmd.options);
  const AovSet aovs = cmd.aov.empty() ? AovSet{} : parse_aov_list(cmd.aov);
  // Every output is checked before the (possibly long) render starts.
  check_output_path(cmd.output, aovs);
  if (!cmd.stats_path.empty()) {
    const std::filesystem::path dir = std::filesystem::path(cmd.stats_path).parent_path();
    if (!dir.empty() && !std::filesystem::is_directory(dir))
      throw InputError(cmd.stats_path, "directory '" + dir.string() + "' does not exist");
  }
  const Scene scene = cmd.scene.empty() ? parse_scene(default_scene_json(), "<default scene>", ".")
                                        : load_scene(cmd.scene);
  RenderOptions options = cmd.options;
  std::optional<Calibration> calibration;
  if (cmd.calibrate) {
    const std::string name = cmd.scene.empty() ? "<default scene>" : std::filesystem::path(cmd.scene).filename().string();
    calibration = calibrate(scene, name, cmd.options, cmd.parse_render_flags);
    options = calibration->candidates[calibration->picked].options;
    std::printf("%s\n", calibration_summary(*calibration).c_str());
  }
  RenderStats stats;
  AovImages aov_images;
  const Image image = render(scene, options, cmd.frames, &stats, aovs, &aov_images);
  write_image(image, aov_images, cmd.output);
  if (!cmd.stats_path.empty()) {
    nlohmann::json json = nlohmann::json::parse(stats.to_json());
    if (calibration) json["calibration"] = calibration_json(*calibration);
    write_text_file(cmd.stats_path, json.dump(2) + "\n");
  }
  std::printf(
      "%s: %dx%d, %s, %lld triangles (%lld drawn, %lld dropped, %lld culled of which %lld hidden), "
      "%d threads, tile %d, %s: %.2f ms (front end %.2f, binning %.2f, raster+shade %.2f)%s, %.1f Mpix/s\n",
      cmd.output.c_str(), image.width, image.height, stats.method.c_str(), stats.triangles_in,
      stats.triangles_drawn, stats.triangles_dropped, stats.triangles_culled, stats.triangles_hidden, stats.threads,
      stats.tile, stats.isa.c_str(), stats.median.total, stats.median.front_end,
      stats.median.binning, stats.median.raster_shade,
      stats.frames > 1 ? (" median of " + std::to_string(stats.frames)).c_str() : "",
      stats.mpix_per_s());
  if (cmd.explain) print_explanation(stats, options);
  return 0;
}

}  // namespace fastshade
