#pragma once
// A scratch folder named after the running test, under the system's
// temporary folder: ctest runs every test as a process of its own, in
// parallel, and two tests writing one folder read each other's files.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace dp::test {

// temp / (prefix + the test's name); the prefix names the file's tests
// (and, where a test's runs must not meet, the process).
inline std::filesystem::path test_folder(const std::string& prefix) {
  return std::filesystem::temp_directory_path() / (prefix + ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

}  // namespace dp::test
