// The figure pipeline (pipelines/figures.mk) as `make -C pipelines figures`
// runs it, on the cheapest scene: its targets produce their files, and a
// second run finds nothing to do.
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "run_command.h"

namespace fs = std::filesystem;

namespace dp {
namespace {

const fs::path kSource = DEWPOINT_SOURCE_DIR;

std::string make_figures(const fs::path& out, const std::string& extra) {
  return "make -C " + (kSource / "pipelines").string() + " figure-files QUALITY=preview FIGURE_SCENES=contact_angles " +
         "TABLE1_SCENES= BUILD=" + DEWPOINT_BINARY_DIR + " OUT=" + out.string() + " " + extra;
}

// Width and height of an image as OpenImageIO reads it; 0x0 when unreadable.
std::pair<int, int> image_size(const fs::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) return {0, 0};
  return {in->spec().width, in->spec().height};
}

TEST(Figures, PreviewTargetsProduceTheirFilesAndAreIncremental) {
  const fs::path out = fs::temp_directory_path() / ("dewpoint-figures-test-" + std::to_string(getpid()));
  fs::remove_all(out);
  const auto first = test::run_command(make_figures(out, "-j2"));
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const fs::path dir = out / "figures/preview";
  // The preview preset renders 480 x 160 (assets/scenes/contact_angles.json).
  for (const char* image : {"contact_angles/images/beauty.0000.exr", "contact_angles/images/beauty.0000.png",
                            "contact_angles/images_uncorrected/beauty.0000.png", "contact_angles/contact_sheet.png"})
    EXPECT_EQ(image_size(dir / image), std::make_pair(480, 160)) << image;
  // Fig. 3: the uncorrected and corrected renders one above the other, 4 pixels apart.
  EXPECT_EQ(image_size(dir / "fig3_single_particle.png"), std::make_pair(480, 2 * 160 + 4));
  for (const char* plot : {"contact_angles/water.png", "contact_angles/transfers.png"})
    EXPECT_EQ(image_size(dir / plot), std::make_pair(800, 450)) << plot;
  // A second run runs no tool: every file is up to date.
  const auto again = test::run_command(make_figures(out, ""));
  EXPECT_EQ(again.exit_code, 0) << again.output;
  for (const char* tool : {"dewpoint-simulate", "dewpoint-mesh", "dewpoint-render", "oiiotool", "gnuplot", "figure_data.py"})
    EXPECT_EQ(again.output.find(tool), std::string::npos) << tool << " ran again:\n" << again.output;
  fs::remove_all(out);
}

}  // namespace
}  // namespace dp
