// RenderOptions as one line for logs, stats and reports.
#include <sstream>

#include "fastshade/options.h"

namespace fastshade {

std::string RenderOptions::to_string() const {
  std::ostringstream s;
  s << "method=" << option_name(method) << " threads=" << threads
    << " tile=" << (tile_px ? std::to_string(tile_px) : "auto") << " isa=" << option_name(isa)
    << " srgb=" << (srgb ? "on" : "off") << " brdf=" << option_name(brdf) << " max_error=" << max_error
    << " normals=" << option_name(normals) << " gouraud=" << option_name(gouraud)
    << " hidden_faces=" << option_name(hidden_faces);
  if (method_classifies(method))
    s << " spec_threshold=" << spec_threshold << " spec_method=" << option_name(spec_method)
      << " classifier=" << option_name(classifier) << " classify_min_px=" << classify_min_px;
  return s.str();
}

}  // namespace fastshade
