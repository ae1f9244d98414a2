#include "cube_triangulation.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "cube_topology.h"
#include "vec3d.h"

namespace dp::mesh {

namespace {

bool is_inside(int inside, int corner) { return (inside >> corner) & 1; }

// Chains segments into loops by following each segment's end to the segment
// that starts there.
std::vector<std::vector<int>> chain_segments(const std::vector<FaceSegment>& segments, int inside) {
  auto fail = [&](const std::string& what) {
    return std::logic_error("marching cubes configuration " + std::to_string(inside) + ": " + what);
  };
  std::array<int, kCubeEdges> next, entered;
  next.fill(-1);
  entered.fill(0);
  for (const FaceSegment& s : segments) {
    if (next[s.from_edge] != -1) throw fail("edge " + std::to_string(s.from_edge) + " is left twice");
    next[s.from_edge] = s.to_edge;
    if (++entered[s.to_edge] > 1) throw fail("edge " + std::to_string(s.to_edge) + " is entered twice");
  }
  for (int e = 0; e < kCubeEdges; ++e)
    if ((next[e] != -1) != (entered[e] == 1)) throw fail("edge " + std::to_string(e) + " is entered and not left, or left and not entered");

  std::vector<std::vector<int>> loops;
  std::array<bool, kCubeEdges> used{};
  for (int start = 0; start < kCubeEdges; ++start) {
    if (next[start] == -1 || used[start]) continue;
    std::vector<int> loop;
    for (int e = start; !used[e]; e = next[e]) {
      used[e] = true;
      loop.push_back(e);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

Vec3d edge_midpoint(int edge) {
  const int a = edge_lower_corner(edge), b = edge_upper_corner(edge);
  Vec3d p;
  for (int axis = 0; axis < 3; ++axis) p[axis] = 0.5 * (corner_coordinate(a, axis) + corner_coordinate(b, axis));
  return p;
}

// Checks the orientation convention on the plainest case, a single inside
// corner at the origin: its outward normal must point away from the corner,
// towards (1, 1, 1). A sign slip anywhere in the face orientation rules
// would flip every configuration alike, so one case decides for all.
bool segments_turn_outward() {
  const std::vector<std::vector<int>> loops = chain_segments(face_segments(1), 1);
  const std::vector<int>& loop = loops.at(0);
  const Vec3d a = edge_midpoint(loop[0]), b = edge_midpoint(loop[1]), c = edge_midpoint(loop[2]);
  return dot(cross(b - a, c - a), Vec3d{1, 1, 1}) > 0;
}

CubeTriangulation fan_triangulation(const std::vector<std::vector<int>>& loops) {
  CubeTriangulation t;
  for (const std::vector<int>& loop : loops)
    for (std::size_t n = 1; n + 1 < loop.size(); ++n)
      t.triangles.push_back({std::int8_t(loop[0]), std::int8_t(loop[n]), std::int8_t(loop[n + 1])});
  return t;
}

}  // namespace

std::vector<FaceSegment> face_segments(int inside) {
  std::vector<FaceSegment> segments;
  for (int face = 0; face < kCubeFaces; ++face) {
    const std::array<int, 4> corner = face_corners_counterclockwise(face);
    // Walking the face's rim counter-clockwise, the rim enters the inside at
    // one crossing and leaves it at a later one. The inside part of the
    // face, seen from outside, then has the rim arc on its boundary and the
    // segment back from the leaving crossing to the entering one; the
    // surface bounding the inside volume shares that segment and so runs
    // it the other way, enter -> leave. Pairing each leaving crossing with
    // the entering one just before it cuts inside corners off one by one.
    int last_enter = -1, first_exit_without_enter = -1;
    for (int n = 0; n < 4; ++n) {
      const int a = corner[n], b = corner[(n + 1) % 4];
      if (is_inside(inside, a) == is_inside(inside, b)) continue;
      const int edge = edge_between(a, b);
      if (is_inside(inside, b)) {
        last_enter = edge;
      } else if (last_enter != -1) {
        segments.push_back({last_enter, edge});
        last_enter = -1;
      } else {
        first_exit_without_enter = edge;  // its entering crossing comes round at the end
      }
    }
    if (first_exit_without_enter != -1) segments.push_back({last_enter, first_exit_without_enter});
  }
  return segments;
}

std::vector<std::vector<int>> surface_loops(int inside) {
  static const bool outward = segments_turn_outward();
  std::vector<std::vector<int>> loops = chain_segments(face_segments(inside), inside);
  if (!outward)
    for (std::vector<int>& loop : loops) std::reverse(loop.begin(), loop.end());
  return loops;
}

const std::array<CubeTriangulation, 256>& cube_triangulations() {
  static const std::array<CubeTriangulation, 256> table = [] {
    std::array<CubeTriangulation, 256> t;
    for (int inside = 0; inside < 256; ++inside) t[inside] = fan_triangulation(surface_loops(inside));
    return t;
  }();
  return table;
}

}  // namespace dp::mesh
