// Front end: back faces that their own mesh provably hides, left out before binning.
//
// Why it holds. Close a mesh's holes with caps (a fan from each rim's centroid, inside the
// convex hull of the rim's vertices) and orient it outward. A ray from an eye outside that
// solid crosses an exiting face (one whose outward side faces away from the eye: a back face)
// only after it has crossed an entering one: the winding number is 0 at the eye and >= 0 on
// the way, and an exit lowers it by one. If the entering crossing is on the mesh, that front
// face is drawn nearer at the pixel and the back face can never show; it may show only where
// the entering crossing is a cap, that is inside the projection of some rim's convex hull.
// So an exiting face whose pixel box misses every rim's screen box is hidden, for any
// method and any lighting, and is culled before it costs binning, set-up or shading.
//
// The preconditions, checked once per mesh (topology) and once per frame (placement):
// - every edge has one face (a rim) or two faces that traverse it in opposite directions;
// - the capped volume is not zero, and each connected part's has the mesh's sign (that sign
//   says whether exiting faces are the screen's back faces or its front faces: an inward-
//   wound mesh such as the shared horse is handled mirrored);
// - this frame, every vertex of the object is inside near, far and the guard band (no
//   triangle of it is clipped, so the hull lies beyond the near plane and the eye is outside it)
//   and finite; and the scene does not cull back faces (the occluders of an inward-wound
//   mesh would be culled).
// The argument is exact for a mesh without self-intersections (the winding number is then 0
// or 1). What rounding can change is only a pixel where a front face and a back face reach
// the same float depth (a silhouette): there the culled frame keeps the front face, which the
// exact surface shows. tests/front/self_occlusion_test.cpp compares frames with and without
// this on every shared mesh and scene.
#pragma once
#include <cstdint>
#include <vector>

#include "front/scene_geometry.h"
#include "front/triangle_fate.h"
#include "front/vertex_stage.h"

namespace fastshade {

// One object's topology, found once per renderer.
struct MeshClosure {
  bool solid = false;     // the preconditions on topology and volume hold
  bool outward = true;    // capped volume > 0 in world space (model transform's sign included)
  std::vector<uint32_t> rim_vertices;  // global vertex indices of all rims, rim after rim
  std::vector<uint32_t> rim_begin;     // rim r: rim_vertices[rim_begin[r], rim_begin[r + 1])
};

// Every object of the scene, in geometry.objects order (parallel inside large meshes).
std::vector<MeshClosure> analyze_closures(const SceneGeometry& geometry);

// This frame's decision for one object's triangles [first_triangle, end_triangle).
struct ObjectOcclusion {
  uint32_t first_triangle = 0, end_triangle = 0;
  bool cull_exiting = false;     // the object's exiting faces may be culled this frame
  bool exiting_is_back = true;   // exiting faces are the screen's back faces (outward winding)
  uint32_t rims_begin = 0, rims_end = 0;  // its rims' boxes in SelfOcclusionPlan::rim_boxes
  // The union of those boxes (empty: x0 > x1): a box that misses it misses every rim, the
  // answer for most exiting faces, in four compares instead of four a rim.
  PixelBox rims_union{0, 0, -1, -1};
};

struct SelfOcclusionPlan {
  std::vector<ObjectOcclusion> objects;
  std::vector<PixelBox> rim_boxes;  // pixels a cap may cover, one pixel of margin around each rim
};

// The frame's plan from the vertex stage's flags and snapped positions.
void plan_self_occlusion(const SceneGeometry& geometry, const std::vector<MeshClosure>& closures,
                         const ProjectedVertices& vertices, SelfOcclusionPlan& plan);

// Triangle setup's question for kept triangles, asked in increasing triangle order from
// first_triangle on: the cursor walks one chunk's objects once. A null plan hides nothing.
class OcclusionCursor {
 public:
  OcclusionCursor(const SelfOcclusionPlan* plan, uint32_t first_triangle);
  bool hidden(uint32_t triangle, bool back_facing, const PixelBox& box) {
    if (!plan_) return false;
    const std::vector<ObjectOcclusion>& objects = plan_->objects;
    while (objects[object_].end_triangle <= triangle) ++object_;
    const ObjectOcclusion& o = objects[object_];
    if (!o.cull_exiting || back_facing != o.exiting_is_back) return false;
    if (!overlaps(box, o.rims_union)) return true;
    for (uint32_t r = o.rims_begin; r < o.rims_end; ++r)
      if (overlaps(box, plan_->rim_boxes[r])) return false;
    return true;
  }

 private:
  static bool overlaps(const PixelBox& a, const PixelBox& b) {
    return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
  }
  const SelfOcclusionPlan* plan_;
  std::size_t object_ = 0;
};

}  // namespace fastshade
