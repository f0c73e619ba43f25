#include "exec/left_out.h"

#include <algorithm>
#include <set>
#include <sstream>

namespace fastshade {

namespace {

std::string plural(long long n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

bool is_zero(const glm::vec3& c) { return c.r == 0.0f && c.g == 0.0f && c.b == 0.0f; }

}  // namespace

std::vector<std::string> left_out_report(const SceneGeometry& g, const ShadeConstants& k, const FrameFacts& f) {
  std::vector<std::string> out;
  const long long empty = f.tiles_total - f.back_end.tiles_nonempty;
  if (empty > 0)
    out.push_back(plural(empty, "empty tile") + " of " + std::to_string(f.tiles_total) +
                  ": background copied, no bins, no scratch");
  if (f.objects_culled > 0)
    out.push_back(plural(f.objects_culled, "object") + " outside the view frustum: never transformed or set up");
  if (f.triangles_hidden > 0)
    out.push_back(plural(f.triangles_hidden, "back face") +
                  " hidden behind their own closed mesh's front faces: never binned or shaded "
                  "(--hidden-faces draw keeps them)");
  if (f.segments_no_specular > 0)
    out.push_back(plural(f.segments_no_specular, "hybrid triangle") +
                  ": segment ends lit without the specular term, which stays below 2^-24 on them");
  if (!f.method_classifies) return out;

  if (k.lights.empty()) {
    out.push_back("no lights: every colour is the ambient one; no normals, no classification, "
                  "flat Gouraud");
    return out;
  }
  std::set<int> used;
  for (const ObjectRange& obj : g.objects) used.insert(obj.material);
  for (int m : used) {
    const MaterialConstants& mat = k.materials[m];
    if (is_zero(mat.kd) && is_zero(mat.ks))
      out.push_back("material " + std::to_string(m) + ": kd = ks = 0, ambient only: Gouraud, no per-pixel normals");
    else if (is_zero(mat.ks))
      out.push_back("material " + std::to_string(m) + ": ks = 0: no specular work on its triangles");
  }
  if (f.tally) {
    for (std::size_t i = 0; i < k.lights.size() && i < 63; ++i)
      if (!(f.tally->lights_with_highlight >> i & 1))
        out.push_back("light " + std::to_string(i) + ": reaches no triangle's highlight above --spec-threshold");
    const auto& t = f.tally->triangles;
    if (f.tally->unclassified > 0) {
      std::ostringstream bound;  // as typed: 80, 12.5
      bound << f.classify_min_px;
      out.push_back(plural(f.tally->unclassified, "triangle") + " in blocks whose screen boxes average under " +
                    bound.str() +
                    " px: specular path without classification, which would cost more than it saves "
                    "(--classify-min-px 0 classifies them)");
    }
    if (t[static_cast<int>(ShadePath::Specular)] == 0)
      out.push_back("no triangle can show a highlight: no specular code ran");
    if (t[static_cast<int>(ShadePath::PixelDiffuse)] == 0 && t[static_cast<int>(ShadePath::Specular)] == 0)
      out.push_back("no triangle needs per-pixel normals: Gouraud only");
    if (f.back_end.single_path_tiles > 0)
      out.push_back(plural(f.back_end.single_path_tiles, "tile") +
                    " held one path only and ran its kernel alone (no per-triangle dispatch)");
  }
  out.push_back(k.local_viewer ? "local viewer: H per pixel on the specular path"
                               : "viewer at infinity: one H per light for the whole frame");
  return out;
}

}  // namespace fastshade
