// A uniformly random unit vector (float or double), the classify and step tests' normals and
// light directions: a normal-distributed vector, redrawn in the rare case it is too short to
// normalise.
#pragma once
#include <random>

#include <glm/geometric.hpp>

namespace fastshade::test {

template <class Vec, class Rng>
Vec random_unit(Rng& rng) {
  std::normal_distribution<typename Vec::value_type> g;
  for (;;) {
    const Vec v(g(rng), g(rng), g(rng));
    if (glm::length(v) > typename Vec::value_type(1e-3)) return glm::normalize(v);
  }
}

}  // namespace fastshade::test
