#pragma once
// The rigid scene as the contact-angle corrections see it (paper Sec. 7):
// for a point, the closest point on any rigid, the wall's normal there and
// the distance, through Embree 3 point queries (rtcPointQuery) over one BVH
// of all rigid triangles.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "triangle_mesh.h"
#include "vec3d.h"
#include "wall_slabs.h"

namespace dp::mesh {

struct WallPoint {
  bool found = false;
  Vec3d point;        // closest point on the rigid surface
  Vec3d face_normal;  // unit geometric normal of the triangle holding it (vertex winding, counter-clockwise)
  double distance = 0;
  int rigid = -1;  // index into the meshes the walls were built from
  unsigned triangle = 0;  // index into that mesh's triangles
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
  // the answer does not depend on the BVH's traversal order. A `hint`, a
  // wall point found for a nearby point, changes nothing in the answer but
  // lets the search start from its triangle's distance to x.
  WallPoint closest(Vec3d x, double max_distance, const WallPoint* hint = nullptr) const;

  // The slabs (wall_slabs.h) that hold every wall triangle within `radius`
  // of x, appended to `out`; a few more may come along.
  void slabs_near(Vec3d x, double radius, std::vector<const WallSlab*>& out) const;

  bool empty() const { return rigids_.empty(); }
  std::size_t rigid_count() const { return rigids_.size(); }

 private:
  struct Rigid {
    // Per triangle, side by side for the search's callbacks.
    std::vector<std::array<Vec3d, 3>> corners;
    std::vector<Vec3d> normal;  // unit, counter-clockwise
    std::vector<std::uint32_t> triangle_of_piece;  // Embree's primitives are pieces of the triangles
  };
  struct Embree;
  struct Search;

  std::vector<Rigid> rigids_;
  std::vector<WallSlab> slabs_;  // of all rigids' triangles
  std::unique_ptr<Embree> embree_;
};

}  // namespace dp::mesh
