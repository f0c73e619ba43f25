// Welding: one vertex per distinct position.
#pragma once
#include "fastshade/mesh.h"

namespace fastshade::io {

// Merges vertices whose positions are bit-for-bit equal (so -0.0 and +0.0 stay apart, as do
// NaNs with different payloads), keeping the first occurrence's slot order and its normal, and
// remaps the triangles. Triangles that become degenerate are kept (they have zero area).
// Returns the number of vertices removed. Linear time: an open-addressing hash of positions.
std::size_t weld_vertices(Mesh& mesh);

}  // namespace fastshade::io
