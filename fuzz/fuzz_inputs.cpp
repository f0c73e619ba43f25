#include "fuzz_inputs.h"

#include <cstdlib>
#include <exception>
#include <fstream>
#include <new>
#include <system_error>

#include <unistd.h>

#include "fastshade/error.h"
#include "fastshade/mesh.h"
#include "fastshade/scene.h"
#include "fastshade/render_config.h"

namespace fastshade::fuzz {

namespace {

// One scratch folder per process (libFuzzer runs one input at a time per process), on tmpfs
// where there is one: every mesh input is written to a file, since the readers take paths.
const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path shm = "/dev/shm";
    const std::filesystem::path base = std::filesystem::is_directory(shm) ? shm : std::filesystem::temp_directory_path();
    std::filesystem::path d = base / ("fastshade_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::filesystem::create_directories(d / "empty");
    std::atexit([] { std::error_code ec; std::filesystem::remove_all(scratch_dir(), ec); });
    return d;
  }();
  return dir;
}

// A rejection is one line that names what was read: the file, or the source given.
std::optional<std::string> check_rejection(const InputError& e, const std::string& source) {
  const std::string message = e.what();
  if (message.find('\n') != std::string::npos) return "rejection over more than one line: " + message;
  if (message.find(source) == std::string::npos) return "rejection that does not name " + source + ": " + message;
  return std::nullopt;
}

// Runs `read`; InputError is the expected rejection, any other exception a finding.
template <typename Read>
std::optional<std::string> accepted_or_rejected(const std::string& source, Read&& read) {
  try {
    read();
    return std::nullopt;
  } catch (const InputError& e) {
    return check_rejection(e, source);
  } catch (const std::bad_alloc&) {
    return "std::bad_alloc escaped (a count the input cannot hold was believed)";
  } catch (const std::exception& e) {
    return std::string("exception other than InputError: ") + e.what();
  }
}

}  // namespace

std::optional<std::string> mesh_file(std::string_view ext, const uint8_t* data, size_t size) {
  const std::filesystem::path path = scratch_dir() / ("input" + std::string(ext));
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  bool loaded = false;
  if (auto finding = accepted_or_rejected(path.string(), [&] {
        load_mesh(path);
        loaded = true;
      }))
    return finding;
  if (!loaded) return std::nullopt;
  return accepted_or_rejected(path.string(), [&] { load_mesh(path, {NormalsMode::Recompute, true}); });
}

std::optional<std::string> scene_json(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  return accepted_or_rejected("fuzz.json", [&] { parse_scene(text, "fuzz.json", scratch_dir() / "empty"); });
}

std::optional<std::string> render_config(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  return accepted_or_rejected("tuned.json", [&] { parse_render_config(text, "tuned.json"); });
}

std::optional<std::string> run_target(std::string_view target, const uint8_t* data, size_t size) {
  if (target == "mesh_obj") return mesh_file(".obj", data, size);
  if (target == "mesh_ply") return mesh_file(".ply", data, size);
  if (target == "mesh_off") return mesh_file(".off", data, size);
  if (target == "mesh_stl") return mesh_file(".stl", data, size);
  if (target == "scene_json") return scene_json(data, size);
  if (target == "render_config") return render_config(data, size);
  return "no fuzz target '" + std::string(target) + "'";
}

}  // namespace fastshade::fuzz
