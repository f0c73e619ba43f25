#include "batch/batch_view.h"

#include <chrono>
#include <memory>

#include "core/ms_between.h"
#include "fastshade/image.h"
#include "fastshade/mesh.h"
#include "fastshade/render.h"

namespace fastshade {

namespace {

using Clock = SteadyClock;
using nlohmann::json;

json camera_json(const Camera& c) {
  if (c.intrinsics) {  // as the scene format writes a calibrated camera, in OpenGL axes
    json pose = json::array();
    for (int row = 0; row < 4; ++row)
      pose.push_back({c.camera_to_world[0][row], c.camera_to_world[1][row], c.camera_to_world[2][row],
                      c.camera_to_world[3][row]});
    const Intrinsics& k = *c.intrinsics;
    return {{"intrinsics", {{"fx", k.fx}, {"fy", k.fy}, {"cx", k.cx}, {"cy", k.cy}}},
            {"pose", pose}, {"convention", "opengl"}, {"near", c.near}, {"far", c.far}};
  }
  const auto vec = [](const glm::vec3& v) { return json::array({v.x, v.y, v.z}); };
  return {{"eye", vec(c.eye)}, {"target", vec(c.target)}, {"up", vec(c.up)},
          {"fovy_deg", c.fovy_deg}, {"near", c.near}, {"far", c.far}};
}

}  // namespace

json batch_line(const BatchMesh& mesh, const BatchImage& image, int views, const char* status) {
  json line = {{"mesh", mesh.key},         {"view", image.view},     {"views", views},
               {"angle_deg", image.angle_deg}, {"output", image.output}, {"status", status},
               {"fingerprint", image.fingerprint}};
  if (!image.aov_output.empty()) line["aov_output"] = image.aov_output;
  return line;
}

json failed_line(const BatchMesh& mesh, const BatchImage& image, int views, const std::string& error, double load_ms) {
  json line = batch_line(mesh, image, views, "failed");
  line["error"] = error;
  line["load_ms"] = load_ms;
  return line;
}

Scene load_batch_scene(const SceneTemplate& scene, const BatchMesh& mesh) {
  return scene.scene_for(std::make_shared<const Mesh>(load_mesh(mesh.path, scene.mesh_options())));
}

json render_batch_view(const BatchContext& context, const Scene& fit_scene, const BatchMesh& mesh,
                       const BatchImage& image, double load_ms) {
  json line = batch_line(mesh, image, context.views, "ok");
  Scene scene = fit_scene;
  scene.camera = orbit_camera(scene.camera, image.angle_deg);
  const Clock::time_point t0 = Clock::now();
  // Safe on several workers at once: a renderer's ISA is its own (core/simd_target.h).
  Renderer renderer(scene, context.options);
  Image frame;
  AovImages aovs;
  renderer.render_frame(frame, context.aovs, aovs);
  const RenderStats stats = renderer.last_stats();
  const Clock::time_point t1 = Clock::now();
  write_image(frame, aovs, context.outdir / image.output);
  const double render_ms = ms_between(t0, t1), write_ms = ms_between(t1, Clock::now());

  const Mesh& loaded = *scene.objects.front().mesh;
  line["vertices"] = loaded.positions.size();
  line["triangles"] = loaded.triangles.size();
  line["triangles_drawn"] = stats.triangles_drawn;
  line["covered_pixels"] = stats.covered_pixels;
  line["load_ms"] = load_ms;
  line["render_ms"] = render_ms;
  line["write_ms"] = write_ms;
  line["time_ms"] = load_ms + render_ms + write_ms;
  line["camera"] = camera_json(scene.camera);
  return line;
}

}  // namespace fastshade
