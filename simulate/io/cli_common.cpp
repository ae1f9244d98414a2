#include "cli_common.h"

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

Progress::Progress(std::string what, long total, bool quiet)
    : what_(std::move(what)), total_(total), quiet_(quiet), start_(std::chrono::steady_clock::now()) {}

void Progress::update(long done, const std::string& detail) {
  if (quiet_) return;
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double eta = done > 0 ? elapsed * static_cast<double>(total_ - done) / static_cast<double>(done) : 0.0;
  std::fprintf(stderr, "%s %ld/%ld  %s  elapsed %.1f s  ETA %.1f s\n", what_.c_str(), done, total_, detail.c_str(),
               elapsed, eta);
}

void Progress::finish(const std::string& summary) {
  if (quiet_) return;
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "%s done in %.1f s: %s\n", what_.c_str(), elapsed, summary.c_str());
}

}  // namespace dp::io
