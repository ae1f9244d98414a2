#pragma once
// Every output file lands whole or not at all: written to a temporary name
// in the same directory, then renamed into place.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace dp::io {

// Calls write(stream) on a temporary file, then renames it to `path`.
// Throws std::runtime_error naming the file on any failure; the previous
// file at `path`, if any, is then untouched.
void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

// The temporary name used for `path`, for writers (such as OpenEXR's) that
// open files themselves; pair with commit_temporary.
std::filesystem::path temporary_path_for(const std::filesystem::path& path);
void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& path);

}  // namespace dp::io
