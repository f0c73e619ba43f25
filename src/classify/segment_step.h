// Hybrid Gouraud/Phong segments (the paper, section II; docs/PAPER.md, "Hybrid segments"): the
// segment length of a triangle, decided once per triangle by the front end
// (front/segment_steps.h) and read by the hybrid kernel (shade/hybrid.cpp) in every tile the
// triangle covers.
#pragma once
#include <algorithm>

#include <glm/vec3.hpp>

#include "classify/classify_limits.h"
#include "classify/highlight_bound.h"
#include "frame/shade_constants.h"

namespace fastshade {

// What the step decision needs of a triangle: unit vertex normals (view space, flipped for
// two-sided back faces), 1/w at the vertices and, for a local viewer, their view-space
// positions; and how the interpolated n/w and p/w change per pixel along x (the planes' x
// gradients, raster/planes.h).
struct SegmentStepInput {
  glm::vec3 n[3];
  float inv_w[3];
  glm::vec3 pos_view[3];
  dvec3 n_over_w_dx{0.0}, pos_over_w_dx{0.0};
  const MaterialConstants* material = nullptr;
  const ShadeConstants* shade = nullptr;
};

// How hybrid draws a triangle: its segment length (16, 8, 4, 2 or 1 px), the light, if any,
// whose N.L it interpolates unclamped between the segment ends and clamps per pixel, and
// whether its ends need the specular term at all.
struct SegmentPlan {
  int step_px = 1;
  int split_light = -1;  // -1: every light's diffuse term is interpolated clamped
  bool specular = true;  // false: every light's ks c^n < limits::kNegligibleSpecular on the triangle
};

// The segment plan for a whole triangle.
//
// A segment of L pixels errs, linearly interpolated, by at most L^2 / 8 * max |f''| along
// the row, plus kd |u'| L / 4 where the terminator's kink crosses it. |f''| is bounded over
// the whole triangle from the normal's turn rate |u'| (the part of d(n/w)/dx across the
// normals, over the smallest |n/w| anywhere on the triangle), the rate's change |u''|, and the
// colour's derivatives at c_max = max N.H (edges' closed-form maxima, docs/PAPER.md, "Peaks of
// N·H along an edge and inside a triangle", or 1 when H lies inside the normals' cone); summed
// over lights weighted by |colour| (derivation in segment_step.cpp; docs/CLASSIFIER.md says what
// the earlier estimate missed).
// A local viewer's H moves too: by the view direction's spread over the triangle and its turn
// along x (docs/STABILITY.md, "B2").
// The longest L whose bound is within tol wins (tol less the specular terms, where the plan
// leaves them out). One fixed length per object fails badly (docs/PAPER.md, "Hybrid segments":
// 19 LSB seen); this adapts to the triangle's curvature and to how near it is to a
// highlight. A decision per 16-px block was measured first and cost more than the Phong
// evaluations it saved on small triangles (3x phong's time on the 4K spot frame).
// Where a light's terminator crosses the triangle, hybrid can instead interpolate that light's
// N.L unclamped and clamp it per pixel: max(., 0) is 1-Lipschitz, so N.L's own interpolation
// error (already in |f''|) bounds the result, and that light's kink term goes. It costs a
// fourth interpolated channel, so the plan splits only the light whose kink weighs most, and
// only where that makes the segments longer (4d691e9).
SegmentPlan hybrid_triangle_step(const SegmentStepInput& in, float tol);

// --max-error in LSB to the interpolation tolerance in colour units: half an LSB goes to the
// final rounding, so that the rounded result stays within max_error of exact Phong.
inline float hybrid_tolerance(double max_error_lsb) {
  return static_cast<float>(std::max(max_error_lsb - 0.5, 0.0) / 255.0);
}

}  // namespace fastshade
