// One view of one mesh, rendered, written and recorded: what every batch engine does per image
// (the command line's workers, fastshade.batch locally and on Ray), so that they write the
// same files and the same results lines.
#pragma once
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "fastshade/batch.h"
#include "fastshade/scene.h"
#include "io/scene_template.h"

namespace fastshade {

// What a batch's views share, read-only.
struct BatchContext {
  const SceneTemplate& scene;
  const RenderOptions& options;  // options.threads: each render's
  AovSet aovs;
  std::filesystem::path outdir;
  int views = 1;
};

// The fields of an image's results line that every status has.
nlohmann::json batch_line(const BatchMesh& mesh, const BatchImage& image, int views, const char* status);
// A failed image's line: `error` and the time its mesh took to load (0 if it did not).
nlohmann::json failed_line(const BatchMesh& mesh, const BatchImage& image, int views, const std::string& error,
                           double load_ms);

// The mesh loaded as the template says and framed by its fit camera. Throws InputError, or
// std::bad_alloc for a mesh too large to hold.
Scene load_batch_scene(const SceneTemplate& scene, const BatchMesh& mesh);

// Renders one view of a loaded mesh's scene, writes its image (and AOVs) whole, and returns
// its "ok" results line with counts and times. Throws on any failure (the image fails alone).
nlohmann::json render_batch_view(const BatchContext& context, const Scene& fit_scene, const BatchMesh& mesh,
                                 const BatchImage& image, double load_ms);

}  // namespace fastshade
