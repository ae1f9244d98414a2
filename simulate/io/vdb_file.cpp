#include "vdb_file.h"

#include <mutex>
#include <stdexcept>
#include <system_error>

#include "atomic_file.h"

namespace dp::io {

void initialize_openvdb() {
  static std::once_flag initialised;
  std::call_once(initialised, [] { openvdb::initialize(); });
}

void write_vdb_file(const std::filesystem::path& file, const openvdb::GridCPtrVec& grids, const std::string& comment) {
  initialize_openvdb();
  const std::filesystem::path tmp = temporary_path_for(file);
  try {
    openvdb::io::File out(tmp.string());
    openvdb::MetaMap meta;
    meta.insertMeta("comment", openvdb::StringMetadata(comment));
    out.write(grids, meta);
    out.close();
  } catch (const openvdb::Exception& e) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error(file.string() + ": cannot write OpenVDB file: " + e.what());
  }
  commit_temporary(tmp, file);
}

}  // namespace dp::io
