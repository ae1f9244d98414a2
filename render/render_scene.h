#pragma once
// The triangles a frame is rendered with, in an Embree BVH: one geometry per
// rigid and one for the liquid, each with its material.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

#include "material.h"
#include "ray.h"
#include "scene.h"
#include "triangle_mesh.h"

namespace dp::render {

enum class ShadingNormals {
  Geometric,     // flat facets: rigids, whose files may average normals across sharp edges
  Interpolated,  // the mesh's per-vertex normals, blended across each triangle: the liquid surface
};

struct SceneObject {
  std::string name;
  dp::io::TriangleMesh mesh;  // with per-vertex normals when they are Interpolated
  dp::io::Material material;
  ShadingNormals normals = ShadingNormals::Geometric;
};

struct SurfaceHit {
  Vec3 position;
  float distance = 0;     // along the ray
  Vec3 geometric_normal;  // unit, towards the object's outside
  Vec3 shading_normal;    // unit, on the outside of the geometric surface
  const Material* material = nullptr;
};

class RenderScene {
 public:
  // Objects without triangles (a frame whose liquid has all evaporated) are
  // left out. Throws std::runtime_error when Embree fails.
  explicit RenderScene(const std::vector<SceneObject>& objects);
  ~RenderScene();
  RenderScene(const RenderScene&) = delete;
  RenderScene& operator=(const RenderScene&) = delete;

  // The nearest surface along the ray, if any. Safe to call from many threads.
  std::optional<SurfaceHit> intersect(const Ray& ray) const;

 private:
  struct Geometry {
    std::unique_ptr<Material> material;
    std::vector<std::array<std::uint32_t, 3>> triangles;  // kept only for interpolated normals
    std::vector<std::array<float, 3>> normals;           // per vertex, or empty
  };

  void attach(const SceneObject& object);
  Vec3 outward_normal(const Geometry& g, unsigned triangle, Vec3 embree_normal) const;
  Vec3 interpolated_normal(const Geometry& g, unsigned triangle, float u, float v) const;

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<Geometry> geometries_;  // indexed by Embree geometry ID
};

}  // namespace dp::render
