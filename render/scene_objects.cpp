#include "scene_objects.h"

#include <stdexcept>

#include "frames.h"
#include "ply.h"

namespace dp::render {

std::filesystem::path rigid_atlas_file(const std::filesystem::path& frames_dir, const std::string& rigid) {
  return frames_dir / ("rigid_" + rigid + ".ply");
}

std::filesystem::path surface_texture_file(const std::filesystem::path& frames_dir, const std::string& rigid, int frame) {
  return frames_dir / dp::io::frame_file_name("surface_" + rigid, frame, "exr");
}

dp::io::TriangleMesh load_rigid_atlas(const std::filesystem::path& file) {
  const dp::io::PlyData ply = dp::io::read_ply(file);
  dp::io::TriangleMesh mesh;
  try {
    const std::vector<float> x = ply.floats("x"), y = ply.floats("y"), z = ply.floats("z");
    const std::vector<float> nx = ply.floats("nx"), ny = ply.floats("ny"), nz = ply.floats("nz");
    const std::vector<float> s = ply.floats("s"), t = ply.floats("t");
    for (std::size_t i = 0; i < ply.vertex_count; ++i) {
      mesh.positions.push_back({x[i], y[i], z[i]});
      mesh.normals.push_back({nx[i], ny[i], nz[i]});
      mesh.uvs.push_back({s[i], t[i]});
    }
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
  mesh.triangles = ply.faces;
  for (const auto& f : mesh.triangles)
    for (std::uint32_t v : f)
      if (v >= ply.vertex_count)
        throw std::runtime_error(file.string() + ": face refers to vertex " + std::to_string(v) + " of " + std::to_string(ply.vertex_count));
  if (mesh.triangles.empty()) throw std::runtime_error(file.string() + ": rigid atlas has no triangles");
  return mesh;
}

std::vector<SceneObject> load_rigid_objects(const dp::io::Scene& scene, const std::filesystem::path& frames_dir) {
  const dp::io::RenderSettings& r = scene.render;
  std::vector<SceneObject> objects;
  for (const dp::io::RigidObject& rigid : scene.simulation.rigids) {
    const std::filesystem::path atlas = frames_dir.empty() ? std::filesystem::path{} : rigid_atlas_file(frames_dir, rigid.name);
    const bool has_atlas = !atlas.empty() && std::filesystem::exists(atlas);
    objects.push_back({rigid.name, has_atlas ? load_rigid_atlas(atlas) : dp::io::load_triangle_mesh(rigid.mesh),
                       r.materials.at(r.rigid_material.at(rigid.name)), ShadingNormals::Geometric, nullptr});
  }
  return objects;
}

std::vector<std::filesystem::path> attach_surface_textures(std::vector<SceneObject>& rigids, const std::filesystem::path& frames_dir,
                                                           int frame) {
  std::vector<std::filesystem::path> used;
  for (SceneObject& rigid : rigids) {
    rigid.texture = nullptr;
    // The atlas's UVs are what a texture is laid over; a scene mesh's own
    // UVs (if any) belong to some other parameterisation.
    if (!std::filesystem::exists(rigid_atlas_file(frames_dir, rigid.name))) continue;
    const std::filesystem::path file = surface_texture_file(frames_dir, rigid.name, frame);
    if (!std::filesystem::exists(file)) continue;
    rigid.texture = std::make_shared<const SurfaceTexture>(SurfaceTexture::load(file));
    used.push_back(file);
  }
  return used;
}

SceneObject liquid_object(dp::io::TriangleMesh surface, const dp::io::RenderSettings& settings) {
  return {"liquid", std::move(surface), settings.materials.at(settings.liquid_material), ShadingNormals::Interpolated, nullptr};
}

}  // namespace dp::render
