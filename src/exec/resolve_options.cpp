#include "exec/resolve_options.h"

#include <cmath>
#include <utility>

#include "core/limits.h"
#include "fastshade/error.h"

namespace fastshade {

namespace {

// A value cast from outside its enum (C++ callers can make one) names no spelling.
template <OptionEnum E>
void check_enum(E value, const char* flag) {
  if (option_name(value) == "?")
    throw InputError(flag, "not a " + std::string(OptionSpellings<E>::kWhat) + " (value " +
                               std::to_string(static_cast<int>(value)) + ")");
}

// The classifier's options keep their defaults unless the method classifies.
void refuse_classifier_options(const RenderOptions& o) {
  const RenderOptions defaults;
  for (const auto& [set, flag] : {std::pair{o.spec_threshold != defaults.spec_threshold, "--spec-threshold"},
                                  std::pair{o.spec_method != defaults.spec_method, "--spec-method"},
                                  std::pair{o.classifier != defaults.classifier, "--classifier"},
                                  std::pair{o.classify_min_px != defaults.classify_min_px, "--classify-min-px"}})
    if (set) throw InputError(flag, "applies to --method auto only");
}

}  // namespace

ResolvedOptions resolve(const RenderOptions& o) {
  if (o.threads < 0 || o.threads > 1024)
    throw InputError("--threads", "expected 0 (all) to 1024, got " + std::to_string(o.threads));
  if (o.tile_px != 0 && (o.tile_px < limits::kMinTilePx || o.tile_px > limits::kMaxTilePx ||
                         (o.tile_px & (o.tile_px - 1)) != 0))
    throw InputError("--tile", "expected a power of two from " + std::to_string(limits::kMinTilePx) + " to " +
                                   std::to_string(limits::kMaxTilePx) +
                                   ", or 0 (sized from the image and threads), got " + std::to_string(o.tile_px));
  check_enum(o.method, "--method");
  check_enum(o.isa, "--isa");
  check_enum(o.brdf.kind, "--brdf");
  check_enum(o.normals, "--normals");
  check_enum(o.gouraud, "--gouraud");
  check_enum(o.spec_method, "--spec-method");
  check_enum(o.classifier, "--classifier");
  check_enum(o.hidden_faces, "--hidden-faces");
  if (o.brdf.kind == BrdfKind::CosK && (o.brdf.k < kMinCosK || o.brdf.k > kMaxCosK))
    throw InputError("--brdf", "cosk takes a power K from " + std::to_string(kMinCosK) + " to " +
                                   std::to_string(kMaxCosK) + ", got " + std::to_string(o.brdf.k));
  ResolvedOptions r;
  r.method = &find_method(o.method);
  r.simd = simd_target(o.isa);
  if (o.gouraud == GouraudMode::Sierpinski && !r.method->lights_subtriangles)
    throw InputError("--gouraud", "sierpinski subtriangles apply to --method gouraud only");
  if (!(o.max_error >= 0 && o.max_error <= 255))
    throw InputError("--max-error", "expected 0 to 255 (8-bit steps), got " + std::to_string(o.max_error));
  if (!r.method->classifies) refuse_classifier_options(o);
  if (!(o.spec_threshold >= 0.0 && o.spec_threshold <= 1.0))
    throw InputError("--spec-threshold", "expected 0 to 1 (colour units; 1/510 is half an 8-bit step), got " +
                                             std::to_string(o.spec_threshold));
  if (!(o.classify_min_px >= 0.0 && std::isfinite(o.classify_min_px)))
    throw InputError("--classify-min-px",
                     "expected a finite number of pixels >= 0 (0: classify every triangle), got " +
                         std::to_string(o.classify_min_px));
  if (const std::string why = r.method->refuse(o); !why.empty()) {
    const std::size_t colon = why.find(": ");  // "--option: reason"
    throw InputError(why.substr(0, colon), why.substr(colon + 2));
  }
  r.options = o;
  return r;
}

void validate(const RenderOptions& options) { (void)resolve(options); }

std::vector<MethodDescription> list_methods() {
  std::vector<MethodDescription> out;
  for (const Method& m : all_methods())
    out.push_back({m.id, std::string(option_name(m.id)), std::string(m.summary), m.classifies});
  return out;
}

bool method_classifies(ShadingMethod method) { return find_method(method).classifies; }

}  // namespace fastshade
