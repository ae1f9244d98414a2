#include "checkpoint_folder.h"

#include <algorithm>
#include <cstdio>
#include <system_error>
#include <utility>

namespace dp::io {

namespace {

// Checkpoints in `dir` with their frames, newest first; other files ignored.
std::vector<std::pair<int, std::filesystem::path>> listed_checkpoints(const std::filesystem::path& dir) {
  std::vector<std::pair<int, std::filesystem::path>> found;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return found;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    int frame = -1;
    char tail = 0;
    if (std::sscanf(name.c_str(), "checkpoint.%d.dpck%c", &frame, &tail) == 1 && frame >= 0 &&
        name == checkpoint_file(dir, frame).filename().string())
      found.emplace_back(frame, entry.path());
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  return found;
}

}  // namespace

std::filesystem::path checkpoint_file(const std::filesystem::path& dir, int frame) {
  char name[40];
  std::snprintf(name, sizeof name, "checkpoint.%06d.dpck", frame);
  return dir / name;
}

void save_checkpoint(const std::filesystem::path& dir, const Checkpoint& checkpoint) {
  std::filesystem::create_directories(dir);
  write_checkpoint(checkpoint_file(dir, checkpoint.frame), checkpoint);
  const auto listed = listed_checkpoints(dir);
  for (std::size_t i = kCheckpointsKept; i < listed.size(); ++i) {
    std::error_code ignored;  // an old checkpoint left behind costs disk, not correctness
    std::filesystem::remove(listed[i].second, ignored);
  }
}

// Throws where a checkpoint cannot be removed: one left behind could later
// be resumed from, unlike the old ones save_checkpoint prunes.
void remove_checkpoints(const std::filesystem::path& dir) {
  for (const auto& [frame, file] : listed_checkpoints(dir)) std::filesystem::remove(file);
}

NewestCheckpoint find_newest_checkpoint(const std::filesystem::path& dir) {
  NewestCheckpoint result;
  for (const auto& [frame, file] : listed_checkpoints(dir)) {
    try {
      result.checkpoint = read_checkpoint(file);
      result.file = file;
      return result;
    } catch (const CheckpointCorrupt& e) {
      result.skipped.push_back(e.what());
    }
  }
  return result;
}

}  // namespace dp::io
