// `auto`'s cost model: whether classifying triangles into shading paths (classify/classifier.h)
// pays on this frame and ISA, or plain per-pixel Phong is the cheaper way to the same ≤ 1 LSB.
// Decided once per renderer from the geometry and the camera, never from a timing, so a scene
// gives the same image on every run, thread count and tile size.
#pragma once
#include "fastshade/options.h"
#include "front/projection.h"
#include "front/scene_geometry.h"
#include "front/vertex_stage.h"
#include "shade/method.h"

namespace fastshade {

// Whether the model decides: `auto` with `--classifier cost` (its default) and lights (without,
// it draws the ambient colour alone).
bool auto_cost_applies(const Method& method, const Scene& scene, const RenderOptions& options);

// The mean screen area, in pixels, of the triangles in front of the camera and on screen, from
// an evenly spaced sample of at most limits::kAutoCostSampleTriangles of them (0 if none).
double sampled_triangle_px(const SceneGeometry& geometry, const ViewTransform& xf, const Viewport& viewport);

// Whether `auto` classifies at this ISA and mean triangle area (exec/exec_limits.h,
// kAutoClassifyMinPx, has the measurements), or draws every triangle with per-pixel Phong.
bool auto_classifies(Isa isa, double triangle_px);

}  // namespace fastshade
