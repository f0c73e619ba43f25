#include "exec/resolve_options.h"

#include <cmath>
#include <utility>

#include "core/limits.h"
#include "fastshade/error.h"
#include "light/brdf.h"
#include "shade/normal_blocks.h"

namespace fastshade {

namespace {

const Method& find_method_or_throw(const std::string& name) {
  if (const Method* method = find_method(name)) return *method;
  std::string names;
  for (const Method& m : all_methods()) names += (names.empty() ? "" : ", ") + std::string(m.name);
  throw InputError("--method", "unknown method '" + name + "' (expected one of: " + names + ")");
}

// One of two spellings, as the flag's value.
bool parse_pair(const std::string& text, const char* flag, const char* first, const char* second) {
  if (text == first) return true;
  if (text == second) return false;
  throw InputError(flag, std::string("expected ") + first + " or " + second + ", got '" + text + "'");
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
  ResolvedOptions r;
  r.method = &find_method_or_throw(o.method);
  r.simd = simd_target(o.isa);
  RenderChoices& c = r.choices;
  c.brdf = parse_brdf(o.brdf, "--brdf");
  c.normals = parse_normals(o.normals, "--normals");
  c.srgb = o.srgb;
  c.sierpinski = !parse_pair(o.gouraud, "--gouraud", "increments", "sierpinski");
  c.skip_hidden_faces = parse_pair(o.hidden_faces, "--hidden-faces", "skip", "draw");
  if (c.sierpinski && !r.method->lights_subtriangles)
    throw InputError("--gouraud", "sierpinski subtriangles apply to --method gouraud only");
  if (!(o.max_error >= 0 && o.max_error <= 255))
    throw InputError("--max-error", "expected 0 to 255 (8-bit steps), got " + std::to_string(o.max_error));
  c.max_error_lsb = o.max_error;
  if (!r.method->classifies) refuse_classifier_options(o);
  c.spec_method = parse_pair(o.spec_method, "--spec-method", "hybrid", "phong") ? SpecMethod::Hybrid
                                                                                 : SpecMethod::Phong;
  c.classifier = parse_pair(o.classifier, "--classifier", "bound", "paper") ? ClassifierRule::Bound
                                                                              : ClassifierRule::Paper;
  if (!(o.spec_threshold >= 0.0 && o.spec_threshold <= 1.0))
    throw InputError("--spec-threshold", "expected 0 to 1 (colour units; 1/510 is half an 8-bit step), got " +
                                             std::to_string(o.spec_threshold));
  c.spec_threshold = o.spec_threshold;
  if (!(o.classify_min_px >= 0.0 && std::isfinite(o.classify_min_px)))
    throw InputError("--classify-min-px",
                     "expected a finite number of pixels >= 0 (0: classify every triangle), got " +
                         std::to_string(o.classify_min_px));
  c.classify_min_px = o.classify_min_px;
  if (const std::string why = r.method->refuse(c); !why.empty()) {
    const std::size_t colon = why.find(": ");  // "--option: reason"
    throw InputError(why.substr(0, colon), why.substr(colon + 2));
  }
  return r;
}

void validate(const RenderOptions& options) { (void)resolve(options); }

std::vector<MethodDescription> list_methods() {
  std::vector<MethodDescription> out;
  for (const Method& m : all_methods()) out.push_back({std::string(m.name), std::string(m.summary), m.classifies});
  return out;
}

bool method_classifies(const std::string& name) {
  const Method* m = find_method(name);
  return m && m->classifies;
}

}  // namespace fastshade
