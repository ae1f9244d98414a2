#include "scene.h"

#include <fstream>

namespace dp::io {

namespace {

double positive(JsonObject& o, const std::string& key, double value) {
  if (!(value > 0)) throw o.error(key, "expected a positive number, found " + std::to_string(value));
  return value;
}

double kelvin_from_celsius(JsonObject& o, const std::string& key, double celsius) {
  if (celsius < -kZeroCelsiusInKelvin) throw o.error(key, "temperature below absolute zero (" + std::to_string(celsius) + " °C)");
  return celsius_to_kelvin(celsius);
}

bool inside(const Vec3d& p, const Vec3d& lo, const Vec3d& hi) {
  for (int a = 0; a < 3; ++a)
    if (p[a] < lo[a] || p[a] > hi[a]) return false;
  return true;
}

LiquidSettings read_liquid(JsonObject o) {
  LiquidSettings l;
  l.rest_density_kg_m3 = positive(o, "rest_density_kg_m3", o.number("rest_density_kg_m3", l.rest_density_kg_m3));
  l.conductivity_w_mk = o.number("conductivity_w_mk", l.conductivity_w_mk);
  if (l.conductivity_w_mk < 0) throw o.error("conductivity_w_mk", "expected a non-negative number");
  l.specific_heat_j_kgk = positive(o, "specific_heat_j_kgk", o.number("specific_heat_j_kgk", l.specific_heat_j_kgk));
  l.xsph_epsilon = o.number("xsph_epsilon", l.xsph_epsilon);
  l.surface_tension = o.number("surface_tension", l.surface_tension);
  if (l.surface_tension < 0) throw o.error("surface_tension", "expected a non-negative number");
  l.boundary_friction = o.number("boundary_friction", l.boundary_friction);
  l.temperature_k = kelvin_from_celsius(o, "temperature_c", o.number("temperature_c", 20));
  // XSPH blends towards the neighbours' mean velocity: beyond 1 it overshoots.
  if (l.xsph_epsilon < 0 || l.xsph_epsilon > 1) throw o.error("xsph_epsilon", "expected a number in [0, 1]");
  if (l.boundary_friction < 0 || l.boundary_friction > 1) throw o.error("boundary_friction", "expected a number in [0, 1]");
  o.finish();
  return l;
}

SimulationSettings read_simulation(JsonObject o, const std::filesystem::path& scene_dir) {
  SimulationSettings s;
  JsonObject domain = o.object("domain");
  s.domain_min_m = domain.vec3("min_m");
  s.domain_max_m = domain.vec3("max_m");
  for (int a = 0; a < 3; ++a)
    if (!(s.domain_min_m[a] < s.domain_max_m[a])) throw domain.error("max_m", "every component must exceed min_m's");
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
    s.pressure_solver.max_density_error =
        positive(*p, "max_density_error", p->number("max_density_error", s.pressure_solver.max_density_error));
    s.pressure_solver.min_iterations = static_cast<int>(p->integer("min_iterations", s.pressure_solver.min_iterations));
    s.pressure_solver.max_iterations = static_cast<int>(p->integer("max_iterations", s.pressure_solver.max_iterations));
    if (s.pressure_solver.min_iterations < 1) throw p->error("min_iterations", "expected a positive integer");
    if (s.pressure_solver.max_iterations < s.pressure_solver.min_iterations)
      throw p->error("max_iterations", "expected at least min_iterations");
    p->finish();
  }

  for (JsonObject b : o.objects("liquid_blocks")) {
    LiquidBlock block;
    block.min_m = b.vec3("min_m");
    block.max_m = b.vec3("max_m");
    block.velocity_m_s = b.vec3("velocity_m_s", block.velocity_m_s);
    for (int a = 0; a < 3; ++a)
      if (!(block.min_m[a] < block.max_m[a])) throw b.error("max_m", "every component must exceed min_m's");
    if (!inside(block.min_m, s.domain_min_m, s.domain_max_m)) throw b.error("min_m", "outside the simulation domain");
    if (!inside(block.max_m, s.domain_min_m, s.domain_max_m)) throw b.error("max_m", "outside the simulation domain");
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
  o.finish();
  return s;
}

MeshSettings read_mesh(std::optional<JsonObject> o) {
  MeshSettings m;
  if (!o) return m;
  m.voxels_per_radius = positive(*o, "voxels_per_radius", o->number("voxels_per_radius", m.voxels_per_radius));
  m.kernel_radius_factor = positive(*o, "kernel_radius_factor", o->number("kernel_radius_factor", m.kernel_radius_factor));
  m.particle_radius_factor = positive(*o, "particle_radius_factor", o->number("particle_radius_factor", m.particle_radius_factor));
  o->finish();
  return m;
}

std::vector<std::string> rigid_names(const SimulationSettings& s) {
  std::vector<std::string> names;
  for (const RigidObject& rigid : s.rigids) names.push_back(rigid.name);
  return names;
}

}  // namespace

Scene load_scene(const std::filesystem::path& file) {
  Scene scene;
  scene.file = std::filesystem::absolute(file).lexically_normal();
  std::ifstream in(scene.file);
  if (!in) throw SceneError(file.string() + ": cannot open scene file");
  try {
    scene.document = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw SceneError(file.string() + ": not valid JSON: " + e.what());
  }
  JsonObject top(scene.document, "", file);
  scene.name = top.string("name", scene.file.stem().string());
  scene.simulation = read_simulation(top.object("simulation"), scene.file.parent_path());
  scene.mesh = read_mesh(top.optional_object("mesh"));
  scene.render = read_render_settings(top.object("render"), rigid_names(scene.simulation), scene.file.parent_path());
  top.finish();
  return scene;
}

}  // namespace dp::io
