#include <algorithm>
#include <cmath>

#include "core/limits.h"
#include "shade/hybrid.h"

namespace fastshade {

namespace {

struct Dir {
  double x, y, z;
};
double dot(const Dir& a, const Dir& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Dir normal_at(const PhongSpanInput& in, int px, int py) {
  const PixelOffsets o = pixel_offsets(in.bary, px, py);
  Dir n{plane_at(in.n[0], o), plane_at(in.n[1], o), plane_at(in.n[2], o)};
  const double len = std::sqrt(dot(n, n));
  return len > 0 ? Dir{n.x / len, n.y / len, n.z / len} : Dir{0, 0, 0};
}

// Largest N.H on the arc from na to nb (normalised lerp), NOTES.md section 2: an interior
// maximum where X + Y > 0 and 0 < t < 1, with peak sqrt((X^2 + Y^2 - 2XYc) / (1 - c^2)).
double arc_max(double x, double y, double c) {
  double best = std::max(x, y);
  if (x + y > 0 && c < 1.0 - 1e-12) {
    const double t = (y - x * c) / ((1 - c) * (x + y));
    if (t > 0 && t < 1) best = std::max(best, std::sqrt(std::max(0.0, (x * x + y * y - 2 * x * y * c) / (1 - c * c))));
  }
  return std::min(best, 1.0);
}

}  // namespace

int hybrid_step(const PhongSpanInput& in, int xb, int py, int xl, int xr, float tol) {
  const int block = limits::kSeedBlockPx;
  if (!(tol > 0)) return 1;
  const int xa = std::clamp(xb, xl, xr), xz = std::clamp(xb + block, xl, xr);
  if (xz - xa < 2) return block;  // no pixel between the ends
  const Dir na = normal_at(in, xa, py), nb = normal_at(in, xz, py);
  const double c_ab = std::clamp(dot(na, nb), -1.0, 1.0);
  const double theta = std::acos(c_ab);
  if (!(theta > 0)) return block;
  const MaterialConstants& m = *in.material;
  const double kd = std::max({m.kd.r, m.kd.g, m.kd.b}), ks = std::max({m.ks.r, m.ks.g, m.ks.b});
  const double n = m.shininess_d;
  double curvature = 0;
  for (const LightView& light : in.shade->lights) {
    const double weight = std::max({light.color.r, light.color.g, light.color.b});
    // A local viewer's H varies across the block by far less than the normal does; the
    // block's centre H stands for it, with the bound's slack.
    Dir h{light.h_view.x, light.h_view.y, light.h_view.z};
    if (in.shade->local_viewer) {
      const PixelOffsets o = pixel_offsets(in.bary, (xa + xz) / 2, py);
      const double w = 1.0 / plane_at(in.inv_w, o);
      Dir v{-plane_at(in.p[0], o) * w, -plane_at(in.p[1], o) * w, -plane_at(in.p[2], o) * w};
      const double lv = std::sqrt(dot(v, v));
      h = {light.l_view.x + v.x / lv, light.l_view.y + v.y / lv, light.l_view.z + v.z / lv};
      const double lh = std::sqrt(dot(h, h));
      h = lh > 0 ? Dir{h.x / lh, h.y / lh, h.z / lh} : Dir{0, 0, 0};
    }
    const double x = dot(na, h), y = dot(nb, h);
    const double c_max = arc_max(x, y, c_ab), c_min = std::max(std::min(x, y), 0.0);
    const double spec = c_max > 0 ? n * std::pow(c_max, std::max(n - 2, 0.0)) * (n * (1 - c_min * c_min) + 1) : 0;
    curvature += weight * (kd + ks * spec);
  }
  for (int step = block; step >= 2; step /= 2) {
    const double angle = theta * step / (xz - xa);
    if (angle * angle / 8 * curvature <= tol) return step;
  }
  return 1;
}

}  // namespace fastshade
