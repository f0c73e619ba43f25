// Procedural meshes (built with OpenMesh) so that the default scene needs no files.
#pragma once
#include "fastshade/mesh.h"

namespace fastshade {

// Unit-less sizes; every primitive is centred at the origin, normals analytic (sphere, torus)
// or per face (plane, cube: vertices are split at the cube's edges).
Mesh make_icosphere(float radius, int subdivisions);
Mesh make_uvsphere(float radius, int segments, int rings);
Mesh make_torus(float major_radius, float minor_radius, int segments, int sides);
Mesh make_plane(float size, int divisions);  // in the XZ plane, normal +Y
Mesh make_cube(float size, int divisions);

}  // namespace fastshade
