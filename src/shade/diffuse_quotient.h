// `auto`'s per-pixel diffuse term as a quotient, without normalising the normal. With m the
// normal over w as the normal planes interpolate it (linear in screen space), N·L = (L·m)/|m|:
// L·m is one plane per light, and |m|² one quadratic in the pixel's offsets (x, y) from the
// triangle's box centre,
//   |m|² = a + x (b + c x + d y) + y (e + f y),
// so a pixel costs two short polynomials, a square root and a division, where normalising
// costs three planes, a dot product, three products and a dot product per light (the
// quotient form of Phong's normal is Duff's, 1979). The algebra is the same as normalising;
// the rounding differs, and set_up_diffuse_quotient() takes a triangle only where it bounds
// that rounding far below the float kernels' reserve (kAutoFloatReserveLsb).
#pragma once
#include <glm/vec3.hpp>

#include "raster/planes.h"
#include "raster/spans.h"
#include "shade/span_kernels.h"

namespace fastshade {

// Lights a quotient holds planes for; a frame with more keeps the normalised planes (a light's
// plane is 12 bytes of the per-triangle set-up, which this bounds).
inline constexpr int kDiffuseQuotientMaxLights = 8;

// Largest ratio R = T / Q_min a triangle may have, where T bounds the magnitudes of the
// quadratic's terms over the triangle's box, (|s| + |g_x| h_x + |g_y| h_y)² with s the normal
// over w at the centre, g its gradients and h the box's half extents, and Q_min bounds |m|²
// from below (the least entry of the Gram matrix of the vertices' normals over w). Evaluated in
// float, |m|² errs by at most 7u T (rounded coefficients, six roundings of partial sums bounded
// by T), so 1/|m| by 3.5u R + 2u; L·m by 5u sqrt(T), which over |m| is 5u sqrt(R); the product
// 1u. At R = 64: (3.5 · 64 + 5 · 8 + 3)u = 267u = 1.6e-5, 0.004 LSB, under half the 0.01 LSB
// reserve (docs/STABILITY.md, B4).
inline constexpr double kDiffuseQuotientMaxTermRatio = 64.0;

struct DiffuseQuotient {
  float cx, cy;  // the centre pixel, as offsets from the anchor (bary.ax, bary.ay)
  float q[6];    // a, b, c, d, e, f above
  float l[kDiffuseQuotientMaxLights][3];  // per light: L·m at the centre, per pixel in x, in y
  int lights;
};

// The quotient of one triangle from its normal planes (in.n, the whole triangle's), its
// barycentrics' anchor, its whole box and its vertices' normals over w (flipped as drawn); false where the
// rounding bound above does not hold or the frame has too many lights.
bool set_up_diffuse_quotient(const PhongSpanInput& in, const Barycentrics& bary, const PixelRect& box,
                             const glm::vec3 n_over_w[3], DiffuseQuotient& dq);

}  // namespace fastshade
