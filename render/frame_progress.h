#pragma once
// Progress of dewpoint-render on stderr: one line at most every few
// seconds, from whichever worker thread finishes a tile, with the fraction
// of all frames done and the ETA, and one line per finished frame.
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

#include "cli_common.h"

namespace dp::render {

class FrameProgress {
 public:
  FrameProgress(const std::string& what, std::size_t frames, bool quiet) : progress_(what, static_cast<long>(frames) * kUnits, quiet, kUnits) {}

  void tile_done(std::size_t frames_before, int frame, double fraction) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::seconds(2)) return;
    last_ = now;
    char detail[64];
    std::snprintf(detail, sizeof detail, "frame %d %3.0f %%", frame, 100 * fraction);
    progress_.update(static_cast<long>(frames_before) * kUnits + static_cast<long>(fraction * kUnits), detail);
  }
  void frame_done(std::size_t frames_done, const std::string& detail) {
    const std::lock_guard<std::mutex> lock(mutex_);
    last_ = std::chrono::steady_clock::now();
    progress_.update(static_cast<long>(frames_done) * kUnits, detail);
  }
  void finish(const std::string& summary) { progress_.finish(summary); }

 private:
  static constexpr long kUnits = 1000;  // per frame
  dp::io::Progress progress_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace dp::render
