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

namespace {

// The clip-space projection of a calibrated camera (scene.h Intrinsics) for a width x height
// image: pixel column u's centre sits at window x = u + 0.5, row v's at y = v + 0.5 from the top
// (front/projection.h project()), so x_ndc = 2 (fx X/Z + cx + 0.5) / width - 1 with Z = -z_view,
// and y_ndc = 1 - 2 (fy Y/Z + cy + 0.5) / height with Y = -y_view; depth as glm::perspective.
glm::dmat4 intrinsic_projection(const Intrinsics& k, int width, int height, double near, double far) {
  glm::dmat4 p(0.0);  // p[column][row]
  p[0][0] = 2.0 * k.fx / width;
  p[2][0] = 1.0 - 2.0 * (k.cx + 0.5) / width;
  p[1][1] = 2.0 * k.fy / height;
  p[2][1] = 2.0 * (k.cy + 0.5) / height - 1.0;
  p[2][2] = -(far + near) / (far - near);
  p[3][2] = -2.0 * far * near / (far - near);
  p[2][3] = -1.0;
  return p;
}

// The inverse of a rigid camera-to-world pose, exactly: the rotation transposed.
glm::dmat4 world_to_camera(const glm::dmat4& camera_to_world) {
  const glm::dmat3 r_t = glm::transpose(glm::dmat3(camera_to_world));
  glm::dmat4 view(r_t);
  view[3] = glm::dvec4(-(r_t * glm::dvec3(camera_to_world[3])), 1.0);
  return view;
}

}  // namespace

ViewTransform view_transform(const Scene& scene) {
  const Camera& c = scene.camera;
  ViewTransform xf;
  if (c.intrinsics) {
    xf.view = glm::mat4(world_to_camera(c.camera_to_world));
    xf.proj = glm::mat4(intrinsic_projection(*c.intrinsics, scene.width, scene.height, c.near, c.far));
    return xf;
  }
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
