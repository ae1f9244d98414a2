#pragma once
// A simulation checkpoint (docs/file-formats.md, checkpoints): the core's
// dynamic state (simulation_state.h) at a frame boundary, with the frame it
// belongs to and a hash of the scene it was made from, as a versioned
// binary file closed by a CRC-32 of everything before it.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "simulation_state.h"

namespace dp::io {

inline constexpr std::uint32_t kCheckpointVersion = 3;

struct Checkpoint {
  int frame = 0;                 // the last frame boundary the state has reached
  std::uint64_t scene_hash = 0;  // scene_document_hash of the scene it was made from
  SimulationState state;
};

// A file that is not a whole, intact checkpoint of this version.
class CheckpointCorrupt : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// CRC-32 of the scene document's canonical text (keys sorted, no spaces)
// in the low half, that text's length in the high half.
std::uint64_t scene_document_hash(const nlohmann::json& document);

std::string encode_checkpoint(const Checkpoint& checkpoint);
// Throws CheckpointCorrupt naming `name` and what is wrong.
Checkpoint decode_checkpoint(const std::string& bytes, const std::string& name);

// Written atomically: a reader never sees half a checkpoint under `file`.
void write_checkpoint(const std::filesystem::path& file, const Checkpoint& checkpoint);
// Throws CheckpointCorrupt (also for an unreadable file).
Checkpoint read_checkpoint(const std::filesystem::path& file);

}  // namespace dp::io
