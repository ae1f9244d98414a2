// dewpoint-simulate --device cuda against --device cpu on a whole short
// shot: the drop landing on the hot plate (preview), with its air, texture,
// heat and evaporation. The CUDA run must lie within the spread of CPU runs
// whose liquid starts 1e-6 spacings apart (shot_ensemble.h), and each run's
// water ledger must close. Skips where no GPU is usable.
#include <gtest/gtest.h>

#include "backend/device.h"
#include "shot_ensemble.h"
#include "../test_folder.h"

namespace dp {
namespace {

TEST(ShotAgreement, TheCudaDropLiesWithinTheCpuEnsemble) {
  std::string why;
  if (cuda_device_count(&why) == 0) GTEST_SKIP() << "no GPU: " << why;
  const test::ShotSpec spec{"drop", "preview", "0-3"};
  const auto work = test::test_folder("dewpoint-shot-gpu-");
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  const std::vector<test::ShotRun> cpu = test::cpu_ensemble(work, spec);
  const auto envelope = test::ensemble_envelope(cpu);
  const test::ShotRun cuda =
      test::run_shot(test::shifted_scene(work, spec, {0, 0, 0}, "cuda"), work / "cuda", spec, "cuda", "cuda");
  RecordProperty("envelope", test::describe_envelope(cpu, envelope));
  for (const test::ShotRun& run : cpu) test::expect_ledgers_close(run);
  test::expect_ledgers_close(cuda);
  const std::vector<std::string> outside = test::outside_envelope(cpu.front(), cuda, envelope);
  for (const std::string& line : outside) ADD_FAILURE() << line;
  EXPECT_TRUE(outside.empty()) << "the ensemble's envelope:\n" << test::describe_envelope(cpu, envelope);
}

}  // namespace
}  // namespace dp
