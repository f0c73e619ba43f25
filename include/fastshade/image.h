// 8-bit RGB images (what the renderer writes) and float images (what compare reads).
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

namespace fastshade {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, top row first, 3 bytes a pixel
};

struct ImageF {
  int width = 0, height = 0;
  std::vector<float> rgb;  // [0, 1] nominal, 3 floats a pixel
};

// Fails (InputError) before any rendering if the file cannot be written there: a missing
// directory, an extension OpenImageIO cannot write, a directory in the way.
void check_output_path(const std::filesystem::path& path);

// The extension picks the format (png, exr, tif, ...). Written to a temporary file beside the
// target and renamed, so a failed or interrupted write leaves no partial output.
void write_image(const Image& image, const std::filesystem::path& path);

// Reads any OpenImageIO format; the first three channels (grey is replicated).
ImageF read_image(const std::filesystem::path& path);

}  // namespace fastshade
