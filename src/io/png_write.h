// 8-bit RGB PNG, written with libpng directly: the format of nearly every image fastshade
// writes, without loading OpenImageIO (io/image_codec.h says why).
#pragma once
#include <cstdint>
#include <string>

namespace fastshade::io {

// Writes width x height RGB8 pixels (rows top to bottom) to `path`; "" or why it failed.
std::string write_png_rgb8(const std::string& path, int width, int height, const uint8_t* rgb);

}  // namespace fastshade::io
