// What a frame's shading method asks of the front end (shade/method.h decides, front/ fills):
// which per-vertex attribute arrays to compute, and which triangles get a hybrid segment length.
#pragma once
#include <cstdint>

namespace fastshade {

struct AttrNeeds {  // which attribute arrays (frame/frame.h AttrArrays) a method reads
  bool normal = false, color = false, position = false;
  bool diffuse_color = false;  // the vertex colour without its specular term (`auto`'s Gouraud)
};

// Which triangles of a frame draw hybrid segments (front/segment_steps.h): none, all
// (`hybrid`), or those on the specular path (`auto` with --spec-method hybrid).
enum class SegmentSteps : uint8_t { None, All, SpecularPath };

}  // namespace fastshade
