// Replays the fuzzing seed corpus (tests/fuzz/corpus) through the readers in
// the ordinary build: every known-bad input is refused with the reader's own
// error type and a message that names the file; the valid seeds parse.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "frames.h"
#include "ply.h"
#include "scene.h"

namespace dp::io {
namespace {

namespace fs = std::filesystem;

fs::path corpus(const std::string& target) { return fs::path(DEWPOINT_SOURCE_DIR) / "tests/fuzz/corpus" / target; }

bool is_valid_seed(const fs::path& file) { return file.filename().string().rfind("valid", 0) == 0; }

// Runs `read` on every file of the corpus; the message of a refused file
// must name the file read (`read_as`, when the reader reads a copy).
template <class Error, class Read>
void replay(const std::string& target, Read read, const std::string& read_as = "") {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(corpus(target))) {
    const fs::path file = entry.path();
    ++files;
    SCOPED_TRACE(file.string());
    try {
      read(file);
      EXPECT_TRUE(is_valid_seed(file)) << "accepted a known-bad input";
    } catch (const Error& e) {
      const std::string name = read_as.empty() ? file.filename().string() : read_as;
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      // The demo scene's meshes live beside the real scene, not beside the
      // corpus copy, so that seed may be refused for its mesh only.
      if (is_valid_seed(file)) EXPECT_NE(std::string(e.what()).find("mesh"), std::string::npos) << e.what();
    }
  }
  EXPECT_GT(files, 5);
}

TEST(InputCorpus, ScenesAreParsedOrRefusedWithTheKey) {
  replay<SceneError>("scene", [](const fs::path& f) { load_scene(f); });
}

TEST(InputCorpus, PlyFilesAreReadOrRefused) {
  replay<std::runtime_error>("ply", [](const fs::path& f) { read_ply(f); });
}

TEST(InputCorpus, ManifestsAreReadOrRefused) {
  // read_manifest takes a folder: each seed is copied in as manifest.json.
  const fs::path dir = fs::temp_directory_path() / ("dewpoint-corpus-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::create_directories(dir);
  replay<std::runtime_error>("manifest", [&](const fs::path& f) {
    fs::copy_file(f, dir / "manifest.json", fs::copy_options::overwrite_existing);
    read_manifest(dir);
  }, "manifest.json");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace dp::io
