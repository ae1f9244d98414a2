#include "liquid_level_set.h"

#include <cmath>

#include <openvdb/tools/SignedFloodFill.h>

#include "vdb_file.h"

namespace dp::mesh {

openvdb::FloatGrid::Ptr liquid_level_set(const ScalarGrid& field, float half_width) {
  io::initialize_openvdb();
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

}  // namespace dp::mesh
