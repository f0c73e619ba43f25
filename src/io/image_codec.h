// OpenImageIO behind a plugin loaded on first use. Linked into the library, it cost every
// process about 0.3 s before main() (Debian's OpenImageIO pulls in some 250 shared libraries
// whose relocations the loader resolves at start-up; an empty program linked with it alone
// took 0.28-0.33 s, docs/PERFORMANCE.md "Batch"): a batch of PNGs, which fastshade writes
// itself (io/png_write.h), and `import fastshade` should not pay that. Every other format, the
// EXR files of the AOVs and every read go through libfastshade_oiio.so (io/oiio_plugin.cpp).
//
// The plugin and the library are built together and share libstdc++, so the table passes
// std::string and std::vector; kImageCodecAbi guards against a stale plugin.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace fastshade::io {

inline constexpr int kImageCodecAbi = 1;
inline constexpr const char* kImageCodecPlugin = "libfastshade_oiio.so";
inline constexpr const char* kImageCodecEntry = "fastshade_image_codec";

// The type of a channel in the file, or of the values handed over.
enum class CodecType : uint8_t { UInt8, Half, Float, UInt32 };

struct CodecImage {
  int width = 0, height = 0;
  std::vector<std::string> channel_names;  // one per channel; empty: the format's defaults
  std::vector<CodecType> channel_types;    // one per channel: as stored in the file
  // The values, interleaved, each channel as `pixel_type`, or (per_channel) each in its own
  // channel_types entry. UInt32 channels hold 4-byte bits as they are.
  CodecType pixel_type = CodecType::UInt8;
  bool per_channel = false;
  const void* pixels = nullptr;
};

// An image read back as float RGB (read_image in include/fastshade/image.h says how).
struct CodecRead {
  int width = 0, height = 0;
  std::vector<float> rgb;
};

struct ImageCodec {
  int abi;
  // Whether a writer exists for the path's extension.
  bool (*can_write)(const std::string& path);
  // Writes `image` to `path` (the caller's temporary file); "" or why it failed, one line.
  std::string (*write)(const std::string& path, const CodecImage& image);
  // Reads `path`, refusing sides above max_side; "" or why it failed, one line.
  std::string (*read)(const std::string& path, int max_side, CodecRead& out);
};

// The plugin's one exported symbol (kImageCodecEntry).
using ImageCodecEntry = const ImageCodec* (*)();

// The plugin's table, loaded once; throws InputError(where, why) if the plugin is missing or
// stale, naming where it was looked for.
const ImageCodec& image_codec(const std::string& where);

}  // namespace fastshade::io
