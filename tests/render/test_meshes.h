#pragma once
// Closed meshes whose exact shapes the render tests reason about.
#include <array>

#include "ply.h"
#include "triangle_mesh.h"

namespace dp::render::test {

// A sphere approximated by a subdivided icosahedron, wound counter-
// clockwise seen from outside, with the exact sphere's normals per vertex.
// subdivisions = 4 gives 5120 triangles.
dp::io::TriangleMesh icosphere(std::array<float, 3> centre, float radius, int subdivisions);

// An axis-aligned box with flat faces: four vertices per face, each with the
// face's outward normal.
dp::io::TriangleMesh box(std::array<float, 3> min, std::array<float, 3> max);

// The mesh as dewpoint-mesh writes it: x, y, z, nx, ny, nz and faces.
dp::io::PlyData liquid_ply(const dp::io::TriangleMesh& mesh);

// A flat disk of `segments` triangles fanned around its centre, in the
// plane y = centre.y, facing -y (counter-clockwise seen from below).
dp::io::TriangleMesh disk_facing_down(std::array<float, 3> centre, float radius, int segments);

// A square in the plane z = z0 spanning [x0, x1] x [y0, y1], facing +z,
// its UV atlas the whole unit square (u along x, v along y).
dp::io::TriangleMesh textured_square(float x0, float x1, float y0, float y1, float z0);

// A rigid's atlas as dewpoint-simulate writes it: x y z nx ny nz s t, faces.
dp::io::PlyData rigid_atlas_ply(const dp::io::TriangleMesh& mesh);

}  // namespace dp::render::test
