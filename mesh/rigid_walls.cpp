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
  ~Embree() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

void throw_on_embree_error(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) throw std::runtime_error(std::string("Embree: ") + what + " failed (error " + std::to_string(int(error)) + ")");
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
    for (const auto& p : mesh.positions) rigid.position.push_back({p[0], p[1], p[2]});
    rigid.triangles = mesh.triangles;
    RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.positions.size()));
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      for (int a = 0; a < 3; ++a) vertices[3 * v + a] = mesh.positions[v][a];
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), mesh.triangles.size()));
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) indices[3 * t + k] = mesh.triangles[t][k];
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
}

RigidWalls::~RigidWalls() = default;

WallPoint RigidWalls::closest(Vec3d x, double max_distance) const {
  if (rigids_.empty() || !(max_distance > 0)) return {};
  struct State {
    const RigidWalls* walls;
    Vec3d x;
    WallPoint best;
    unsigned best_triangle;
  } state{this, x, {}, 0};
  state.best.distance = max_distance;

  RTCPointQuery query;
  query.x = float(x.x);
  query.y = float(x.y);
  query.z = float(x.z);
  query.time = 0;
  // Embree's bounds are float: widen by a float ulp of the coordinates so no
  // triangle within max_distance in double is culled.
  const double scale = std::max({std::abs(x.x), std::abs(x.y), std::abs(x.z), max_distance});
  query.radius = float(max_distance + 4 * scale * std::numeric_limits<float>::epsilon());
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(embree_->scene, &query, &context, [](RTCPointQueryFunctionArguments* args) -> bool {
    auto& s = *static_cast<State*>(args->userPtr);
    const Rigid& rigid = s.walls->rigids_[args->geomID];
    const auto& t = rigid.triangles[args->primID];
    const Vec3d a = rigid.position[t[0]], b = rigid.position[t[1]], c = rigid.position[t[2]];
    const Vec3d q = closest_point_on_triangle(s.x, a, b, c);
    const double d = length(q - s.x);
    const bool closer = d < s.best.distance;
    const bool tie_with_lower_id = s.best.found && d == s.best.distance &&
                                   (int(args->geomID) < s.best.rigid ||
                                    (int(args->geomID) == s.best.rigid && args->primID < s.best_triangle));
    if (!closer && !tie_with_lower_id) return false;
    s.best.found = true;
    s.best.point = q;
    s.best.distance = d;
    s.best.face_normal = normalized(cross(b - a, c - a));
    s.best.rigid = int(args->geomID);
    s.best_triangle = args->primID;
    // Shrinking the query sphere lets the BVH skip what cannot be closer; a
    // little slack keeps exact ties reachable.
    args->query->radius = std::min(args->query->radius, float(d * (1 + 1e-6)) + 1e-12f);
    return true;
  }, &state);
  return state.best;
}

}  // namespace dp::mesh
