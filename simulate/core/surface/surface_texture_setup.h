#pragma once
// The static textures of one rigid (paper Sec. 4.3) as plain numbers, made
// by simulate/io from the rigid's mesh and UV atlas, and the snapshot of the
// dynamic textures that the core hands back. Only texels inside a chart are
// stored (a compact list with each texel's pixel), so the chart mask is the
// list itself and no work is spent on the atlas's empty space.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "math/vec3.h"
#include "surface/texel_mass_units.h"

namespace dp {

struct TexelGeometry {
  int width = 0, height = 0;          // atlas resolution
  std::vector<std::uint32_t> pixel;   // row * width + col; row 0 is the top (v = 1 - (row + 0.5) / height)
  std::vector<Vec3> position;         // x_t: world centroid of the surface patch that maps into the texel (m)
  std::vector<Vec3> normal;           // unit, area-weighted over the patch
  std::vector<float> area;            // A_t: world area of the patch (m^2)
  std::vector<float> max_mass;        // m_t^max (kg)

  std::size_t size() const { return pixel.size(); }
  // 1 for pixels inside a chart, 0 elsewhere; width * height entries.
  std::vector<std::uint8_t> chart_mask() const {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(width) * height, 0);
    for (std::uint32_t p : pixel) mask[p] = 1;
    return mask;
  }
};

// One rigid's texture in SimulationSetup::surfaces.
struct SurfaceTextureSetup {
  // This rigid's particles: SimulationSetup::rigid_position[rigid_first, rigid_first + rigid_count).
  // Eq. 7 interpolates only from them.
  std::size_t rigid_first = 0, rigid_count = 0;
  TexelGeometry texels;
  float initial_mass_per_area = 0;   // kg/m^2; each texel starts with min(this * A_t, m_t^max)
  float initial_temperature = 293.15f;  // K, for texels no rigid particle reaches
  float wetting_decay = 1.0f;        // s: the wetting history falls by 1/e in this time once dry (0: no memory)
  std::vector<float> initial_wetting;  // per texel in [0, 1]; empty: dry
};

// Seeding points of liquid particles on a surface (Sec. 4.3, 6.2), each with
// the texels it takes mass from: texel_index[texel_offset[s], texel_offset[s + 1]).
struct SeedingPoints {
  std::vector<Vec3> position, normal;
  std::vector<std::uint32_t> texel_offset, texel_index;
  std::size_t size() const { return position.size(); }
};

// The dynamic textures of one rigid, in the order of its TexelGeometry.
struct SurfaceSnapshot {
  int width = 0, height = 0;
  std::vector<std::uint32_t> pixel;
  std::vector<TexelMassUnits> mass_units;  // m_t, exact
  double kg_per_unit = 0;                  // kg of one texel mass unit
  std::vector<float> max_mass;             // m_t^max (kg)
  std::vector<float> temperature;          // T_t (K)
  std::vector<float> wetting;              // wetting history in [0, 1]
  std::size_t size() const { return pixel.size(); }
  TexelMassSum total_mass() const {
    TexelMassSum sum;
    for (TexelMassUnits m : mass_units) sum.add(m);
    return sum;
  }
};

}  // namespace dp
