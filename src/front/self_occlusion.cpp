#include "front/self_occlusion.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "core/limits.h"

namespace fastshade {

namespace {

// Vertex sets joined by edges: a mesh's connected parts, or its rims.
class DisjointSets {
 public:
  explicit DisjointSets(uint32_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  uint32_t find(uint32_t v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void join(uint32_t a, uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<uint32_t> parent_;
};

// An edge as one sortable key: the undirected edge in the high bits, its direction (as the
// face traverses it) in bit 0. Vertex indices are below 2^31 (flatten_scene), so it fits.
uint64_t edge_key(uint32_t a, uint32_t b) {
  return uint64_t(std::min(a, b)) << 32 | uint64_t(std::max(a, b)) << 1 | uint64_t(a > b);
}

double det(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return glm::dot(a, glm::cross(b, c));
}

using Triangle = std::array<uint32_t, 3>;
using Edge = std::array<uint32_t, 2>;

// The object's edge keys in ascending order. Sorted by their lower vertex first, by counting
// (vertices [base, base + vertex_count)), then each vertex's few keys by comparison: on
// dragon_871k's 2.6 million keys a parallel comparison sort was a sixth of the batch's time to
// load and render the mesh (perf), and this is linear. False for an index outside the object
// (a mesh built in memory reaches here unchecked): such a mesh is not analysed.
bool sorted_edge_keys(const Triangle* tris, uint32_t count, uint32_t base, uint32_t vertex_count,
                      std::vector<uint64_t>& keys) {
  std::vector<uint32_t> start(std::size_t(vertex_count) + 1, 0);
  for (uint32_t t = 0; t < count; ++t)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = tris[t][e], b = tris[t][(e + 1) % 3];
      if (a - base >= vertex_count || b - base >= vertex_count) return false;
      if (a != b) ++start[std::min(a, b) - base + 1];
    }
  std::partial_sum(start.begin(), start.end(), start.begin());
  keys.resize(start.back());
  std::vector<uint32_t> next(start.begin(), start.end() - 1);
  for (uint32_t t = 0; t < count; ++t)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = tris[t][e], b = tris[t][(e + 1) % 3];
      if (a != b) keys[next[std::min(a, b) - base]++] = edge_key(a, b);
    }
  for (uint32_t v = 0; v < vertex_count; ++v) std::sort(keys.begin() + start[v], keys.begin() + start[v + 1]);
  return true;
}

// The object's rim edges, as their one face traverses them; false if an edge has more than
// two faces or two that traverse it the same way.
bool find_rim_edges(const Triangle* tris, uint32_t count, uint32_t base, uint32_t vertex_count,
                    std::vector<Edge>& rim_edges) {
  std::vector<uint64_t> keys;
  if (!sorted_edge_keys(tris, count, base, vertex_count, keys)) return false;

  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i + 1;
    while (j < keys.size() && keys[j] >> 1 == keys[i] >> 1) ++j;
    if (j - i > 2 || (j - i == 2 && keys[i] == keys[i + 1])) return false;
    if (j - i == 1) {
      const uint32_t lo = static_cast<uint32_t>(keys[i] >> 32), hi = static_cast<uint32_t>(keys[i] >> 1) & 0x7FFFFFFFu;
      rim_edges.push_back(keys[i] & 1 ? Edge{hi, lo} : Edge{lo, hi});
    }
    i = j;
  }
  return true;
}

// The rims' vertices, rim after rim (a rim: rim edges joined at their vertices).
void group_rims(const std::vector<Edge>& rim_edges, uint32_t base, uint32_t vertex_count, MeshClosure& out) {
  DisjointSets rims(vertex_count);
  for (const Edge& e : rim_edges) rims.join(e[0] - base, e[1] - base);
  std::vector<std::pair<uint32_t, uint32_t>> by_rim;  // (rim's root, vertex)
  for (const Edge& e : rim_edges)
    for (uint32_t v : e) by_rim.push_back({rims.find(v - base), v});
  std::sort(by_rim.begin(), by_rim.end());
  by_rim.erase(std::unique(by_rim.begin(), by_rim.end()), by_rim.end());
  for (std::size_t i = 0; i < by_rim.size(); ++i) {
    if (i == 0 || by_rim[i].first != by_rim[i - 1].first) out.rim_begin.push_back(static_cast<uint32_t>(i));
    out.rim_vertices.push_back(by_rim[i].second);
  }
  out.rim_begin.push_back(static_cast<uint32_t>(by_rim.size()));
}

MeshClosure analyze_object(const SceneGeometry& g, const ObjectRange& o) {
  MeshClosure out;
  if (o.triangle_count == 0) return out;
  const Triangle* tris = &g.triangles[o.first_triangle];
  std::vector<Edge> rim_edges;
  const uint32_t base = o.first_vertex;
  if (!find_rim_edges(tris, o.triangle_count, base, o.vertex_count, rim_edges)) return out;  // non-manifold, or misoriented
  group_rims(rim_edges, base, o.vertex_count, out);
  const std::vector<uint32_t>& rim_vertices = out.rim_vertices;
  const std::vector<uint32_t>& rim_begin = out.rim_begin;
  if (rim_begin.size() - 1 > limits::kMaxOcclusionRims) return {};

  // Volumes about the box centre (less cancellation than about the origin), per connected
  // part; each rim's cap is the fan from its centroid, closing the part the rim belongs to.
  const glm::dvec3 centre = (glm::dvec3(o.box_min) + glm::dvec3(o.box_max)) * 0.5;
  const auto at = [&](uint32_t v) { return glm::dvec3(g.positions[v]) - centre; };
  std::vector<glm::dvec3> rim_centroid(rim_begin.size() - 1, glm::dvec3(0.0));
  std::vector<uint32_t> rim_of(o.vertex_count, 0);
  for (std::size_t r = 0; r + 1 < rim_begin.size(); ++r) {
    for (uint32_t i = rim_begin[r]; i < rim_begin[r + 1]; ++i) {
      rim_centroid[r] += at(rim_vertices[i]);
      rim_of[rim_vertices[i] - base] = static_cast<uint32_t>(r);
    }
    rim_centroid[r] /= double(rim_begin[r + 1] - rim_begin[r]);
  }
  DisjointSets parts(o.vertex_count);
  for (uint32_t t = 0; t < o.triangle_count; ++t) {
    parts.join(tris[t][0] - base, tris[t][1] - base);
    parts.join(tris[t][0] - base, tris[t][2] - base);
  }
  std::vector<double> volume(o.vertex_count, 0.0);
  std::vector<uint8_t> has_faces(o.vertex_count, 0);
  for (uint32_t t = 0; t < o.triangle_count; ++t) {
    const uint32_t part = parts.find(tris[t][0] - base);
    volume[part] += det(at(tris[t][0]), at(tris[t][1]), at(tris[t][2]));
    has_faces[part] = 1;
  }
  for (const auto& e : rim_edges)  // the cap traverses the rim edge the other way
    volume[parts.find(e[0] - base)] += det(rim_centroid[rim_of[e[0] - base]], at(e[1]), at(e[0]));

  // A part whose volume is within rounding of zero (a flat sheet) has no inside.
  const glm::dvec3 extent = glm::dvec3(o.box_max) - glm::dvec3(o.box_min);
  const double size = std::max({extent.x, extent.y, extent.z});
  const double flat = limits::kFlatVolumeRelative * size * size * size;
  int sign = 0;
  for (uint32_t v = 0; v < o.vertex_count; ++v) {
    if (!has_faces[v]) continue;
    if (!(std::fabs(volume[v]) > flat)) return {};
    const int s = volume[v] > 0 ? 1 : -1;
    if (sign != 0 && s != sign) return {};
    sign = s;
  }
  out.solid = true;
  out.outward = (sign > 0) != (glm::determinant(glm::mat3(o.model)) < 0.0f);
  return out;
}

}  // namespace

std::vector<MeshClosure> analyze_closures(const SceneGeometry& g) {
  std::vector<MeshClosure> out;
  out.reserve(g.objects.size());
  for (const ObjectRange& o : g.objects) out.push_back(analyze_object(g, o));
  return out;
}

void plan_self_occlusion(const SceneGeometry& g, const std::vector<MeshClosure>& closures,
                         const ProjectedVertices& pv, SelfOcclusionPlan& plan) {
  plan.objects.resize(g.objects.size());
  plan.rim_boxes.clear();
  for (std::size_t i = 0; i < g.objects.size(); ++i) {
    const ObjectRange& o = g.objects[i];
    const MeshClosure& c = closures[i];
    ObjectOcclusion& oc = plan.objects[i];
    oc.first_triangle = o.first_triangle;
    oc.end_triangle = o.first_triangle + o.triangle_count;
    oc.exiting_is_back = c.outward;
    oc.rims_begin = oc.rims_end = static_cast<uint32_t>(plan.rim_boxes.size());
    oc.rims_union = PixelBox{0, 0, -1, -1};
    uint8_t any = 0;
    for (uint32_t v = o.first_vertex; v < o.first_vertex + o.vertex_count; ++v) any |= pv.flags[v];
    oc.cull_exiting = c.solid && !(any & (kNeedsClip | kNonFinite));
    if (!oc.cull_exiting) continue;
    for (std::size_t r = 0; r + 1 < c.rim_begin.size(); ++r) {
      int32_t x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;
      for (uint32_t k = c.rim_begin[r]; k < c.rim_begin[r + 1]; ++k) {
        const ScreenVertex& s = pv.screen[c.rim_vertices[k]];
        x0 = std::min(x0, s.x_fx), x1 = std::max(x1, s.x_fx);
        y0 = std::min(y0, s.y_fx), y1 = std::max(y1, s.y_fx);
      }
      // Pixels whose centres the rim's hull may reach, and one more on each side for snapping.
      const PixelBox rim{(x0 >> limits::kSubpixelBits) - 1, (y0 >> limits::kSubpixelBits) - 1,
                         (x1 >> limits::kSubpixelBits) + 1, (y1 >> limits::kSubpixelBits) + 1};
      plan.rim_boxes.push_back(rim);
      PixelBox& u = oc.rims_union;
      u = r == 0 ? rim
                 : PixelBox{std::min(u.x0, rim.x0), std::min(u.y0, rim.y0), std::max(u.x1, rim.x1),
                            std::max(u.y1, rim.y1)};
    }
    oc.rims_end = static_cast<uint32_t>(plan.rim_boxes.size());
  }
}

OcclusionCursor::OcclusionCursor(const SelfOcclusionPlan* plan, uint32_t first_triangle) : plan_(plan) {
  if (!plan_) return;
  const auto& objects = plan_->objects;
  object_ = static_cast<std::size_t>(
      std::partition_point(objects.begin(), objects.end(),
                           [&](const ObjectOcclusion& o) { return o.end_triangle <= first_triangle; }) -
      objects.begin());
}

}  // namespace fastshade
