// Procedural meshes (built with OpenMesh) so that the default scene needs no files.
#pragma once
#include <cstdint>

#include "fastshade/mesh.h"

namespace fastshade {

// Unit-less sizes; every primitive is centred at the origin, normals analytic (sphere, torus)
// or per face (plane, cube: vertices are split at the cube's edges). Triangles are wound
// counter-clockwise seen from the side the normals point to (outside).
//
// icosphere: 20·4^s triangles, 10·4^s + 2 shared vertices (edge midpoints pushed onto the sphere).
// uvsphere:  poles on ±Y, `segments` around Y, `rings` bands from pole to pole; one vertex per
//            pole and no seam duplicates, so the mesh is closed.
// torus:     around the Y axis (lies in the XZ plane), 0 < minor < major; closed.
// plane:     XZ, side length `size`, `divisions` quads per side, normal +Y.
// cube:      edge length `size`, `divisions` quads per face side, 4 own vertices per face corner.
//
// Every function throws InputError (where = the primitive's name) for a parameter outside the
// limits below, a non-finite or non-positive size, or a mesh above kMaxPrimitiveTriangles.
Mesh make_icosphere(float radius, int subdivisions);
Mesh make_uvsphere(float radius, int segments, int rings);
Mesh make_torus(float major_radius, float minor_radius, int segments, int sides);
Mesh make_plane(float size, int divisions);  // in the XZ plane, normal +Y
Mesh make_cube(float size, int divisions);

// Limits on procedural meshes (the scene parser checks the same ranges to name the key).
// 8 subdivisions = 1,310,720 triangles, already more than any model the project tests with.
inline constexpr int kMaxIcosphereSubdivisions = 8;
// Per-parameter cap on segments / rings / sides / divisions; keeps every count product in int64
// far from overflow before the triangle cap below is checked.
inline constexpr int kMaxPrimitiveSegments = 4096;
// 4,194,304 triangles (e.g. a 2048 x 1024 torus): five times the largest shared model, and the
// OpenMesh build of it (~100 bytes a triangle) stays well under a gigabyte.
inline constexpr int64_t kMaxPrimitiveTriangles = int64_t{1} << 22;
// Largest radius / size: keeps squared distances (bounding spheres, dot products) finite in
// float with a wide margin (1e12 << 3.4e38) and leaves 7 digits of detail per unit.
inline constexpr float kMaxPrimitiveSize = 1e6f;

}  // namespace fastshade
