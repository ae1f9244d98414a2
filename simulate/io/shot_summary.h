#pragma once
// What a shot's frames say about its water and its motion, frame by frame:
// the quantities by which two runs of one scene (CPU and GPU, or two CPU
// runs a rounding apart) are compared (docs/gpu.md, "GPU against CPU").
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace dp::io {

struct FrameSummary {
  int index = 0;
  double time_s = 0;
  double particles = 0;            // liquid particle count
  double liquid_kg = 0, texels_kg = 0, vapor_kg = 0;
  double relative_drift = 0;       // the water ledger's (docs/file-formats.md)
  std::array<double, 3> centre_of_mass{};   // of the liquid, m (mass-weighted)
  std::array<double, 3> centre_velocity{};  // its velocity, m/s (momentum / mass)
};

// The quantities compared, by name, in FrameSummary's order after index and
// time: particles, liquid_kg, texels_kg, vapor_kg, com_x ... com_vz.
const std::vector<std::string>& summary_quantity_names();
std::vector<double> summary_quantities(const FrameSummary& f);

// Reads FRAMES/manifest.json and every frame's particle PLY. Throws
// std::runtime_error naming the file when one cannot be read.
std::vector<FrameSummary> summarize_shot(const std::filesystem::path& frames_dir);

}  // namespace dp::io
