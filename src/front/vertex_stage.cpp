#include "front/vertex_stage.h"

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shade/lighting.h"

namespace fastshade {

ViewTransform view_transform(const Scene& scene) {
  const Camera& c = scene.camera;
  ViewTransform xf;
  xf.view = glm::lookAt(c.eye, c.target, c.up);
  const float aspect = static_cast<float>(scene.width) / static_cast<float>(scene.height);
  xf.proj = glm::perspective(glm::radians(c.fovy_deg), aspect, c.near, c.far);
  return xf;
}

ShadeConstants shade_constants(const Scene& scene, const ViewTransform& xf, bool srgb,
                              const BrdfChoice& brdf) {
  ShadeConstants k;
  k.ambient = scene.ambient;
  k.background = scene.background;
  k.local_viewer = scene.viewer == Viewer::Local;
  k.two_sided = scene.two_sided;
  k.srgb = srgb;
  k.brdf = brdf;
  const glm::mat3 view_rot(xf.view);  // lookAt is a rigid motion: its 3x3 is a rotation
  for (const Light& light : scene.lights) {
    LightView lv;
    lv.l_view = glm::normalize(light.space == LightSpace::World ? view_rot * light.direction
                                                                : light.direction);
    // A light straight behind the infinite viewer has no half vector: no highlight at all.
    const glm::vec3 h = lv.l_view + glm::vec3(0, 0, 1);
    lv.h_view = glm::length(h) > 1e-6f ? glm::normalize(h) : glm::vec3(0.0f);
    lv.color = light.color;
    k.lights.push_back(lv);
  }
  for (const Material& m : scene.materials)
    k.materials.push_back({m.diffuse, m.specular, static_cast<float>(m.shininess), m.shininess,
                           make_brdf(brdf, m.shininess)});
  return k;
}

void run_vertex_stage(const SceneGeometry& g, const ViewTransform& xf, const Viewport& vp,
                      const AttrNeeds& needs, const ShadeConstants& shade, ProjectedVertices& out,
                      AttrArrays& attrs) {
  const std::size_t n = g.positions.size();
  out.resize(n);
  // Gouraud's vertex lighting reads the normal (and the position, for a local viewer) even
  // when the method interpolates only the colour; those stay in locals.
  attrs.n_view.resize(needs.normal ? n : 0);
  attrs.color.resize(needs.color ? n : 0);
  attrs.pos_view.resize(needs.position ? n : 0);
  for (const ObjectRange& o : g.objects) {
    const glm::mat4 model_view = xf.view * o.model;
    const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(model_view));
    const glm::mat4 proj = xf.proj;
    const MaterialConstants& material = shade.materials[o.material];
    tbb::parallel_for(
        tbb::blocked_range<uint32_t>(o.first_vertex, o.first_vertex + o.vertex_count,
                                      limits::kVerticesPerBlock),
        [&](const tbb::blocked_range<uint32_t>& r) {
          for (uint32_t i = r.begin(); i != r.end(); ++i) {
            const glm::vec4 pos_view = model_view * glm::vec4(g.positions[i], 1.0f);
            out.store(i, proj * pos_view, vp);
            if (!(needs.normal || needs.color || needs.position)) continue;
            const glm::vec3 n_view = glm::normalize(normal_matrix * g.normals[i]);
            if (needs.normal) attrs.n_view[i] = n_view;
            if (needs.position) attrs.pos_view[i] = glm::vec3(pos_view);
            if (needs.color) {
              const glm::vec3 v_view = shade.local_viewer ? glm::normalize(-glm::vec3(pos_view))
                                                          : glm::vec3(0, 0, 1);
              attrs.color[i] = glm::clamp(
                  blinn_phong<float>(n_view, v_view, !shade.local_viewer, material, shade), 0.0f,
                  1.0f);
            }
          }
        });
  }
}

}  // namespace fastshade
