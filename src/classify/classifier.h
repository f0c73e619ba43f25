// The highlight classifier: per triangle, per light, the largest specular term the triangle
// can reach and the largest error Gouraud makes on its diffuse term, both bounded over the
// normals the pipeline actually draws (linear, then normalised); from those, its shading path.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "classify/cone_batch.h"
#include "classify/highlight_bound.h"
#include "core/limits.h"
#include "frame/shade_constants.h"
#include "frame/shade_path.h"

namespace fastshade {

struct ClassifierParams {
  // A triangle whose specular term stays below this (colour units) gets no specular work.
  double spec_threshold = 1.0 / 510.0;
  // A triangle without specular work takes Gouraud if its diffuse interpolation error plus
  // the specular term it leaves out stays within this (colour units).
  double gouraud_budget = 0.0;
  // --classifier paper: highlight -> specular, everything else -> Gouraud (no error check).
  bool paper_rule = false;
};

// One triangle's unit vertex normals and, for a local viewer, unit directions toward the eye
// (view space; two-sided back faces already flipped).
struct ClassifyInput {
  dvec3 n[3];
  dvec3 v[3];
  bool local_viewer = false;
};

struct Classification {
  ShadePath path = ShadePath::Specular;
  double specular_bound = 0;  // colour units: largest specular term anywhere on the triangle
  double diffuse_bound = 0;   // colour units: largest |Gouraud - per-pixel| of the diffuse term
  uint64_t lights_with_highlight = 0;  // bit i: light i reaches the threshold
};

// Upper bound of max N.H over the triangle for light direction l (unit).
double max_cos_nh(const ClassifyInput& in, const dvec3& l, const dvec3& h_infinite);

// --max-error (8-bit steps) to the Gouraud path's budget in colour units.
inline double auto_gouraud_budget(double max_error_lsb) {
  return std::max(max_error_lsb - limits::kAutoFloatReserveLsb, 0.0) / 255.0;
}

// Built once per frame: per material and light the weights of the bounds and the cosine
// below which a highlight is negligible, so that most triangles need neither pow nor the
// exact edge maxima.
class Classifier {
 public:
  Classifier(const ShadeConstants& shade, const ClassifierParams& params);
  Classification classify(const ClassifyInput& in, int material) const;
  // The constants for deciding this material's triangles in lanes (classify/cone_batch.h), or
  // nullptr where the lanes cannot match classify(): local viewer, two-sided lighting (the
  // normals depend on facing), or colours that may saturate.
  const ConeBatchTerms* cone_batch_terms(int material) const;
  const ShadeConstants& shade() const { return shade_; }
  // Whether the lights' specular terms on this material can reach the threshold anywhere (all
  // at N.H = 1; a threshold of 0 asks only for a term), and the lights whose term alone may
  // reach it somewhere (bit i: light i; 63: 63 and up): a superset of what classify() reports
  // for any of its triangles.
  bool can_highlight(int material) const { return materials_[material].can_highlight; }
  uint64_t highlight_lights(int material) const { return materials_[material].highlight_lights; }

 private:
  struct LightTerms {
    double spec_weight;    // max channel of ks * light colour
    double cos_negligible; // N.H below this: the term is under kNegligible * threshold
    double cos_share;      // N.H below this: the term is under threshold / lights
    double cos_alone;      // N.H at or above this: the term alone reaches the threshold
    double diffuse_weight; // max channel of kd * light colour
  };
  struct MaterialTerms {
    std::vector<LightTerms> lights;
    double shininess;
    bool may_saturate;     // ambient + sum kd * colour can exceed 1 in some channel
    bool can_highlight = false;
    uint64_t highlight_lights = 0;  // lights with spec_weight >= the threshold
  };
  struct Bounds {
    double specular = 0, diffuse = 0;
    uint64_t lights_with_highlight = 0;
  };
  Bounds specular(const ClassifyInput& in, const MaterialTerms& m, const NormalCone* cone) const;
  double diffuse(const ClassifyInput& in, const MaterialTerms& m, const NormalCone* cone) const;
  bool saturates(const ClassifyInput& in, int material) const;

  const ShadeConstants& shade_;
  ClassifierParams params_;
  std::vector<MaterialTerms> materials_;
  std::vector<ConeBatchTerms> batch_;  // per material
};

}  // namespace fastshade
