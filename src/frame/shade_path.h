// The shading paths a classifying method (`auto`) sends triangles down: decided per triangle
// by the front end (classify/classifier.h), read by the back end's tile loop.
#pragma once
#include <array>
#include <cstdint>

namespace fastshade {

enum class ShadePath : uint8_t {
  Unclassified = 0,  // the frame's method draws every triangle alike
  GouraudDiffuse,    // no highlight can show, the diffuse term is near-linear: Gouraud
  PixelDiffuse,      // no highlight can show, but curvature or the terminator bends diffuse
  Specular,          // a highlight may show: the specular method (--spec-method)
};
inline constexpr int kShadePathCount = 4;
inline constexpr const char* kShadePathNames[kShadePathCount] = {"unclassified", "gouraud_diffuse",
                                                                  "pixel_diffuse", "specular"};

// What the classifier decided over some triangles: how many took each path, and which lights
// could put a highlight on any of them (bit i: light i; bit 63 stands for lights 63 and up).
struct PathTally {
  std::array<long long, kShadePathCount> triangles{};
  uint64_t lights_with_highlight = 0;
  long long unclassified = 0;  // of triangles[Specular]: sent there without classifying (dense blocks)
  void add(const PathTally& o) {
    for (int p = 0; p < kShadePathCount; ++p) triangles[p] += o.triangles[p];
    unclassified += o.unclassified;
    lights_with_highlight |= o.lights_with_highlight;
  }
};

}  // namespace fastshade
