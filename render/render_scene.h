#pragma once
// The triangles a frame is rendered with, in an Embree BVH: one geometry per
// rigid and one for the liquid, each with its material, its UV atlas and
// surface texture where the simulator wrote one, and the emissive ones
// gathered as area lights.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

#include "area_lights.h"
#include "material.h"
#include "ray.h"
#include "render_settings.h"
#include "surface_texture.h"
#include "triangle_mesh.h"

namespace dp::render {

enum class ShadingNormals {
  Geometric,     // flat facets: rigids, whose files may average normals across sharp edges
  Interpolated,  // the mesh's per-vertex normals, blended across each triangle: the liquid surface
};

struct SceneObject {
  std::string name;
  dp::io::TriangleMesh mesh;  // with per-vertex normals when they are Interpolated, uvs with a texture
  dp::io::Material material;
  ShadingNormals normals = ShadingNormals::Geometric;
  std::shared_ptr<const SurfaceTexture> texture = nullptr;  // over mesh.uvs; none: a dry surface
};

struct SurfaceHit {
  Vec3 position;
  float distance = 0;     // along the ray
  Vec3 geometric_normal;  // unit, towards the object's outside
  Vec3 shading_normal;    // unit, on the outside of the geometric surface
  SurfaceState surface;   // from the texture, if the object has one
  const Material* material = nullptr;
  unsigned geometry = 0, primitive = 0;  // Embree IDs
};

class RenderScene {
 public:
  // Objects without triangles (a frame whose liquid has all evaporated) are
  // left out. wet_paths: whether wetting histories change the look. Throws
  // std::runtime_error when Embree fails, std::invalid_argument when a
  // textured object has no UV per vertex.
  explicit RenderScene(const std::vector<SceneObject>& objects, bool wet_paths = true);
  ~RenderScene();
  RenderScene(const RenderScene&) = delete;
  RenderScene& operator=(const RenderScene&) = delete;

  // The nearest surface along the ray, if any. Safe to call from many threads.
  std::optional<SurfaceHit> intersect(const Ray& ray) const;
  // Whether nothing lies on the segment between two points (each end
  // excluded by a hair); for shadow rays.
  bool visible(Vec3 from, Vec3 to) const;
  // Whether the ray leaves the scene without meeting anything.
  bool escapes(const Ray& ray) const;

  const AreaLights& area_lights() const { return area_lights_; }

 private:
  struct Geometry {
    std::unique_ptr<Material> material;
    std::vector<std::array<std::uint32_t, 3>> triangles;  // kept for normals and UVs
    std::vector<std::array<float, 3>> normals;           // per vertex, or empty
    std::vector<std::uint8_t> wound_inwards;             // per triangle, with vertex normals: winding disagrees with them
    std::vector<std::array<float, 2>> uvs;               // per vertex, with a texture
    std::shared_ptr<const SurfaceTexture> texture;
  };

  bool occluded(Vec3 origin, Vec3 direction, float max_distance) const;
  void attach(const SceneObject& object, bool wet_paths);
  void add_area_light(unsigned id, const SceneObject& object);
  Vec3 outward_normal(const Geometry& g, unsigned triangle, Vec3 embree_normal) const;
  Vec3 interpolated_normal(const Geometry& g, unsigned triangle, float u, float v) const;
  SurfaceState surface_state(const Geometry& g, unsigned triangle, float u, float v) const;

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<Geometry> geometries_;  // indexed by Embree geometry ID
  AreaLights area_lights_;
};

}  // namespace dp::render
