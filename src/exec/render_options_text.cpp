// RenderOptions as one line for logs, stats and reports.
#include <sstream>

#include "fastshade/render.h"

namespace fastshade {

std::string RenderOptions::to_string() const {
  std::ostringstream s;
  s << "method=" << method << " threads=" << threads << " tile=" << (tile_px ? std::to_string(tile_px) : "auto")
    << " isa=" << isa
    << " srgb=" << (srgb ? "on" : "off") << " brdf=" << brdf << " max_error=" << max_error
    << " normals=" << normals << " gouraud=" << gouraud << " hidden_faces=" << hidden_faces;
  if (method_classifies(method))
    s << " spec_threshold=" << spec_threshold << " spec_method=" << spec_method
      << " classifier=" << classifier << " classify_min_px=" << classify_min_px;
  return s.str();
}

}  // namespace fastshade
