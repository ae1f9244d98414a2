#include "render_settings.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace dp::io {

namespace {

using Rgb = std::array<double, 3>;

double positive_number(JsonObject& o, const std::string& key, double fallback) {
  const double value = o.number(key, fallback);
  if (!(value > 0)) throw o.error(key, "expected a positive number, found " + std::to_string(value));
  return value;
}

double number_in(JsonObject& o, const std::string& key, double fallback, double lo, double hi) {
  const double value = o.number(key, fallback);
  if (!(value >= lo && value <= hi))
    throw o.error(key, "expected a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], found " + std::to_string(value));
  return value;
}

Rgb non_negative_rgb(JsonObject& o, const std::string& key, Rgb fallback) {
  Rgb c = o.vec3(key, fallback);
  for (double v : c)
    if (!(v >= 0)) throw o.error(key, "expected non-negative colour components");
  return c;
}

MaterialType material_type(JsonObject& o) {
  const std::string type = o.string("type");
  if (type == "diffuse") return MaterialType::Diffuse;
  if (type == "dielectric") return MaterialType::Dielectric;
  if (type == "conductor") return MaterialType::Conductor;
  throw o.error("type", "expected one of diffuse, dielectric, conductor; found '" + type + "'");
}

Material read_material(JsonObject o) {
  Material m;
  m.type = material_type(o);
  // A conductor's albedo tints its Fresnel reflectance: untinted by default.
  if (m.type == MaterialType::Conductor) m.albedo = {1, 1, 1};
  m.albedo = non_negative_rgb(o, "albedo", m.albedo);
  for (double v : m.albedo)
    if (v > 1) throw o.error("albedo", "expected components in [0, 1]");
  m.ior = positive_number(o, "ior", m.ior);
  m.absorption_per_m = non_negative_rgb(o, "absorption_per_m", m.absorption_per_m);
  m.conductor_eta = non_negative_rgb(o, "eta_rgb", m.conductor_eta);
  m.conductor_k = non_negative_rgb(o, "k_rgb", m.conductor_k);
  m.roughness = number_in(o, "roughness", m.roughness, 0, 1);
  m.fogged_roughness = number_in(o, "fogged_roughness", m.roughness, 0, 1);
  m.wet_roughness = number_in(o, "wet_roughness", m.roughness, 0, 1);
  m.wet_darkening = number_in(o, "wet_darkening", m.wet_darkening, 0, 1);
  m.emission = non_negative_rgb(o, "emission_rgb", m.emission);
  o.finish();
  return m;
}

CameraSettings read_camera(JsonObject cam) {
  CameraSettings c;
  const std::string model = cam.string("model", "pinhole");
  if (model == "pinhole") c.model = CameraModel::Pinhole;
  else if (model == "thin_lens") c.model = CameraModel::ThinLens;
  else throw cam.error("model", "expected pinhole or thin_lens, found '" + model + "'");
  c.position_m = cam.vec3("position_m");
  c.look_at_m = cam.vec3("look_at_m");
  c.up = cam.vec3("up", c.up);
  c.fov_deg = cam.number("fov_deg", c.fov_deg);
  if (!(c.fov_deg > 0 && c.fov_deg < 180)) throw cam.error("fov_deg", "expected a number in (0, 180)");
  if (c.model == CameraModel::ThinLens) {
    c.aperture_radius_m = cam.number("aperture_radius_m");
    if (!(c.aperture_radius_m >= 0)) throw cam.error("aperture_radius_m", "expected a non-negative number");
    c.focus_distance_m = cam.number("focus_distance_m", 0);
    if (!(c.focus_distance_m >= 0)) throw cam.error("focus_distance_m", "expected a non-negative number (0: distance to look_at_m)");
  }
  cam.finish();
  return c;
}

FilterSettings read_filter(std::optional<JsonObject> o) {
  FilterSettings f;
  if (!o) return f;
  const std::string type = o->string("type", "gaussian");
  if (type == "box") f.type = FilterType::Box, f.radius_px = 0.5;
  else if (type == "tent") f.type = FilterType::Tent, f.radius_px = 1;
  else if (type == "gaussian") f.type = FilterType::Gaussian;
  else throw o->error("type", "expected box, tent or gaussian, found '" + type + "'");
  f.radius_px = positive_number(*o, "radius_px", f.radius_px);
  if (f.type == FilterType::Gaussian) f.sigma_px = positive_number(*o, "sigma_px", f.sigma_px);
  o->finish();
  return f;
}

EnvironmentSettings read_environment(std::optional<JsonObject> o, const std::filesystem::path& scene_dir) {
  EnvironmentSettings e;
  if (!o) return e;
  const std::string type = o->string("type", "sky");
  if (type == "sky") {
    e.type = EnvironmentType::Sky;
    e.zenith = non_negative_rgb(*o, "zenith_rgb", e.zenith);
    e.horizon = non_negative_rgb(*o, "horizon_rgb", e.horizon);
    e.ground = non_negative_rgb(*o, "ground_rgb", e.ground);
  } else if (type == "constant") {
    e.type = EnvironmentType::Constant;
    e.radiance = non_negative_rgb(*o, "radiance_rgb", e.radiance);
  } else if (type == "map") {
    e.type = EnvironmentType::Map;
    e.map = scene_dir / o->string("file");
    e.rotation_deg = o->number("rotation_deg", 0);
  } else {
    throw o->error("type", "expected sky, constant or map, found '" + type + "'");
  }
  e.intensity = o->number("intensity", 1);
  if (!(e.intensity >= 0)) throw o->error("intensity", "expected a non-negative number");
  o->finish();
  return e;
}

}  // namespace

