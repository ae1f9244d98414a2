#pragma once
// Writing OpenVDB files the way every output of ours is written: through a
// temporary name, renamed into place whole, with a `comment` metadata entry
// naming the generator. Shared by the simulator's air frames and the
// mesher's level sets.
#include <filesystem>
#include <string>

#include <openvdb/openvdb.h>

namespace dp::io {

// Registers OpenVDB's grid types once per process (needed to write or read files).
void initialize_openvdb();

// Throws std::runtime_error naming the file on failure; an earlier file at
// `file` is then untouched.
void write_vdb_file(const std::filesystem::path& file, const openvdb::GridCPtrVec& grids, const std::string& comment);

}  // namespace dp::io
