// What `fastshade report` renders: scene files, bare meshes framed by the fit camera, and the
// directories that hold them; by default the repository's scenes/ and the shared meshes.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "fastshade/scene.h"

namespace fastshade {

struct SceneInput {
  std::string name;             // the file name, made unique among the inputs
  std::filesystem::path path;
  bool mesh = false;            // a mesh file, rendered through mesh_scene_json
};

// The first of `dir`, its parent and its grandparent that holds `sub` as a directory, searched
// from the executable's directory and then the working directory: from build/fastshade that
// finds the repository's scenes/ and, beside the repository, shared/models.
std::filesystem::path find_near_program(const std::filesystem::path& sub);

// The default inputs: scenes/ and the shared meshes (`models_dir` if given, which must then
// exist, else shared/models found by find_near_program). Either may be missing; both missing
// is an InputError.
std::vector<std::filesystem::path> default_report_inputs(const std::string& models_dir);

// Scene files (.json), mesh files (.obj .off .ply .stl) and directories of them (not
// recursive, sorted by name). Throws InputError for a missing path or another kind of file.
std::vector<SceneInput> expand_scene_inputs(const std::vector<std::filesystem::path>& inputs);

// The scene a bare mesh is measured in: 1920x1080, the fit camera at 2.5 radii, one view-space
// light toward (1, 1, 1), ambient 0.1, kd 0.7, ks 0.5, n 100, normals recomputed, two-sided:
// the frame of docs/KERNELS.md's table, at the middle of its three shininesses.
std::string mesh_scene_json(const std::filesystem::path& mesh);

Scene load_report_scene(const SceneInput& input);

}  // namespace fastshade
