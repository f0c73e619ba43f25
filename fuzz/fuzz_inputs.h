// What the fuzz targets feed, as plain functions that libFuzzer (fuzz/*_fuzzer.cpp) and the
// test suite (tests/fuzz/fuzz_regressions_test.cpp) both call: bytes go through the readers
// exactly as `fastshade render` runs them, and must come back accepted or rejected with the
// project's one-line InputError. Anything else is a finding: another exception (the function
// returns its description), a crash or a sanitizer report (the process dies).
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace fastshade::fuzz {

// A mesh file with extension `ext` (".obj", ".ply", ".off", ".stl") holding `data`, loaded as
// `render` loads an object's mesh, then again welded with recomputed normals.
std::optional<std::string> mesh_file(std::string_view ext, const uint8_t* data, size_t size);

// Scene JSON text, parsed and resolved as `render SCENE.json` does (meshes it names are read
// relative to an empty folder).
std::optional<std::string> scene_json(const uint8_t* data, size_t size);

// A `render --config` file's text.
std::optional<std::string> render_config(const uint8_t* data, size_t size);

// Every target by name, for the regression test and the fuzz script: "mesh_obj", "mesh_ply",
// "mesh_off", "mesh_stl", "scene_json", "render_config".
std::optional<std::string> run_target(std::string_view target, const uint8_t* data, size_t size);
inline constexpr std::string_view kTargets[] = {"mesh_obj", "mesh_ply",   "mesh_off",
                                                "mesh_stl", "scene_json", "render_config"};

}  // namespace fastshade::fuzz
