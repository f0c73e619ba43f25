// libfastshade_oiio.so: OpenImageIO's formats for the library, loaded on first use
// (io/image_codec.h says why). Built as its own module, not into the library.
#include <OpenImageIO/imageio.h>

#include "io/image_codec.h"

namespace fastshade::io {

namespace {

// OIIO messages may span lines and may repeat the file name; keep them on one line.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// The global OIIO error (set by failed create()/open()), consumed so that it is neither
// reported against a later call nor printed as "pending" when the program exits.
std::string take_global_error() { return one_line(OIIO::geterror()); }

OIIO::TypeDesc type_desc(CodecType t) {
  switch (t) {
    case CodecType::UInt8: return OIIO::TypeDesc::UINT8;
    case CodecType::Half: return OIIO::TypeDesc::HALF;
    case CodecType::Float: return OIIO::TypeDesc::FLOAT;
    case CodecType::UInt32: return OIIO::TypeDesc::UINT32;
  }
  return OIIO::TypeDesc::UNKNOWN;
}

bool can_write(const std::string& path) {
  const bool ok = OIIO::ImageOutput::create(path) != nullptr;
  if (!ok) take_global_error();
  return ok;
}

std::string write(const std::string& path, const CodecImage& image) {
  const int channels = static_cast<int>(image.channel_types.size());
  OIIO::ImageSpec spec(image.width, image.height, channels, type_desc(image.channel_types.front()));
  if (!image.channel_names.empty()) spec.channelnames = image.channel_names;
  for (const CodecType t : image.channel_types) spec.channelformats.push_back(type_desc(t));
  // OpenImageIO stamps EXR and TIFF files with the time of writing unless DateTime is set;
  // empty, the same pixels give the same file bytes, run after run and engine after engine.
  spec.attribute("DateTime", "");
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    const std::string err = take_global_error();
    return "cannot create image writer" + (err.empty() ? std::string() : ": " + err);
  }
  // ImageOutput::open creates the file, so from here on the file may exist on disk.
  bool ok = out->open(path, spec);
  if (ok) {
    ok = out->write_image(image.per_channel ? OIIO::TypeDesc::UNKNOWN : type_desc(image.pixel_type), image.pixels);
    ok = out->close() && ok;
  }
  if (ok) return "";
  const std::string err = one_line(out->geterror());
  return "cannot write image: " + (err.empty() ? std::string("unknown error") : err);
}

// Integer formats come back divided by their maximum (UINT8 / 255), float formats as stored.
// Grey is replicated; grey + alpha keeps the grey; three or more channels keep the first three.
// Colour is returned as stored, never multiplied by alpha.
std::string read(const std::string& path, int max_side, CodecRead& image) {
  // Keep stored colour as is: without this hint, OIIO's PNG (and other) readers multiply
  // colour by alpha on the way in, so grey + alpha or RGBA would not come back as stored.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) {
    const std::string err = take_global_error();
    return "cannot read image" + (err.empty() ? std::string() : ": " + err);
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.deep) return "deep images are not supported";
  if (spec.depth != 1) return "volume images are not supported";
  if (spec.width <= 0 || spec.height <= 0 || spec.width > max_side || spec.height > max_side)
    return "image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " is outside 1.." +
           std::to_string(max_side);
  const int nch = spec.nchannels;
  if (nch < 1) return "image has no channels";

  // Grey and grey + alpha: read channel 0 only. Otherwise channels 0..2.
  const int keep = nch >= 3 ? 3 : 1;
  const size_t pixels = static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height);
  std::vector<float> buf(pixels * keep);
  if (!in->read_image(0, 0, 0, keep, OIIO::TypeDesc::FLOAT, buf.data())) {
    const std::string err = one_line(in->geterror());
    return "cannot read image" + (err.empty() ? std::string() : ": " + err);
  }
  in->close();
  image.width = spec.width;
  image.height = spec.height;
  if (keep == 3) {
    image.rgb = std::move(buf);
  } else {
    image.rgb.resize(pixels * 3);
    for (size_t i = 0; i < pixels; ++i) image.rgb[3 * i] = image.rgb[3 * i + 1] = image.rgb[3 * i + 2] = buf[i];
  }
  return "";
}

constexpr ImageCodec kCodec{kImageCodecAbi, can_write, write, read};

}  // namespace

}  // namespace fastshade::io

extern "C" __attribute__((visibility("default"))) const fastshade::io::ImageCodec* fastshade_image_codec() {
  return &fastshade::io::kCodec;
}
