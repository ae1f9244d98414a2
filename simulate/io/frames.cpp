#include "frames.h"

#include <cstdio>
#include <fstream>

#include "atomic_file.h"
#include "ply.h"

namespace dp::io {

namespace {
constexpr const char* kManifestName = "manifest.json";
constexpr int kManifestVersion = 1;

template <class F>
std::vector<double> column(std::size_t n, F f) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = f(i);
  return v;
}
}  // namespace

std::string frame_file_name(const std::string& kind, int frame, const std::string& extension) {
  char number[16];
  std::snprintf(number, sizeof number, "%04d", frame);
  return kind + "." + number + "." + extension;
}

void write_particle_frame(const std::filesystem::path& file, const ParticleSnapshot& p, float particle_radius,
                          const std::string& comment) {
  PlyData ply;
  ply.comments.push_back(comment);
  const std::size_t n = p.size();
  ply.vertex_count = n;
  ply.add("x", PlyType::Float32, column(n, [&](std::size_t i) { return p.position[i].x; }));
  ply.add("y", PlyType::Float32, column(n, [&](std::size_t i) { return p.position[i].y; }));
  ply.add("z", PlyType::Float32, column(n, [&](std::size_t i) { return p.position[i].z; }));
  ply.add("vx", PlyType::Float32, column(n, [&](std::size_t i) { return p.velocity[i].x; }));
  ply.add("vy", PlyType::Float32, column(n, [&](std::size_t i) { return p.velocity[i].y; }));
  ply.add("vz", PlyType::Float32, column(n, [&](std::size_t i) { return p.velocity[i].z; }));
  ply.add("weight", PlyType::Float32, column(n, [&](std::size_t i) { return p.weight[i]; }));
  ply.add("radius", PlyType::Float32, column(n, [&](std::size_t i) { return particle_radius_of(particle_radius, p.weight[i]); }));
  ply.add("temperature", PlyType::Float32, column(n, [&](std::size_t i) { return p.temperature[i]; }));
  ply.add("density", PlyType::Float32, column(n, [&](std::size_t i) { return p.density[i]; }));
  ply.add("pressure", PlyType::Float32, column(n, [&](std::size_t i) { return p.pressure[i]; }));
  ply.add("surface_area", PlyType::Float32, column(n, [&](std::size_t i) { return p.surface_area[i]; }));
  ply.add("id", PlyType::UInt32, column(n, [&](std::size_t i) { return p.id[i]; }));
  write_ply(file, ply);
}

void write_rigid_particles(const std::filesystem::path& file, const std::vector<Vec3>& position,
                           const std::vector<float>& volume, const std::vector<float>& temperature,
                           const std::string& comment) {
  PlyData ply;
  ply.comments.push_back(comment);
  const std::size_t n = position.size();
  ply.vertex_count = n;
  ply.add("x", PlyType::Float32, column(n, [&](std::size_t i) { return position[i].x; }));
  ply.add("y", PlyType::Float32, column(n, [&](std::size_t i) { return position[i].y; }));
  ply.add("z", PlyType::Float32, column(n, [&](std::size_t i) { return position[i].z; }));
  ply.add("volume", PlyType::Float32, column(n, [&](std::size_t i) { return volume[i]; }));
  ply.add("temperature", PlyType::Float32, column(n, [&](std::size_t i) { return temperature[i]; }));
  write_ply(file, ply);
}

void write_manifest(const std::filesystem::path& frames_dir, const FramesManifest& m) {
  nlohmann::json j = m.extra;
  j["format"] = "dewpoint-frames";
  j["format_version"] = kManifestVersion;
  j["scene_file"] = m.scene_file.string();
  j["scene_name"] = m.scene_name;
  j["particle_spacing_m"] = m.particle_spacing_m;
  j["particle_radius_m"] = m.particle_radius_m;
  j["rigid_particles"] = m.rigid_particles_file;
  j["rigids"] = nlohmann::json::array();
  for (const auto& r : m.rigids)
    j["rigids"].push_back({{"name", r.name}, {"mesh", r.mesh_file}, {"texture_resolution", r.texture_resolution}});
  j["frames"] = nlohmann::json::array();
  for (const auto& f : m.frames) {
    nlohmann::json entry = {{"index", f.index},
                            {"time_s", f.time_s},
                            {"step", f.step},
                            {"liquid_particles", f.liquid_particles},
                            {"files", {{"particles", f.particles_file}}}};
    if (!f.surface_files.empty()) entry["files"]["surfaces"] = f.surface_files;
    if (!f.air_file.empty()) entry["files"]["air"] = f.air_file;
    if (!f.air_vapor.is_null()) entry["air_vapor"] = f.air_vapor;
    if (!f.water.is_null()) entry["water"] = f.water;
    j["frames"].push_back(entry);
  }
  write_atomically(frames_dir / kManifestName, [&](std::ostream& out) { out << j.dump(2) << "\n"; });
}

