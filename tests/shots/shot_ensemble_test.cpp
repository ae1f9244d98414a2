// The yardstick of shot_agreement_gpu_test, on the CPU: the ensemble of runs
// 1e-6 spacings apart has a spread that opens as the drop lands, and runs
// with a model changed by a tenth of what drives it (surface tension 10 %
// stronger; the plate's excess over the drop's temperature, 130 K, 10 %
// larger, which drives the heat flux that evaporates the drop) fall outside
// it. (A plate 1 K warmer lies within: over three frames its effect on the
// evaporated mass is smaller than the spread the landing opens.) So a GPU
// run that passes does not pass because the spread swallows anything. One test, so the ensemble is run once.
#include <gtest/gtest.h>

#include <functional>

#include "shot_ensemble.h"
#include "../test_folder.h"

namespace dp {
namespace {

const test::ShotSpec kSpec{"drop", "preview", "0-3"};

// The scene with one change applied to its preset's simulation section.
test::ShotRun changed(const std::filesystem::path& work, const std::string& label,
                      const std::function<void(nlohmann::json&)>& change) {
  const auto scene = test::shifted_scene(work, kSpec, {0, 0, 0}, label);
  nlohmann::json doc;
  {
    std::ifstream in(scene);
    doc = nlohmann::json::parse(in);
  }
  change(doc["presets"][kSpec.preset]["simulation"]);
  std::ofstream(scene) << doc.dump(2);
  return test::run_shot(scene, work / label, kSpec, "cpu", label);
}

TEST(ShotEnsemble, OpensAsTheDropLandsAndChangedModelsFallOutside) {
  const auto work = test::test_folder("dewpoint-shot-ensemble-");
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  const std::vector<test::ShotRun> members = test::cpu_ensemble(work, kSpec);
  const auto envelope = test::ensemble_envelope(members);
  std::cout << test::describe_envelope(members, envelope);
  RecordProperty("envelope", test::describe_envelope(members, envelope));
  for (const test::ShotRun& run : members) test::expect_ledgers_close(run);

  // The perturbation is real: the liquid's centre differs at frame 0 by
  // about the shift (1e-6 of the preset's 4 mm spacing, rounded to float).
  const std::size_t com_y = 5;
  EXPECT_GT(envelope.front()[com_y], 0.5e-6 * 0.004);
  EXPECT_LT(envelope.front()[com_y], 2e-6 * 0.004);
  // Chaos amplifies it: by the last frame the centres lie further apart.
  EXPECT_GT(envelope.back()[com_y], 10 * envelope.front()[com_y]);

  // An unperturbed rerun is the same run (the CPU is deterministic): it
  // lies within an envelope of zero.
  const test::ShotRun again =
      test::run_shot(test::shifted_scene(work, kSpec, {0, 0, 0}, "again"), work / "again", kSpec, "cpu", "again");
  const std::vector<std::vector<double>> zero(envelope.size(), std::vector<double>(envelope.front().size(), 0.0));
  EXPECT_TRUE(test::outside_envelope(members.front(), again, zero).empty());

  const test::ShotRun tension = changed(work, "tension", [](nlohmann::json& sim) {
    sim["liquid"]["surface_tension"] = sim["liquid"]["surface_tension"].get<double>() * 1.1;
  });
  const test::ShotRun plate = changed(work, "plate", [](nlohmann::json& sim) {
    const double plate_c = sim["rigids"][0]["temperature_c"].get<double>();
    const double drop_c = 20.0;  // the scene's liquid, which the preset keeps
    sim["rigids"][0]["temperature_c"] = plate_c + 0.1 * (plate_c - drop_c);
  });
  for (const test::ShotRun* run : {&tension, &plate}) {
    const auto outside = test::outside_envelope(members.front(), *run, envelope);
    for (const std::string& line : outside) std::cout << line << "\n";
    EXPECT_FALSE(outside.empty()) << run->label << " lies within the ensemble";
  }
  std::filesystem::remove_all(work);
}

}  // namespace
}  // namespace dp
