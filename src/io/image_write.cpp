// check_output_path and write_image: 8-bit RGB out through OpenImageIO, via a temporary file
// in the target's directory that is renamed onto the target, so no partial file ever remains.
//
// Formats: the data are written as UINT8 where the format takes it (png, tif, ...). EXR has no
// 8-bit channels: there the file holds HALF channels with value/255 (0..1, linear in the 8-bit
// code, no transfer curve applied). Half's 11-bit significand keeps v/255 within 2^-12 of the
// exact value, far inside half an 8-bit step, so reading it back and rounding to 8 bits gives
// the same codes.
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <string>
#include <system_error>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "fastshade/error.h"
#include "fastshade/image.h"
#include "io/atomic_file.h"
#include "io/oiio_error.h"

namespace fastshade {
namespace fs = std::filesystem;

namespace {

fs::path parent_dir(const fs::path& path) {
  fs::path dir = path.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

bool is_exr(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".exr";
}

}  // namespace

void check_output_path(const fs::path& path) {
  const std::string where = path.string();
  if (path.empty()) throw InputError("<output>", "empty output path");
  if (!path.has_filename()) throw InputError(where, "output path names a directory");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(where, "output path is a directory");
  const fs::path dir = parent_dir(path);
  if (!fs::exists(dir, ec)) throw InputError(where, "directory '" + dir.string() + "' does not exist");
  if (!fs::is_directory(dir, ec))
    throw InputError(where, "'" + dir.string() + "' is not a directory");
  // As root, access() says yes to any directory not on a read-only file system; the real
  // write can still fail, and write_image reports that too.
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError(where, "directory '" + dir.string() + "' is not writable");
  const std::string ext = path.extension().string();
  if (ext.empty()) throw InputError(where, "no file extension to choose an image format");
  auto out = OIIO::ImageOutput::create(where);
  if (!out) {
    io::take_global_error();
    throw InputError(where, "unsupported output format '" + ext + "'");
  }
}

void write_image(const Image& image, const fs::path& path) {
  check_output_path(path);
  const std::string where = path.string();
  if (image.width <= 0 || image.height <= 0)
    throw InputError(where, "cannot write an empty image (" + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ")");
  const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 3;
  if (image.rgb.size() != n)
    throw InputError(where, "image buffer holds " + std::to_string(image.rgb.size()) +
                                " bytes, expected " + std::to_string(n));

  TempFile temp(path);
  const std::string temp_name = temp.path().string();
  auto out = OIIO::ImageOutput::create(temp_name);
  if (!out) {
    std::string err = io::take_global_error();
    throw InputError(where, "cannot create image writer: " + err);
  }

  const bool exr = is_exr(path);
  OIIO::ImageSpec spec(image.width, image.height, 3, exr ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
  std::vector<float> as_float;
  if (exr) {
    as_float.resize(n);
    for (size_t i = 0; i < n; ++i) as_float[i] = static_cast<float>(image.rgb[i]) / 255.0f;
  }

  // ImageOutput::open creates the file, so from here on the temp file may exist on disk.
  bool ok = out->open(temp_name, spec);
  if (ok) {
    ok = exr ? out->write_image(OIIO::TypeDesc::FLOAT, as_float.data())
             : out->write_image(OIIO::TypeDesc::UINT8, image.rgb.data());
    ok = out->close() && ok;
  }
  if (!ok) {
    std::string err = io::one_line(out->geterror());
    out.reset();
    throw InputError(where, "cannot write image: " + (err.empty() ? std::string("unknown error") : err));
  }
  out.reset();

  temp.commit();
}

}  // namespace fastshade
