#pragma once
// The wetting history texture (paper Sec. 4.3, 6.2, after Wang, Mucha &
// Turk 2005, "Water Drops on Surfaces"): 1 where a liquid particle touches a
// texel, fading as exp(-elapsed / decay time) once the texel is dry. It
// records the paths particles ran along (for rendering) and marks recently
// wetted texels, which do not condense (Sec. 6.2). The paper does not say
// when a particle touches a texel; here it is when the particle's centre
// lies on the texel's front side within the contact radius (sqrt(2) times
// the particle spacing: a particle resting at its equilibrium distance of
// one spacing from an Akinci 2012 boundary then wets a disc of radius one
// spacing, the wall area it covers in a packed layer).
#include <cstdint>

#include "backend/host_device.h"
#include "sph/uniform_grid.h"

namespace dp {

// Per grid cell: 1 when any liquid particle lies in the 27 cells around it.
// Most texels are far from the liquid; this lets each of them decide with
// one load instead of walking nine rows of cells. With `cells`, only for
// the listed cells (those holding texels), near[s] for cells[s]: the grid
// around a small drop is mostly empty air that no texel reads.
struct MarkCellsNearLiquid {
  GridView liquid;
  std::uint8_t* near;
  const std::uint32_t* cells = nullptr;  // null: every cell, near[c]

  DP_HD void operator()(std::size_t s) const {
    const std::size_t c = cells ? cells[s] : s;
    const UniformGrid& g = liquid.grid;
    const int i = static_cast<int>(c % g.nx), j = static_cast<int>((c / g.nx) % g.ny), k = static_cast<int>(c / (static_cast<std::size_t>(g.nx) * g.ny));
    const int i0 = i > 0 ? i - 1 : 0, i1 = i + 1 < g.nx ? i + 1 : g.nx - 1;
    bool any = false;
    for (int kk = k - 1; kk <= k + 1; ++kk)
      for (int jj = j - 1; jj <= j + 1; ++jj)
        if (kk >= 0 && kk < g.nz && jj >= 0 && jj < g.ny)
          any = any || liquid.cell_begin[g.linear(i0, jj, kk)] < liquid.cell_end[g.linear(i1, jj, kk)];
    near[s] = any ? 1 : 0;
  }
};

struct RecordWetting {
  GridView liquid;              // this step's liquid particles
  const std::uint8_t* near;     // MarkCellsNearLiquid of the same step
  const Vec3* texel_position;
  const Vec3* texel_normal;
  float contact_radius;         // m; negative: nothing touches
  float dry_factor;             // exp(-dt / decay time)
  float* wetting;
  const std::uint32_t* near_slot = nullptr;  // per texel, its cell's entry in `near` (null: the cell's key)

  DP_HD float contact_radius2() const { return contact_radius < 0.0f ? -1.0f : contact_radius * contact_radius; }

  // Only the cells within the contact radius are visited (it is below the
  // cell size h: about 8 cells in place of 27). A row of cells is tested
  // whole, its particles' tests or-ed without a branch (the loop
  // vectorises), and the rows after the first touching one are skipped: a
  // branch per particle was mispredicted at random.
  DP_HD void operator()(std::size_t t) const {
    const Vec3 xt = texel_position[t], nt = texel_normal[t];
    const float r2 = contact_radius2();
    bool touched = false;
    if (near[near_slot ? near_slot[t] : liquid.grid.key_of(xt)])
      liquid.for_each_run_within(xt, contact_radius, [&](std::uint32_t first, std::uint32_t end) {
        if (touched) return;
        unsigned any = 0;
        for (std::uint32_t i = first; i < end; ++i) {
          const Vec3 d = liquid.position[i] - xt;
          any |= static_cast<unsigned>(length_squared(d) < r2) & static_cast<unsigned>(dot(d, nt) >= 0.0f);
        }
        touched = any != 0;
      });
    wetting[t] = touched ? 1.0f : wetting[t] * dry_factor;
  }
};

// Once per texture: each texel's slot in the list of the liquid grid's
// cells that hold texels (runs of the texels sorted by cell).
struct TexelSlotOfRun {
  const std::uint32_t* run_begin;
  const std::uint32_t* sorted_texel;
  std::uint32_t* slot;
  DP_HD void operator()(std::size_t r) const {
    for (std::uint32_t q = run_begin[r]; q < run_begin[r + 1]; ++q) slot[sorted_texel[q]] = static_cast<std::uint32_t>(r);
  }
};

inline constexpr float kWettingContactSpacings = 1.41421356f;

}  // namespace dp
