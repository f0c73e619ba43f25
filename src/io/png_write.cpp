#include "io/png_write.h"

#include <csetjmp>
#include <cstdio>
#include <memory>

#include <png.h>

namespace fastshade::io {

namespace {

// PNG stays lossless; only how hard zlib tries changes. A 1080p bunny frame (mostly
// background) took 95 ms at zlib level 6 with libpng's adaptive filters (OpenImageIO's
// default) and 22 ms at level 1 with the Up filter, for a file 23 % larger (285 KB against
// 232 KB); level 3 with Up took 31 ms for 8 % (docs/PERFORMANCE.md, "Batch"). At 1080p a
// batch spent more on encoding than on rendering.
constexpr int kZlibLevel = 1;

struct Writer {
  png_structp png = nullptr;
  png_infop info = nullptr;
  char message[256] = "";
  ~Writer() { png_destroy_write_struct(&png, info ? &info : nullptr); }
};

void on_error(png_structp png, png_const_charp text) {
  auto* w = static_cast<Writer*>(png_get_error_ptr(png));
  std::snprintf(w->message, sizeof w->message, "%s", text);
  png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

// The libpng calls alone, between setjmp and its longjmp: no object with a destructor lives
// in this frame.
bool encode(Writer& w, std::FILE* file, int width, int height, const uint8_t* rgb) {
  if (setjmp(png_jmpbuf(w.png))) return false;
  png_init_io(w.png, file);
  png_set_IHDR(w.png, w.info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(w.png, kZlibLevel);
  png_set_filter(w.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_write_info(w.png, w.info);
  const std::size_t row_bytes = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height; ++y) png_write_row(w.png, rgb + static_cast<std::size_t>(y) * row_bytes);
  png_write_end(w.png, nullptr);
  return true;
}

}  // namespace

std::string write_png_rgb8(const std::string& path, int width, int height, const uint8_t* rgb) {
  Writer w;
  w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w, on_error, on_warning);
  if (w.png) w.info = png_create_info_struct(w.png);
  if (!w.png || !w.info) return "cannot start the PNG writer";
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"), std::fclose);
  if (!file) return "cannot open for writing";
  if (!encode(w, file.get(), width, height, rgb)) return std::string("PNG: ") + w.message;
  const bool failed = std::ferror(file.get()) != 0;
  if (std::fclose(file.release()) != 0 || failed) return "write failed (disk full?)";
  return "";
}

}  // namespace fastshade::io
