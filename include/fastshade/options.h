// What a renderer is asked to do, as typed values; each value's spelling (the one the command
// line, config files, Python and the statistics use); the methods and the ISAs this CPU offers.
#pragma once
#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fastshade {

// The shading methods (list_methods() says what each does; docs/PIPELINE.md, "Methods").
enum class ShadingMethod : uint8_t { Auto, Reference, Phong, Hybrid, Gouraud };

// A renderer's SIMD target: Highway's portable scalar fallback, SSE4, AVX2, AVX-512, or the
// best this CPU runs (available_isas()).
enum class Isa : uint8_t { Best, Scalar, Sse4, Avx2, Avx512 };

// The specular lobe: how cos^n(gamma) = max(N.H, 0)^n is evaluated (definitions, errors and the
// readings chosen for garbled formulas: docs/KERNELS.md).
enum class BrdfKind : uint8_t {
  Exact,         // c^n as exp2(n log2 c)
  CosK,          // cos^K(sqrt(n/K) gamma), 0 once the argument passes pi/2 (paper, section II)
  Schlick,       // c / (n - n c + c)
  SchlickPow2,   // Schlick with exponent n / 2^m in [1, 2), squared m times (eq. 5 as
                 // docs/PAPER.md reads it)
  Quadratic,     // ((n/2)(c - 1) + 1)^2, 0 past its root (paper, section III)
  QuadraticFit,  // (a (c - 1) + 1)^2 with the minimax a for this n
  Poly2,         // a0 + a1 x + a2 x^2, x = 1 - c, minimax for this n on a fitted support [0, X],
                 // zero past X or the first root
  Poly3,         // the same, cubic
};
inline constexpr int kMinCosK = 1, kMaxCosK = 8;  // CosK's powers: the paper's table stops at 8
struct BrdfChoice {
  BrdfKind kind = BrdfKind::Exact;
  int k = 3;  // CosK: the power K, kMinCosK to kMaxCosK
  bool operator==(const BrdfChoice&) const = default;
};

// phong: how per-pixel normals become unit length: normalised at every pixel, in blocks within
// the error budget (the paper's eq. 6), or rotated at equal angles (eq. 7).
enum class PhongNormals : uint8_t { Normalize, Adaptive, EqualAngle };
// gouraud: colour increments along spans, or large triangles split at edge midpoints first.
enum class GouraudMode : uint8_t { Increments, Sierpinski };
// auto: the kernel of triangles that may show a highlight.
enum class SpecMethod : uint8_t { Hybrid, Phong };
// auto: how triangles are sent down its shading paths. Cost: the error-checked classifier where
// the cost model finds it pays on this frame and ISA, per-pixel Phong everywhere where it cannot
// (docs/CLASSIFIER.md, "When auto classifies"); Bound: the error-checked classifier always;
// Paper: the paper's literal rule (highlight -> specular path, the rest -> Gouraud).
enum class ClassifierRule : uint8_t { Cost, Bound, Paper };
// Skip: back faces that their own closed (or capped) mesh provably hides are culled at set-up;
// Draw: every face is drawn, as a z-buffer without the test would.
enum class HiddenFaces : uint8_t { Skip, Draw };

// Every value of an option enum with its spelling, and what the option is called in errors.
template <class E>
struct OptionSpellings;
template <>
struct OptionSpellings<ShadingMethod> {
  static constexpr std::string_view kWhat = "method";
  static constexpr std::pair<ShadingMethod, std::string_view> kValues[] = {
      {ShadingMethod::Auto, "auto"},       {ShadingMethod::Reference, "reference"},
      {ShadingMethod::Phong, "phong"},     {ShadingMethod::Hybrid, "hybrid"},
      {ShadingMethod::Gouraud, "gouraud"}};
};
template <>
struct OptionSpellings<Isa> {
  static constexpr std::string_view kWhat = "ISA";
  static constexpr std::pair<Isa, std::string_view> kValues[] = {
      {Isa::Scalar, "scalar"}, {Isa::Sse4, "sse4"}, {Isa::Avx2, "avx2"}, {Isa::Avx512, "avx512"}, {Isa::Best, "best"}};
};
template <>
struct OptionSpellings<BrdfKind> {  // CosK is spelled with its power, as cosk:3 (BrdfChoice)
  static constexpr std::string_view kWhat = "BRDF";
  static constexpr std::pair<BrdfKind, std::string_view> kValues[] = {
      {BrdfKind::Exact, "exact"},           {BrdfKind::CosK, "cosk"},
      {BrdfKind::Schlick, "schlick"},       {BrdfKind::SchlickPow2, "schlick-pow2"},
      {BrdfKind::Quadratic, "quadratic"},   {BrdfKind::QuadraticFit, "quadratic-fit"},
      {BrdfKind::Poly2, "poly2"},           {BrdfKind::Poly3, "poly3"}};
};
template <>
struct OptionSpellings<PhongNormals> {
  static constexpr std::string_view kWhat = "normals mode";
  static constexpr std::pair<PhongNormals, std::string_view> kValues[] = {
      {PhongNormals::Normalize, "normalize"}, {PhongNormals::Adaptive, "adaptive"},
      {PhongNormals::EqualAngle, "equal-angle"}};
};
template <>
struct OptionSpellings<GouraudMode> {
  static constexpr std::string_view kWhat = "gouraud mode";
  static constexpr std::pair<GouraudMode, std::string_view> kValues[] = {
      {GouraudMode::Increments, "increments"}, {GouraudMode::Sierpinski, "sierpinski"}};
};
template <>
struct OptionSpellings<SpecMethod> {
  static constexpr std::string_view kWhat = "specular method";
  static constexpr std::pair<SpecMethod, std::string_view> kValues[] = {{SpecMethod::Hybrid, "hybrid"},
                                                                        {SpecMethod::Phong, "phong"}};
};
template <>
struct OptionSpellings<ClassifierRule> {
  static constexpr std::string_view kWhat = "classifier";
  static constexpr std::pair<ClassifierRule, std::string_view> kValues[] = {
      {ClassifierRule::Cost, "cost"}, {ClassifierRule::Bound, "bound"}, {ClassifierRule::Paper, "paper"}};
};
template <>
struct OptionSpellings<HiddenFaces> {
  static constexpr std::string_view kWhat = "hidden-faces mode";
  static constexpr std::pair<HiddenFaces, std::string_view> kValues[] = {{HiddenFaces::Skip, "skip"},
                                                                         {HiddenFaces::Draw, "draw"}};
};

