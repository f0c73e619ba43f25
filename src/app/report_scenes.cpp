#include "app/report_scenes.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <set>
#include <system_error>

#include <nlohmann/json.hpp>

#include "fastshade/error.h"

namespace fastshade {

namespace fs = std::filesystem;

namespace {

// Directory levels searched upward: the executable's own (build/), the repository, its parent.
constexpr int kSearchLevels = 3;

// The mesh frame (docs/KERNELS.md, "Error and time of every method"): 1920x1080 keeps each
// shared mesh at the size its timings are quoted for elsewhere in docs/, and the full default
// report (about 18 meshes and scenes x 18 configurations) within minutes on 2 cores.
constexpr int kMeshSceneWidth = 1920, kMeshSceneHeight = 1080;
constexpr double kMeshShininess = 100;  // issue 3's spot frame; middle of KERNELS.md's 10/100/1000

std::string lower_extension(const fs::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool is_mesh_file(const fs::path& p) {
  static const std::set<std::string> kMeshExtensions = {".obj", ".off", ".ply", ".stl"};
  return kMeshExtensions.count(lower_extension(p)) > 0;
}
bool is_scene_file(const fs::path& p) { return lower_extension(p) == ".json"; }

fs::path program_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

}  // namespace

fs::path find_near_program(const fs::path& sub) {
  std::error_code ec;
  for (fs::path start : {program_dir(), fs::current_path(ec)}) {
    if (start.empty()) continue;
    for (int level = 0; level < kSearchLevels; ++level, start = start.parent_path()) {
      if (fs::is_directory(start / sub, ec)) return fs::weakly_canonical(start / sub, ec);
      if (start == start.parent_path()) break;
    }
  }
  return {};
}

std::vector<fs::path> default_report_inputs(const std::string& models_dir) {
  std::vector<fs::path> inputs;
  if (const fs::path scenes = find_near_program("scenes"); !scenes.empty()) inputs.push_back(scenes);
  if (!models_dir.empty()) {
    if (!fs::is_directory(models_dir)) throw InputError(models_dir, "not a directory (--models)");
    inputs.push_back(models_dir);
  } else if (const fs::path models = find_near_program(fs::path("shared") / "models"); !models.empty()) {
    inputs.push_back(models);
  }
  if (inputs.empty())
    throw InputError("report", "no scenes given and neither scenes/ nor ../shared/models found "
                               "near the program or the working directory");
  return inputs;
}

std::vector<SceneInput> expand_scene_inputs(const std::vector<fs::path>& inputs) {
  std::vector<SceneInput> out;
  const auto add = [&](const fs::path& p) { out.push_back({p.filename().string(), p, is_mesh_file(p)}); };
  for (const fs::path& in : inputs) {
    std::error_code ec;
    if (fs::is_directory(in, ec)) {
      std::vector<fs::path> files;
      for (const fs::directory_entry& e : fs::directory_iterator(in, ec))
        if (e.is_regular_file() && (is_mesh_file(e.path()) || is_scene_file(e.path())))
          files.push_back(e.path());
      if (ec) throw InputError(in.string(), "cannot list the directory: " + ec.message());
      std::sort(files.begin(), files.end());
      for (const fs::path& f : files) add(f);
    } else if (!fs::exists(in, ec)) {
      throw InputError(in.string(), "no such file or directory");
    } else if (is_mesh_file(in) || is_scene_file(in)) {
      add(in);
    } else {
      throw InputError(in.string(), "expected a scene (.json), a mesh (.obj, .off, .ply, .stl) or a "
                                    "directory of them");
    }
  }
  // Rows are keyed by scene name: "default.json" twice becomes "default.json" and "default.json#2".
  std::set<std::string> names;
  for (SceneInput& s : out) {
    const std::string base = s.name;
    for (int k = 2; !names.insert(s.name).second; ++k) s.name = base + "#" + std::to_string(k);
  }
  return out;
}

std::string mesh_scene_json(const fs::path& mesh) {
  using nlohmann::json;
  const json scene = {
      {"image", {{"width", kMeshSceneWidth}, {"height", kMeshSceneHeight}, {"background", {0, 0, 0}}}},
      {"camera", {{"fit", true}, {"distance", 2.5}, {"fovy_deg", 45}}},
      {"lights", {{{"type", "directional"}, {"direction", {1, 1, 1}}, {"color", {1, 1, 1}}, {"space", "view"}}}},
      {"ambient", {0.1, 0.1, 0.1}},
      {"materials", {{"m", {{"diffuse", 0.7}, {"specular", 0.5}, {"shininess", kMeshShininess}}}}},
      // Two-sided: open meshes (bunny, suzanne) show their inside, and horse.ply winds inward.
      {"objects", {{{"mesh", fs::absolute(mesh).string()}, {"material", "m"}, {"normals", "recompute"}}}},
      {"options", {{"cull", "none"}, {"two_sided", true}}}};
  return scene.dump(2);
}

Scene load_report_scene(const SceneInput& input) {
  if (!input.mesh) return load_scene(input.path);
  return parse_scene(mesh_scene_json(input.path), input.path.string(), input.path.parent_path());
}

}  // namespace fastshade
