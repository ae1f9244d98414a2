#include "simulation_setup.h"

#include <cmath>
#include <sstream>

#include "rigid/sample_surface.h"
#include "atlas_rasterization.h"
#include "max_mass_texture.h"
#include "triangle_mesh.h"

namespace dp::io {

namespace {
Vec3 to_vec3(const Vec3d& v) { return Vec3{static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])}; }

// A rigid reaching past the domain would put boundary particles where
// liquid particles count as unstable (docs/scene-format.md).
void check_inside_domain(const TriangleMesh& mesh, const SimulationSettings& s, const std::string& key) {
  for (const auto& p : mesh.positions)
    for (int a = 0; a < 3; ++a)
      if (p[a] < s.domain_min_m[a] || p[a] > s.domain_max_m[a]) {
        std::ostringstream m;
        m << key << ".mesh: vertex (" << p[0] << ", " << p[1] << ", " << p[2] << ") m lies outside the simulation domain ["
          << s.domain_min_m[0] << ", " << s.domain_max_m[0] << "] x [" << s.domain_min_m[1] << ", " << s.domain_max_m[1] << "] x ["
          << s.domain_min_m[2] << ", " << s.domain_max_m[2] << "] m (simulation.domain)";
        throw SceneError(m.str());
      }
}

}  // namespace

namespace {
bool inside_shape(const LiquidBlock& block, double x, double y, double z) {
  const double dx = x - block.center_m[0], dy = y - block.center_m[1], dz = z - block.center_m[2];
  const double r2 = block.radius_m * block.radius_m;
  switch (block.shape) {
    case LiquidShape::Sphere: return dx * dx + dy * dy + dz * dz <= r2;
    case LiquidShape::Cylinder: return dx * dx + dz * dz <= r2;  // y is inside the bounding box already
    case LiquidShape::Box: break;
  }
  return true;
}
}  // namespace

