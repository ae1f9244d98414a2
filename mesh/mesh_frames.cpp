#include "mesh_frames.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "dewpoint/version.h"
#include "frames.h"
#include "liquid_level_set.h"
#include "liquid_surface.h"
#include "mesh_check.h"
#include "mesh_ply.h"
#include "mesh_sidecar.h"
#include "ply.h"
#include "rigid_surfaces.h"
#include "scene.h"
#include "vdb_file.h"

namespace dp::mesh {

namespace fs = std::filesystem;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string describe(const io::FrameRange& r) {
  return std::to_string(r.first) + "-" + (r.last < 0 ? std::string() : std::to_string(r.last));
}

std::vector<io::FrameEntry> selected_frames(const io::FramesManifest& manifest, const io::FrameRange& range,
                                            const fs::path& frames_dir) {
  const fs::path manifest_file = frames_dir / "manifest.json";
  std::vector<io::FrameEntry> frames;
  for (const io::FrameEntry& f : manifest.frames)
    if (range.contains(f.index)) frames.push_back(f);
  if (frames.empty())
    throw std::runtime_error(manifest_file.string() + ": no frame in range " + describe(range) + " (the manifest lists " +
                             std::to_string(manifest.frames.size()) + " frames)");
  for (const io::FrameEntry& f : frames) {
    const fs::path file = frames_dir / f.particles_file;
    if (!fs::is_regular_file(file))
      throw std::runtime_error(file.string() + ": particle file of frame " + std::to_string(f.index) + " not found");
  }
  return frames;
}

LiquidParticles read_liquid_particles(const fs::path& file, const io::FrameEntry& frame, double nominal_radius) {
  const io::PlyData ply = io::read_ply(file);  // its errors name the file already
  try {
    LiquidParticles particles = liquid_particles_from_ply(ply, nominal_radius);
    if (particles.size() != frame.liquid_particles)
      throw std::runtime_error("has " + std::to_string(particles.size()) + " particles; the manifest lists " +
                               std::to_string(frame.liquid_particles) + " for frame " + std::to_string(frame.index));
    return particles;
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
}

// Bad input is reported before any output exists (docs/architecture.md),
// so every selected frame is read once up front, and its grid sized. Reading
// costs little next to meshing, and only one frame is held at a time.
void check_frames(const fs::path& frames_dir, const std::vector<io::FrameEntry>& frames,
                  const SurfaceParameters& parameters) {
  for (const io::FrameEntry& f : frames) {
    const fs::path file = frames_dir / f.particles_file;
    const LiquidParticles particles = read_liquid_particles(file, f, parameters.particle_radius);
    try {
      if (particles.size() > 0) zhu_bridson_grid_box(particles, parameters.kernel_radius, parameters.voxel_size);
    } catch (const std::exception& e) {
      throw std::runtime_error(file.string() + ": " + e.what());
    }
  }
}

// Scenes are named absolute by dewpoint-simulate; a relative name is taken
// relative to the frames folder, so a moved shot folder still works.
fs::path scene_file_of(const io::FramesManifest& manifest, const fs::path& frames_dir) {
  return manifest.scene_file.is_absolute() ? manifest.scene_file : frames_dir / manifest.scene_file;
}

}  // namespace

MeshFramesResult mesh_frames(const MeshFramesOptions& options) {
  const io::FramesManifest manifest = io::read_manifest(options.frames_dir);
  const fs::path scene_file = scene_file_of(manifest, options.frames_dir);
  const io::Scene scene = io::load_scene(scene_file, options.preset.value_or(io::recorded_preset(manifest)));
  SurfaceParameters parameters;
  try {
    parameters = surface_parameters(manifest.particle_spacing_m, scene.mesh, options.voxel_size, options.voxels_per_radius);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(scene_file.string() + ": mesh settings: " + e.what());
  }
  const std::vector<io::FrameEntry> frames = selected_frames(manifest, options.range, options.frames_dir);
  check_frames(options.frames_dir, frames, parameters);

  // The walls are built once for the run: rigids do not move.
  auto start = std::chrono::steady_clock::now();
  const bool correct = scene.mesh.correction && !options.no_correction;
  const bool level_set = scene.mesh.level_set || options.level_set;
  RigidSurfaces rigids;
  if (correct) rigids = load_rigid_surfaces(scene, manifest, options.frames_dir);
  const RigidWalls walls(rigids.meshes);
  const ContactAngleSettings angles = contact_angle_settings(scene.mesh, rigids.names, options.contact_angle_deg);
  const ContactAngleCorrection_HochstetterKolb2017 correction(walls, angles);
  const double walls_seconds = seconds_since(start);

  fs::create_directories(options.out_dir);
  const std::string generator = std::string("dewpoint-mesh ") + kVersion;
  io::Progress progress("mesh " + manifest.scene_name, static_cast<long>(frames.size()), options.quiet);
  long done = 0;
  MeshFramesResult result;
  for (const io::FrameEntry& frame : frames) {
    const fs::path particles_file = options.frames_dir / frame.particles_file;
    const std::string mesh_name = io::frame_file_name("liquid", frame.index, "ply");
    const std::string level_set_name = level_set ? io::frame_file_name("liquid", frame.index, "vdb") : std::string();
    const fs::path sidecar_file = options.out_dir / io::frame_file_name("liquid", frame.index, "json");

    MeshSidecar sidecar;
    sidecar.frame = frame.index;
    sidecar.time_s = frame.time_s;
    sidecar.frames_dir = fs::absolute(options.frames_dir).lexically_normal();
    sidecar.particles_file = frame.particles_file;
    sidecar.mesh_file = mesh_name;
    sidecar.level_set_file = level_set_name;
    sidecar.scene_file = scene_file;
    sidecar.parameters = parameters;
    sidecar.threads = options.threads;
    sidecar.correction = correct;
    sidecar.rigid_names = rigids.names;
    sidecar.rigid_files = rigids.files;
    sidecar.angles = angles;
    sidecar.walls_seconds = walls_seconds;

    start = std::chrono::steady_clock::now();
    const LiquidParticles particles = read_liquid_particles(particles_file, frame, parameters.particle_radius);
    sidecar.liquid_particles = particles.size();
    sidecar.read_seconds = seconds_since(start);

    ScalarGrid field;
    const LiquidSurface surface = liquid_surface(particles, parameters, correct ? &correction : nullptr, level_set ? &field : nullptr);
    if (options.check) {
      start = std::chrono::steady_clock::now();
      sidecar.check = check_mesh(surface.mesh);
      sidecar.check_seconds = seconds_since(start);
      if (!sidecar.check->passed()) ++result.failed_checks;
    }

    // A sidecar from an earlier run must not vouch for the new mesh while
    // it is being replaced.
    fs::remove(sidecar_file);
    start = std::chrono::steady_clock::now();
    const std::string comment = generator + " frame " + std::to_string(frame.index) + " from " + particles_file.string();
    write_mesh_ply(options.out_dir / mesh_name, surface.mesh, comment);
    // One field, two outputs: the mesh is this grid's zero contour.
    if (level_set) io::write_vdb_file(options.out_dir / level_set_name, openvdb::GridCPtrVec{liquid_level_set(field)}, comment);
    sidecar.write_seconds = seconds_since(start);
    const nlohmann::json record = mesh_sidecar_json(sidecar, surface);
    write_mesh_sidecar(sidecar_file, record);

    char detail[200];
    std::snprintf(detail, sizeof detail, "frame %d: %zu particles, %zu triangles, %.2f s%s", frame.index, particles.size(),
                  surface.mesh.triangles.size(), record["seconds"].get<double>(),
                  !sidecar.check ? "" : sidecar.check->passed() ? ", check passed" : ", CHECK FAILED (see the sidecar)");
    progress.update(++done, detail);
  }
  progress.finish(std::to_string(done) + " meshes in " + options.out_dir.string());
  result.frames = static_cast<int>(done);
  return result;
}

}  // namespace dp::mesh
