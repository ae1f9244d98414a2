#pragma once
// --log-level and --quiet, the same on every dewpoint executable.
#include <CLI/CLI.hpp>

#include <string>

#include "log_level.h"

namespace dp::io {

struct LogOptions {
  std::string level = "info";
  bool quiet = false;
  // --quiet is --log-level error.
  LogLevel effective() const { return quiet ? LogLevel::Error : parse_log_level(level); }
};

inline void add_log_options(CLI::App& app, LogOptions& options) {
  CLI::Option* level = app.add_option("--log-level", options.level,
                                      "what to say on stderr: error, warn (also warnings), info (also progress; the default) "
                                      "or debug (also one line per step)")
                           ->check(CLI::IsMember({"error", "warn", "info", "debug"}));
  app.add_flag("--quiet", options.quiet, "errors only (--log-level error)")->excludes(level);
}

}  // namespace dp::io
