#include "front/vertex_stage.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/limits.h"
#include "front/vertex_transform.h"
#include "light/vertex_light.h"

namespace fastshade {

ViewTransform view_transform(const Scene& scene) {
  const Camera& c = scene.camera;
  ViewTransform xf;
  xf.view = glm::lookAt(c.eye, c.target, c.up);
  const float aspect = static_cast<float>(scene.width) / static_cast<float>(scene.height);
  xf.proj = glm::perspective(glm::radians(c.fovy_deg), aspect, c.near, c.far);
  return xf;
}

namespace {

// All eight corners of the box outside one clip plane: nothing inside can be seen.
bool outside_frustum(const glm::mat4& model_to_clip, const glm::vec3& lo, const glm::vec3& hi) {
  uint8_t common = kOutcodeMask;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
    common &= frustum_outcode(model_to_clip * glm::vec4(p, 1.0f));
  }
  return common != 0;
}

}  // namespace

int run_vertex_stage(SimdTarget simd, const SceneGeometry& g, const ViewTransform& xf, const Viewport& vp,
                      const AttrNeeds& needs, const ShadeConstants& shade, ProjectedVertices& out,
                      AttrArrays& attrs) {
  const std::size_t n = g.positions.size();
  out.resize(n);
  // Gouraud's vertex lighting reads the normal (and the position, for a local viewer) even
  // when the method interpolates only the colour; those stay in locals.
  attrs.n_view.resize(needs.normal ? n : 0);
  attrs.color.resize(needs.color ? n : 0);
  attrs.pos_view.resize(needs.position ? n : 0);
  int culled = 0;
  for (const ObjectRange& o : g.objects) {
    const glm::mat4 model_view = xf.view * o.model;
    if (outside_frustum(xf.proj * model_view, o.box_min, o.box_max)) {
      std::fill_n(out.flags.begin() + o.first_vertex, o.vertex_count, kOutcodeMask);
      ++culled;
      continue;
    }
    VertexTransform transform;
    transform.model_view = model_view;
    transform.proj = xf.proj;
    transform.normal_matrix = glm::inverseTranspose(glm::mat3(model_view));
    transform.viewport = vp;
    const bool lanes_need_normals = needs.normal || needs.color || needs.position;
    const MaterialConstants& material = shade.materials[o.material];
    tbb::parallel_for(
        tbb::blocked_range<uint32_t>(o.first_vertex, o.first_vertex + o.vertex_count,
                                      limits::kVerticesPerBlock),
        [&](const tbb::blocked_range<uint32_t>& r) {
          // Batches of transformed vertices, then their lighting, both in SIMD lanes; a batch's
          // normals and positions wait in local arrays even where the method keeps neither.
          constexpr uint32_t kBatch = limits::kVertexLightBatch;
          glm::vec3 n_batch[kBatch], pos_batch[kBatch];
          for (uint32_t first = r.begin(); first < r.end(); first += kBatch) {
            const uint32_t count = std::min(kBatch, r.end() - first);
            transform_vertices(simd, transform, &g.positions[first], lanes_need_normals ? &g.normals[first] : nullptr, count,
                               {&out.clip[first], &out.screen[first], &out.flags[first], n_batch, pos_batch});
            if (needs.normal) std::copy_n(n_batch, count, &attrs.n_view[first]);
            if (needs.position) std::copy_n(pos_batch, count, &attrs.pos_view[first]);
            if (needs.color)
              light_vertices(simd, n_batch, pos_batch, count, material, shade, !needs.diffuse_color,
                             attrs.color.data() + first);
          }
        });
  }
  return culled;
}

}  // namespace fastshade
