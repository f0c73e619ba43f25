#include "shade/method.h"

#include <array>

#include "shade/methods.h"

namespace fastshade {

namespace {

const std::array kMethods = {
    Method{"reference",
           "per-pixel Blinn-Phong in double precision from exact barycentrics: the yardstick",
           reference_needs, select_reference, reference_refuses},
    Method{"phong", "per-pixel Blinn-Phong in float with exact pow, as a GL fragment shader does",
           phong_needs, select_phong, accepts_all},
    Method{"hybrid",
           "Phong at the ends of 2^m-pixel segments, linear between, m adapted per 16-px block "
           "to --max-error",
           phong_needs, select_hybrid, refuses_normals},
    Method{"gouraud", "Blinn-Phong per vertex, colour interpolated perspective-correctly",
           gouraud_needs, select_gouraud, refuses_normals},
};

}  // namespace

std::string refuses_normals(const RenderOptions& o) {
  if (o.normals != "normalize")
    return "--normals: only phong interpolates normals along a span; use --method phong";
  return {};
}

std::span<const Method> all_methods() { return kMethods; }

const Method* find_method(std::string_view name) {
  for (const Method& m : kMethods)
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace fastshade
