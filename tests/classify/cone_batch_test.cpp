// The classifier in lanes (classify/cone_batch.h) against its scalar reference, classify():
// on every compiled ISA and batch length 0..2W+1 and beyond, every triangle gets the path (and
// reported lights) classify() gives it; with more lights than the lanes' exact bounds take, a
// triangle the cheap look settles gets classify()'s path too.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "classify/classifier.h"
#include "core/simd_target.h"
#include "support/random_unit.h"

namespace fastshade {
namespace {

using test::random_unit;

// Vertex normals as a mesh has them (float): around a random axis, spread from flat to wide.
std::vector<glm::vec3> random_triangles(std::mt19937& rng, int count) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec3> normals;
  for (int t = 0; t < count; ++t) {
    const glm::vec3 axis = random_unit<glm::vec3>(rng);
    const float spread = std::pow(10.0f, -3.0f * u(rng));  // 1e-3 .. 1 rad
    for (int v = 0; v < 3; ++v) normals.push_back(glm::normalize(axis + spread * random_unit<glm::vec3>(rng)));
  }
  return normals;
}

ShadeConstants scene(int lights, float shininess, float ks) {
  ShadeConstants k;
  const glm::vec3 dirs[] = {glm::normalize(glm::vec3(1, 1, 1)), glm::normalize(glm::vec3(-1, 0.2f, 0.3f)),
                            glm::vec3(0, 0, 1)};
  for (int i = 0; i < lights; ++i)
    k.lights.push_back({dirs[i % 3], glm::normalize(dirs[i % 3] + glm::vec3(0, 0, 1)), glm::vec3(1.2f / float(lights))});
  MaterialConstants m{};
  m.kd = glm::vec3(0.7f), m.ks = glm::vec3(ks), m.shininess = shininess, m.shininess_d = shininess;
  k.materials = {m};
  k.ambient = glm::vec3(0.1f);
  return k;
}

TEST(ConeBatch, SettlesTrianglesAsClassifyDoes) {
  std::mt19937 rng(5);
  const std::vector<glm::vec3> normals = random_triangles(rng, 4000);
  struct Setting {
    int lights;
    float shininess, ks;
    ClassifierParams params;
  };
  const Setting settings[] = {{1, 32, 0.5f, {1.0 / 510.0, 1.0 / 255.0, false}},
                              {2, 100, 0.3f, {1.0 / 510.0, 2.0 / 255.0, false}},
                              {3, 10, 0.5f, {1.0 / 255.0, 4.0 / 255.0, false}},
                              {1, 1000, 1.0f, {1.0 / 510.0, 1.0 / 255.0, true}},
                              {1, 5, 0.0f, {1.0 / 510.0, 0.5 / 255.0, false}},
                              {33, 20, 0.5f, {1.0 / 510.0, 2.0 / 255.0, false}}};
  int isas = 0;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    ++isas;
    for (const Setting& s : settings) {
      const ShadeConstants k = scene(s.lights, s.shininess, s.ks);
      const Classifier classifier(k, s.params);
      const ConeBatchTerms* terms = classifier.cone_batch_terms(0);
      ASSERT_NE(terms, nullptr);
      // Batch lengths 0..2W+1 for every width, then one long batch.
      std::vector<std::size_t> lengths;
      for (std::size_t n = 0; n <= 17; ++n) lengths.push_back(n);
      lengths.push_back(normals.size() / 3);
      int settled = 0, gouraud = 0, specular = 0;
      for (std::size_t count : lengths) {
        std::vector<double> soa(9 * count);
        NormalsSoA view;
        for (int c = 0; c < 9; ++c) view.n[c] = soa.data() + c * count;
        for (std::size_t t = 0; t < count; ++t)
          for (int v = 0; v < 3; ++v)
            for (int c = 0; c < 3; ++c) soa[(3 * v + c) * count + t] = normals[3 * t + v][c];
        std::vector<ShadePath> path(count + 1, ShadePath::Unclassified);  // a sentinel past the end
        std::vector<uint64_t> light(count + 1, 99);
        decide_paths_batch(simd, *terms, view, count, path.data(), light.data());
        ASSERT_EQ(path[count], ShadePath::Unclassified) << isa << ": wrote past the batch";
        ASSERT_EQ(light[count], 99) << isa << ": wrote past the batch";
        for (std::size_t t = 0; t < count; ++t) {
          ClassifyInput in;
          for (int v = 0; v < 3; ++v) in.n[v] = dvec3(normals[3 * t + v]);
          const Classification expected = classifier.classify(in, 0);
          if (s.lights <= 32) {
            ASSERT_NE(path[t], ShadePath::Unclassified) << isa << ": the lanes settle every triangle";
          }
          if (path[t] != ShadePath::Unclassified) {
            ASSERT_EQ(expected.path, path[t]) << isa << " triangle " << t << " of " << count;
          }
          if (path[t] == ShadePath::Specular) {
            ASSERT_EQ(expected.lights_with_highlight, light[t]) << isa << " triangle " << t;
          }
          if (count == lengths.back()) {
            settled += path[t] == ShadePath::GouraudDiffuse;
            gouraud += expected.path == ShadePath::GouraudDiffuse;
            specular += path[t] == ShadePath::Specular;
          }
        }
      }
      // With the cheap look alone (33 lights) most Gouraud triangles must still be settled, or
      // the lanes would save nothing there.
      EXPECT_GT(gouraud, 100) << isa << ": the cases must reach Gouraud to test anything";
      EXPECT_GE(settled, gouraud * 6 / 10) << isa << " settled " << settled << " of " << gouraud;
      if (s.ks > 0.0f) {
        EXPECT_GT(specular, 0) << isa << ": vertex highlights must be settled too";
      }
    }
  }
  EXPECT_GE(isas, 1);
}

TEST(ConeBatch, NoLanesWhereTheyCannotMatchClassify) {
  ShadeConstants k = scene(1, 32, 0.5f);
  k.local_viewer = true;
  EXPECT_EQ(Classifier(k, {}).cone_batch_terms(0), nullptr);
  k = scene(1, 32, 0.5f);
  k.two_sided = true;
  EXPECT_EQ(Classifier(k, {}).cone_batch_terms(0), nullptr);
  k = scene(1, 32, 0.5f);
  k.ambient = glm::vec3(0.5f);  // 0.5 + 1.2 * 0.7 > 1: colours may clamp
  EXPECT_EQ(Classifier(k, {}).cone_batch_terms(0), nullptr);
}

}  // namespace
}  // namespace fastshade
