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
#include "shade/shade_limits.h"
#include "shade/span_kernels.h"

namespace fastshade {

struct DiffuseQuotient {
  float cx, cy;  // the centre pixel, as offsets from the anchor (bary.ax, bary.ay)
  float q[6];    // a, b, c, d, e, f above
  float l[limits::kDiffuseQuotientMaxLights][3];  // per light: L·m at the centre, per pixel in x, in y
  int lights;
};

// The quotient of one triangle from its normal planes (in.n, the whole triangle's), its
// barycentrics' anchor, its whole box and its vertices' normals over w (flipped as drawn); false where the
// rounding bound above does not hold or the frame has too many lights.
bool set_up_diffuse_quotient(const PhongSpanInput& in, const Barycentrics& bary, const PixelRect& box,
                             const glm::vec3 n_over_w[3], DiffuseQuotient& dq);

}  // namespace fastshade
