#include "atomic_file.h"

#include <fstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace dp::io {

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  std::filesystem::path tmp = path;
  tmp += ".tmp" + std::to_string(::getpid());
  return tmp;
}

void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    // The reason is taken before the clean-up, which reuses (and clears) ec.
    const std::string reason = ec.message();
    std::filesystem::remove(temporary, ec);
    throw std::runtime_error(path.string() + ": cannot move the finished file into place: " + reason);
  }
}

void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
  const std::filesystem::path tmp = temporary_path_for(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
    try {
      write(out);
    } catch (...) {
      out.close();
      std::filesystem::remove(tmp);
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      std::filesystem::remove(tmp);
      throw std::runtime_error(path.string() + ": write failed (disk full?)");
    }
  }
  commit_temporary(tmp, path);
}

}  // namespace dp::io
