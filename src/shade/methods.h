// Entry points of each shading method, for the registry (method.cpp) only.
#pragma once
#include "core/simd_target.h"
#include "shade/method.h"

namespace fastshade {

AttrNeeds reference_needs(const ShadeConstants& shade);
// The yardstick's drawer: also the float methods' fallback for a material whose highlight
// float cannot hold (MaterialConstants::shade_in_double), decided per triangle at setup.
void draw_reference(const Frame& frame, uint32_t entry, const TileTarget& target);
DrawTriangleFn select_reference(SimdTarget simd, const ShadeConstants& shade);  // scalar: ignores simd
std::string reference_refuses(const RenderOptions& options);

AttrNeeds phong_needs(const ShadeConstants& shade);
DrawTriangleFn select_phong(SimdTarget simd, const ShadeConstants& shade);
DrawTriangleFn select_phong_normals(SimdTarget simd, const ShadeConstants& shade);  // --normals other than normalize

// Methods that interpolate no per-pixel normal refuse --normals.
std::string refuses_normals(const RenderOptions& options);

// For methods that take every option.
inline std::string accepts_all(const RenderOptions&) { return {}; }

AttrNeeds gouraud_needs(const ShadeConstants& shade);
DrawTriangleFn select_gouraud(SimdTarget simd, const ShadeConstants& shade);

// `auto`'s paths without a highlight: diffuse-only Gouraud, and per-pixel diffuse (normalised
// per pixel, or by --normals adaptive|equal-angle).
DrawTriangleFn select_gouraud_diffuse(SimdTarget simd, const ShadeConstants& shade);
DrawTriangleFn select_phong_diffuse(SimdTarget simd, const ShadeConstants& shade);
DrawTriangleFn select_phong_normals_diffuse(SimdTarget simd, const ShadeConstants& shade);

AttrNeeds auto_needs(const ShadeConstants& shade);
TileDraw select_auto(SimdTarget simd, const ShadeConstants& shade, const RenderOptions& options);
SegmentSteps auto_segment_steps(const RenderOptions& options);

DrawTriangleFn select_hybrid(SimdTarget simd, const ShadeConstants& shade);

}  // namespace fastshade
