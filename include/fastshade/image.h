// 8-bit RGB images (what the renderer writes) and float images (what compare reads).
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace fastshade {

// Storage that starts on a cache line. The back end streams whole 64-byte lines of the
// framebuffer (exec/tile_io.cpp); at 64-pixel tiles and image widths that are multiples of 64
// every tile row is whole lines, but only if the buffer starts on one. malloc's large blocks
// start 16 bytes into a page, which left a partial line at both ends of every tile row: copied
// with ordinary stores, shared with the neighbouring tile (often another thread's).
// The block is allocated out of line (src/io/image_bytes.cpp): where GCC 12 sees its size, it
// reports false -Wstringop-overflow warnings on the vector's element-wise copies.
void* allocate_cache_lines(std::size_t bytes);
void free_cache_lines(void* block);

template <class T>
struct CacheLineAllocator {
  using value_type = T;
  CacheLineAllocator() = default;
  template <class U>
  CacheLineAllocator(const CacheLineAllocator<U>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(allocate_cache_lines(n * sizeof(T))); }
  void deallocate(T* p, std::size_t) { free_cache_lines(p); }
  friend bool operator==(const CacheLineAllocator&, const CacheLineAllocator&) { return true; }
};

using ImageBytes = std::vector<uint8_t, CacheLineAllocator<uint8_t>>;

struct Image {
  int width = 0, height = 0;
  ImageBytes rgb;  // row-major, top row first, 3 bytes a pixel
};

// Per-pixel outputs beside colour ("arbitrary output variables"; docs/PIPELINE.md, "Outputs
// beyond colour"). Each is of the pixel's visible surface, the one whose colour the image shows.
struct AovSet {
  bool depth = false;        // distance along the camera's viewing axis, scene units
  bool normal = false;       // the shading normal, interpolated and normalised, world space
  bool triangle_id = false;  // the face's index in its object's mesh as loaded
  bool object_id = false;    // the object's index in Scene::objects
  bool any() const { return depth || normal || triangle_id || object_id; }
  bool ids() const { return triangle_id || object_id; }
  bool operator==(const AovSet&) const = default;
};

// Row-major, top row first, like Image. Only the arrays `present` names are filled; the others
// are empty.
struct AovImages {
  int width = 0, height = 0;
  AovSet present;
  std::vector<float> depth;          // width*height; 0 where nothing is drawn (as pyrender)
  std::vector<float> normal;         // width*height*3, unit length; 0 where nothing is drawn
  std::vector<int32_t> triangle_id;  // width*height; -1 where nothing is drawn
  std::vector<int32_t> object_id;    // width*height; -1 where nothing is drawn
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

// Colour and AOVs. To an .exr path: one multi-channel EXR (R, G, B as FLOAT value/255, then Z,
// N.X, N.Y, N.Z as FLOAT and triangle_id, object_id as UINT holding the int32's bits: -1 reads
// as 4294967295), only the AOVs `aovs.present` names; without any, write_image(image, path). To any other format: colour
// to `path` and the AOVs to aov_path(path). Both files are written to temporaries first and
// renamed only once both are whole.
void write_image(const Image& image, const AovImages& aovs, const std::filesystem::path& path);
// check_output_path() for every file write_image(image, aovs, path) would write.
void check_output_path(const std::filesystem::path& path, const AovSet& aovs);
// Where the AOVs of a non-EXR output go: "out/a.png" -> "out/a.aov.exr".
std::filesystem::path aov_path(const std::filesystem::path& path);

// Reads any OpenImageIO format; the first three channels (grey is replicated).
ImageF read_image(const std::filesystem::path& path);

}  // namespace fastshade
