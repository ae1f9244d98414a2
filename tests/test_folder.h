#pragma once
// A scratch folder named after the running test and its process, under the
// system's temporary folder: ctest runs every test as a process of its own,
// in parallel, and two tests writing one folder read each other's files; so
// do two builds tested at once on one machine (a CI clone beside a
// developer's build collided on the shot ensemble's folder).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

namespace dp::test {

// temp / (prefix + the test's name + "-" + the process id); the prefix
// names the file's tests.
inline std::filesystem::path test_folder(const std::string& prefix) {
  return std::filesystem::temp_directory_path() /
         (prefix + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "-" + std::to_string(::getpid()));
}

}  // namespace dp::test