std::vector<Vec3> fill_block(const LiquidBlock& block, double spacing) {
  int n[3];
  double offset[3];
  for (int a = 0; a < 3; ++a) {
    double extent = block.max_m[a] - block.min_m[a];
    n[a] = std::max(1, static_cast<int>(std::floor(extent / spacing + 1e-9)));
    offset[a] = block.min_m[a] + 0.5 * (extent - (n[a] - 1) * spacing);
  }
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const double x = offset[0] + i * spacing, y = offset[1] + j * spacing, z = offset[2] + k * spacing;
        if (inside_shape(block, x, y, z))
          points.push_back(Vec3{static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
      }
  return points;
}

AirSettings make_air_settings(const AirSectionSettings& a) {
  AirSettings air;
  air.domain_min = to_vec3(a.domain_min_m);
  air.domain_max = to_vec3(a.domain_max_m);
  air.resolution = a.resolution;
  air.ambient_temperature = static_cast<float>(a.temperature_k);
  air.ambient_vapor = a.vapor_kg_m3;
  air.buoyancy_alpha = static_cast<float>(a.buoyancy_alpha);
  air.buoyancy_beta = static_cast<float>(a.buoyancy_beta);
  air.vorticity_epsilon = static_cast<float>(a.vorticity_epsilon);
  air.vapor_diffusivity = static_cast<float>(a.vapor_diffusivity_m2_s);
  air.heat_diffusivity = static_cast<float>(a.heat_diffusivity_m2_s);
  air.advection = a.maccormack ? AirAdvection::MacCormack : AirAdvection::SemiLagrangian;
  air.open_face = a.open_face;
  air.projection_tolerance = static_cast<float>(a.projection_tolerance);
  air.projection_max_iterations = a.projection_max_iterations;
  const float dx = mac_grid_covering(air.domain_min, air.domain_max, air.resolution).dx;
  for (const AirInflowSettings& in : a.inflows) {
    AirInflow f;
    f.shape = in.disc ? AirInflow::Shape::Disc : AirInflow::Shape::Box;
    f.box_min = to_vec3(in.min_m);
    f.box_max = to_vec3(in.max_m);
    f.center = to_vec3(in.center_m);
    f.normal = to_vec3(in.normal);
    f.radius = static_cast<float>(in.radius_m);
    // A disc without thickness is one cell thick, so it catches cell centres.
    f.thickness = in.thickness_m > 0 ? static_cast<float>(in.thickness_m) : dx;
    f.velocity = to_vec3(in.velocity_m_s);
    f.temperature = static_cast<float>(in.temperature_k);
    f.vapor = in.vapor_kg_m3;
    air.inflows.push_back(f);
  }
  return air;
}

SurfaceTextureSetup make_surface_texture(const Scene& scene, std::size_t rigid_index, const TriangleMesh& mesh,
                                         AtlasMesh* atlas_out) {
  const RigidObject& rigid = scene.simulation.rigids[rigid_index];
  const TextureSettings& tex = *rigid.texture;
  const std::string key = scene.file.string() + ": simulation.rigids[" + std::to_string(rigid_index) + "].texture";
  AtlasMesh atlas;
  try {
    atlas = make_surface_atlas(mesh, tex.width, tex.height, rigid.mesh.string());
  } catch (const std::runtime_error& e) {
    throw SceneError(key + ": " + e.what());
  }
  AtlasRaster raster = rasterize_atlas(atlas, tex.width, tex.height);
  SurfaceTextureSetup s;
  s.texels = std::move(raster.texels);
  if (tex.max_mass_image.empty()) {
    set_constant_max_mass(s.texels, tex.max_mass_kg_m2);
  } else {
    try {
      set_max_mass_from_image(s.texels, tex.max_mass_image, tex.max_mass_image_scale_kg_m2);
    } catch (const std::runtime_error& e) {
      throw SceneError(key + ".max_mass_image: " + e.what());
    }
  }
  // Texel masses are 64-bit counts of a unit tied to the particle mass
  // (surface/texel_mass_units.h); say so when a texel's cap exceeds them.
  const double particle_mass = scene.simulation.liquid.rest_density_kg_m3 * std::pow(scene.simulation.particle_spacing_m, 3);
  const double limit = max_texel_mass_kg(particle_mass);
  for (float m : s.texels.max_mass)
    if (m > limit)
      throw SceneError(key + ": a texel may hold " + std::to_string(m) + " kg, more than the " + std::to_string(limit) +
                       " kg a texel can count at this particle mass; lower the maximum mass or raise the resolution");
  s.initial_mass_per_area = static_cast<float>(tex.initial_mass_kg_m2);
  s.initial_temperature = static_cast<float>(rigid.temperature_k);
  s.wetting_decay = static_cast<float>(tex.wetting_decay_s);
  if (atlas_out) *atlas_out = std::move(atlas);
  return s;
}

SimulationSetup make_simulation_setup(const Scene& scene) { return make_simulation_setup(scene, nullptr); }

SimulationSetup make_simulation_setup(const Scene& scene, std::vector<RigidAtlas>* atlases) {
  const SimulationSettings& s = scene.simulation;
  SimulationSetup setup;
  setup.domain_min = to_vec3(s.domain_min_m);
  setup.domain_max = to_vec3(s.domain_max_m);
  setup.leaving = s.domain_leaving == "remove" ? DomainLeaving::Remove : DomainLeaving::Stop;
  setup.gravity = to_vec3(s.gravity_m_s2);
  setup.particle_spacing = static_cast<float>(s.particle_spacing_m);
  setup.time_step.mode = s.cfl_time_step ? TimeStepMode::Cfl : TimeStepMode::Fixed;
  setup.time_step.max_step = static_cast<float>(s.time_step_s);
  setup.time_step.cfl_number = static_cast<float>(s.cfl_number);
  setup.pressure.method = s.pressure_solver.method == "dfsph" ? PressureSolverMethod::Dfsph : PressureSolverMethod::Pcisph;
  setup.pressure.max_density_error = static_cast<float>(s.pressure_solver.max_density_error);
  setup.pressure.max_divergence_error = static_cast<float>(s.pressure_solver.max_divergence_error);
  setup.pressure.min_iterations = s.pressure_solver.min_iterations;
  setup.pressure.max_iterations = s.pressure_solver.max_iterations;
  setup.pressure.warm_start = s.pressure_solver.warm_start;
  setup.settle.duration = static_cast<float>(s.settle.duration_s);
  setup.settle.damping = static_cast<float>(s.settle.damping_per_s);
  setup.max_speed = static_cast<float>(s.max_speed_m_s);
  setup.liquid.rest_density = static_cast<float>(s.liquid.rest_density_kg_m3);
  setup.liquid.xsph_epsilon = static_cast<float>(s.liquid.xsph_epsilon);
  setup.liquid.kinematic_viscosity = static_cast<float>(s.liquid.kinematic_viscosity_m2_s);
  setup.liquid.conductivity = static_cast<float>(s.liquid.conductivity_w_mk);
  setup.liquid.surface_tension = static_cast<float>(s.liquid.surface_tension);
  setup.liquid.specific_heat = static_cast<float>(s.liquid.specific_heat_j_kgk);
  setup.rigid.density = static_cast<float>(s.rigid_material.density_kg_m3);
  setup.rigid.conductivity = static_cast<float>(s.rigid_material.conductivity_w_mk);
  setup.rigid.specific_heat = static_cast<float>(s.rigid_material.specific_heat_j_kgk);
  setup.coupling.coefficients.a = s.coupling.evaporation_a;
  setup.coupling.coefficients.b = s.coupling.evaporation_b;
  setup.coupling.phase_change_time_scale = s.coupling.phase_change_time_scale;
  setup.coupling.heat_exchange = s.coupling.heat_exchange;
  setup.coupling.particle_evaporation = s.coupling.particle_evaporation;
  setup.coupling.texel_exchange = s.coupling.texel_exchange;
  setup.coupling.particle_emission = s.coupling.particle_emission;
  setup.coupling.latent_heat = s.coupling.latent_heat;
  setup.coupling.latent_heat_j_kg = static_cast<float>(s.coupling.latent_heat_j_kg);
  setup.coupling.path_force = s.coupling.path_force;
  setup.coupling.path_adhesion = static_cast<float>(s.coupling.path_adhesion);
  setup.coupling.air.density = static_cast<float>(s.coupling.air_density_kg_m3);
  setup.coupling.air.specific_heat = static_cast<float>(s.coupling.air_specific_heat_j_kgk);
  setup.coupling.air.conductivity = static_cast<float>(s.coupling.air_conductivity_w_mk);
  setup.liquid.boundary_friction = static_cast<float>(s.liquid.boundary_friction);
  setup.liquid.wall_shear = s.liquid.wall_shear == "spalding1961" ? WallShear::Spalding1961 : WallShear::NoSlip;
  setup.liquid.temperature = static_cast<float>(s.liquid.temperature_k);
  if (s.air) setup.air = make_air_settings(*s.air);
  for (const LiquidBlock& block : s.liquid_blocks) {
    std::vector<Vec3> points = fill_block(block, s.particle_spacing_m);
    setup.liquid_position.insert(setup.liquid_position.end(), points.begin(), points.end());
    setup.liquid_velocity.insert(setup.liquid_velocity.end(), points.size(), to_vec3(block.velocity_m_s));
  }
  for (std::size_t r = 0; r < s.rigids.size(); ++r) {
    const RigidObject& rigid = s.rigids[r];
    const std::string key = scene.file.string() + ": simulation.rigids[" + std::to_string(r) + "]";
    TriangleMesh mesh;
    try {
      mesh = load_triangle_mesh(rigid.mesh);
    } catch (const std::runtime_error& e) {
      throw SceneError(key + ".mesh: " + e.what());
    }
    check_inside_domain(mesh, s, key);
    std::vector<Vec3> samples = sample_surface(mesh.positions, mesh.triangles, setup.particle_spacing);
    if (rigid.texture) {
      AtlasMesh atlas;
      SurfaceTextureSetup surface = make_surface_texture(scene, r, mesh, atlases ? &atlas : nullptr);
      surface.rigid_first = setup.rigid_position.size();
      surface.rigid_count = samples.size();
      setup.surfaces.push_back(std::move(surface));
      if (atlases) atlases->push_back(RigidAtlas{rigid.name, std::move(atlas)});
    }
    setup.rigid_position.insert(setup.rigid_position.end(), samples.begin(), samples.end());
    setup.rigid_temperature.insert(setup.rigid_temperature.end(), samples.size(), static_cast<float>(rigid.temperature_k));
    setup.rigid_held.insert(setup.rigid_held.end(), samples.size(), rigid.hold_temperature ? 1 : 0);
    setup.rigid_adhesion.insert(setup.rigid_adhesion.end(), samples.size(), static_cast<float>(rigid.adhesion));
  }
  return setup;
}

}  // namespace dp::io