AovSelection parse_aov_list(const std::string& text) {
  AovSelection a{false, false, false};
  if (text == "none") return a;
  std::stringstream list(text);
  std::string name;
  bool any = false;
  while (std::getline(list, name, ',')) {
    if (name == "albedo") a.albedo = true;
    else if (name == "normal") a.normal = true;
    else if (name == "depth") a.depth = true;
    else throw std::invalid_argument("expected a comma-separated list of albedo, normal, depth (or none), found '" + name + "' in '" + text + "'");
    any = true;
  }
  if (!any) throw std::invalid_argument("expected a comma-separated list of albedo, normal, depth (or none), found '" + text + "'");
  return a;
}

RenderSettings read_render_settings(JsonObject o, const std::vector<std::string>& rigid_names,
                                    const std::filesystem::path& scene_dir) {
  RenderSettings r;
  auto res = o.int2("resolution");
  if (res[0] <= 0 || res[1] <= 0) throw o.error("resolution", "expected two positive integers");
  r.width = static_cast<int>(res[0]);
  r.height = static_cast<int>(res[1]);
  r.spp = static_cast<int>(o.integer("spp", r.spp));
  if (r.spp <= 0) throw o.error("spp", "expected a positive integer");
  r.max_depth = static_cast<int>(o.integer("max_depth", r.max_depth));
  if (r.max_depth <= 0) throw o.error("max_depth", "expected a positive integer");
  std::int64_t seed = o.integer("seed", 1);
  if (seed < 0) throw o.error("seed", "expected a non-negative integer");
  r.seed = static_cast<std::uint64_t>(seed);
  const std::string sampler = o.string("sampler", "sobol");
  if (sampler == "sobol") r.sampler = SamplerType::Sobol;
  else if (sampler == "independent") r.sampler = SamplerType::Independent;
  else throw o.error("sampler", "expected sobol or independent, found '" + sampler + "'");
  r.exposure_stops = o.number("exposure_stops", 0);
  r.camera = read_camera(o.object("camera"));
  r.filter = read_filter(o.optional_object("filter"));
  r.environment = read_environment(o.optional_object("environment"), scene_dir);
  try {
    r.aovs = parse_aov_list(o.string("aovs", "albedo,normal,depth"));
  } catch (const std::invalid_argument& e) {
    throw o.error("aovs", e.what());
  }
  r.wet_paths = o.boolean("wet_paths", r.wet_paths);

  for (auto& [name, m] : o.entries("materials")) r.materials[name] = read_material(m);
  r.liquid_material = o.string("liquid_material", r.liquid_material);
  if (!r.materials.count(r.liquid_material)) throw o.error("liquid_material", "names no entry of render.materials ('" + r.liquid_material + "')");

  // Every rigid of the simulation appears in render.objects with a material.
  for (auto& [name, obj] : o.entries("objects")) {
    if (std::find(rigid_names.begin(), rigid_names.end(), name) == rigid_names.end())
      throw obj.error("material", "render.objects." + name + " names no rigid of simulation.rigids");
    std::string material = obj.string("material");
    if (!r.materials.count(material)) throw obj.error("material", "names no entry of render.materials ('" + material + "')");
    obj.finish();
    r.rigid_material[name] = material;
  }
  for (const std::string& rigid : rigid_names)
    if (!r.rigid_material.count(rigid)) throw o.error("objects", "has no entry for rigid '" + rigid + "'");
  o.finish();
  return r;
}

}  // namespace dp::io
