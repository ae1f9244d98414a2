#include "liquid_level_set.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include <openvdb/tools/SignedFloodFill.h>

#include "atomic_file.h"

namespace dp::mesh {

openvdb::FloatGrid::Ptr liquid_level_set(const ScalarGrid& field, float half_width) {
  static std::once_flag initialised;
  std::call_once(initialised, [] { openvdb::initialize(); });
  const GridBox& box = field.box;
  const float band = half_width * static_cast<float>(box.voxel_size);
  auto grid = openvdb::FloatGrid::create(band);
  grid->setName("surface");
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  auto transform = openvdb::math::Transform::createLinearTransform(box.voxel_size);
  transform->postTranslate(openvdb::Vec3d(box.origin.x, box.origin.y, box.origin.z));
  grid->setTransform(transform);
  auto acc = grid->getAccessor();
  for (int k = 0; k < box.nodes[2]; ++k)
    for (int j = 0; j < box.nodes[1]; ++j)
      for (int i = 0; i < box.nodes[0]; ++i) {
        const float phi = field.at(i, j, k);
        if (std::fabs(phi) < band) acc.setValueOn(openvdb::Coord(i, j, k), phi);
      }
  // The inactive voxels and tiles enclosed by the band take -band: inside.
  openvdb::tools::signedFloodFill(grid->tree());
  return grid;
}

void write_liquid_level_set(const std::filesystem::path& file, const openvdb::FloatGrid::Ptr& grid, const std::string& comment) {
  const std::filesystem::path tmp = io::temporary_path_for(file);
  try {
    openvdb::io::File out(tmp.string());
    openvdb::MetaMap meta;
    meta.insertMeta("comment", openvdb::StringMetadata(comment));
    out.write(openvdb::GridCPtrVec{grid}, meta);
    out.close();
  } catch (const openvdb::Exception& e) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error(file.string() + ": cannot write OpenVDB file: " + e.what());
  }
  io::commit_temporary(tmp, file);
}

}  // namespace dp::mesh
