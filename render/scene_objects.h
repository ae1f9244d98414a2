#pragma once
// What a scene file puts in front of the camera: its rigids, each with the
// material render.objects assigns, and a frame's liquid surface with
// render.liquid_material.
#include <vector>

#include "render_scene.h"
#include "scene.h"

namespace dp::render {

// Loads every rigid's mesh; throws naming the file when one cannot be read.
std::vector<SceneObject> load_rigid_objects(const dp::io::Scene& scene);

SceneObject liquid_object(dp::io::TriangleMesh surface, const dp::io::RenderSettings& settings);

}  // namespace dp::render
