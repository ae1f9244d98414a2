#pragma once
// The renderer's material for a scene file's material description.
#include <memory>

#include "material.h"
#include "scene.h"

namespace dp::render {

std::unique_ptr<Material> make_material(const dp::io::Material& description);

}  // namespace dp::render
