// PLY round trip and damaged-file errors.
#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "ply.h"

namespace fs = std::filesystem;

namespace dp::io {
namespace {

TEST(Ply, RoundTripKeepsNamedPropertiesAndFaces) {
  PlyData d;
  d.vertex_count = 3;
  d.add("x", PlyType::Float32, {0.5, 1.25, -2});
  d.add("id", PlyType::UInt32, {7, 4000000000.0, 0});
  d.add("phase", PlyType::UInt8, {1, 2, 255});
  d.faces.push_back({0, 1, 2});
  fs::path f = fs::temp_directory_path() / "dewpoint_ply_roundtrip.ply";
  write_ply(f, d);
  PlyData r = read_ply(f);
  ASSERT_EQ(r.vertex_count, 3u);
  EXPECT_EQ(r.floats("x"), (std::vector<float>{0.5f, 1.25f, -2.0f}));
  EXPECT_EQ(r.find("id")->values[1], 4000000000.0);
  EXPECT_EQ(r.find("phase")->values[2], 255.0);
  ASSERT_EQ(r.faces.size(), 1u);
  EXPECT_EQ(r.faces[0][2], 2u);
  EXPECT_THROW(r.floats("missing"), std::runtime_error);
}

TEST(Ply, TruncatedFileIsAnErrorNamingTheFile) {
  PlyData d;
  d.vertex_count = 100;
  std::vector<double> v(100, 1.0);
  d.add("x", PlyType::Float32, v);
  fs::path f = fs::temp_directory_path() / "dewpoint_ply_truncated.ply";
  write_ply(f, d);
  fs::resize_file(f, fs::file_size(f) - 10);
  try {
    read_ply(f);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("dewpoint_ply_truncated.ply"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos);
  }
}

TEST(Ply, WritingReplacesAtomically) {
  fs::path f = fs::temp_directory_path() / "dewpoint_ply_atomic.ply";
  PlyData d;
  d.vertex_count = 1;
  d.add("x", PlyType::Float32, {1});
  write_ply(f, d);
  for (const auto& e : fs::directory_iterator(f.parent_path()))
    EXPECT_EQ(e.path().filename().string().find("dewpoint_ply_atomic.ply.tmp"), std::string::npos) << "temporary left behind";
}

// A folder where the file goes: the error names the file and gives the
// operating system's reason (EISDIR), and nothing is left behind.
TEST(Ply, FailedRenameNamesTheSystemsReason) {
  const fs::path dir = fs::temp_directory_path() / "dewpoint_ply_rename_blocked";
  fs::remove_all(dir);
  const fs::path f = dir / "blocked.ply";
  fs::create_directories(f);
  PlyData d;
  d.vertex_count = 1;
  d.add("x", PlyType::Float32, {1});
  try {
    write_ply(f, d);
    ADD_FAILURE() << "write_ply over a folder succeeded";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(f.string()), std::string::npos) << message;
    EXPECT_NE(message.find(std::strerror(EISDIR)), std::string::npos) << message;
  }
  EXPECT_TRUE(fs::is_directory(f));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "temporary left behind";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace dp::io
