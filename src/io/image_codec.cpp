#include "io/image_codec.h"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <system_error>

#include "fastshade/error.h"

namespace fastshade::io {

namespace {

namespace fs = std::filesystem;

struct Loaded {
  const ImageCodec* codec = nullptr;
  std::string why;  // set when codec is null
};

// Where the plugin may be, in order: beside the binary holding this code (the Python module of
// an installed package, or a program), in lib/fastshade beside an installed program's bin/, in
// the build tree the library was built in and in the prefix it was configured for.
std::vector<fs::path> plugin_dirs() {
  std::vector<fs::path> binaries;
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&image_codec), &info) != 0 && info.dli_fname && *info.dli_fname)
    binaries.emplace_back(info.dli_fname);
  std::error_code ec;
  if (const fs::path exe = fs::read_symlink("/proc/self/exe", ec); !ec) binaries.push_back(exe);
  std::vector<fs::path> dirs;
  for (const fs::path& binary : binaries) {
    const fs::path dir = fs::weakly_canonical(binary, ec).parent_path();
    dirs.push_back(dir);
    dirs.push_back(dir.parent_path() / FASTSHADE_INSTALL_LIBDIR_NAME / "fastshade");
  }
  dirs.emplace_back(FASTSHADE_BUILD_PLUGIN_DIR);
  dirs.emplace_back(FASTSHADE_INSTALL_PLUGIN_DIR);
  std::vector<fs::path> unique;  // the program is both the binary holding this code and /proc/self/exe
  for (const fs::path& dir : dirs)
    if (std::find(unique.begin(), unique.end(), dir) == unique.end()) unique.push_back(dir);
  return unique;
}

Loaded load() {
  std::string looked;
  for (const fs::path& dir : plugin_dirs()) {
    const fs::path path = dir / kImageCodecPlugin;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
      looked += (looked.empty() ? "" : ", ") + dir.string();
      continue;
    }
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) return {nullptr, "cannot load " + path.string() + ": " + dlerror()};
    const auto entry = reinterpret_cast<ImageCodecEntry>(dlsym(handle, kImageCodecEntry));
    const ImageCodec* codec = entry ? entry() : nullptr;
    if (!codec || codec->abi != kImageCodecAbi)
      return {nullptr, path.string() + " is from another build of fastshade (rebuild or reinstall it)"};
    return {codec, ""};  // kept loaded for the process's life
  }
  return {nullptr, std::string("needs OpenImageIO through ") + kImageCodecPlugin + ", which is in none of " + looked +
                       " (PNG output needs no plugin)"};
}

}  // namespace

const ImageCodec& image_codec(const std::string& where) {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded.codec) throw InputError(where, loaded.why);
  return *loaded.codec;
}

}  // namespace fastshade::io
