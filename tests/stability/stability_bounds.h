// The error bounds of docs/STABILITY.md as code: for one scene (its lights and materials) and
// one method configuration, the largest error against `reference` the method may show, in
// 8-bit steps (LSB). The derivations are in STABILITY.md, section "Bounds"; the names here
// follow it (W_d, W_s, L_n, eps_c, delta_dir).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <string>
#include <vector>

#include "core/limits.h"
#include "fastshade/scene.h"
#include "front/shade_setup.h"
#include "light/brdf.h"
#include "stability/stability_methods.h"

namespace fastshade::stability {

enum class Status { Holds, Fallback, NoBound };

inline const char* status_name(Status s) {
  switch (s) {
    case Status::Holds: return "holds";
    case Status::Fallback: return "fallback";
    case Status::NoBound: return "no bound";
  }
  return "?";
}

struct Bound {
  double lsb = 0;
  Status status = Status::Holds;
};

// Float rounding unit (half an ulp of 1).
inline constexpr double kUnit = 0x1p-24;

// Direction error of the float-interpolated normal, radians: the plane's float evaluation
// (make_plane's rounding and four operations, each within kUnit of the sum of the magnitudes
// of its terms) over three components, 9 kUnit times the plane's conditioning R = (sum of
// the magnitudes of the terms) / |n/w|. R is below 4 for any triangle whose vertex normals
// span less than 90 degrees and whose 1/w varies by less than 2x over its box; the cases
// that break this (slivers, w near 0) are the renderer's fallbacks.
inline constexpr double kPlaneConditioning = 4;
inline constexpr double kDirectionError = 9 * kUnit * kPlaneConditioning;

// Per light, the largest channel of colour * kd and of colour * ks, summed over lights.
struct Weights {
  double diffuse = 0, specular = 0;
};
inline Weights weights(const Scene& scene, const Material& m) {
  Weights w;
  for (const Light& light : scene.lights) {
    double d = 0, s = 0;
    for (int c = 0; c < 3; ++c) {
      d = std::max(d, double(light.color[c]) * m.diffuse[c]);
      s = std::max(s, double(light.color[c]) * m.specular[c]);
    }
    w.diffuse += d;
    w.specular += s;
  }
  return w;
}

// L_n = max over gamma of |d cos^n(gamma) / d gamma| = sqrt(n) ((n - 1) / n)^((n - 1) / 2).
inline double lobe_slope(double n) {
  return n <= 1 ? 1.0 : std::sqrt(n) * std::pow((n - 1) / n, (n - 1) / 2);
}

// max |d approximation / dc|: n for every kind (each reaches its steepest slope n at c = 1),
// but a fitted polynomial may be steeper: its derivative on its support.
inline double brdf_slope(const BrdfParams& p, double n) {
  double slope = n;
  if (p.kind == BrdfKind::Poly2 || p.kind == BrdfKind::Poly3)
    for (int i = 0; i <= 1000; ++i) {
      const double x = p.x_root * i / 1000.0;
      slope = std::max(slope, std::fabs(p.poly[1] + 2 * p.poly[2] * x + 3 * p.poly[3] * x * x));
    }
  return slope;
}

// max |approximation - cos^n| over gamma in [0, pi/2], on the grid `fastshade brdf-table`
// uses (uniform in gamma plus dense in the lobe), with 2 % slack for what falls between.
inline double brdf_error(const BrdfParams& p, double n) {
  if (p.kind == BrdfKind::Exact) return 0;
  static std::mutex mutex;
  static std::map<std::pair<int, double>, double> cache;  // by (kind, n): every case asks again
  std::lock_guard lock(mutex);
  const auto key = std::make_pair(int(p.kind) * 16 + p.k, n);
  if (const auto it = cache.find(key); it != cache.end()) return it->second;
  return cache[key] = brdf_max_error(p, n, 20000) * 1.02 + 1e-6;
}

// Two values each rounded to 8 bits once differ by at most floor(255 |a - b|) + 1 steps.
inline double rounded_lsb(double colour_error) { return std::floor(255.0 * colour_error) + 1.0; }

// What a scene needs beyond its lights and materials: the largest angle between two vertex
// normals of one triangle (gouraud's bound).
struct CaseGeometry {
  double normal_spread_rad = 0;
};

// B1's float terms for one material, in colour units.
struct FloatTerms {
  double lipschitz = 0;  // of the colour in the normal's angle: W_d + W_s L_n
  double direction = 0;  // the normal's direction error through it
  double lobe = 0;       // the lobe's approximation error (0 for exact cos^n)
  double rounding = 0;   // N.H's float rounding through the lobe's slope
};
// make_brdf, remembered: the fitted approximations take milliseconds, and every case and
// configuration asks for the same few.
inline BrdfParams fitted_brdf(const BrdfChoice& brdf, double n) {
  static std::mutex mutex;
  static std::map<std::pair<int, double>, BrdfParams> cache;
  std::lock_guard lock(mutex);
  const auto key = std::make_pair(int(brdf.kind) * 16 + brdf.k, n);
  if (const auto it = cache.find(key); it != cache.end()) return it->second;
  return cache[key] = make_brdf(brdf, n);
}

inline FloatTerms float_terms(const Scene& scene, const Material& m, const BrdfChoice& brdf) {
  const double n = m.shininess;
  const Weights w = weights(scene, m);
  const BrdfParams p = fitted_brdf(brdf, n);
  FloatTerms t;
  t.lipschitz = w.diffuse + w.specular * lobe_slope(n);
  t.direction = t.lipschitz * kDirectionError;
  t.lobe = w.specular * brdf_error(p, n);
  t.rounding = w.specular * brdf_slope(p, n) * limits::kFloatNdotHError;
  return t;
}

// The bare float kernel's bound (no fallback): what the span kernels hold.
inline double float_kernel_lsb(const Scene& scene, const BrdfChoice& brdf = {}) {
  double worst = 0;
  for (const Material& m : scene.materials) {
    const FloatTerms t = float_terms(scene, m, brdf);
    worst = std::max(worst, rounded_lsb(t.direction + t.lobe + t.rounding));
  }
  return worst;
}

inline Bound derive_bound(const MethodConfig& config, const Scene& scene, const CaseGeometry& geo) {
  const RenderOptions& o = config.options;
  const BrdfChoice brdf = o.brdf;
  // The renderer's own fallback decision; only exact cos^n falls back (asking with the exact
  // lobe spares the approximations' fits).
  ShadeConstants k = shade_constants(scene, view_transform(scene));
  if (brdf.kind != BrdfKind::Exact)
    for (MaterialConstants& m : k.materials) m.shade_in_double = false;
  Bound worst;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const FloatTerms t = float_terms(scene, scene.materials[i], brdf);
    // For exact cos^n the renderer keeps the rounding term within kFloatSpecularBudgetLsb,
    // shading in double beyond (vertex_stage.cpp); an approximation carries all of it.
    const double rounding = brdf.kind == BrdfKind::Exact
                                ? std::min(t.rounding, limits::kFloatSpecularBudgetLsb / 255.0)
                                : t.rounding;
    const double float_error = t.direction + t.lobe + rounding;
    Bound b;
    switch (config.rule) {
      case BoundRule::Yardstick:
        b = {0, Status::Holds};
        break;
      case BoundRule::PerPixelFloat:
      case BoundRule::ErrorBudget:
        if (k.materials[i].shade_in_double) {
          b = {0, Status::Fallback};
        } else if (config.rule == BoundRule::PerPixelFloat || o.max_error <= 0.5) {
          b = {rounded_lsb(float_error), Status::Holds};
        } else {
          // B2: interpolation within E - 1/2 LSB, then one rounding: floor(E + 1/2 + float).
          b = {std::floor(o.max_error + 0.5 + 255.0 * float_error), Status::Holds};
        }
        break;
      case BoundRule::Classified: {
        // Diffuse paths: below E - 0.01 LSB before rounding, so ceil(E) after (never in double);
        // the specular path: B2 as hybrid, or 0 where the material falls back to double.
        const double specular = k.materials[i].shade_in_double
                                    ? 0.0
                                    : std::floor(o.max_error + 0.5 + 255.0 * float_error);
        b = {std::max(std::ceil(o.max_error), specular), Status::Holds};
        break;
      }
      case BoundRule::VertexLighting:
        // With the vertices lit in double (the fallback) their colours carry no rounding term.
        b.lsb = rounded_lsb(t.lipschitz * geo.normal_spread_rad + float_error -
                            (k.materials[i].shade_in_double ? rounding : 0.0));
        b.status = b.lsb >= 255                       ? Status::NoBound  // says nothing
                   : k.materials[i].shade_in_double ? Status::Fallback
                                                    : Status::Holds;
        break;
    }
    if (b.lsb > worst.lsb || (b.lsb == worst.lsb && b.status != Status::Holds)) worst = b;
  }
  return worst;
}

}  // namespace fastshade::stability
