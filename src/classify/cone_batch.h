// The classifier (classify/classifier.h: vertex terms, the normal cone's cheap bounds, then the
// exact ones) for many triangles at once, one per SIMD lane: in lanes it costs tens of
// instructions a triangle instead of several hundred. Classifier::classify() is the scalar
// reference: a lane settled here gets exactly the path (and reported lights) classify() would
// choose (the same double operations in the same order, so the same bits; std::pow itself is
// called per lane). Lanes are left to classify() only for materials lit by more than 32 lights
// (those get the cheap bounds in lanes alone).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/simd_target.h"
#include "frame/shade_path.h"

namespace fastshade {

struct ConeLight {
  double h[3], l[3];  // view space, unit (infinite viewer)
  double spec_weight, cos_negligible, cos_share, cos_alone, diffuse_weight;
};

// One material's constants, from Classifier::cone_batch_terms().
struct ConeBatchTerms {
  std::vector<ConeLight> lights;
  double spec_threshold = 0, gouraud_budget = 0;
  double negligible_share = 0;  // the classifier's kNegligible
  double shininess = 1;
  bool paper_rule = false;
};

// Unit vertex normals of `count` triangles as structure of arrays: n[3 * k + c][i] is
// component c of vertex k of triangle i.
struct NormalsSoA {
  const double* n[9];
};

// What the lanes settled, per triangle: path[i] as classify() decides it (lights[i]: its
// lights_with_highlight where Specular), Unclassified where only classify() can. Runs on the
// ISA `simd` (core/simd_target.h).
void decide_paths_batch(SimdTarget simd, const ConeBatchTerms& terms, const NormalsSoA& normals, std::size_t count,
                        ShadePath* path, uint64_t* lights);

}  // namespace fastshade
