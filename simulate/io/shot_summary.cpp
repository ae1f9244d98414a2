#include "shot_summary.h"

#include "frames.h"
#include "ply.h"

namespace dp::io {
namespace {

double ledger_value(const nlohmann::json& water, const char* key) {
  return water.is_object() && water.contains(key) ? water[key].get<double>() : 0.0;
}

}  // namespace

const std::vector<std::string>& summary_quantity_names() {
  static const std::vector<std::string> names{"particles", "liquid_kg", "texels_kg", "vapor_kg",
                                              "com_x", "com_y", "com_z", "com_vx", "com_vy", "com_vz"};
  return names;
}

std::vector<double> summary_quantities(const FrameSummary& f) {
  return {f.particles,          f.liquid_kg,          f.texels_kg,          f.vapor_kg,
          f.centre_of_mass[0],  f.centre_of_mass[1],  f.centre_of_mass[2],
          f.centre_velocity[0], f.centre_velocity[1], f.centre_velocity[2]};
}

std::vector<FrameSummary> summarize_shot(const std::filesystem::path& frames_dir) {
  const FramesManifest manifest = read_manifest(frames_dir);
  std::vector<FrameSummary> shot;
  for (const FrameEntry& entry : manifest.frames) {
    FrameSummary f;
    f.index = entry.index;
    f.time_s = entry.time_s;
    f.particles = static_cast<double>(entry.liquid_particles);
    f.liquid_kg = ledger_value(entry.water, "liquid_kg");
    f.texels_kg = ledger_value(entry.water, "texels_kg");
    f.vapor_kg = ledger_value(entry.water, "vapor_kg");
    f.relative_drift = ledger_value(entry.water, "relative_drift");
    const PlyData ply = read_ply(frames_dir / entry.particles_file);
    if (ply.vertex_count > 0) {
      // The mass weight alone: ρ0 spacing³ is common to every particle.
      const std::vector<float> w = ply.floats("weight");
      const char* position[3] = {"x", "y", "z"};
      const char* velocity[3] = {"vx", "vy", "vz"};
      double total = 0;
      for (float wi : w) total += wi;
      for (int a = 0; a < 3; ++a) {
        const std::vector<float> x = ply.floats(position[a]), v = ply.floats(velocity[a]);
        double moment = 0, momentum = 0;
        for (std::size_t i = 0; i < w.size(); ++i) {
          moment += static_cast<double>(w[i]) * x[i];
          momentum += static_cast<double>(w[i]) * v[i];
        }
        f.centre_of_mass[a] = moment / total;
        f.centre_velocity[a] = momentum / total;
      }
    }
    shot.push_back(f);
  }
  return shot;
}

}  // namespace dp::io
