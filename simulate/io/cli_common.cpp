#include "cli_common.h"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace dp::io {

namespace {
int parse_frame_number(const std::string& s, const std::string& whole) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos)
    throw std::invalid_argument("--frames: expected A-B with non-negative integers, found '" + whole + "'");
  return std::stoi(s);
}
}  // namespace

FrameRange parse_frame_range(const std::string& text) {
  FrameRange r;
  auto dash = text.find('-');
  if (dash == std::string::npos) {
    r.first = r.last = parse_frame_number(text, text);
    return r;
  }
  r.first = parse_frame_number(text.substr(0, dash), text);
  std::string tail = text.substr(dash + 1);
  r.last = tail.empty() ? -1 : parse_frame_number(tail, text);
  if (r.last >= 0 && r.last < r.first) throw std::invalid_argument("--frames: the last frame precedes the first in '" + text + "'");
  return r;
}

namespace {
// A terminal's line is rewritten no more often than this.
constexpr std::chrono::milliseconds kTerminalInterval(250);
}  // namespace

Progress::Progress(std::string what, long total, bool quiet, long units_per_item)
    : what_(std::move(what)),
      total_(total),
      quiet_(quiet),
      units_per_item_(units_per_item > 0 ? units_per_item : 1),
      terminal_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()) {}

bool Progress::due(long done) const {
  if (quiet_) return false;
  if (terminal_) return done >= total_ || std::chrono::steady_clock::now() - last_print_ >= kTerminalInterval;
  return done / units_per_item_ > last_item_printed_;
}

void Progress::update(long done, const std::string& detail) {
  if (!due(done)) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed / static_cast<double>(units_per_item_) : 0.0;
  const double eta = done > 0 ? elapsed * static_cast<double>(total_ - done) / static_cast<double>(done) : 0.0;
  // "\r\033[K": back to the line's start and clear it, so a shorter line leaves no tail.
  std::fprintf(stderr, "%s%s %ld/%ld  %.2f/s  %s  elapsed %.1f s  ETA %.1f s%s", terminal_ ? "\r\033[K" : "", what_.c_str(),
               done / units_per_item_, total_ / units_per_item_, rate, detail.c_str(), elapsed, eta, terminal_ ? "" : "\n");
  std::fflush(stderr);
  last_print_ = now;
  last_item_printed_ = done / units_per_item_;
  line_open_ = terminal_;
}

void Progress::finish(const std::string& summary) {
  if (quiet_) return;
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "%s%s done in %.1f s: %s\n", line_open_ ? "\n" : "", what_.c_str(), elapsed, summary.c_str());
  line_open_ = false;
}

}  // namespace dp::io
