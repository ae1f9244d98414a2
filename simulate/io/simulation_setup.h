#pragma once
// Turns a validated scene into the core's plain-number setup: liquid blocks
// filled with particles, rigid meshes sampled into boundary particles.
#include "scene.h"
#include "simulation.h"
#include "surface_atlas.h"
#include "triangle_mesh.h"

namespace dp::io {

// Loads the rigid meshes (throws naming the mesh file on failure).
SimulationSetup make_simulation_setup(const Scene& scene);

// A textured rigid's atlas, for the frames folder (rigid_NAME.ply).
struct RigidAtlas {
  std::string rigid_name;
  AtlasMesh mesh;
};

// The same, also handing back the atlas of every textured rigid, in the
// order of SimulationSetup::surfaces.
SimulationSetup make_simulation_setup(const Scene& scene, std::vector<RigidAtlas>* atlases);

// The static textures of one rigid (paper Sec. 4.3): atlas, texels, m_t^max.
// Throws SceneError naming the scene key when the texture cannot be made.
SurfaceTextureSetup make_surface_texture(const Scene& scene, std::size_t rigid, const TriangleMesh& mesh, AtlasMesh* atlas);
// The air section's core settings (vapor already a density, kelvin).
AirSettings make_air_settings(const AirSectionSettings& air);

// Particles on a cubic lattice of the given spacing, cell-centred in the block.
std::vector<Vec3> fill_block(const LiquidBlock& block, double spacing);

}  // namespace dp::io
