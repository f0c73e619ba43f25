#include "front/projection.h"

namespace fastshade {

Viewport make_viewport(int width, int height) {
  Viewport vp;
  vp.width = width;
  vp.height = height;
  vp.guard_x = static_cast<float>(limits::kGuardPx) / static_cast<float>(width);
  vp.guard_y = static_cast<float>(limits::kGuardPx) / static_cast<float>(height);
  vp.planes = guard_band_planes(vp.guard_x, vp.guard_y);
  return vp;
}

}  // namespace fastshade
