#include "light/brdf.h"
#include "light/brdf_testing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/limits.h"
#include "light/fast_math.h"

namespace fastshade {

namespace {

constexpr float kHalfPi = static_cast<float>(std::numbers::pi / 2);

// Where cos^n lives: gamma on a grid dense in gamma sqrt(n) (the lobe is ~1/sqrt(n) wide) plus
// a uniform grid over [0, pi/2] for the tail. Used to fit and to measure.
std::vector<double> fit_angles(double n) {
  std::vector<double> g;
  const double lobe = 1.0 / std::sqrt(n);
  for (int i = 0; i <= 2048; ++i) g.push_back(std::min(std::numbers::pi / 2, 8.0 * lobe * i / 2048));
  for (int i = 0; i <= 512; ++i) g.push_back(std::numbers::pi / 2 * i / 512);
  return g;
}

double quadratic_value(double a, double c) {
  const double u = std::max(a * (c - 1.0) + 1.0, 0.0);
  return u * u;
}

// The a of (a (c - 1) + 1)^2 with the least maximum error on the grid: a coarse log scan,
// then golden-section refinement around the best point.
double fit_quadratic_slope(double n) {
  const std::vector<double> angles = fit_angles(n);
  auto max_error = [&](double a) {
    double worst = 0;
    for (double g : angles) {
      const double c = std::cos(g);
      worst = std::max(worst, std::fabs(quadratic_value(a, c) - cos_power(c, n)));
    }
    return worst;
  };
  double best_a = 0.5 * n, best_e = max_error(best_a);
  for (int i = 0; i <= 64; ++i) {
    const double a = n * std::pow(10.0, -2.0 + 2.0 * i / 64);  // 0.01 n .. n
    const double e = max_error(a);
    if (e < best_e) best_e = e, best_a = a;
  }
  double lo = best_a / 1.08, hi = best_a * 1.08;
  const double r = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 40; ++it) {
    const double a1 = hi - r * (hi - lo), a2 = lo + r * (hi - lo);
    if (max_error(a1) < max_error(a2)) hi = a2;
    else lo = a1;
  }
  return 0.5 * (lo + hi);
}

// Minimax fit of a0 + a1 x + ... + ad x^d to cos^n in x = 1 - cos(gamma) on [0, support],
// by Lawson's iteratively reweighted least squares. The constant is free: pinning P(0) = 1
// forbids the steep drop a narrow lobe needs.
std::array<double, 4> fit_polynomial(const std::vector<double>& x, const std::vector<double>& f,
                                     int degree, double support) {
  std::vector<double> xs, fs;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] <= support) xs.push_back(x[i]), fs.push_back(f[i]);
  const std::size_t m = xs.size();
  const int unknowns = degree + 1;
  std::vector<double> w(m, 1.0 / m);
  std::array<double, 4> a{};
  for (int it = 0; it < 60 && m > std::size_t(unknowns); ++it) {
    double ata[4][4] = {}, atb[4] = {};
    for (std::size_t i = 0; i < m; ++i) {
      const double basis[4] = {1.0, xs[i], xs[i] * xs[i], xs[i] * xs[i] * xs[i]};
      for (int r = 0; r < unknowns; ++r) {
        atb[r] += w[i] * basis[r] * fs[i];
        for (int c = 0; c < unknowns; ++c) ata[r][c] += w[i] * basis[r] * basis[c];
      }
    }
    // Gaussian elimination with partial pivoting on the (at most 4x4) normal equations.
    for (int col = 0; col < unknowns; ++col) {
      int pivot = col;
      for (int r = col + 1; r < unknowns; ++r)
        if (std::fabs(ata[r][col]) > std::fabs(ata[pivot][col])) pivot = r;
      std::swap(ata[col], ata[pivot]);
      std::swap(atb[col], atb[pivot]);
      if (ata[col][col] == 0) return a;
      for (int r = col + 1; r < unknowns; ++r) {
        const double factor = ata[r][col] / ata[col][col];
        for (int c = col; c < unknowns; ++c) ata[r][c] -= factor * ata[col][c];
        atb[r] -= factor * atb[col];
      }
    }
    for (int r = unknowns - 1; r >= 0; --r) {
      double s = atb[r];
      for (int c = r + 1; c < unknowns; ++c) s -= ata[r][c] * a[c];
      a[r] = s / ata[r][r];
    }
    double total = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const double p = a[0] + xs[i] * (a[1] + xs[i] * (a[2] + xs[i] * a[3]));
      w[i] *= std::fabs(p - fs[i]) + 1e-300;
      total += w[i];
    }
    for (double& wi : w) wi /= total;
  }
  return a;
}

double first_root(const std::array<double, 4>& a) {
  auto p = [&](double x) { return a[0] + x * (a[1] + x * (a[2] + x * a[3])); };
  double prev = 0;
  for (int i = 1; i <= 4096; ++i) {
    const double x = i / 4096.0;
    if (p(x) <= 0) {
      double lo = prev, hi = x;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (p(mid) > 0 ? lo : hi) = mid;
      }
      return hi;
    }
    prev = x;
  }
  return 1.0;
}

