#include "air_vdb.h"

#include <openvdb/openvdb.h>

#include "vdb_file.h"

namespace dp::io {

namespace {

// Voxel centres in OpenVDB's index space sit on integer coordinates, so the
// index-to-world map is a scale by dx and a shift to cell (0, 0, 0)'s centre.
openvdb::math::Transform::Ptr cell_centre_transform(const MacGrid& g) {
  auto t = openvdb::math::Transform::createLinearTransform(g.dx);
  const Vec3 c = g.cell_center(0, 0, 0);
  t->postTranslate(openvdb::Vec3d(c.x, c.y, c.z));
  return t;
}

template <class GridT, class ValueAt>
typename GridT::Ptr dense_grid(const MacGrid& g, const char* name, const ValueAt& value) {
  auto grid = GridT::create();
  grid->setName(name);
  grid->setTransform(cell_centre_transform(g));
  auto acc = grid->getAccessor();
  // Every cell is written, ambient ones too: a reader sees the whole domain.
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) acc.setValueOn(openvdb::Coord(i, j, k), value(i, j, k));
  return grid;
}

}  // namespace

void write_air_frame(const std::filesystem::path& file, const AirSnapshot& air, const std::string& comment) {
  initialize_openvdb();
  const MacGrid& g = air.grid;
  auto vapor = dense_grid<openvdb::FloatGrid>(g, "vapor_density", [&](int i, int j, int k) {
    return static_cast<float>(air.vapor[g.cell(i, j, k)]);
  });
  vapor->setGridClass(openvdb::GRID_FOG_VOLUME);
  auto temperature = dense_grid<openvdb::FloatGrid>(g, "temperature", [&](int i, int j, int k) {
    return air.temperature[g.cell(i, j, k)];
  });
  auto velocity = dense_grid<openvdb::Vec3SGrid>(g, "velocity", [&](int i, int j, int k) {
    const Vec3 v = air.cell_velocity(i, j, k);
    return openvdb::Vec3s(v.x, v.y, v.z);
  });
  velocity->setVectorType(openvdb::VEC_INVARIANT);
  write_vdb_file(file, openvdb::GridCPtrVec{vapor, temperature, velocity}, comment);
}

}  // namespace dp::io
