#pragma once
// Whole shots of one scene compared where bits cannot agree. SPH is chaotic:
// runs whose float sums add in another order (the GPU's) drift apart as
// runs whose initial positions differ by a rounding do. So the yardstick
// is an ensemble of CPU runs whose liquid starts 1e-6 particle spacings
// apart: a run agrees with the CPU when, at every frame, each compared
// quantity (shot_summary.h) lies no further from the unperturbed CPU run
// than the ensemble's members have lain from each other up to that frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../cli/run_command.h"
#include "shot_summary.h"

namespace dp::test {

namespace fs = std::filesystem;

// The executable and the source tree: compiled in, or, for the GPU bundle
// (pipelines/gpu-shot.sh), where the environment says.
inline std::string simulate_executable() {
  const char* from_env = std::getenv("DEWPOINT_SIMULATE");
  return from_env && *from_env ? from_env : DEWPOINT_SIMULATE;
}
inline fs::path source_dir() {
  const char* from_env = std::getenv("DEWPOINT_SOURCE_DIR");
  return from_env && *from_env ? fs::path(from_env) : fs::path(DEWPOINT_SOURCE_DIR);
}

struct ShotSpec {
  std::string scene;   // assets/scenes/NAME.json
  std::string preset;  // applied to every run
  std::string frames;  // --frames A-B
};

struct ShotRun {
  std::string label;
  std::vector<io::FrameSummary> frames;
};

// A copy of the scene (in WORK/assets, so its relative asset paths hold)
// whose liquid blocks are moved by `shift` particle spacings of the preset.
inline fs::path shifted_scene(const fs::path& work, const ShotSpec& spec, const std::array<double, 3>& shift,
                              const std::string& label) {
  if (!fs::exists(work / "assets")) fs::copy(source_dir() / "assets", work / "assets", fs::copy_options::recursive);
  std::ifstream in(work / "assets/scenes" / (spec.scene + ".json"));
  nlohmann::json doc = nlohmann::json::parse(in);
  const nlohmann::json& preset = doc["presets"][spec.preset];
  if (preset["simulation"].contains("liquid_blocks"))
    throw std::runtime_error(spec.scene + ": the preset replaces the liquid blocks; shift them there");
  const double spacing = preset["simulation"].value("particle_spacing_m", doc["simulation"]["particle_spacing_m"].get<double>());
  for (auto& block : doc["simulation"]["liquid_blocks"])
    for (const char* key : {"center_m", "min_m", "max_m"})
      if (block.contains(key))
        for (int a = 0; a < 3; ++a) block[key][a] = block[key][a].get<double>() + shift[a] * spacing;
  const fs::path file = work / "assets/scenes" / (spec.scene + "." + label + ".json");
  std::ofstream(file) << doc.dump(2);
  return file;
}

inline ShotRun run_shot(const fs::path& scene, const fs::path& out, const ShotSpec& spec, const std::string& device,
                        const std::string& label, const std::string& extra = "") {
  fs::remove_all(out);
  const std::string command = simulate_executable() + " " + scene.string() + " -o " + out.string() + " --preset " +
                              spec.preset + " --frames " + spec.frames + " --device " + device + " --quiet " + extra;
  const CommandResult r = run_command(command);
  if (r.exit_code != 0) throw std::runtime_error(command + " exited " + std::to_string(r.exit_code) + ": " + r.output);
  return ShotRun{label, io::summarize_shot(out / "frames")};
}

// envelope[f][q]: the largest |difference| of quantity q between any two
// members at any frame up to f. Running, because a spread that has opened
// can close again by chance (two chaotic runs cross); the GPU's difference
// is held to the widest the ensemble reached so far.
inline std::vector<std::vector<double>> ensemble_envelope(const std::vector<ShotRun>& members) {
  const std::size_t frames = members.front().frames.size();
  std::vector<std::vector<double>> envelope;
  std::vector<double> widest(io::summary_quantity_names().size(), 0.0);
  for (std::size_t f = 0; f < frames; ++f) {
    for (std::size_t i = 0; i < members.size(); ++i)
      for (std::size_t j = i + 1; j < members.size(); ++j) {
        const std::vector<double> a = io::summary_quantities(members[i].frames.at(f));
        const std::vector<double> b = io::summary_quantities(members[j].frames.at(f));
        for (std::size_t q = 0; q < a.size(); ++q) widest[q] = std::max(widest[q], std::abs(a[q] - b[q]));
      }
    envelope.push_back(widest);
  }
  return envelope;
}

// Each frame and quantity where `run` lies further from `reference` than the
// envelope allows, as a readable line; empty when it agrees.
inline std::vector<std::string> outside_envelope(const ShotRun& reference, const ShotRun& run,
                                                 const std::vector<std::vector<double>>& envelope) {
  std::vector<std::string> outside;
  if (run.frames.size() != reference.frames.size()) {
    outside.push_back(run.label + ": " + std::to_string(run.frames.size()) + " frames, the reference has " +
                      std::to_string(reference.frames.size()));
    return outside;
  }
  const auto& names = io::summary_quantity_names();
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const std::vector<double> a = io::summary_quantities(reference.frames[f]);
    const std::vector<double> b = io::summary_quantities(run.frames[f]);
    for (std::size_t q = 0; q < a.size(); ++q)
      if (std::abs(a[q] - b[q]) > envelope[f][q]) {
        std::ostringstream line;
        line << run.label << " frame " << run.frames[f].index << " " << names[q] << ": " << b[q] << " against "
             << a[q] << ", |difference| " << std::abs(a[q] - b[q]) << " > the ensemble's " << envelope[f][q];
        outside.push_back(line.str());
      }
  }
  return outside;
}

// The CPU ensemble: the scene as it is, and its liquid shifted by 1e-6
// spacings along +x, +y and +z (4 members, 6 pairs).
inline std::vector<ShotRun> cpu_ensemble(const fs::path& work, const ShotSpec& spec) {
  std::vector<ShotRun> members;
  const std::vector<std::pair<std::string, std::array<double, 3>>> shifts{
      {"cpu", {0, 0, 0}}, {"cpu+dx", {1e-6, 0, 0}}, {"cpu+dy", {0, 1e-6, 0}}, {"cpu+dz", {0, 0, 1e-6}}};
  for (const auto& [label, shift] : shifts)
    members.push_back(run_shot(shifted_scene(work, spec, shift, label), work / label, spec, "cpu", label));
  return members;
}

// The water ledger of each run closes on its own (docs/file-formats.md).
inline void expect_ledgers_close(const ShotRun& run) {
  for (const io::FrameSummary& f : run.frames) EXPECT_LE(std::abs(f.relative_drift), 1e-9) << run.label << " frame " << f.index;
}

// One line per frame and quantity: the ensemble's envelope, for the record.
inline std::string describe_envelope(const std::vector<ShotRun>& members, const std::vector<std::vector<double>>& envelope) {
  std::ostringstream out;
  const auto& names = io::summary_quantity_names();
  for (std::size_t f = 0; f < envelope.size(); ++f) {
    out << "frame " << members.front().frames[f].index;
    for (std::size_t q = 0; q < names.size(); ++q) out << " " << names[q] << "=" << envelope[f][q];
    out << "\n";
  }
  return out.str();
}

}  // namespace dp::test
