// The whole flow of DESIGN §1 through the three executables: a shortened
// demo scene is simulated, meshed and rendered, and the liquid shows in the
// image: pixels differ from a render of the same frame without liquid.
#include <unistd.h>

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "frames.h"
#include "ply.h"
#include "run_command.h"

namespace fs = std::filesystem;

namespace dp {
namespace {

std::vector<float> read_rgb(const fs::path& file, int& width, int& height) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  width = spec.width;
  height = spec.height;
  std::vector<float> rgba(static_cast<std::size_t>(width) * height * spec.nchannels);
  in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, rgba.data());
  std::vector<float> rgb;
  for (std::size_t p = 0; p < rgba.size(); p += spec.nchannels)
    for (int c = 0; c < 3; ++c) rgb.push_back(rgba[p + c]);
  return rgb;
}

TEST(Pipeline, SimulateMeshRenderShowsTheLiquid) {
  const fs::path work = fs::temp_directory_path() / ("dewpoint-pipeline-test-" + std::to_string(getpid()));
  fs::remove_all(work);
  fs::create_directories(work / "scenes");
  fs::create_directories(work / "meshes");
  fs::copy_file(fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj", work / "meshes/tray.obj");
  std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["simulation"]["duration_s"] = 0.05;
  doc["simulation"]["frame_rate_hz"] = 20;
  std::ofstream(work / "scenes/shot.json") << doc.dump(2);
  const std::string scene = (work / "scenes/shot.json").string();
  const std::string out = (work / "out").string();

  auto sim = test::run_command(std::string(DEWPOINT_SIMULATE) + " " + scene + " -o " + out + " --quiet");
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  auto mesh = test::run_command(std::string(DEWPOINT_MESH) + " " + out + "/frames -o " + out + "/meshes --quiet");
  ASSERT_EQ(mesh.exit_code, 0) << mesh.output;
  io::PlyData liquid = io::read_ply(work / "out/meshes/liquid.0001.ply");
  EXPECT_GT(liquid.faces.size(), 1000u);

  const std::string render_args = " --frames 1-1 --resolution 96x54 --spp 8 --quiet";
  auto render = test::run_command(std::string(DEWPOINT_RENDER) + " " + scene + " --frames-dir " + out + "/frames --meshes-dir " +
                                  out + "/meshes -o " + out + "/images" + render_args);
  ASSERT_EQ(render.exit_code, 0) << render.output;

  // The same frame with an empty liquid mesh: the background the liquid hides.
  fs::create_directories(work / "out/empty_meshes");
  io::PlyData empty;
  empty.add("x", io::PlyType::Float32, {});
  empty.add("y", io::PlyType::Float32, {});
  empty.add("z", io::PlyType::Float32, {});
  empty.add("nx", io::PlyType::Float32, {});
  empty.add("ny", io::PlyType::Float32, {});
  empty.add("nz", io::PlyType::Float32, {});
  io::write_ply(work / "out/empty_meshes/liquid.0001.ply", empty);
  auto dry = test::run_command(std::string(DEWPOINT_RENDER) + " " + scene + " --frames-dir " + out + "/frames --meshes-dir " + out +
                               "/empty_meshes -o " + out + "/dry" + render_args);
  ASSERT_EQ(dry.exit_code, 0) << dry.output;

  int w = 0, h = 0, w2 = 0, h2 = 0;
  std::vector<float> wet = read_rgb(work / "out/images/beauty.0001.exr", w, h);
  std::vector<float> bare = read_rgb(work / "out/dry/beauty.0001.exr", w2, h2);
  ASSERT_EQ(w, 96);
  ASSERT_EQ(h, 54);
  ASSERT_EQ(wet.size(), bare.size());
  EXPECT_TRUE(fs::exists(work / "out/images/beauty.0001.png"));

  // A block of liquid 0.2 m wide seen from the demo camera covers a few
  // percent of the frame: more than 1 %, far less than half.
  std::size_t differing = 0;
  for (std::size_t p = 0; p < wet.size(); p += 3) {
    float d = std::fabs(wet[p] - bare[p]) + std::fabs(wet[p + 1] - bare[p + 1]) + std::fabs(wet[p + 2] - bare[p + 2]);
    if (d > 0.15f) ++differing;
  }
  const double fraction = static_cast<double>(differing) / (w * h);
  RecordProperty("liquid_pixel_fraction", std::to_string(fraction));
  EXPECT_GT(fraction, 0.01);
  EXPECT_LT(fraction, 0.5);
}

}  // namespace
}  // namespace dp
