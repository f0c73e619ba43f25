// Gouraud's vertex lighting in lanes (light/vertex_light.h) against its scalar reference,
// vertex_color(), on every compiled ISA, for every BRDF and batch lengths 0..2W+1.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "core/simd_target.h"
#include "light/brdf.h"
#include "light/vertex_light.h"

namespace fastshade {
namespace {

// The lanes differ from the scalar colour only through the BRDF kernels (tests/shade/
// brdf_test.cpp: exp2/log2 1e-6 and acos/cos 4e-6 of the lobe, the others exact), scaled by
// ks times the light's colour: far below the half LSB (2e-3) that would change a pixel.
constexpr float kTolerance = 1e-5f;

ShadeConstants two_lights() {
  ShadeConstants k;
  k.ambient = glm::vec3(0.05f, 0.1f, 0.02f);
  k.lights.push_back({glm::normalize(glm::vec3(1, 1, 1)), glm::normalize(glm::vec3(1, 1, 2.732f)), glm::vec3(1)});
  const glm::vec3 l2 = glm::normalize(glm::vec3(-0.3f, 0.2f, 0.9f));
  k.lights.push_back({l2, glm::normalize(l2 + glm::vec3(0, 0, 1)), glm::vec3(0.6f, 0.5f, 0.9f)});
  return k;
}

TEST(VertexLight, LanesMatchVertexColorOnEveryIsaBrdfAndLength) {
  std::mt19937 rng(17);
  std::normal_distribution<float> g(0.0f, 1.0f);
  std::vector<glm::vec3> normals(40);
  for (glm::vec3& n : normals) n = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
  normals[1] = glm::normalize(glm::vec3(1, 1, 2.732f));  // on the first light's half vector
  normals[2] = glm::vec3(0, 0, -1);                        // facing away from both lights
  const ShadeConstants k = two_lights();
  int isas = 0;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    ++isas;
    for (const BrdfChoice& brdf : brdf_choices())
      for (double n : {1.0, 37.5, 1000.0}) {
        const MaterialConstants m{glm::vec3(0.7f, 0.6f, 0.5f), glm::vec3(0.5f, 0.4f, 0.6f), float(n), n,
                                  make_brdf(brdf, n)};
        for (bool specular : {true, false})
          for (std::size_t len = 0; len <= 2 * 16 + 1; ++len) {
            std::vector<glm::vec3> lanes(len + 1, glm::vec3(-7.0f)), scalar(len + 1, glm::vec3(-7.0f));
            light_vertices(simd, normals.data() + 1, nullptr, len, m, k, specular, lanes.data());
            light_vertices_scalar(normals.data() + 1, nullptr, len, m, k, specular, scalar.data());
            ASSERT_EQ(lanes[len], glm::vec3(-7.0f)) << "wrote past the end: " << isa;
            for (std::size_t i = 0; i < len; ++i)
              for (int c = 0; c < 3; ++c) {
                ASSERT_NEAR(lanes[i][c], scalar[i][c], kTolerance)
                    << isa << " " << option_name(brdf) << " n=" << n << " specular " << specular << " vertex " << i;
                ASSERT_TRUE(lanes[i][c] >= 0.0f && lanes[i][c] <= 1.0f);
              }
            // Without a BRDF approximation in play, the lanes are the scalar arithmetic exactly.
            if (!specular) {
              for (std::size_t i = 0; i < len; ++i) ASSERT_EQ(lanes[i], scalar[i]) << isa << " vertex " << i;
            }
          }
      }
  }
  EXPECT_GE(isas, 1);
}

// A local viewer and a material lit in double take the scalar loop: the same colours exactly.
TEST(VertexLight, LocalViewerAndDoubleMaterialsAreTheScalarColours) {
  ShadeConstants k = two_lights();
  k.local_viewer = true;
  const std::vector<glm::vec3> normals = {glm::normalize(glm::vec3(0.2f, 0.3f, 1)), glm::vec3(0, 1, 0)};
  const std::vector<glm::vec3> positions = {glm::vec3(0.5f, -0.2f, -3), glm::vec3(-1, 0.4f, -5)};
  MaterialConstants m{glm::vec3(0.7f), glm::vec3(0.5f), 100.0f, 100.0, make_brdf(parse_option<BrdfChoice>("exact", "test"), 100.0)};
  for (bool in_double : {false, true}) {
    m.shade_in_double = in_double;
    k.local_viewer = !in_double;
    std::vector<glm::vec3> lanes(2), scalar(2);
    light_vertices(SimdTarget{}, normals.data(), positions.data(), 2, m, k, true, lanes.data());
    light_vertices_scalar(normals.data(), positions.data(), 2, m, k, true, scalar.data());
    EXPECT_EQ(lanes, scalar) << (in_double ? "material in double" : "local viewer");
  }
}

}  // namespace
}  // namespace fastshade
