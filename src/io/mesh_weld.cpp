// Welding vertices at bit-equal positions.
#include "io/mesh_weld.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace fastshade::io {

namespace {

struct Key {
  uint32_t x, y, z;
  bool operator==(const Key&) const = default;
};

Key key_of(const glm::vec3& p) {
  return {std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y), std::bit_cast<uint32_t>(p.z)};
}

uint64_t hash_of(const Key& k) {
  // Mix the three words (a multiply-xorshift in the style of splitmix64).
  uint64_t h = (uint64_t{k.x} << 32 | k.y) * 0x9E3779B97F4A7C15ull;
  h ^= (h >> 29) ^ (uint64_t{k.z} * 0xBF58476D1CE4E5B9ull);
  h *= 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

}  // namespace

std::size_t weld_vertices(Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  if (n == 0) return 0;
  constexpr uint32_t kEmpty = std::numeric_limits<uint32_t>::max();
  std::size_t capacity = 16;
  while (capacity < 2 * n) capacity *= 2;  // load factor <= 1/2
  std::vector<uint32_t> slots(capacity, kEmpty);  // new vertex index, or kEmpty
  std::vector<uint32_t> remap(n);
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  positions.reserve(n);
  const bool has_normals = mesh.normals.size() == n;
  if (has_normals) normals.reserve(n);

  for (std::size_t i = 0; i < n; ++i) {
    const Key k = key_of(mesh.positions[i]);
    std::size_t s = hash_of(k) & (capacity - 1);
    while (slots[s] != kEmpty && !(key_of(positions[slots[s]]) == k)) s = (s + 1) & (capacity - 1);
    if (slots[s] == kEmpty) {
      slots[s] = static_cast<uint32_t>(positions.size());
      positions.push_back(mesh.positions[i]);
      if (has_normals) normals.push_back(mesh.normals[i]);
    }
    remap[i] = slots[s];
  }
  const std::size_t removed = n - positions.size();
  if (removed == 0) return 0;
  for (auto& tri : mesh.triangles) {
    for (auto& v : tri) v = remap[v];
  }
  mesh.positions = std::move(positions);
  if (has_normals) mesh.normals = std::move(normals);
  return removed;
}

}  // namespace fastshade::io
