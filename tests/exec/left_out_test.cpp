// What a frame leaves out: objects outside the frustum are never transformed, and the image
// is the same as without them.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "fastshade/render.h"
#include "fastshade/scene.h"

namespace fastshade {
namespace {

std::string spheres(const std::string& extra_objects) {
  return R"({"image": {"width": 160, "height": 120},
    "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 40, "near": 0.1, "far": 100},
    "lights": [{"direction": [0, 0, 1], "color": [1, 1, 1]}],
    "materials": {"m": {"diffuse": 0.6, "specular": 0.5, "shininess": 50}},
    "objects": [{"primitive": "icosphere", "material": "m"})" + extra_objects + "]}";
}

TEST(LeftOut, ObjectsOutsideTheFrustumAreSkippedAndChangeNothing) {
  // One beside the view, one behind the eye (beyond the near plane's other side).
  const Scene with = parse_scene(spheres(R"(,
      {"primitive": "icosphere", "material": "m", "transform": {"translate": [30, 0, 0]}},
      {"primitive": "icosphere", "material": "m", "transform": {"translate": [0, 0, 20]}})"), "with", ".");
  const Scene without = parse_scene(spheres(""), "without", ".");
  for (const char* method : {"auto", "phong", "gouraud"}) {
    RenderOptions o;
    o.method = parse_option<ShadingMethod>(method, "method");
    RenderStats s;
    const Image a = render(with, o, 1, &s);
    EXPECT_EQ(a.rgb, render(without, o).rgb) << method;
    EXPECT_TRUE(std::any_of(s.left_out.begin(), s.left_out.end(), [](const std::string& line) {
      return line.find("2 objects outside the view frustum") != std::string::npos;
    })) << method;
    EXPECT_GE(s.triangles_culled, s.triangles_in / 3 * 2) << method;  // the two outside
  }
}

}  // namespace
}  // namespace fastshade
