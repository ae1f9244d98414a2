#include "log_level.h"

#include <stdexcept>

namespace dp::io {

LogLevel parse_log_level(const std::string& name) {
  if (name == "error") return LogLevel::Error;
  if (name == "warn") return LogLevel::Warn;
  if (name == "info") return LogLevel::Info;
  if (name == "debug") return LogLevel::Debug;
  throw std::invalid_argument(std::string("--log-level: expected one of ") + kLogLevelNames + ", found '" + name + "'");
}

}  // namespace dp::io
