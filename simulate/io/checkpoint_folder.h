#pragma once
// OUT/checkpoints: checkpoint.NNNNNN.dpck per checkpointed frame, the newest
// two kept (the older one stands in if the newer is damaged).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "checkpoint.h"

namespace dp::io {

inline constexpr int kCheckpointsKept = 2;

std::filesystem::path checkpoint_file(const std::filesystem::path& dir, int frame);

// Writes the checkpoint, then removes all but the newest kCheckpointsKept.
void save_checkpoint(const std::filesystem::path& dir, const Checkpoint& checkpoint);

// Removes every checkpoint in `dir` (other files stay).
void remove_checkpoints(const std::filesystem::path& dir);

struct NewestCheckpoint {
  std::optional<Checkpoint> checkpoint;  // none: no intact checkpoint
  std::filesystem::path file;
  std::vector<std::string> skipped;      // why each newer file was passed over
};

// The newest intact checkpoint in `dir` (none when `dir` does not exist).
NewestCheckpoint find_newest_checkpoint(const std::filesystem::path& dir);

}  // namespace dp::io
