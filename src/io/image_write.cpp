// check_output_path and write_image: 8-bit RGB out, via a temporary file in the target's
// directory that is renamed onto the target, so no partial file ever remains. PNG is written
// here (io/png_write.h), every other format through OpenImageIO's plugin (io/image_codec.h).
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

#include "fastshade/error.h"
#include "fastshade/image.h"
#include "fastshade/atomic_file.h"
#include "io/image_codec.h"
#include "io/png_write.h"

namespace fastshade {
namespace fs = std::filesystem;

namespace {

fs::path parent_dir(const fs::path& path) {
  fs::path dir = path.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}
bool is_exr(const fs::path& path) { return lower_extension(path) == ".exr"; }
bool is_png(const fs::path& path) { return lower_extension(path) == ".png"; }

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
  if (!is_png(path) && !io::image_codec(where).can_write(where))
    throw InputError(where, "unsupported output format '" + ext + "'");
}

namespace {

void check_image(const Image& image, const std::string& where) {
  if (image.width <= 0 || image.height <= 0)
    throw InputError(where, "cannot write an empty image (" + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ")");
  const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 3;
  if (image.rgb.size() != n)
    throw InputError(where, "image buffer holds " + std::to_string(image.rgb.size()) +
                                " bytes, expected " + std::to_string(n));
}

// Through the plugin into the temporary file, which the caller commits. Throws InputError
// naming `where`.
void write_codec(const TempFile& temp, const std::string& where, const io::CodecImage& image) {
  const std::string why = io::image_codec(where).write(temp.path().string(), image);
  if (!why.empty()) throw InputError(where, why);
}

// EXR has no 8-bit channels: colour goes there as value/255.
std::vector<float> unit_floats(const Image& image) {
  std::vector<float> out(image.rgb.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = static_cast<float>(image.rgb[i]) / 255.0f;
  return out;
}

void write_colour(const Image& image, const TempFile& temp, const std::string& where, const fs::path& path) {
  if (is_png(path)) {
    const std::string why = io::write_png_rgb8(temp.path().string(), image.width, image.height, image.rgb.data());
    if (!why.empty()) throw InputError(where, "cannot write image: " + why);
    return;
  }
  io::CodecImage out;
  out.width = image.width;
  out.height = image.height;
  if (!is_exr(path)) {
    out.channel_types.assign(3, io::CodecType::UInt8);
    out.pixels = image.rgb.data();
    return write_codec(temp, where, out);
  }
  const std::vector<float> unit = unit_floats(image);
  out.channel_types.assign(3, io::CodecType::Half);
  out.pixel_type = io::CodecType::Float;
  out.pixels = unit.data();
  write_codec(temp, where, out);
}

// One EXR channel: its name, its type in the file, and where pixel i's value is.
struct AovChannel {
  std::string name;
  io::CodecType type;
  const void* data;
  int stride;  // values per pixel in `data`
  int offset;
};

// Colour (if given) and the present AOVs as one EXR, each channel in its own type: FLOAT for
// colour (value/255), depth and normal; UINT for ids, holding the int32 bits.
void write_aov_exr(const Image* colour, const AovImages& aovs, const TempFile& temp, const std::string& where) {
  std::vector<AovChannel> channels;
  std::vector<float> rgb;
  if (colour) {
    rgb = unit_floats(*colour);
    for (int c = 0; c < 3; ++c) channels.push_back({std::string(1, "RGB"[c]), io::CodecType::Float, rgb.data(), 3, c});
  }
  if (aovs.present.depth) channels.push_back({"Z", io::CodecType::Float, aovs.depth.data(), 1, 0});
  if (aovs.present.normal)
    for (int c = 0; c < 3; ++c)
      channels.push_back({std::string("N.") + "XYZ"[c], io::CodecType::Float, aovs.normal.data(), 3, c});
  if (aovs.present.triangle_id) channels.push_back({"triangle_id", io::CodecType::UInt32, aovs.triangle_id.data(), 1, 0});
  if (aovs.present.object_id) channels.push_back({"object_id", io::CodecType::UInt32, aovs.object_id.data(), 1, 0});
  io::CodecImage out;
  out.width = aovs.width;
  out.height = aovs.height;
  for (const AovChannel& c : channels) {
    out.channel_names.push_back(c.name);
    out.channel_types.push_back(c.type);
  }
  // Every channel is 4 bytes: pixel i's channel k at (i * channels + k) * 4.
  const size_t pixels = size_t(aovs.width) * size_t(aovs.height);
  std::vector<uint32_t> native(pixels * channels.size());
  for (size_t k = 0; k < channels.size(); ++k) {
    const auto* src = static_cast<const uint32_t*>(channels[k].data);  // float or int32 bits
    for (size_t i = 0; i < pixels; ++i)
      native[i * channels.size() + k] = src[i * channels[k].stride + channels[k].offset];
  }
  out.per_channel = true;
  out.pixels = native.data();
  write_codec(temp, where, out);
}

void check_aovs(const AovImages& aovs, const Image& image, const std::string& where) {
  const size_t n = size_t(image.width) * size_t(image.height);
  const AovSet& p = aovs.present;
  if (aovs.width != image.width || aovs.height != image.height || aovs.depth.size() != (p.depth ? n : 0) ||
      aovs.normal.size() != (p.normal ? 3 * n : 0) || aovs.triangle_id.size() != (p.triangle_id ? n : 0) ||
      aovs.object_id.size() != (p.object_id ? n : 0))
    throw InputError(where, "AOV buffers do not match the " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " image");
}

}  // namespace

void write_image(const Image& image, const fs::path& path) {
  check_output_path(path);
  const std::string where = path.string();
  check_image(image, where);
  TempFile temp(path);
  write_colour(image, temp, where, path);
  temp.commit();
}

fs::path aov_path(const fs::path& path) {
  fs::path out = path;
  return out.replace_filename(path.stem().string() + ".aov.exr");
}

void check_output_path(const fs::path& path, const AovSet& aovs) {
  check_output_path(path);
  if (aovs.any() && !is_exr(path)) check_output_path(aov_path(path));
}

void write_image(const Image& image, const AovImages& aovs, const fs::path& path) {
  if (!aovs.present.any()) return write_image(image, path);
  check_output_path(path, aovs.present);
  const std::string where = path.string();
  check_image(image, where);
  check_aovs(aovs, image, where);
  if (is_exr(path)) {
    TempFile temp(path);
    write_aov_exr(&image, aovs, temp, where);
    temp.commit();
    return;
  }
  const fs::path beside = aov_path(path);
  TempFile colour(path), aov(beside);
  write_colour(image, colour, where, path);
  write_aov_exr(nullptr, aovs, aov, beside.string());
  aov.commit();
  colour.commit();
}

}  // namespace fastshade
