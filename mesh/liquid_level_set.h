#pragma once
// The field the mesher contours (Zhu-Bridson's distance with the wall
// corrections, paper Eq. 19-24) as an OpenVDB level set, for users who mesh
// or simulate further in Houdini or Blender: a FloatGrid of class level set
// named "surface", negative inside, in world units, with a transform that
// puts voxel (i, j, k) on the sampling grid's node (i, j, k). Voxels within
// `half_width` voxels of the surface are active and hold the field; the rest
// hold -/+ half_width voxel sizes inside/outside, as OpenVDB level sets do.
// The field is Zhu-Bridson's approximate distance, not a redistanced one:
// |grad phi| is near 1 at the surface only.
#include <openvdb/openvdb.h>

#include "scalar_grid.h"

namespace dp::mesh {

inline constexpr float kLevelSetHalfWidth = 3.0f;  // voxels, OpenVDB's LEVEL_SET_HALF_WIDTH

openvdb::FloatGrid::Ptr liquid_level_set(const ScalarGrid& field, float half_width = kLevelSetHalfWidth);

}  // namespace dp::mesh
