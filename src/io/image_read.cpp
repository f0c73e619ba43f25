// read_image: any format OpenImageIO reads, as float RGB. Integer formats come back divided by
// their maximum (UINT8 / 255), float formats as stored. Grey is replicated; grey + alpha keeps
// the grey; three or more channels keep the first three. Colour is returned as stored, never
// multiplied by alpha.
#include <string>
#include <system_error>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "fastshade/error.h"
#include "fastshade/image.h"
#include "fastshade/scene.h"
#include "io/oiio_error.h"

namespace fastshade {
namespace fs = std::filesystem;

ImageF read_image(const fs::path& path) {
  const std::string where = path.string();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(where, "no such file");
  if (fs::is_directory(path, ec)) throw InputError(where, "is a directory, not an image");

  // Keep stored colour as is: without this hint, OIIO's PNG (and other) readers multiply
  // colour by alpha on the way in, so grey + alpha or RGBA would not come back as stored.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(where, &config);
  if (!in) {
    std::string err = io::take_global_error();
    throw InputError(where, "cannot read image" + (err.empty() ? std::string() : ": " + err));
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.deep) throw InputError(where, "deep images are not supported");
  if (spec.depth != 1) throw InputError(where, "volume images are not supported");
  if (spec.width <= 0 || spec.height <= 0 || spec.width > kMaxImageSide ||
      spec.height > kMaxImageSide)
    throw InputError(where, "image size " + std::to_string(spec.width) + "x" +
                                std::to_string(spec.height) + " is outside 1.." +
                                std::to_string(kMaxImageSide));
  const int nch = spec.nchannels;
  if (nch < 1) throw InputError(where, "image has no channels");

  // Grey and grey + alpha: read channel 0 only. Otherwise channels 0..2.
  const int keep = nch >= 3 ? 3 : 1;
  const size_t pixels = static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height);
  std::vector<float> buf(pixels * keep);
  if (!in->read_image(0, 0, 0, keep, OIIO::TypeDesc::FLOAT, buf.data())) {
    std::string err = io::one_line(in->geterror());
    throw InputError(where, "cannot read image" + (err.empty() ? std::string() : ": " + err));
  }
  in->close();

  ImageF image;
  image.width = spec.width;
  image.height = spec.height;
  if (keep == 3) {
    image.rgb = std::move(buf);
  } else {
    image.rgb.resize(pixels * 3);
    for (size_t i = 0; i < pixels; ++i)
      image.rgb[3 * i] = image.rgb[3 * i + 1] = image.rgb[3 * i + 2] = buf[i];
  }
  return image;
}

}  // namespace fastshade
