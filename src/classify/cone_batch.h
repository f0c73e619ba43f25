// The classifier's first look (classify/classifier.h: vertex terms, then the normal cone's
// bounds) for many triangles at once, one per SIMD lane: most triangles of a mesh are settled
// by it, and in lanes it costs a few instructions a triangle instead of several hundred.
// Lanes it cannot settle are left to Classifier::classify(), which is also the scalar
// reference: a lane settled here gets exactly the path (and reported light) classify() would
// choose (the same double operations in the same order, so the same bits).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

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
  bool paper_rule = false;
};

// Unit vertex normals of `count` triangles as structure of arrays: n[3 * k + c][i] is
// component c of vertex k of triangle i.
struct NormalsSoA {
  const double* n[9];
};

// What the lanes settled, per triangle: path[i] is Specular where a vertex's own term reaches
// the threshold (light[i]: the first such light, 63 standing for 63 and up, as classify()
// reports it), GouraudDiffuse where the cone bounds settle it, Unclassified where they cannot
// (highlight possible, bounds too loose, degenerate cone). Runs on the process's ISA
// (exec/isa.h).
void decide_paths_batch(const ConeBatchTerms& terms, const NormalsSoA& normals, std::size_t count,
                        ShadePath* path, uint8_t* light);

}  // namespace fastshade
