#pragma once
// What a scene file puts in front of the camera: its rigids, each with the
// material render.objects assigns, and a frame's liquid surface with
// render.liquid_material.
//
// Where the simulator wrote a rigid's UV atlas (frames/rigid_NAME.ply) the
// rigid is rendered from it, and each frame's surface texture
// (frames/surface_NAME.%04d.exr) drives its roughness; without them the
// scene's mesh is rendered dry (docs/file-formats.md).
#include <filesystem>
#include <vector>

#include "render_scene.h"
#include "scene.h"

namespace dp::render {

// Loads every rigid's mesh, the atlas in frames_dir when present (an empty
// frames_dir: none). Throws naming the file when one cannot be read.
std::vector<SceneObject> load_rigid_objects(const dp::io::Scene& scene, const std::filesystem::path& frames_dir = {});

// frames/rigid_NAME.ply: x y z nx ny nz s t, triangles. Throws naming the
// file and the missing property.
dp::io::TriangleMesh load_rigid_atlas(const std::filesystem::path& file);

// Gives every rigid with an atlas its surface texture of this frame, if the
// simulator wrote one; returns the texture files used.
std::vector<std::filesystem::path> attach_surface_textures(std::vector<SceneObject>& rigids,
                                                           const std::filesystem::path& frames_dir, int frame);

SceneObject liquid_object(dp::io::TriangleMesh surface, const dp::io::RenderSettings& settings);

std::filesystem::path rigid_atlas_file(const std::filesystem::path& frames_dir, const std::string& rigid);
std::filesystem::path surface_texture_file(const std::filesystem::path& frames_dir, const std::string& rigid, int frame);

}  // namespace dp::render
