// The generated marching-cubes triangulations, checked configuration by
// configuration against what any crack-free, closed triangulation must
// satisfy.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>

#include "cube_topology.h"
#include "cube_triangulation.h"
#include "vec3d.h"

namespace dp::mesh {
namespace {

bool inside(int configuration, int corner) { return (configuration >> corner) & 1; }

bool is_crossed(int configuration, int edge) {
  return inside(configuration, edge_lower_corner(edge)) != inside(configuration, edge_upper_corner(edge));
}

Vec3d edge_midpoint(int edge) {
  Vec3d p;
  for (int a = 0; a < 3; ++a)
    p[a] = 0.5 * (corner_coordinate(edge_lower_corner(edge), a) + corner_coordinate(edge_upper_corner(edge), a));
  return p;
}

TEST(mesh_CubeTopology, EdgesJoinCornersDifferingAlongTheirAxis) {
  for (int e = 0; e < kCubeEdges; ++e) {
    EXPECT_EQ(edge_lower_corner(e) ^ edge_upper_corner(e), 1 << edge_axis(e));
    EXPECT_EQ(edge_between(edge_lower_corner(e), edge_upper_corner(e)), e);
    EXPECT_EQ(edge_between(edge_upper_corner(e), edge_lower_corner(e)), e);
  }
}

TEST(mesh_CubeTopology, FaceCornersTurnCounterClockwiseSeenFromOutside) {
  for (int f = 0; f < kCubeFaces; ++f) {
    const auto c = face_corners_counterclockwise(f);
    auto corner_point = [](int corner) {
      return Vec3d{double(corner_coordinate(corner, 0)), double(corner_coordinate(corner, 1)),
                   double(corner_coordinate(corner, 2))};
    };
    Vec3d outward;
    outward[f / 2] = f % 2 ? 1 : -1;
    const Vec3d a = corner_point(c[0]), b = corner_point(c[1]), d = corner_point(c[2]);
    EXPECT_GT(dot(cross(b - a, d - a), outward), 0) << "face " << f;
  }
}

TEST(mesh_CubeTriangulation, EveryConfigurationEntersAndLeavesEachCrossedEdgeOnce) {
  for (int config = 0; config < 256; ++config) {
    std::map<int, int> leaving, entering;
    for (const FaceSegment& s : face_segments(config)) {
      ++leaving[s.from_edge];
      ++entering[s.to_edge];
    }
    for (int e = 0; e < kCubeEdges; ++e) {
      const int expected = is_crossed(config, e) ? 1 : 0;
      EXPECT_EQ(leaving[e], expected) << "configuration " << config << " edge " << e;
      EXPECT_EQ(entering[e], expected) << "configuration " << config << " edge " << e;
    }
  }
}

TEST(mesh_CubeTriangulation, EveryConfigurationFormsClosedLoopsOverAllCrossedEdges) {
  for (int config = 0; config < 256; ++config) {
    std::vector<std::vector<int>> loops;
    ASSERT_NO_THROW(loops = surface_loops(config)) << "configuration " << config;
    std::set<int> seen;
    for (const auto& loop : loops) {
      EXPECT_GE(loop.size(), 3u) << "configuration " << config;
      for (int e : loop) EXPECT_TRUE(seen.insert(e).second) << "configuration " << config << " repeats edge " << e;
    }
    for (int e = 0; e < kCubeEdges; ++e) EXPECT_EQ(seen.count(e) == 1, is_crossed(config, e)) << "configuration " << config;
  }
}

// Inside the cube, a loop's fan has each diagonal once each way; what is
// left are the loop's own edges, which must be the face segments (run in the
// loop's direction), or neighbouring cubes would not share them.
TEST(mesh_CubeTriangulation, TriangleBoundaryIsTheFaceSegments) {
  const auto& table = cube_triangulations();
  for (int config = 0; config < 256; ++config) {
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : table[config].triangles)
      for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    std::set<std::pair<int, int>> boundary;
    for (const auto& [edge, count] : directed) {
      EXPECT_EQ(count, 1) << "configuration " << config;
      if (!directed.count({edge.second, edge.first})) boundary.insert(edge);
    }
    std::set<std::pair<int, int>> loop_edges;
    for (const auto& loop : surface_loops(config))
      for (std::size_t k = 0; k < loop.size(); ++k) loop_edges.insert({loop[k], loop[(k + 1) % loop.size()]});
    EXPECT_EQ(boundary, loop_edges) << "configuration " << config;
  }
}

// Two cubes sharing a face see it from opposite sides, so their segments on
// it must coincide with opposite directions, for every pattern of the
// face's corners.
TEST(mesh_CubeTriangulation, CubesSharingAFaceAgreeOnItsSegments) {
  for (int axis = 0; axis < 3; ++axis) {
    const int high_face = 2 * axis + 1;
    const auto face_corner = face_corners_counterclockwise(high_face);
    for (int pattern = 0; pattern < 16; ++pattern) {
      int below = 0, above = 0;  // the lower cube's high face is the upper cube's low face
      for (int n = 0; n < 4; ++n)
        if ((pattern >> n) & 1) {
          below |= 1 << face_corner[n];
          above |= 1 << (face_corner[n] & ~(1 << axis));
        }
      auto on_face = [](int edge, int face) {
        const int a = face / 2, side = face % 2;
        return edge_axis(edge) != a && corner_coordinate(edge_lower_corner(edge), a) == side;
      };
      auto across = [axis](int edge) {  // the same grid edge, numbered in the upper cube
        return edge_between(edge_lower_corner(edge) & ~(1 << axis), edge_upper_corner(edge) & ~(1 << axis));
      };
      std::set<std::pair<int, int>> from_below, from_above;
      for (const FaceSegment& s : face_segments(below))
        if (on_face(s.from_edge, high_face) && on_face(s.to_edge, high_face))
          from_below.insert({across(s.to_edge), across(s.from_edge)});
      for (const FaceSegment& s : face_segments(above))
        if (on_face(s.from_edge, high_face - 1) && on_face(s.to_edge, high_face - 1)) from_above.insert({s.from_edge, s.to_edge});
      EXPECT_EQ(from_below, from_above) << "axis " << axis << " face pattern " << pattern;
    }
  }
}

TEST(mesh_CubeTriangulation, SingleInsideCornerTriangleFacesAwayFromIt) {
  const auto& table = cube_triangulations();
  for (int corner = 0; corner < kCubeCorners; ++corner) {
    const auto& triangles = table[1 << corner].triangles;
    ASSERT_EQ(triangles.size(), 1u);
    const auto& t = triangles[0];
    const Vec3d a = edge_midpoint(t[0]), b = edge_midpoint(t[1]), c = edge_midpoint(t[2]);
    const Vec3d corner_point{double(corner_coordinate(corner, 0)), double(corner_coordinate(corner, 1)),
                             double(corner_coordinate(corner, 2))};
    EXPECT_GT(dot(cross(b - a, c - a), a - corner_point), 0) << "corner " << corner;
  }
}

TEST(mesh_CubeTriangulation, UniformCubesHaveNoTriangles) {
  EXPECT_TRUE(cube_triangulations()[0].triangles.empty());
  EXPECT_TRUE(cube_triangulations()[255].triangles.empty());
}

}  // namespace
}  // namespace dp::mesh
