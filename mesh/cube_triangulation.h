#pragma once
// Marching-cubes triangulations, generated rather than tabulated: for each
// of the 256 inside/outside patterns of a cube's corners (bit c set: corner
// c inside), the surface crosses each face in segments between the face's
// edge crossings; the segments chain into closed loops, and each loop is
// fanned into triangles.
//
// Where a face has its two inside corners diagonally opposite, the segments
// cut off each inside corner on its own. That choice depends only on the
// face's four corners, so the two cubes sharing a face make the same
// segments and the surface has no cracks.
#include <array>
#include <cstdint>
#include <vector>

namespace dp::mesh {

// A directed surface segment on one face, between two crossed cube edges.
struct FaceSegment {
  int from_edge, to_edge;
};

// The segments of configuration `inside` on all six faces, oriented so that
// the loops they form turn counter-clockwise about the surface's outward
// normal (pointing from inside to outside).
std::vector<FaceSegment> face_segments(int inside);

// The segments chained into closed loops of cube edges.
// Throws std::logic_error if they do not chain (a crossed edge not entered
// and left exactly once).
std::vector<std::vector<int>> surface_loops(int inside);

struct CubeTriangulation {
  // Triangles as cube edge numbers, counter-clockwise seen from outside.
  std::vector<std::array<std::int8_t, 3>> triangles;
};

// All 256, built on first use.
const std::array<CubeTriangulation, 256>& cube_triangulations();

}  // namespace dp::mesh
