#pragma once
// Pieces every dewpoint executable's command line shares.
#include <chrono>
#include <string>

namespace dp::io {

struct FrameRange {
  int first = 0;
  int last = -1;  // -1: to the end
  bool contains(int frame) const { return frame >= first && (last < 0 || frame <= last); }
};

// Parses "A-B", "A-" or "A"; throws std::invalid_argument with the reason.
FrameRange parse_frame_range(const std::string& text);

// One line per update on stderr: what, done/total, rate, ETA.
class Progress {
 public:
  Progress(std::string what, long total, bool quiet);
  void update(long done, const std::string& detail = "");
  void finish(const std::string& summary);

 private:
  std::string what_;
  long total_;
  bool quiet_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace dp::io
