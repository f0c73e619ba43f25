// The user's rendering options as typed values (parsed once from RenderOptions by
// exec/resolve_options.h): what set-up, the classifier and the shading methods read. Plain
// data, so that the layers below exec/ never see an option's spelling.
#pragma once
#include <cstdint>

#include "frame/brdf_params.h"
#include "frame/shade_constants.h"

namespace fastshade {

enum class SpecMethod : uint8_t { Hybrid, Phong };      // --spec-method
enum class ClassifierRule : uint8_t { Bound, Paper };  // --classifier

struct RenderChoices {
  BrdfChoice brdf;                                // --brdf
  SpanNormals normals = SpanNormals::Normalize;   // --normals
  bool srgb = false;                              // --srgb
  bool sierpinski = false;                        // --gouraud sierpinski
  bool skip_hidden_faces = true;                  // --hidden-faces skip
  double max_error_lsb = 1.0;                     // --max-error, 8-bit steps
  // Classifying methods only (--spec-threshold, --spec-method, --classifier, --classify-min-px).
  double spec_threshold = 1.0 / 510.0;
  SpecMethod spec_method = SpecMethod::Hybrid;
  ClassifierRule classifier = ClassifierRule::Bound;
  double classify_min_px = 80.0;
};

}  // namespace fastshade