FramesManifest read_manifest(const std::filesystem::path& frames_dir) {
  const std::filesystem::path file = frames_dir / kManifestName;
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open frame manifest (is " + frames_dir.string() + " a dewpoint-simulate frames folder?)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not valid JSON: " + e.what());
  }
  auto need = [&](const nlohmann::json& o, const char* key, const std::string& where) -> const nlohmann::json& {
    if (!o.is_object() || !o.contains(key)) throw std::runtime_error(file.string() + ": " + where + key + ": missing");
    return o[key];
  };
  // Frame files are plain names in the frames folder: a manifest must not
  // send a reader elsewhere.
  auto file_name = [&](const nlohmann::json& value, const std::string& key) {
    const std::string name = value.get<std::string>();
    if (name.empty() || name == "." || name == ".." || name.find_first_of("/\\") != std::string::npos)
      throw std::runtime_error(file.string() + ": " + key + ": expected a file name in the frames folder, found \"" + name + "\"");
    return name;
  };
  try {
    if (need(j, "format", "") != "dewpoint-frames") throw std::runtime_error(file.string() + ": format: expected \"dewpoint-frames\"");
    if (need(j, "format_version", "").get<int>() != kManifestVersion)
      throw std::runtime_error(file.string() + ": format_version: expected " + std::to_string(kManifestVersion));
    FramesManifest m;
    m.scene_file = need(j, "scene_file", "").get<std::string>();
    m.scene_name = need(j, "scene_name", "").get<std::string>();
    m.particle_spacing_m = need(j, "particle_spacing_m", "").get<double>();
    m.particle_radius_m = need(j, "particle_radius_m", "").get<double>();
    m.rigid_particles_file = file_name(need(j, "rigid_particles", ""), "rigid_particles");
    if (j.contains("rigids"))  // absent in frames written before surface textures
      for (std::size_t i = 0; i < j["rigids"].size(); ++i) {
        const std::string where = "rigids[" + std::to_string(i) + "].";
        const auto& r = j["rigids"][i];
        m.rigids.push_back(RigidSurfaceEntry{need(r, "name", where).get<std::string>(), file_name(need(r, "mesh", where), where + "mesh"),
                                             need(r, "texture_resolution", where).get<std::array<int, 2>>()});
      }
    const auto& frames = need(j, "frames", "");
    for (std::size_t i = 0; i < frames.size(); ++i) {
      std::string where = "frames[" + std::to_string(i) + "].";
      const auto& f = frames[i];
      FrameEntry e;
      e.index = need(f, "index", where).get<int>();
      e.time_s = need(f, "time_s", where).get<double>();
      e.step = need(f, "step", where).get<std::int64_t>();
      e.liquid_particles = need(f, "liquid_particles", where).get<std::size_t>();
      e.particles_file = file_name(need(need(f, "files", where), "particles", where + "files."), where + "files.particles");
      if (f["files"].contains("surfaces"))
        for (const auto& [rigid, name] : f["files"]["surfaces"].items())
          e.surface_files[rigid] = file_name(name, where + "files.surfaces." + rigid);
      if (f["files"].contains("air")) e.air_file = file_name(f["files"]["air"], where + "files.air");
      if (f.contains("air_vapor")) e.air_vapor = f["air_vapor"];
      if (f.contains("water")) e.water = f["water"];
      m.frames.push_back(e);
    }
    m.extra = j;
    return m;
  } catch (const nlohmann::json::exception& e) {  // wrong types, arrays of the wrong length
    throw std::runtime_error(file.string() + ": wrong type or size: " + e.what());
  }
}

std::string recorded_preset(const FramesManifest& manifest) {
  const auto it = manifest.extra.find("preset");
  return it != manifest.extra.end() && it->is_string() ? it->get<std::string>() : std::string();
}

}  // namespace dp::io
