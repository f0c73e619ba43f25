// read_image: any format OpenImageIO reads, through its plugin (io/image_codec.h), as float
// RGB. Integer formats come back divided by their maximum (UINT8 / 255), float formats as
// stored. Grey is replicated; grey + alpha keeps the grey; three or more channels keep the
// first three. Colour is returned as stored, never multiplied by alpha.
#include <string>
#include <system_error>

#include "fastshade/error.h"
#include "fastshade/image.h"
#include "fastshade/scene.h"
#include "io/image_codec.h"

namespace fastshade {
namespace fs = std::filesystem;

ImageF read_image(const fs::path& path) {
  const std::string where = path.string();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(where, "no such file");
  if (fs::is_directory(path, ec)) throw InputError(where, "is a directory, not an image");
  io::CodecRead read;
  const std::string why = io::image_codec(where).read(where, kMaxImageSide, read);
  if (!why.empty()) throw InputError(where, why);
  ImageF image;
  image.width = read.width;
  image.height = read.height;
  image.rgb = std::move(read.rgb);
  return image;
}

}  // namespace fastshade
