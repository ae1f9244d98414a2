#include "render_scene.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "make_material.h"

namespace dp::render {

namespace {

void throw_if_failed(RTCDevice device, const std::string& what) {
  RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) throw std::runtime_error("Embree: " + what + " failed (error code " + std::to_string(error) + ")");
}

Vec3 to_vec3(const std::array<float, 3>& a) { return {a[0], a[1], a[2]}; }

}  // namespace

RenderScene::RenderScene(const std::vector<SceneObject>& objects) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw_if_failed(nullptr, "creating a device");
  scene_ = rtcNewScene(device_);
  for (const SceneObject& object : objects)
    if (!object.mesh.triangles.empty()) attach(object);
  rtcCommitScene(scene_);
  throw_if_failed(device_, "building the scene");
}

RenderScene::~RenderScene() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

void RenderScene::attach(const SceneObject& object) {
  const auto& mesh = object.mesh;
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree allocates these buffers itself, with the padding its SIMD loads need.
  void* vertices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                           mesh.positions.size());
  void* indices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                          3 * sizeof(std::uint32_t), mesh.triangles.size());
  throw_if_failed(device_, "allocating the buffers of '" + object.name + "'");
  std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * 3 * sizeof(float));
  std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * 3 * sizeof(std::uint32_t));
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);  // the scene holds it now

  Geometry g;
  g.material = make_material(object.material);
  if (object.normals == ShadingNormals::Interpolated) {
    if (mesh.normals.size() != mesh.positions.size())
      throw std::invalid_argument(object.name + ": interpolated shading needs one normal per vertex");
    g.triangles = mesh.triangles;
    g.normals = mesh.normals;
  }
  if (id != geometries_.size()) throw std::logic_error("Embree geometry IDs are not sequential");
  geometries_.push_back(std::move(g));
}

// Embree's normal follows the winding (counter-clockwise is its front). A
// mesh with vertex normals says itself where its outside is, whatever its
// winding; flat-shaded rigids must wind counter-clockwise seen from outside.
Vec3 RenderScene::outward_normal(const Geometry& g, unsigned triangle, Vec3 embree_normal) const {
  Vec3 n = normalize(embree_normal);
  if (g.normals.empty()) return n;
  const auto& t = g.triangles[triangle];
  const Vec3 vertex_sum = to_vec3(g.normals[t[0]]) + to_vec3(g.normals[t[1]]) + to_vec3(g.normals[t[2]]);
  return dot(vertex_sum, n) < 0 ? -n : n;
}

Vec3 RenderScene::interpolated_normal(const Geometry& g, unsigned triangle, float u, float v) const {
  const auto& t = g.triangles[triangle];
  return (1 - u - v) * to_vec3(g.normals[t[0]]) + u * to_vec3(g.normals[t[1]]) + v * to_vec3(g.normals[t[2]]);
}

std::optional<SurfaceHit> RenderScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = ray.origin.x;
  rh.ray.org_y = ray.origin.y;
  rh.ray.org_z = ray.origin.z;
  rh.ray.dir_x = ray.direction.x;
  rh.ray.dir_y = ray.direction.y;
  rh.ray.dir_z = ray.direction.z;
  rh.ray.tnear = 0;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  const Geometry& g = geometries_[rh.hit.geomID];
  SurfaceHit hit;
  hit.distance = rh.ray.tfar;
  hit.position = ray.origin + hit.distance * ray.direction;
  hit.geometric_normal = outward_normal(g, rh.hit.primID, {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
  hit.shading_normal = hit.geometric_normal;
  if (!g.normals.empty()) {
    Vec3 n = interpolated_normal(g, rh.hit.primID, rh.hit.u, rh.hit.v);
    // Normals of opposite vertices can cancel; the facet is then the best guess.
    if (dot(n, hit.geometric_normal) > 0) hit.shading_normal = normalize(n);
  }
  hit.material = g.material.get();
  return hit;
}

}  // namespace dp::render
