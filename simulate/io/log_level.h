#pragma once
// How much the dewpoint executables say on stderr: errors only (--quiet),
// also warnings, also progress and summaries (the default), also one line
// per simulation step.
#include <string>

namespace dp::io {

enum class LogLevel { Error = 0, Warn = 1, Info = 2, Debug = 3 };

inline constexpr const char* kLogLevelNames = "error|warn|info|debug";

// Parses one of kLogLevelNames; throws std::invalid_argument naming the choices.
LogLevel parse_log_level(const std::string& name);

inline bool logs(LogLevel level, LogLevel message) { return static_cast<int>(message) <= static_cast<int>(level); }

}  // namespace dp::io
