#include "scene_objects.h"

namespace dp::render {

std::vector<SceneObject> load_rigid_objects(const dp::io::Scene& scene) {
  const dp::io::RenderSettings& r = scene.render;
  std::vector<SceneObject> objects;
  for (const dp::io::RigidObject& rigid : scene.simulation.rigids)
    objects.push_back({rigid.name, dp::io::load_triangle_mesh(rigid.mesh), r.materials.at(r.rigid_material.at(rigid.name)),
                       ShadingNormals::Geometric});
  return objects;
}

SceneObject liquid_object(dp::io::TriangleMesh surface, const dp::io::RenderSettings& settings) {
  return {"liquid", std::move(surface), settings.materials.at(settings.liquid_material), ShadingNormals::Interpolated};
}

}  // namespace dp::render
