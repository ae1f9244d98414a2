#include "scene.h"
#include "scene_presets.h"

#include <cctype>
#include <cmath>
#include <fstream>

#include "air/air_cell_size.h"
#include "air/vapor_pressure.h"
#include "simulation.h"

namespace dp::io {

namespace {

double positive(JsonObject& o, const std::string& key, double value) {
  if (!(value > 0)) throw o.error(key, "expected a positive number, found " + std::to_string(value));
  return value;
}

double kelvin_from_celsius(JsonObject& o, const std::string& key, double celsius) {
  if (!(celsius >= -kZeroCelsiusInKelvin))
    throw o.error(key, "temperature below absolute zero: expected at least -273.15 °C, found " + std::to_string(celsius) + " °C");
  return celsius_to_kelvin(celsius);
}

std::string format_vec3(const Vec3d& v) {
  return "(" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) + ")";
}

// "a point inside [lo, hi] (what), found p": the expected-versus-found half of an out-of-domain error.
std::string outside_message(const Vec3d& p, const Vec3d& lo, const Vec3d& hi, const std::string& domain) {
  return "outside the " + domain + ": expected a point in " + format_vec3(lo) + " .. " + format_vec3(hi) + " m, found " +
         format_vec3(p) + " m";
}

bool inside(const Vec3d& p, const Vec3d& lo, const Vec3d& hi) {
  for (int a = 0; a < 3; ++a)
    if (p[a] < lo[a] || p[a] > hi[a]) return false;
  return true;
}

double non_negative(JsonObject& o, const std::string& key, double value) {
  if (!(value >= 0)) throw o.error(key, "expected a non-negative number, found " + std::to_string(value));
  return value;
}

// rigids[i].texture: the rigid's surface textures (paper Sec. 4.3).
TextureSettings read_texture(JsonObject o, const std::filesystem::path& scene_dir) {
  TextureSettings t;
  // 16384^2 texels of four channels is already 4 GiB per frame.
  constexpr std::int64_t kMaxResolution = 16384;
  const auto res = o.int2("resolution");
  if (res[0] <= 0 || res[1] <= 0 || res[0] > kMaxResolution || res[1] > kMaxResolution)
    throw o.error("resolution", "expected two integers in [1, " + std::to_string(kMaxResolution) + "] (texels), found [" +
                                    std::to_string(res[0]) + ", " + std::to_string(res[1]) + "]");
  t.width = static_cast<int>(res[0]);
  t.height = static_cast<int>(res[1]);
  if (o.has("max_mass_image")) {
    if (o.has("max_mass_kg_m2")) throw o.error("max_mass_kg_m2", "give either max_mass_kg_m2 or max_mass_image, not both");
    std::filesystem::path image = o.string("max_mass_image");
    t.max_mass_image = image.is_absolute() ? image : (scene_dir / image).lexically_normal();
    if (!std::ifstream(t.max_mass_image)) throw o.error("max_mass_image", "cannot read image file " + t.max_mass_image.string());
    t.max_mass_image_scale_kg_m2 =
        non_negative(o, "max_mass_image_scale_kg_m2", o.number("max_mass_image_scale_kg_m2", t.max_mass_image_scale_kg_m2));
  } else {
    if (o.has("max_mass_image_scale_kg_m2")) throw o.error("max_mass_image_scale_kg_m2", "only allowed with max_mass_image");
    t.max_mass_kg_m2 = non_negative(o, "max_mass_kg_m2", o.number("max_mass_kg_m2", t.max_mass_kg_m2));
  }
  t.initial_mass_kg_m2 = non_negative(o, "initial_mass_kg_m2", o.number("initial_mass_kg_m2", t.initial_mass_kg_m2));
  t.wetting_decay_s = non_negative(o, "wetting_decay_s", o.number("wetting_decay_s", t.wetting_decay_s));
  o.finish();
  return t;
}

LiquidSettings read_liquid(JsonObject o) {
  LiquidSettings l;
  l.rest_density_kg_m3 = positive(o, "rest_density_kg_m3", o.number("rest_density_kg_m3", l.rest_density_kg_m3));
  l.conductivity_w_mk = o.number("conductivity_w_mk", l.conductivity_w_mk);
  if (l.conductivity_w_mk < 0) throw o.error("conductivity_w_mk", "expected a non-negative number");
  l.specific_heat_j_kgk = positive(o, "specific_heat_j_kgk", o.number("specific_heat_j_kgk", l.specific_heat_j_kgk));
  l.xsph_epsilon = o.number("xsph_epsilon", l.xsph_epsilon);
  l.kinematic_viscosity_m2_s =
      non_negative(o, "kinematic_viscosity_m2_s", o.number("kinematic_viscosity_m2_s", l.kinematic_viscosity_m2_s));
  l.surface_tension = o.number("surface_tension", l.surface_tension);
  if (l.surface_tension < 0) throw o.error("surface_tension", "expected a non-negative number");
  l.boundary_friction = o.number("boundary_friction", l.boundary_friction);
  l.wall_shear = o.string("wall_shear", l.wall_shear);
  if (l.wall_shear != "no_slip" && l.wall_shear != "spalding1961")
    throw o.error("wall_shear", "expected \"no_slip\" or \"spalding1961\", found \"" + l.wall_shear + "\"");
  l.temperature_k = kelvin_from_celsius(o, "temperature_c", o.number("temperature_c", 20));
  // XSPH blends towards the neighbours' mean velocity: beyond 1 it overshoots.
  if (l.xsph_epsilon < 0 || l.xsph_epsilon > 1) throw o.error("xsph_epsilon", "expected a number in [0, 1]");
  if (l.boundary_friction < 0 || l.boundary_friction > 1) throw o.error("boundary_friction", "expected a number in [0, 1]");
  o.finish();
  return l;
}

// A vapor density given either as relative_humidity (of saturation at
// `kelvin`, Eq. 10-11) or as vapor_kg_m3; not both.
double read_vapor(JsonObject& o, double kelvin, double fallback) {
  const bool rh = o.has("relative_humidity"), density = o.has("vapor_kg_m3");
  if (rh && density) throw o.error("vapor_kg_m3", "give relative_humidity or vapor_kg_m3, not both");
  if (density) {
    const double v = o.number("vapor_kg_m3");
    if (v < 0) throw o.error("vapor_kg_m3", "expected a non-negative number, found " + std::to_string(v));
    return v;
  }
  if (!rh) return fallback;
  const double r = o.number("relative_humidity");
  if (!(r >= 0 && r <= 1)) throw o.error("relative_humidity", "expected a number in [0, 1], found " + std::to_string(r));
  return vapor_density_at_humidity(r, kelvin);
}

AirInflowSettings read_air_inflow(JsonObject o, const AirSectionSettings& air) {
  AirInflowSettings in;
  const std::string shape = o.string("shape");
  if (shape == "box") {
    in.min_m = o.vec3("min_m");
    in.max_m = o.vec3("max_m");
    for (int a = 0; a < 3; ++a)
      if (!(in.min_m[a] < in.max_m[a])) throw o.error("max_m", "every component must exceed min_m's");
    // A box may reach past the domain (one covering a face), but must cover some of it.
    for (int a = 0; a < 3; ++a)
      if (in.max_m[a] <= air.domain_min_m[a] || in.min_m[a] >= air.domain_max_m[a])
        throw o.error("min_m", "the box " + format_vec3(in.min_m) + " .. " + format_vec3(in.max_m) +
                                   " m lies outside the air domain " + format_vec3(air.domain_min_m) + " .. " +
                                   format_vec3(air.domain_max_m) + " m (simulation.air.domain or simulation.domain)");
  } else if (shape == "disc") {
    in.disc = true;
    in.center_m = o.vec3("center_m");
    in.normal = o.vec3("normal");
    const double n = std::sqrt(in.normal[0] * in.normal[0] + in.normal[1] * in.normal[1] + in.normal[2] * in.normal[2]);
    if (!(n > 0)) throw o.error("normal", "expected a non-zero vector");
    for (double& c : in.normal) c /= n;
    if (!inside(in.center_m, air.domain_min_m, air.domain_max_m))
      throw o.error("center_m", outside_message(in.center_m, air.domain_min_m, air.domain_max_m,
                                                "air domain (simulation.air.domain or simulation.domain)"));
    in.radius_m = positive(o, "radius_m", o.number("radius_m"));
    in.thickness_m = o.number("thickness_m", 0);
    if (in.thickness_m < 0) throw o.error("thickness_m", "expected a non-negative number");
  } else {
    throw o.error("shape", "expected \"box\" or \"disc\", found \"" + shape + "\"");
  }
  in.velocity_m_s = o.vec3("velocity_m_s", in.velocity_m_s);
  in.temperature_k = kelvin_from_celsius(o, "temperature_c", o.number("temperature_c", air.temperature_k - kZeroCelsiusInKelvin));
  in.vapor_kg_m3 = read_vapor(o, in.temperature_k, air.vapor_kg_m3);
  o.finish();
  return in;
}

CouplingSectionSettings read_coupling(JsonObject o) {
  CouplingSectionSettings c;
  c.evaporation_a = o.number("evaporation_a_kg_m2_s_pa", c.evaporation_a);
  if (!(c.evaporation_a >= 0)) throw o.error("evaporation_a_kg_m2_s_pa", "expected a non-negative number");
  c.evaporation_b = o.number("evaporation_b_kg_m3_pa", c.evaporation_b);
  if (!(c.evaporation_b >= 0)) throw o.error("evaporation_b_kg_m3_pa", "expected a non-negative number");
  c.phase_change_time_scale = positive(o, "phase_change_time_scale", o.number("phase_change_time_scale", c.phase_change_time_scale));
  c.heat_exchange = o.boolean("heat_exchange", c.heat_exchange);
  c.particle_evaporation = o.boolean("particle_evaporation", c.particle_evaporation);
  c.texel_exchange = o.boolean("texel_exchange", c.texel_exchange);
  c.particle_emission = o.boolean("particle_emission", c.particle_emission);
  c.latent_heat = o.boolean("latent_heat", c.latent_heat);
  c.latent_heat_j_kg = positive(o, "latent_heat_j_kg", o.number("latent_heat_j_kg", c.latent_heat_j_kg));
  c.path_force = o.boolean("path_force", c.path_force);
  c.path_adhesion = o.number("path_adhesion", c.path_adhesion);
  if (!(c.path_adhesion >= 0)) throw o.error("path_adhesion", "expected a non-negative number");
  c.air_density_kg_m3 = positive(o, "air_density_kg_m3", o.number("air_density_kg_m3", c.air_density_kg_m3));
  c.air_specific_heat_j_kgk = positive(o, "air_specific_heat_j_kgk", o.number("air_specific_heat_j_kgk", c.air_specific_heat_j_kgk));
  c.air_conductivity_w_mk = o.number("air_conductivity_w_mk", c.air_conductivity_w_mk);
  if (!(c.air_conductivity_w_mk >= 0)) throw o.error("air_conductivity_w_mk", "expected a non-negative number");
  o.finish();
  return c;
}

AirSectionSettings read_air(JsonObject o, const SimulationSettings& sim) {
  AirSectionSettings a;
  a.resolution = static_cast<int>(o.integer("resolution", a.resolution));
  if (a.resolution < 4) throw o.error("resolution", "expected an integer of at least 4, found " + std::to_string(a.resolution));
  a.domain_min_m = sim.domain_min_m;
  a.domain_max_m = sim.domain_max_m;
  if (auto d = o.optional_object("domain")) {
    a.domain_min_m = d->vec3("min_m");
    a.domain_max_m = d->vec3("max_m");
    for (int i = 0; i < 3; ++i)
      if (!(a.domain_min_m[i] < a.domain_max_m[i])) throw d->error("max_m", "every component must exceed min_m's");
    d->finish();
  }
  a.temperature_k = kelvin_from_celsius(o, "temperature_c", o.number("temperature_c", 20));
  a.vapor_kg_m3 = read_vapor(o, a.temperature_k, vapor_density_at_humidity(0.5, a.temperature_k));
  a.buoyancy_alpha = o.number("buoyancy_alpha", a.buoyancy_alpha);
  a.buoyancy_beta = o.number("buoyancy_beta", a.buoyancy_beta);
  a.vorticity_epsilon = o.number("vorticity_epsilon", a.vorticity_epsilon);
  if (a.vorticity_epsilon < 0) throw o.error("vorticity_epsilon", "expected a non-negative number");
  a.vapor_diffusivity_m2_s = o.number("vapor_diffusivity_m2_s", a.vapor_diffusivity_m2_s);
  if (a.vapor_diffusivity_m2_s < 0) throw o.error("vapor_diffusivity_m2_s", "expected a non-negative number");
  a.heat_diffusivity_m2_s = o.number("heat_diffusivity_m2_s", a.heat_diffusivity_m2_s);
  if (a.heat_diffusivity_m2_s < 0) throw o.error("heat_diffusivity_m2_s", "expected a non-negative number");
  const std::string advection = o.string("advection", "semi_lagrangian");
  if (advection != "semi_lagrangian" && advection != "maccormack")
    throw o.error("advection", "expected \"semi_lagrangian\" or \"maccormack\", found \"" + advection + "\"");
  a.maccormack = advection == "maccormack";
  if (auto b = o.optional_object("boundary")) {
    const char* names[6] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
    for (int f = 0; f < 6; ++f) {
      const std::string v = b->string(names[f], "closed");
      if (v != "closed" && v != "open") throw b->error(names[f], "expected \"closed\" or \"open\", found \"" + v + "\"");
      a.open_face[f] = v == "open";
    }
    b->finish();
  }
  if (o.has("inflows"))
    for (JsonObject in : o.objects("inflows")) a.inflows.push_back(read_air_inflow(in, a));
  if (a.inflows.size() > 255) throw o.error("inflows", "at most 255 inflows");
  bool any_open = false, blowing = false;
  for (bool f : a.open_face) any_open = any_open || f;
  for (const auto& in : a.inflows) blowing = blowing || in.velocity_m_s != Vec3d{0, 0, 0};
  if (blowing && !any_open)
    throw o.error("inflows", "blow air into a closed domain; open at least one face in simulation.air.boundary");
  if (auto p = o.optional_object("projection")) {
    a.projection_tolerance = positive(*p, "tolerance", p->number("tolerance", a.projection_tolerance));
    a.projection_max_iterations = static_cast<int>(p->integer("max_iterations", a.projection_max_iterations));
    if (a.projection_max_iterations < 1) throw p->error("max_iterations", "expected a positive integer");
    p->finish();
  }
  o.finish();
  return a;
}

// The shape of a liquid block; its bounding box goes to min_m/max_m.
LiquidBlock read_liquid_region(JsonObject& b) {
  LiquidBlock block;
  const std::string shape = b.string("shape", "box");
  if (shape == "box") {
    block.min_m = b.vec3("min_m");
    block.max_m = b.vec3("max_m");
    return block;
  }
  if (shape != "sphere" && shape != "cylinder")
    throw b.error("shape", "expected \"box\", \"sphere\" or \"cylinder\", found \"" + shape + "\"");
  block.shape = shape == "sphere" ? LiquidShape::Sphere : LiquidShape::Cylinder;
  block.center_m = b.vec3("center_m");
  block.radius_m = positive(b, "radius_m", b.number("radius_m"));
  const double r = block.radius_m;
  const Vec3d& c = block.center_m;
  if (block.shape == LiquidShape::Sphere) {
    block.min_m = {c[0] - r, c[1] - r, c[2] - r};
    block.max_m = {c[0] + r, c[1] + r, c[2] + r};
  } else {
    block.height_m = positive(b, "height_m", b.number("height_m"));
    block.min_m = {c[0] - r, c[1], c[2] - r};
    block.max_m = {c[0] + r, c[1] + block.height_m, c[2] + r};
  }
  return block;
}

SimulationSettings read_simulation(JsonObject o, const std::filesystem::path& scene_dir) {
  SimulationSettings s;
  JsonObject domain = o.object("domain");
  s.domain_min_m = domain.vec3("min_m");
  s.domain_max_m = domain.vec3("max_m");
  for (int a = 0; a < 3; ++a)
    if (!(s.domain_min_m[a] < s.domain_max_m[a])) throw domain.error("max_m", "every component must exceed min_m's");
  s.domain_leaving = domain.string("leaving", s.domain_leaving);
  if (s.domain_leaving != "stop" && s.domain_leaving != "remove")
    throw domain.error("leaving", "expected \"stop\" or \"remove\", found \"" + s.domain_leaving + "\"");
  domain.finish();

  s.gravity_m_s2 = o.vec3("gravity_m_s2", s.gravity_m_s2);
  s.particle_spacing_m = positive(o, "particle_spacing_m", o.number("particle_spacing_m"));
  s.time_step_s = positive(o, "time_step_s", o.number("time_step_s"));
  std::string mode = o.string("time_step_mode", "cfl");
  if (mode != "cfl" && mode != "fixed") throw o.error("time_step_mode", "expected \"cfl\" or \"fixed\", found \"" + mode + "\"");
  s.cfl_time_step = mode == "cfl";
  s.cfl_number = o.number("cfl_number", s.cfl_number);
  if (!(s.cfl_number > 0 && s.cfl_number <= 1)) throw o.error("cfl_number", "expected a number in (0, 1]");
  s.duration_s = positive(o, "duration_s", o.number("duration_s"));
  s.frame_rate_hz = positive(o, "frame_rate_hz", o.number("frame_rate_hz", s.frame_rate_hz));
  s.max_speed_m_s = positive(o, "max_speed_m_s", o.number("max_speed_m_s", s.max_speed_m_s));
  s.liquid = read_liquid(o.object("liquid"));
  if (auto p = o.optional_object("pressure_solver")) {
    s.pressure_solver.method = p->string("method", s.pressure_solver.method);
    if (s.pressure_solver.method != "pcisph" && s.pressure_solver.method != "dfsph")
      throw p->error("method", "expected \"pcisph\" or \"dfsph\", found \"" + s.pressure_solver.method + "\"");
    s.pressure_solver.max_divergence_error =
        positive(*p, "max_divergence_error", p->number("max_divergence_error", s.pressure_solver.max_divergence_error));
    s.pressure_solver.max_density_error =
        positive(*p, "max_density_error", p->number("max_density_error", s.pressure_solver.max_density_error));
    s.pressure_solver.min_iterations = static_cast<int>(p->integer("min_iterations", s.pressure_solver.min_iterations));
    s.pressure_solver.max_iterations = static_cast<int>(p->integer("max_iterations", s.pressure_solver.max_iterations));
    s.pressure_solver.warm_start = p->boolean("warm_start", s.pressure_solver.warm_start);
    if (s.pressure_solver.warm_start && s.pressure_solver.method == "dfsph")
      throw p->error("warm_start", "a warm start is PCISPH's; DFSPH solves from zero (remove warm_start or use method \"pcisph\")");
    if (s.pressure_solver.min_iterations < 1) throw p->error("min_iterations", "expected a positive integer");
    if (s.pressure_solver.max_iterations < s.pressure_solver.min_iterations)
      throw p->error("max_iterations", "expected at least min_iterations");
    p->finish();
  }
  if (auto p = o.optional_object("settle")) {
    s.settle.duration_s = non_negative(*p, "duration_s", p->number("duration_s", s.settle.duration_s));
    s.settle.damping_per_s = positive(*p, "damping_per_s", p->number("damping_per_s", s.settle.damping_per_s));
    p->finish();
  }

  for (JsonObject b : o.objects("liquid_blocks")) {
    LiquidBlock block = read_liquid_region(b);
    block.velocity_m_s = b.vec3("velocity_m_s", block.velocity_m_s);
    for (int a = 0; a < 3; ++a)
      if (!(block.min_m[a] < block.max_m[a])) throw b.error("max_m", "every component must exceed min_m's");
    // Spheres and cylinders are checked by their bounding box, reported under their own keys.
    const bool box = block.shape == LiquidShape::Box;
    if (!inside(block.min_m, s.domain_min_m, s.domain_max_m))
      throw b.error(box ? "min_m" : "center_m", (box ? "" : "the shape's lowest corner is ") +
                                                     outside_message(block.min_m, s.domain_min_m, s.domain_max_m, "simulation domain"));
    if (!inside(block.max_m, s.domain_min_m, s.domain_max_m))
      throw b.error(box ? "max_m" : "radius_m", (box ? "" : "the shape's highest corner is ") +
                                                     outside_message(block.max_m, s.domain_min_m, s.domain_max_m, "simulation domain"));
    b.finish();
    s.liquid_blocks.push_back(block);
  }

  for (JsonObject r : o.objects("rigids")) {
    RigidObject rigid;
    rigid.name = r.string("name");
    if (rigid.name.empty() || rigid.name == "liquid") throw r.error("name", "expected a non-empty name other than 'liquid'");
    for (const auto& other : s.rigids)
      if (other.name == rigid.name) throw r.error("name", "duplicate rigid name '" + rigid.name + "'");
    std::filesystem::path mesh = r.string("mesh");
    rigid.mesh = mesh.is_absolute() ? mesh : (scene_dir / mesh).lexically_normal();
    if (!std::ifstream(rigid.mesh)) throw r.error("mesh", "cannot read mesh file " + rigid.mesh.string());
    rigid.temperature_k = kelvin_from_celsius(r, "temperature_c", r.number("temperature_c", 20));
    rigid.hold_temperature = r.boolean("hold_temperature", false);
    rigid.adhesion = r.number("adhesion", 0);
    if (rigid.adhesion < 0) throw r.error("adhesion", "expected a non-negative number");
    if (auto texture = r.optional_object("texture")) {
      rigid.texture = read_texture(*texture, scene_dir);
      // The name becomes part of file names (rigid_NAME.ply, surface_NAME.%04d.exr).
      for (char c : rigid.name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-')
          throw r.error("name", "a textured rigid's name may hold only letters, digits, '_' and '-' (it names its files); found '" +
                                    rigid.name + "'");
    }
    r.finish();
    s.rigids.push_back(rigid);
  }
  if (auto m = o.optional_object("rigid_material")) {
    s.rigid_material.density_kg_m3 = positive(*m, "density_kg_m3", m->number("density_kg_m3", s.rigid_material.density_kg_m3));
    s.rigid_material.conductivity_w_mk = m->number("conductivity_w_mk", s.rigid_material.conductivity_w_mk);
    if (s.rigid_material.conductivity_w_mk < 0) throw m->error("conductivity_w_mk", "expected a non-negative number");
    s.rigid_material.specific_heat_j_kgk =
        positive(*m, "specific_heat_j_kgk", m->number("specific_heat_j_kgk", s.rigid_material.specific_heat_j_kgk));
    m->finish();
  }
  if (auto c = o.optional_object("coupling")) s.coupling = read_coupling(*c);
  if (auto air = o.optional_object("air")) {
    s.air = read_air(*air, s);
    // The core's check, reported against the scene's key.
    SimulationSetup probe;
    probe.particle_spacing = static_cast<float>(s.particle_spacing_m);
    probe.air = AirSettings{};
    probe.air->domain_min = Vec3{static_cast<float>(s.air->domain_min_m[0]), static_cast<float>(s.air->domain_min_m[1]),
                                 static_cast<float>(s.air->domain_min_m[2])};
    probe.air->domain_max = Vec3{static_cast<float>(s.air->domain_max_m[0]), static_cast<float>(s.air->domain_max_m[1]),
                                 static_cast<float>(s.air->domain_max_m[2])};
    probe.air->resolution = s.air->resolution;
    try {
      check_air_cell_size(probe);
    } catch (const std::invalid_argument& e) {
      throw air->error("resolution", e.what());
    }
  }
  o.finish();
  return s;
}

// A contact angle strictly between 0 and 180 degrees: at either end the
// Deserno meniscus (paper Eq. 20) degenerates.
double contact_angle(JsonObject& o, const std::string& key, double fallback) {
  const double deg = o.number(key, fallback);
  if (!(deg > 0 && deg < 180)) throw o.error(key, "expected an angle in (0, 180) degrees, found " + std::to_string(deg));
  return deg;
}


MeshSettings read_mesh(std::optional<JsonObject> o, const SimulationSettings& sim) {
  MeshSettings m;
  if (!o) return m;
  m.voxels_per_radius = positive(*o, "voxels_per_radius", o->number("voxels_per_radius", m.voxels_per_radius));
  m.kernel_radius_factor = positive(*o, "kernel_radius_factor", o->number("kernel_radius_factor", m.kernel_radius_factor));
  m.particle_radius_factor = positive(*o, "particle_radius_factor", o->number("particle_radius_factor", m.particle_radius_factor));
  m.correction = o->boolean("correction", m.correction);
  m.contact_angle_deg = contact_angle(*o, "contact_angle_deg", m.contact_angle_deg);
  m.advancing_deg = non_negative(*o, "advancing_deg", o->number("advancing_deg", m.advancing_deg));
  m.receding_deg = non_negative(*o, "receding_deg", o->number("receding_deg", m.receding_deg));
  m.correction_reach_factor =
      positive(*o, "correction_reach_factor", o->number("correction_reach_factor", m.correction_reach_factor));
  m.level_set = o->boolean("level_set", m.level_set);
  if (o->has("rigids"))
    for (auto& [name, r] : o->entries("rigids")) {
      bool known = false;
      for (const RigidObject& rigid : sim.rigids) known = known || rigid.name == name;
      if (!known) throw o->error("rigids", "names rigid '" + name + "', which simulation.rigids does not have");
      m.rigid_contact_angle_deg[name] = contact_angle(r, "contact_angle_deg", m.contact_angle_deg);
      r.finish();
    }
  o->finish();
  return m;
}

std::vector<std::string> rigid_names(const SimulationSettings& s) {
  std::vector<std::string> names;
  for (const RigidObject& rigid : s.rigids) names.push_back(rigid.name);
  return names;
}

void read_sections(Scene& scene, const std::filesystem::path& file) {
  JsonObject top(scene.document, "", file);
  scene.name = top.string("name", scene.file.stem().string());
  scene.simulation = read_simulation(top.object("simulation"), scene.file.parent_path());
  scene.mesh = read_mesh(top.optional_object("mesh"), scene.simulation);
  scene.render = read_render_settings(top.object("render"), rigid_names(scene.simulation), scene.file.parent_path());
  top.finish();
}

}  // namespace

Scene load_scene(const std::filesystem::path& file, const std::string& preset) {
  Scene scene;
  scene.file = std::filesystem::absolute(file).lexically_normal();
  std::ifstream in(scene.file);
  if (!in) throw SceneError(file.string() + ": cannot open scene file");
  try {
    scene.document = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {  // parse errors, and numbers beyond double (1e400)
    throw SceneError(file.string() + ": not valid JSON: " + e.what());
  }
  scene.document = apply_preset(scene.document, preset, file);
  scene.preset = preset;
  try {
    read_sections(scene, file);
  } catch (const SceneError& e) {
    // The key is in the patched document: say which patch made it.
    if (preset.empty()) throw;
    throw SceneError(std::string(e.what()) + " (with preset '" + preset + "')");
  }
  return scene;
}

}  // namespace dp::io
