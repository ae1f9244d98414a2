#pragma once
// The rigid scene as the contact-angle corrections see it (paper Sec. 7):
// for a point, the closest point on any rigid, the wall's normal there and
// the distance, through Embree 3 point queries (rtcPointQuery) over one BVH
// of all rigid triangles.
#include <memory>
#include <string>
#include <vector>

#include "triangle_mesh.h"
#include "vec3d.h"

namespace dp::mesh {

struct WallPoint {
  bool found = false;
  Vec3d point;        // closest point on the rigid surface
  Vec3d face_normal;  // unit geometric normal of the triangle holding it (vertex winding, counter-clockwise)
  double distance = 0;
  int rigid = -1;  // index into the meshes the walls were built from
};

class RigidWalls {
 public:
  // One rigid per mesh, in world space; the mesh's index is its rigid id.
  explicit RigidWalls(const std::vector<io::TriangleMesh>& rigids);
  ~RigidWalls();
  RigidWalls(const RigidWalls&) = delete;
  RigidWalls& operator=(const RigidWalls&) = delete;

  // The closest point of any rigid strictly within max_distance of x, or
  // found = false. Safe to call from many threads at once. Ties between
  // triangles at the same distance go to the lower (rigid, triangle) id, so
  // the answer does not depend on the BVH's traversal order.
  WallPoint closest(Vec3d x, double max_distance) const;

  bool empty() const { return rigids_.empty(); }
  std::size_t rigid_count() const { return rigids_.size(); }

 private:
  struct Rigid {
    std::vector<Vec3d> position;
    std::vector<std::array<std::uint32_t, 3>> triangles;
  };
  struct Embree;

  std::vector<Rigid> rigids_;
  std::unique_ptr<Embree> embree_;
};

}  // namespace dp::mesh
