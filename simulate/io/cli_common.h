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

// Progress on stderr: what, done/total, rate, ETA and a detail. On a
// terminal one line rewritten in place at most 4 times a second; elsewhere
// (farm logs, pipes) at most one line per item, an item being
// `units_per_item` units of `done`.
class Progress {
 public:
  Progress(std::string what, long total, bool quiet, long units_per_item = 1);
  // Whether update(done) would print now: lets callers skip building a detail.
  bool due(long done) const;
  void update(long done, const std::string& detail = "");
  void finish(const std::string& summary);

 private:
  std::string what_;
  long total_;
  bool quiet_;
  long units_per_item_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_{};
  long last_item_printed_ = 0;  // a pipe's first line is the first item done
  bool line_open_ = false;  // a terminal line not yet ended by a newline
};

}  // namespace dp::io
