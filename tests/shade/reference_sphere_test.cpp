// The yardstick against the analytic sphere: the reference method on a fine icosphere must
// match ray-traced Blinn-Phong on the true sphere within a bound derived below.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "fastshade/primitives.h"
#include "fastshade/render.h"
#include "front/shade_setup.h"
#include "light/lighting.h"

namespace fastshade {
namespace {

// Why the bound is small: the icosphere's vertices lie on the sphere and their normals are
// radial, so at any point P of a facet the perspective-correct interpolated normal
// normalize(sum beta_i N_i) = normalize(sum beta_i V_i / r) = P/|P| is exactly radial. The only
// difference from the true normal at Q (the ray's hit on the sphere) is the angle between P
// and Q seen from the centre. With facet edge angle alpha, P lies at most r(1 - cos alpha)
// inside the sphere; along a ray meeting the surface at incidence cos >= c_min the distance
// |PQ| <= r(1 - cos alpha) / (c_min - alpha), so the normal angle
//   delta <= (1 - cos alpha) / ((c_min - alpha) cos alpha).
// Colour is Lipschitz in the normal angle with constant L = sum_lights |color| (kd + ks n)
// (d/dtheta cos^n <= n), so |I_mesh - I_true| <= L delta; both are rounded to 8 bits, which
// adds at most 1 LSB. Bound: 1 + 255 L delta LSB, on pixels whose ray meets the sphere with
// cos >= c_min (the silhouette, where the polygon and the circle disagree, is left out).
TEST(ReferenceShading, FineIcosphereMatchesAnalyticSphereWithinDerivedBound) {
  const int subdivisions = 6;
  const double alpha = 1.1071487177940904 / std::pow(2.0, subdivisions);  // icosahedron edge angle
  const double c_min = 0.3;
  const double kd = 0.6, ks = 0.3, n = 8.0;

  Scene scene;
  scene.width = scene.height = 256;
  scene.camera = Camera{{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 35.0f, 1.0f, 10.0f};
  scene.lights.push_back({glm::normalize(glm::vec3(1, 1, 2)), glm::vec3(1), LightSpace::View});
  scene.ambient = glm::vec3(0.05f);
  scene.materials.push_back({"m", glm::vec3(float(kd)), glm::vec3(float(ks)), n});
  scene.objects.push_back({std::make_shared<Mesh>(make_icosphere(1.0f, subdivisions)), 0, glm::mat4(1.0f)});

  RenderOptions options;
  options.method = ShadingMethod::Reference;
  options.threads = 2;
  const Image image = render(scene, options);

  const double delta = (1 - std::cos(alpha)) / ((c_min - alpha) * std::cos(alpha));
  const double bound_lsb = 1.0 + 255.0 * (kd + ks * n) * delta;
  ASSERT_LT(bound_lsb, 2.0) << "the bound is meant to be tight: it would not catch much";

  const ViewTransform xf = view_transform(scene);
  const ShadeConstants k = shade_constants(scene, xf);
  const glm::dmat4 inv = glm::inverse(glm::dmat4(xf.proj) * glm::dmat4(xf.view));
  const glm::dvec3 eye(scene.camera.eye);
  double worst = 0, sum = 0;
  int checked = 0;
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x) {
      const double x_ndc = (x + 0.5) / scene.width * 2 - 1, y_ndc = 1 - (y + 0.5) / scene.height * 2;
      const glm::dvec4 far_h = inv * glm::dvec4(x_ndc, y_ndc, 1, 1);
      const glm::dvec3 dir = glm::normalize(glm::dvec3(far_h) / far_h.w - eye);
      const double b = glm::dot(eye, dir), c = glm::dot(eye, eye) - 1.0;  // |eye + t dir| = 1
      const double disc = b * b - c;
      if (disc <= 0) continue;
      const glm::dvec3 hit = eye + dir * (-b - std::sqrt(disc));
      const glm::dvec3 n_world = glm::normalize(hit);
      if (glm::dot(n_world, -dir) < c_min) continue;
      const glm::dvec3 n_view = glm::dmat3(xf.view) * n_world;
      const glm::dvec3 color = blinn_phong<double>(n_view, glm::dvec3(0, 0, 1), true, k.materials[0], k);
      for (int ch = 0; ch < 3; ++ch) {
        const double expected = quantize(color[ch], false);
        const double got = image.rgb[(std::size_t(y) * scene.width + x) * 3 + ch];
        const double err = std::fabs(got - expected);
        worst = std::max(worst, err);
        sum += err;
        ASSERT_LE(err, bound_lsb) << "pixel (" << x << ", " << y << ") channel " << ch;
      }
      ++checked;
    }
  EXPECT_GT(checked, 20000);  // the sphere fills a good part of the frame
  EXPECT_LT(sum / (3.0 * checked), 0.25) << "mean error in LSB; worst " << worst;
}

}  // namespace
}  // namespace fastshade