template <class E>
concept OptionEnum = requires { OptionSpellings<E>::kValues; };
// What an option's text can name: an enum's value, or a BRDF with its power ("cosk:3").
template <class T>
concept OptionValue = OptionEnum<T> || std::same_as<T, BrdfChoice>;

template <OptionEnum E>
constexpr std::string_view option_name(E value) {
  for (const auto& [v, name] : OptionSpellings<E>::kValues)
    if (v == value) return name;
  return "?";  // only a value cast from outside the enum's range
}
inline std::string option_name(const BrdfChoice& brdf) {  // "exact", "cosk:3"
  std::string name(option_name(brdf.kind));
  return brdf.kind == BrdfKind::CosK ? name + ":" + std::to_string(brdf.k) : name;
}

// Reads a spelling (option_name's); throws InputError naming `where` (a flag, a config key, a
// keyword) and the spellings it accepts. The command line, config files and Python read options
// through this.
template <OptionValue T>
T parse_option(std::string_view text, const std::string& where);
template <>
BrdfChoice parse_option<BrdfChoice>(std::string_view text, const std::string& where);

// The one options struct that reaches the renderer; printable for logs and stats.
struct RenderOptions {
  int threads = 0;         // 0 = all hardware threads
  int tile_px = 64;        // power of two in [kMinTilePx, kMaxTilePx], or 0: sized from the
                           // image and threads (exec/tile_size.h)
  ShadingMethod method = ShadingMethod::Auto;
  bool srgb = false;       // encode with the sRGB curve before quantising
  Isa isa = Isa::Best;     // this renderer's SIMD target
  BrdfChoice brdf;         // specular approximation (docs/KERNELS.md)
  double max_error = 1.0;  // auto, hybrid, PhongNormals::Adaptive: error budget in 8-bit steps (LSB)
  PhongNormals normals = PhongNormals::Normalize;  // phong only
  GouraudMode gouraud = GouraudMode::Increments;   // gouraud only
  // auto: a triangle whose specular term stays below this (colour units) gets no specular work
  double spec_threshold = 1.0 / 510.0;
  SpecMethod spec_method = SpecMethod::Hybrid;         // auto only
  ClassifierRule classifier = ClassifierRule::Cost;  // auto only
  // auto (cost, bound): a block of triangles whose screen boxes average fewer pixels than this takes
  // the specular path unclassified, where classifying would cost more than it saves; 0:
  // classify every triangle. 80: the 1080p bunny (boxes of about 30 px) ran 1.25-1.28x gouraud
  // with 40 and 1.13-1.19x with 80 against 1.21-1.42x classified, and meshes with larger
  // triangles (cow, teapot, dragon_11k, spot) did not change beyond noise (docs/CLASSIFIER.md,
  // "Dense blocks")
  double classify_min_px = 80.0;
  HiddenFaces hidden_faces = HiddenFaces::Skip;
  std::string to_string() const;
  bool operator==(const RenderOptions&) const = default;
};

// Throws InputError ("--tile: ...") if an option is out of range, the CPU cannot run the ISA,
// or the method refuses a combination (--normals adaptive with gouraud, say).
void validate(const RenderOptions& options);

// Each method with one line of description, and whether it classifies triangles into shading
// paths (spec_threshold, spec_method, classifier and classify_min_px apply to such methods
// only).
struct MethodDescription {
  ShadingMethod method;
  std::string name, summary;
  bool classifies = false;
};
std::vector<MethodDescription> list_methods();
bool method_classifies(ShadingMethod method);

// The ISAs this build compiled and this CPU runs, from the portable fallback to the best.
std::vector<Isa> available_isas();
// The ISA a renderer asked for `isa` runs: Best becomes the best of available_isas(). Throws
// InputError ("--isa: ...") for one this CPU or build cannot run.
Isa resolve_isa(Isa isa);

}  // namespace fastshade
