#include "rigid_walls.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "closest_point_triangle.h"

namespace dp::mesh {

struct RigidWalls::Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  RTCScene slab_scene = nullptr;  // one user primitive per slab, bounded by its triangles' box
  ~Embree() {
    if (slab_scene) rtcReleaseScene(slab_scene);
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

void throw_on_embree_error(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) throw std::runtime_error(std::string("Embree: ") + what + " failed (error " + std::to_string(int(error)) + ")");
}

using Triangle = std::array<std::uint32_t, 3>;

// The sum of the areas of three faces of the triangle's bounding box, over
// the triangle's area: about 2 for a triangle along two axes, 4.6 for a
// well-shaped one at any angle, but large for a long sliver across the
// axes (the spokes of a fan-triangulated disc), whose box holds many points
// the triangle is nowhere near.
double box_looseness(Vec3d a, Vec3d b, Vec3d c) {
  Vec3d extent;
  for (int axis = 0; axis < 3; ++axis) extent[axis] = std::max({a[axis], b[axis], c[axis]}) - std::min({a[axis], b[axis], c[axis]});
  const double box_faces = extent.x * extent.y + extent.y * extent.z + extent.z * extent.x;
  const double area = 0.5 * length(cross(b - a, c - a));
  return area > 0 ? box_faces / area : 0;
}

// Embree bounds each primitive by its box and calls the point query back
// for every box the query sphere touches, so a loosely boxed triangle is
// handed to Embree as pieces (halving the longest edge) that are boxed
// tightly. Pieces only steer the search: distances are always taken to the
// whole triangle. New vertices are appended to `vertices`.
void append_pieces(std::vector<Vec3d>& vertices, Triangle t, int depth, std::vector<Triangle>& pieces) {
  constexpr double kLooseBox = 8;
  constexpr int kMostHalvings = 8;  // a fan's tip stays loose however often it is halved
  const Vec3d p[3] = {vertices[t[0]], vertices[t[1]], vertices[t[2]]};
  if (depth == kMostHalvings || box_looseness(p[0], p[1], p[2]) <= kLooseBox) {
    pieces.push_back(t);
    return;
  }
  int longest = 0;  // the edge from corner `longest` to the next corner
  for (int e = 1; e < 3; ++e)
    if (length_squared(p[(e + 1) % 3] - p[e]) > length_squared(p[(longest + 1) % 3] - p[longest])) longest = e;
  const std::uint32_t a = t[longest], b = t[(longest + 1) % 3], c = t[(longest + 2) % 3];
  vertices.push_back(0.5 * (vertices[a] + vertices[b]));
  const std::uint32_t middle = std::uint32_t(vertices.size() - 1);
  append_pieces(vertices, {a, middle, c}, depth + 1, pieces);
  append_pieces(vertices, {middle, b, c}, depth + 1, pieces);
}

// Embree's bounds, pieces and query point are float: the sphere it searches
// is widened by a few float ulps of the coordinates (each rounding moves a
// point by at most one), so that everything within `distance` of x in
// double, ties included, is offered.
float widened_radius(Vec3d x, double distance) {
  const double scale = std::max({std::abs(x.x), std::abs(x.y), std::abs(x.z), distance});
  return float(distance + 8 * scale * std::numeric_limits<float>::epsilon());
}

RTCPointQuery point_query(Vec3d x, double distance) {
  RTCPointQuery query;
  query.x = float(x.x);
  query.y = float(x.y);
  query.z = float(x.z);
  query.time = 0;
  query.radius = widened_radius(x, distance);
  return query;
}

// The slabs' boxes hold float corners, so they are exact in float.
void slab_bounds(const RTCBoundsFunctionArguments* args) {
  const auto& slab = static_cast<const WallSlab*>(args->geometryUserPtr)[args->primID];
  *args->bounds_o = {float(slab.box_lo.x), float(slab.box_lo.y), float(slab.box_lo.z), 0,
                     float(slab.box_hi.x), float(slab.box_hi.y), float(slab.box_hi.z), 0};
}

RTCScene slab_scene(RTCDevice device, std::vector<WallSlab>& slabs) {
  RTCScene scene = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, unsigned(slabs.size()));
  rtcSetGeometryUserData(geometry, slabs.data());
  rtcSetGeometryBoundsFunction(geometry, slab_bounds, nullptr);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcCommitScene(scene);
  return scene;
}

}  // namespace

