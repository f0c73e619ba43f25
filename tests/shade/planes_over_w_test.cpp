// PlanesOverW (shade/planes_over_w-inl.h) against make_plane (raster/planes.h), bit for bit,
// on every compiled ISA, as the Gouraud (scale 255) and Phong (scale +-1) set-ups call it:
// random and degenerate inputs (equal vertex values, zeros of both signs, huge and tiny
// gradients of slivers).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "core/simd_target.h"
#include "shade/planes_over_w_testing.h"

namespace fastshade {
namespace {

bool same_bits(const Plane& a, const Plane& b) { return std::memcmp(&a, &b, sizeof(Plane)) == 0; }

TEST(PlanesOverW, EqualsMakePlaneOnEveryIsa) {
  int isas = 0;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    ++isas;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> lambda(-2.0, 2.0), gradient_exp(-12.0, 3.0);
    std::uniform_real_distribution<float> value(-1.5f, 1.5f), w(1e-3f, 4.0f);
    const float picks[] = {0.0f, -0.0f, 1.0f, 0.5f};
    long long planes = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      Barycentrics b{};
      for (int k = 0; k < 3; ++k) {
        b.at_anchor[k] = lambda(rng);
        b.d_dx[k] = lambda(rng) * std::pow(10.0, gradient_exp(rng));
        b.d_dy[k] = lambda(rng) * std::pow(10.0, gradient_exp(rng));
      }
      glm::vec3 v[3];
      float inv_w[3];
      for (int i = 0; i < 3; ++i) {
        for (int c = 0; c < 3; ++c)
          v[i][c] = trial % 3 == 0 ? picks[(trial / 3 + i + c) % 4] : value(rng);  // ties and signed zeros
        inv_w[i] = trial % 7 == 0 ? inv_w[0] : w(rng);
      }
      if (trial % 11 == 0) v[1] = v[2] = v[0];  // a flat triangle: lo == hi
      const float scale_f = trial % 2 ? 1.0f : -1.0f;
      for (const double scale : {255.0, static_cast<double>(scale_f)}) {
        Plane got[4];
        planes_over_w(simd, b, v, scale, inv_w, got);
        for (int c = 0; c < 3; ++c) {
          // What the scalar set-ups compute: Gouraud (255.0 * c) * w, Phong double(s * c) * w.
          auto q = [&](int i) {
            return scale == 255.0 ? 255.0 * v[i][c] * inv_w[i] : double(scale_f * v[i][c]) * inv_w[i];
          };
          const Plane want = make_plane(b, q(0), q(1), q(2));
          ASSERT_TRUE(same_bits(got[c], want)) << isa << " trial " << trial << " component " << c;
        }
        ASSERT_TRUE(same_bits(got[3], make_plane(b, inv_w[0], inv_w[1], inv_w[2]))) << isa << " trial " << trial;
        planes += 4;
      }
    }
    EXPECT_EQ(planes, 20000 * 2 * 4);
  }
  EXPECT_GE(isas, 1);
}

}  // namespace
}  // namespace fastshade
