#include "front/clip.h"

#include <glm/geometric.hpp>

namespace fastshade {

ClipPlanes guard_band_planes(float gx, float gy) {
  ClipPlanes p;
  p.plane[0] = {0, 0, 1, 1};    // near: z + w >= 0
  p.plane[1] = {0, 0, -1, 1};   // far:  w - z >= 0
  p.plane[2] = {-1, 0, 0, gx};  // x <= gx w
  p.plane[3] = {1, 0, 0, gx};   // x >= -gx w
  p.plane[4] = {0, -1, 0, gy};
  p.plane[5] = {0, 1, 0, gy};
  p.count = 6;
  return p;
}

namespace {

VertexAttrs attrs_of(const ClipVertex& v, const AttrArrays& source) {
  if (v.source == kNewVertex) return v.attrs;
  VertexAttrs a;
  if (!source.n_view.empty()) a.n_view = source.n_view[v.source];
  if (!source.color.empty()) a.color = source.color[v.source];
  if (!source.pos_view.empty()) a.pos_view = source.pos_view[v.source];
  return a;
}

VertexAttrs lerp(const VertexAttrs& a, const VertexAttrs& b, float t) {
  // Linear in clip space is perspective-correct: attributes vary linearly with homogeneous
  // position. The normal is renormalised later, per pixel, by whoever interpolates it.
  return {a.n_view + (b.n_view - a.n_view) * t, a.color + (b.color - a.color) * t,
          a.pos_view + (b.pos_view - a.pos_view) * t};
}

}  // namespace

int clip_polygon(ClipVertex* poly, int count, const ClipPlanes& planes, bool with_attrs,
                 const AttrArrays& source_attrs) {
  ClipVertex scratch[kMaxClipVertices];
  ClipVertex* in = poly;
  ClipVertex* out = scratch;
  for (int p = 0; p < planes.count && count > 0; ++p) {
    const glm::vec4 plane = planes.plane[p];
    int n = 0;
    for (int i = 0; i < count; ++i) {
      const ClipVertex& a = in[i];
      const ClipVertex& b = in[(i + 1) % count];
      const float da = glm::dot(plane, a.pos_clip), db = glm::dot(plane, b.pos_clip);
      if (da >= 0) out[n++] = a;
      if ((da >= 0) != (db >= 0)) {
        // Interpolate from the inside vertex so the same edge clipped from either of its two
        // triangles gives the same point (shared edges stay watertight).
        const bool a_in = da >= 0;
        const ClipVertex& from = a_in ? a : b;
        const ClipVertex& to = a_in ? b : a;
        const float d_from = a_in ? da : db, d_to = a_in ? db : da;
        const float t = d_from / (d_from - d_to);
        ClipVertex v;
        v.pos_clip = from.pos_clip + (to.pos_clip - from.pos_clip) * t;
        v.source = kNewVertex;
        if (with_attrs) v.attrs = lerp(attrs_of(from, source_attrs), attrs_of(to, source_attrs), t);
        out[n++] = v;
      }
    }
    count = n;
    std::swap(in, out);
  }
  if (in != poly)
    for (int i = 0; i < count; ++i) poly[i] = in[i];
  return count;
}

}  // namespace fastshade