RigidWalls::RigidWalls(const std::vector<io::TriangleMesh>& rigids) : embree_(std::make_unique<Embree>()) {
  if (rigids.empty()) return;
  embree_->device = rtcNewDevice(nullptr);
  if (!embree_->device) throw std::runtime_error("Embree: cannot create a device");
  embree_->scene = rtcNewScene(embree_->device);
  for (std::size_t r = 0; r < rigids.size(); ++r) {
    const io::TriangleMesh& mesh = rigids[r];
    Rigid rigid;
    std::vector<Vec3d> piece_vertices;
    for (const auto& p : mesh.positions) piece_vertices.push_back({p[0], p[1], p[2]});
    std::vector<Triangle> pieces;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const Triangle& corner = mesh.triangles[t];
      const Vec3d a = piece_vertices[corner[0]], b = piece_vertices[corner[1]], c = piece_vertices[corner[2]];
      rigid.corners.push_back({a, b, c});
      rigid.normal.push_back(normalized(cross(b - a, c - a)));
      append_pieces(piece_vertices, corner, 0, pieces);
      rigid.triangle_of_piece.resize(pieces.size(), std::uint32_t(t));
    }
    RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), piece_vertices.size()));
    for (std::size_t v = 0; v < piece_vertices.size(); ++v)
      for (int a = 0; a < 3; ++a) vertices[3 * v + a] = float(piece_vertices[v][a]);
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), pieces.size()));
    for (std::size_t t = 0; t < pieces.size(); ++t)
      for (int k = 0; k < 3; ++k) indices[3 * t + k] = pieces[t][k];
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(embree_->scene, geometry, static_cast<unsigned>(r));
    rtcReleaseGeometry(geometry);
    rigids_.push_back(std::move(rigid));
  }
  // Point queries need the robust build: the fast one may miss primitives
  // whose bounds only touch the query sphere.
  rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcCommitScene(embree_->scene);
  throw_on_embree_error(embree_->device, "building the rigid scene");
  for (const Rigid& rigid : rigids_) {
    const std::vector<WallSlab> slabs = coplanar_slabs(rigid.corners, rigid.normal);
    slabs_.insert(slabs_.end(), slabs.begin(), slabs.end());
  }
  embree_->slab_scene = slab_scene(embree_->device, slabs_);
  throw_on_embree_error(embree_->device, "building the wall slabs");
}

RigidWalls::~RigidWalls() = default;

// One closest-point search: the best wall point offered so far.
struct RigidWalls::Search {
  const RigidWalls& walls;
  Vec3d x;
  WallPoint best;
  int last_rigid = -1;
  unsigned last_triangle = 0;

  // Takes triangle `triangle` of rigid `rigid` if its closest point beats
  // the best so far: closer, or as close with a lower (rigid, triangle) id,
  // so the answer does not depend on the order of the offers.
  bool offer(int rigid, unsigned triangle) {
    // Pieces of one triangle often meet the sphere one after another, and
    // the best triangle's pieces keep meeting it: a triangle offered again
    // cannot change the best.
    if (rigid == last_rigid && triangle == last_triangle) return false;
    last_rigid = rigid, last_triangle = triangle;
    if (best.found && rigid == best.rigid && triangle == best.triangle) return false;
    const Rigid& r = walls.rigids_[std::size_t(rigid)];
    const auto& [a, b, c] = r.corners[triangle];
    const Vec3d q = closest_point_on_triangle(x, a, b, c);
    const double d_squared = length_squared(q - x);
    // Clearly farther: its rounded distance can neither beat nor tie the
    // best, so the square root can wait for candidates that might.
    if (d_squared > best.distance * best.distance * (1 + 1e-12)) return false;
    const double d = std::sqrt(d_squared);
    const bool closer = d < best.distance;
    const bool tie_with_lower_id =
        best.found && d == best.distance && (rigid < best.rigid || (rigid == best.rigid && triangle < best.triangle));
    if (!closer && !tie_with_lower_id) return false;
    best = {true, q, r.normal[triangle], d, rigid, triangle};
    return true;
  }

  float query_radius(double distance) const { return widened_radius(x, distance); }
};

WallPoint RigidWalls::closest(Vec3d x, double max_distance, const WallPoint* hint) const {
  if (rigids_.empty() || !(max_distance > 0)) return {};
  Search search{*this, x, {}};
  search.best.distance = max_distance;
  // Offering the hint first only shrinks the sphere Embree has to search.
  if (hint && hint->found) search.offer(hint->rigid, hint->triangle);

  RTCPointQuery query = point_query(x, search.best.distance);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(embree_->scene, &query, &context, [](RTCPointQueryFunctionArguments* args) -> bool {
    auto& s = *static_cast<Search*>(args->userPtr);
    const int rigid = int(args->geomID);
    if (!s.offer(rigid, s.walls.rigids_[std::size_t(rigid)].triangle_of_piece[args->primID])) return false;
    // Shrinking the query sphere lets the BVH skip what cannot be closer.
    args->query->radius = std::min(args->query->radius, s.query_radius(s.best.distance));
    return true;
  }, &search);
  return search.best;
}

void RigidWalls::slabs_near(Vec3d x, double radius, std::vector<const WallSlab*>& out) const {
  if (slabs_.empty()) return;
  struct Found {
    const std::vector<WallSlab>& slabs;
    std::vector<const WallSlab*>& out;
  } found{slabs_, out};
  RTCPointQuery query = point_query(x, radius);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(embree_->slab_scene, &query, &context, [](RTCPointQueryFunctionArguments* args) -> bool {
    auto& f = *static_cast<Found*>(args->userPtr);
    f.out.push_back(&f.slabs[args->primID]);
    return false;
  }, &found);
}

}  // namespace dp::mesh
