#include "render_scene.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace dp::render {

namespace {

void throw_if_failed(RTCDevice device, const std::string& what) {
  RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) throw std::runtime_error("Embree: " + what + " failed (error code " + std::to_string(error) + ")");
}

Vec3 to_vec3(const std::array<float, 3>& a) { return {a[0], a[1], a[2]}; }

RTCRay embree_ray(Vec3 origin, Vec3 direction, float t_far) {
  RTCRay r{};
  r.org_x = origin.x;
  r.org_y = origin.y;
  r.org_z = origin.z;
  r.dir_x = direction.x;
  r.dir_y = direction.y;
  r.dir_z = direction.z;
  r.tnear = 0;
  r.tfar = t_far;
  r.mask = ~0u;
  return r;
}

}  // namespace

RenderScene::RenderScene(const std::vector<SceneObject>& objects, bool wet_paths) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw_if_failed(nullptr, "creating a device");
  scene_ = rtcNewScene(device_);
  for (const SceneObject& object : objects)
    if (!object.mesh.triangles.empty()) attach(object, wet_paths);
  rtcCommitScene(scene_);
  throw_if_failed(device_, "building the scene");
  area_lights_.finish();
}

RenderScene::~RenderScene() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

void RenderScene::attach(const SceneObject& object, bool wet_paths) {
  const auto& mesh = object.mesh;
  if (object.texture && mesh.uvs.size() != mesh.positions.size())
    throw std::invalid_argument(object.name + ": a surface texture needs one UV per vertex");
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
  g.material = std::make_unique<Material>(object.material, wet_paths);
  g.triangles = mesh.triangles;
  if (object.normals == ShadingNormals::Interpolated) {
    if (mesh.normals.size() != mesh.positions.size())
      throw std::invalid_argument(object.name + ": interpolated shading needs one normal per vertex");
    g.normals = mesh.normals;
    g.wound_inwards.resize(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      const Vec3 a = to_vec3(mesh.positions[tri[0]]), b = to_vec3(mesh.positions[tri[1]]), c = to_vec3(mesh.positions[tri[2]]);
      const Vec3 vertex_sum = to_vec3(mesh.normals[tri[0]]) + to_vec3(mesh.normals[tri[1]]) + to_vec3(mesh.normals[tri[2]]);
      g.wound_inwards[t] = dot(vertex_sum, cross(b - a, c - a)) < 0;
    }
  }
  if (object.texture) {
    g.uvs = mesh.uvs;
    g.texture = object.texture;
  }
  if (id != geometries_.size()) throw std::logic_error("Embree geometry IDs are not sequential");
  geometries_.push_back(std::move(g));
  if (geometries_.back().material->emissive()) add_area_light(id, object);
}

void RenderScene::add_area_light(unsigned id, const SceneObject& object) {
  const Geometry& g = geometries_[id];
  std::vector<std::array<Vec3, 3>> triangles;
  std::vector<Vec3> normals;
  for (std::size_t t = 0; t < g.triangles.size(); ++t) {
    const auto& tri = g.triangles[t];
    const Vec3 a = to_vec3(object.mesh.positions[tri[0]]), b = to_vec3(object.mesh.positions[tri[1]]),
               c = to_vec3(object.mesh.positions[tri[2]]);
    const Vec3 winding = cross(b - a, c - a);
    if (!(length(winding) > 0)) continue;  // a degenerate triangle emits nothing and is never hit
    triangles.push_back({a, b, c});
    normals.push_back(outward_normal(g, static_cast<unsigned>(t), winding));
  }
  area_lights_.add(id, triangles, normals, g.material->emission());
}

// Embree's normal follows the winding (counter-clockwise is its front). A
// mesh with vertex normals says itself where its outside is, whatever its
// winding; flat-shaded rigids must wind counter-clockwise seen from outside.
Vec3 RenderScene::outward_normal(const Geometry& g, unsigned triangle, Vec3 embree_normal) const {
  const Vec3 n = normalize(embree_normal);
  return !g.wound_inwards.empty() && g.wound_inwards[triangle] ? -n : n;
}

Vec3 RenderScene::interpolated_normal(const Geometry& g, unsigned triangle, float u, float v) const {
  const auto& t = g.triangles[triangle];
  return (1 - u - v) * to_vec3(g.normals[t[0]]) + u * to_vec3(g.normals[t[1]]) + v * to_vec3(g.normals[t[2]]);
}

SurfaceState RenderScene::surface_state(const Geometry& g, unsigned triangle, float u, float v) const {
  if (!g.texture) return {};
  const auto& t = g.triangles[triangle];
  const auto &a = g.uvs[t[0]], &b = g.uvs[t[1]], &c = g.uvs[t[2]];
  const float w = 1 - u - v;
  return g.texture->at(w * a[0] + u * b[0] + v * c[0], w * a[1] + u * b[1] + v * c[1]);
}

std::optional<SurfaceHit> RenderScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray = embree_ray(ray.origin, ray.direction, std::numeric_limits<float>::infinity());
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
  hit.surface = surface_state(g, rh.hit.primID, rh.hit.u, rh.hit.v);
  hit.material = g.material.get();
  hit.geometry = rh.hit.geomID;
  hit.primitive = rh.hit.primID;
  return hit;
}

bool RenderScene::occluded(Vec3 origin, Vec3 direction, float max_distance) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = embree_ray(origin, direction, max_distance);
  rtcOccluded1(scene_, &context, &r);
  return r.tfar < 0;  // Embree sets tfar to -inf on a hit
}

bool RenderScene::visible(Vec3 from, Vec3 to) const {
  const Vec3 d = to - from;
  const float distance = length(d);
  if (!(distance > 0)) return true;
  // The far end is a surface point too: stop a hair short of it.
  return !occluded(from, (1 / distance) * d, distance * (1 - 1e-4f));
}

bool RenderScene::escapes(const Ray& ray) const {
  return !occluded(ray.origin, ray.direction, std::numeric_limits<float>::infinity());
}

}  // namespace dp::render
