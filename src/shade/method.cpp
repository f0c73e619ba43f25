#include "shade/method.h"

#include <array>

#include "shade/methods.h"

namespace fastshade {

namespace {

template <SegmentSteps kSteps>
SegmentSteps steps(const RenderOptions&) {
  return kSteps;
}

template <DrawTriangleFn (*kSelect)(SimdTarget, const ShadeConstants&)>
TileDraw select_one(SimdTarget simd, const ShadeConstants& shade, const RenderOptions&) {
  return {kSelect(simd, shade)};
}

const std::array kMethods = {
    Method{ShadingMethod::Auto,
           "the classifier's plan: diffuse-only Gouraud where no highlight can show and "
           "interpolation stays within --max-error, per-pixel diffuse where it would not, "
           "--spec-method where a highlight may show (docs/CLASSIFIER.md)",
           auto_needs, select_auto, accepts_all, true, false, auto_segment_steps},
    Method{ShadingMethod::Reference,
           "per-pixel Blinn-Phong in double precision from exact barycentrics: the yardstick",
           reference_needs, select_one<select_reference>, reference_refuses, false, false,
           steps<SegmentSteps::None>},
    Method{ShadingMethod::Phong, "per-pixel Blinn-Phong in float with exact pow, as a GL fragment shader does",
           phong_needs, select_one<select_phong>, accepts_all, false, false, steps<SegmentSteps::None>},
    Method{ShadingMethod::Hybrid,
           "Phong at the ends of 2^m-pixel segments, linear between, m adapted per triangle "
           "to --max-error",
           phong_needs, select_one<select_hybrid>, refuses_normals, false, false, steps<SegmentSteps::All>},
    Method{ShadingMethod::Gouraud, "Blinn-Phong per vertex, colour interpolated perspective-correctly",
           gouraud_needs, select_one<select_gouraud>, refuses_normals, false, true,
           steps<SegmentSteps::None>},
};

}  // namespace

std::string refuses_normals(const RenderOptions& c) {
  if (c.normals != PhongNormals::Normalize)
    return "--normals: only phong interpolates normals along a span; use --method phong";
  return {};
}

std::span<const Method> all_methods() { return kMethods; }

const Method& find_method(ShadingMethod id) {
  for (const Method& m : kMethods)
    if (m.id == id) return m;
  return kMethods[0];  // unreachable: resolve() refuses ids outside ShadingMethod
}

}  // namespace fastshade
