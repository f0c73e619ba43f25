// The yardstick: per pixel, exact barycentrics from the integer edge functions, the
// perspective-correct normal, normalised, and Blinn-Phong, all in double. Scalar on purpose.
#include <glm/geometric.hpp>

#include "light/lighting.h"
#include "raster/triangle_in_tile.h"
#include "shade/methods.h"

namespace fastshade {

void draw_reference(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  TriangleInTile tri;
  if (!prepare_triangle(frame.triangle(entry), tt.rect, tri)) return;
  const SetupTriangle& t = *tri.tri;
  const ShadeConstants& k = frame.shade;
  const MaterialConstants& material = k.materials[t.material];
  const double flip = (k.two_sided && (t.flags & kBackFacing)) ? -1.0 : 1.0;
  glm::dvec3 n_view[3], pos_view[3];
  for (int i = 0; i < 3; ++i) {
    n_view[i] = glm::dvec3(frame.vertex(entry, t.attr[i], &AttrArrays::n_view)) * flip;
    if (k.local_viewer) pos_view[i] = glm::dvec3(frame.vertex(entry, t.attr[i], &AttrArrays::pos_view));
  }
  const double inv_area = 1.0 / (4.0 * static_cast<double>(doubled_area(t)));  // edge units
  const TriangleEdges shape = shape_edges(t);  // a Sierpinski part interpolates its parent
  for_each_span(tri.edges, tri.rect, [&](int py, int x0, int x1) {
    tri.set_up_planes();
    float* depth = tt.depth + (py - tt.y_origin) * tt.stride - tt.x_origin;
    uint32_t* color = tt.color + (py - tt.y_origin) * tt.stride - tt.x_origin;
    for (int px = x0; px <= x1; ++px) {
      const float z = plane_at(tri.depth, pixel_offsets(tri.bary, px, py));
      if (!(z < depth[px])) continue;
      depth[px] = z;
      double mu[3], mu_sum = 0;
      for (int i = 0; i < 3; ++i) {
        const int64_t e = shape.e[i].at(pixel_centre_fx(px), pixel_centre_fx(py));
        mu[i] = static_cast<double>(e) * inv_area * static_cast<double>(t.inv_w[i]);
        mu_sum += mu[i];
      }
      glm::dvec3 n(0.0), pos(0.0);
      for (int i = 0; i < 3; ++i) {
        n += n_view[i] * mu[i];
        pos += pos_view[i] * (mu[i] / mu_sum);
      }
      const double len = glm::length(n);
      n = len > 0 ? n / len : glm::dvec3(0.0);
      const glm::dvec3 v_view = k.local_viewer ? glm::normalize(-pos) : glm::dvec3(0, 0, 1);
      const glm::dvec3 c = blinn_phong<double>(n, v_view, !k.local_viewer, material, k);
      color[px] = pack_rgba(quantize(c.r, k.srgb), quantize(c.g, k.srgb), quantize(c.b, k.srgb)) ^ tt.alpha_xor;
    }
  });
}

AttrNeeds reference_needs(const ShadeConstants& shade) {
  return {.normal = true, .color = false, .position = shade.local_viewer};
}

DrawTriangleFn select_reference(SimdTarget, const ShadeConstants&) { return draw_reference; }

std::string reference_refuses(const RenderOptions& c) {
  if (c.normals != PhongNormals::Normalize)
    return "--normals: the reference method normalises exactly in double; use --method phong";
  if (c.brdf.kind != BrdfKind::Exact)
    return "--brdf: the reference method evaluates cos^n exactly in double; use --brdf with "
           "phong, gouraud or hybrid";
  return {};
}

}  // namespace fastshade
