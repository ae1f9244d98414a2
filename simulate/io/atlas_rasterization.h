#pragma once
// Rasterises an atlas into the static texel data of paper Sec. 4.3: each
// triangle's image in the atlas is clipped exactly against every texel
// square it overlaps, and the clipped piece carries the world area it maps
// from (a triangle's UV map is affine, so areas scale by one factor per
// triangle). Hence A_t sums to the mesh's area up to rounding, x_t is the
// world centroid of the texel's surface patch and n_t its area-weighted
// normal. m_t^max is left at zero (max_mass_texture.h fills it).
#include "surface/surface_texture_setup.h"
#include "surface_atlas.h"

namespace dp::io {

struct AtlasRaster {
  TexelGeometry texels;
  double mesh_area = 0;       // world area of all triangles (m^2)
  double lost_area = 0;       // world area of triangles with no UV area (m^2)
  double max_coverage = 0;    // largest fraction of a texel covered by triangles; above 1: overlapping UVs
};

AtlasRaster rasterize_atlas(const AtlasMesh& atlas, int width, int height);

}  // namespace dp::io
