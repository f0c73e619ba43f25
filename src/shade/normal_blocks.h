// Per-pixel normals along a span without per-pixel normalisation (`--normals`): the paper's
// adaptive normalisation (eq. 6) and equal-angle recurrence (eq. 7), recast for vector lanes.
//
// On a row, q = n/w is affine in x, so inside a 16-pixel seed block whose ends xa, xz are
// clamped to the row's covered run [xl, xr], every normal is a weighted sum
// alpha_k Na + beta_k Nz of the two unit end normals (k = x - xa). The weights are computed
// once per block in scalar code and the lanes only multiply: N.L = alpha (Na.L) + beta (Nz.L),
// likewise N.H, with no normal vector, no normalisation and no division per pixel. Both modes
// keep the error within the budget tol (docs/STABILITY.md, "B2"):
//  - the exact normal at t = k / (xz - xa) is the direction of (1 - t) |qa| Na + t |qz| Nz;
//    plain t is kept while it turns the normal off that by little enough (|qa| near |qz|),
//    else the weights are the exact ones scaled to sum 1 (folds of antiparallel normals too);
//  - adaptive (eq. 6): those weights times g, g = 1 where skipping normalisation errs within
//    the budget (the weighted unit normals are short by at most 1 - cos(psi/2), psi the ends'
//    angle; docs/PAPER.md, "Normal blocks") and g = 1 / |sum| else;
//  - equal-angle (eq. 7): alpha = sin((L - k) phi) / sin(L phi), beta = sin(k phi) / sin(L phi)
//    with the per-pixel angle phi = psi / L, the sines from the recurrence in its stable
//    difference form d += kappa s, s += d, kappa = -4 sin^2(phi / 2) (docs/PAPER.md, "Rotation
//    by the difference form": the printed form rounds 2 cos(phi) to 2 below phi = 2.4e-4),
//    re-seeded every block; where even angles stray from the exact ones past the budget, the
//    exact weights, normalised.
#pragma once
#include <string>
#include <string_view>

#include "core/limits.h"
#include "frame/shade_constants.h"
#include "shade/span_kernels.h"

namespace fastshade {

struct NormalBlock {
  float na[3], nz[3];                       // unit normals at the block's clamped ends
  // By x - xb; padded so a vector starting anywhere in the block may load past its end.
  static constexpr int kSize = 2 * limits::kSeedBlockPx;
  float alpha[kSize], beta[kSize];
};

// [xl, xr]: the row's covered run in the whole triangle. tol: the shading error allowed, in
// colour units (adaptive only).
void make_normal_block(const PhongSpanInput& in, PhongNormals mode, float tol, int xb, int py,
                       int xl, int xr, NormalBlock& out);

}  // namespace fastshade