// The polynomial approximation as evaluated: clamped to [0, 1], zero from x_root on. Its
// support (where the fit is made) is searched too: a narrow lobe is best fitted on [0, X]
// with zero beyond, not over the whole quarter circle.
void fit_poly_params(double n, int degree, BrdfParams& p) {
  const std::vector<double> angles = fit_angles(n);
  std::vector<double> x(angles.size()), f(angles.size());
  for (std::size_t i = 0; i < angles.size(); ++i) {
    x[i] = 1.0 - std::cos(angles[i]);
    f[i] = cos_power(std::cos(angles[i]), n);
  }
  double best_error = 2.0;
  for (int s = 0; s <= 30; ++s) {
    const double support = std::min(1.0, 0.3 / n * std::pow(n / 0.3, s / 30.0));
    const std::array<double, 4> a = fit_polynomial(x, f, degree, support);
    const double x_root = std::min(first_root(a), support);
    double error = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double v = x[i] < x_root ? std::clamp(a[0] + x[i] * (a[1] + x[i] * (a[2] + x[i] * a[3])), 0.0, 1.0) : 0.0;
      error = std::max(error, std::fabs(v - f[i]));
    }
    if (error < best_error) {
      best_error = error;
      for (int j = 0; j < 4; ++j) p.poly[j] = static_cast<float>(a[j]);
      p.x_root = static_cast<float>(x_root);
    }
  }
}

}  // namespace

float eval_brdf_one(const BrdfParams& p, float c_in) {
  const float c = std::min(c_in, 1.0f);
  if (!(c > 0.0f)) return 0.0f;  // also NaN
  switch (p.kind) {
    case BrdfKind::Exact:
      return fast_math::exp2(p.n * fast_math::log2(c));
    case BrdfKind::CosK: {
      const float t = p.scale * std::acos(c);
      if (!(t < kHalfPi)) return 0.0f;
      const float v = std::cos(t);
      float r = v;
      for (int i = 1; i < p.k; ++i) r = r * v;
      return r;
    }
    case BrdfKind::Schlick:
      return c / (p.n * (1.0f - c) + c);
    case BrdfKind::SchlickPow2: {
      // s = 1 - delta with delta = n' x / (n' x + c), x = 1 - c; squaring s is delta <-
      // delta (2 - delta), which keeps delta's relative error at ~1e-7 a step, where squaring
      // s itself would multiply s's rounding by 2^m (5e-4 at n = 1e4, 5e-2 at 1e6).
      const float nx = p.n_reduced * (1.0f - c);
      float delta = nx / (nx + c);
      for (int i = 0; i < p.squarings; ++i) delta = delta * (2.0f - delta);
      return 1.0f - delta;
    }
    case BrdfKind::Quadratic:
    case BrdfKind::QuadraticFit: {
      const float u = std::max(p.scale * (c - 1.0f) + 1.0f, 0.0f);
      return u * u;
    }
    case BrdfKind::Poly2:
    case BrdfKind::Poly3: {
      const float x = 1.0f - c;
      if (!(x < p.x_root)) return 0.0f;
      const float v = p.poly[0] + x * (p.poly[1] + x * (p.poly[2] + x * p.poly[3]));
      return std::clamp(v, 0.0f, 1.0f);
    }
  }
  return 0.0f;
}

double cos_power(double c, double n) { return c > 0 ? std::pow(std::min(c, 1.0), n) : 0.0; }

double brdf_max_error(const BrdfParams& p, double n, int points) {
  std::vector<float> c;
  for (int i = 0; i <= points; ++i) c.push_back(float(std::cos(std::numbers::pi / 2 * i / points)));
  for (int i = 0; i <= points; ++i)
    c.push_back(float(std::cos(std::min(std::numbers::pi / 2, 10.0 / std::sqrt(n) * i / points))));
  std::vector<float> out(c.size());
  eval_brdf(SimdTarget{}, p, c.data(), out.data(), c.size());  // the best ISA: all agree (brdf_test.cpp)
  double worst = 0;
  for (std::size_t i = 0; i < c.size(); ++i) worst = std::max(worst, std::fabs(double(out[i]) - cos_power(c[i], n)));
  return worst;
}

std::vector<BrdfChoice> brdf_choices() {
  std::vector<BrdfChoice> out;
  for (const auto& [kind, name] : OptionSpellings<BrdfKind>::kValues) {
    if (kind == BrdfKind::CosK)
      for (const int k : {1, 3}) out.push_back({kind, k});
    else
      out.push_back({kind});
  }
  return out;
}

BrdfParams make_brdf(const BrdfChoice& choice, double n) {
  n = std::clamp(n, 1.0, limits::kMaxShininess);
  BrdfParams p;
  p.kind = choice.kind;
  p.n = static_cast<float>(n);
  p.k = choice.k;
  switch (choice.kind) {
    case BrdfKind::CosK:
      p.scale = static_cast<float>(std::sqrt(n / choice.k));
      break;
    case BrdfKind::SchlickPow2: {
      // n = n_reduced 2^m with n_reduced in [1, 2).
      p.squarings = static_cast<int>(std::floor(std::log2(n)));
      double reduced = n / std::ldexp(1.0, p.squarings);
      if (reduced >= 2.0) reduced /= 2, ++p.squarings;  // log2 rounding at powers of two
      if (reduced < 1.0) reduced *= 2, --p.squarings;
      p.n_reduced = static_cast<float>(reduced);
      break;
    }
    case BrdfKind::Quadratic:
      p.scale = static_cast<float>(n / 2);
      break;
    case BrdfKind::QuadraticFit:
      p.scale = static_cast<float>(fit_quadratic_slope(n));
      break;
    case BrdfKind::Poly2:
    case BrdfKind::Poly3:
      fit_poly_params(n, choice.kind == BrdfKind::Poly2 ? 2 : 3, p);
      break;
    case BrdfKind::Exact:
    case BrdfKind::Schlick:
      break;
  }
  return p;
}

void eval_brdf_scalar(const BrdfParams& p, const float* n_dot_h, float* out, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) out[i] = eval_brdf_one(p, n_dot_h[i]);
}

}  // namespace fastshade
