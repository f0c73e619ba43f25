// The vertex transform in lanes (front/vertex_transform.cpp) against its scalar reference, bit
// for bit, on every compiled ISA: batch lengths 0..2W+1 and a long one at an unaligned start,
// vertices inside the frustum, behind the eye, across near and far, past the guard band, and
// with NaN and infinite coordinates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/simd_target.h"
#include "front/vertex_transform.h"

namespace fastshade {
namespace {

struct Outputs {
  std::vector<glm::vec4> clip;
  std::vector<ScreenVertex> screen;
  std::vector<uint8_t> flags;
  std::vector<glm::vec3> n_view, pos_view;
  explicit Outputs(std::size_t n) : clip(n), screen(n), flags(n), n_view(n), pos_view(n) {}
  VertexOutputs view(std::size_t first) {
    return {&clip[first], &screen[first], &flags[first], &n_view[first], &pos_view[first]};
  }
};

template <typename T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

TEST(VertexTransform, LanesEqualScalarOnEveryIsa) {
  VertexTransform xf;
  const glm::mat4 model = glm::rotate(glm::scale(glm::mat4(1.0f), glm::vec3(1.3f, 0.7f, 1.1f)), 0.4f,
                                      glm::normalize(glm::vec3(1, 2, 3)));
  xf.model_view = glm::lookAt(glm::vec3(0.3f, 0.2f, 4.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0)) * model;
  xf.proj = glm::perspective(glm::radians(45.0f), 16.0f / 9.0f, 1.0f, 7.0f);
  xf.normal_matrix = glm::inverseTranspose(glm::mat3(xf.model_view));
  xf.viewport = make_viewport(1920, 1080);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> near_box(-1.5f, 1.5f), far_box(-400.0f, 400.0f), unit(-1.0f, 1.0f);
  const std::size_t n = 2000;
  std::vector<glm::vec3> positions(n), normals(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Mostly in view; every 7th far out (behind the eye, past near/far or the guard band).
    const bool far = i % 7 == 0;
    positions[i] = far ? glm::vec3(far_box(rng), far_box(rng), far_box(rng))
                       : glm::vec3(near_box(rng), near_box(rng), near_box(rng));
    normals[i] = glm::vec3(unit(rng), unit(rng), unit(rng));
  }
  positions[5].x = std::numeric_limits<float>::quiet_NaN();
  positions[11].y = std::numeric_limits<float>::infinity();
  positions[12].z = -std::numeric_limits<float>::infinity();
  normals[13] = glm::vec3(0.0f);  // a zero normal: NaN after normalising, in both
  int isas = 0;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    ++isas;
    std::vector<std::pair<std::size_t, std::size_t>> runs;  // (first, count)
    for (std::size_t count = 0; count <= 33; ++count) runs.push_back({0, count});
    runs.push_back({1, n - 1});
    for (const auto& [first, count] : runs)
      for (bool with_normals : {true, false}) {
        Outputs lanes(n), scalar(n);
        transform_vertices(simd, xf, &positions[first], with_normals ? &normals[first] : nullptr, count, lanes.view(first));
        transform_vertices_scalar(xf, &positions[first], with_normals ? &normals[first] : nullptr, count,
                                  scalar.view(first));
        int projected = 0, clipped = 0;
        for (std::size_t i = first; i < first + count; ++i) {
          ASSERT_TRUE(same_bits(lanes.clip[i], scalar.clip[i])) << isa << " vertex " << i;
          ASSERT_EQ(lanes.flags[i], scalar.flags[i]) << isa << " vertex " << i;
          if (!(scalar.flags[i] & (kNeedsClip | kNonFinite))) {
            ++projected;
            ASSERT_EQ(lanes.screen[i].x_fx, scalar.screen[i].x_fx) << isa << " vertex " << i;
            ASSERT_EQ(lanes.screen[i].y_fx, scalar.screen[i].y_fx) << isa << " vertex " << i;
            ASSERT_TRUE(same_bits(lanes.screen[i].depth, scalar.screen[i].depth)) << isa << " vertex " << i;
            ASSERT_TRUE(same_bits(lanes.screen[i].inv_w, scalar.screen[i].inv_w)) << isa << " vertex " << i;
          } else {
            ++clipped;
          }
          if (with_normals) {
            ASSERT_TRUE(same_bits(lanes.n_view[i], scalar.n_view[i])) << isa << " vertex " << i;
            ASSERT_TRUE(same_bits(lanes.pos_view[i], scalar.pos_view[i])) << isa << " vertex " << i;
          }
        }
        if (count == n - 1) {  // the long run must reach both kinds of vertex
          EXPECT_GT(projected, 1000) << isa;
          EXPECT_GT(clipped, 100) << isa;
        }
      }
  }
  EXPECT_GE(isas, 1);
}

}  // namespace
}  // namespace fastshade
