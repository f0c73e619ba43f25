// RenderStats as JSON: what `render --stats` writes and the Python module's Frame.stats holds.
#include <nlohmann/json.hpp>

#include "fastshade/render.h"

namespace fastshade {

std::string RenderStats::to_json() const {
  const RenderStats& s = *this;
  nlohmann::json paths = nlohmann::json::object();
  for (const PathStats& p : s.paths) paths[p.name] = {{"triangles", p.triangles}, {"pixels", p.pixels}};
  nlohmann::json segments = nlohmann::json::object();
  if (!s.segment_triangles.empty()) {  // arrays, in order of length (an object's keys sort as text)
    nlohmann::json lengths = nlohmann::json::array();
    for (std::size_t m = 0; m < s.segment_triangles.size(); ++m) lengths.push_back(1 << m);
    segments = {{"length_px", lengths},
                {"triangles", s.segment_triangles},
                {"split_light", s.segment_split},
                {"no_specular", s.segment_no_specular}};
  }
  const nlohmann::json json = {{"triangles_in", s.triangles_in},
          {"triangles_drawn", s.triangles_drawn},
          {"triangles_dropped", s.triangles_dropped},
          {"triangles_culled", s.triangles_culled},
          {"triangles_hidden", s.triangles_hidden},
          {"tiles_total", s.tiles_total},
          {"tiles_nonempty", s.tiles_nonempty},
          {"covered_pixels", s.covered_pixels},
          {"threads", s.threads},
          {"tile", s.tile},
          {"isa", s.isa},
          {"method", s.method},
          {"drawn_as", s.drawn_as},
          {"frames", s.frames},
          {"median_ms",
           {{"front_end", s.median.front_end},
            {"binning", s.median.binning},
            {"raster_shade", s.median.raster_shade},
            {"total", s.median.total}}},
          {"mpix_per_s", s.mpix_per_s()},
          {"mtri_per_s", s.mtri_per_s()},
          {"paths", paths},
          {"triangles_unclassified", s.triangles_unclassified},
          {"hybrid_segments", segments},
          {"left_out", s.left_out}};
  return json.dump();
}

}  // namespace fastshade
