#pragma once
// A closed air box with a set of free texels in it, for Alg. 2's tests:
// the air grid and the textures' arrays are built here directly, so the
// exchange is tested apart from the rest of the step.
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "../air/air_test_setups.h"
#include "coupling/texel_vapor_exchange.h"
#include "surface/texel_mass_units.h"

namespace dp::test {

inline constexpr double kTestParticleMass = 1e-3;  // 1 cm spacing

struct TexelBox {
  CpuExec exec;
  AirSettings settings;
  SortedParticles none;
  AirGrid<CpuExec> air;
  std::vector<Vec3> position;
  std::vector<float> area, temperature, wetting;
  std::vector<TexelMassUnits> max_mass, mass;
  TexelVaporExchange<CpuExec> exchange;
  ExchangeParameters params;
  std::int64_t air_units = 0;  // units the air gained from the texels so far

  TexelBox(int threads, const AirSettings& s)
      : exec(threads), settings(s), none(exec, {}, s.domain_min, s.domain_max, 0.1f),
        air(exec, s, Vec3{0, -9.81f, 0}, none.view()) {
    params.kg_per_unit = kg_per_texel_unit(kTestParticleMass);
  }

  // count x count texels of side `step` on the plane y = height, from (x0, z0).
  void add_lattice(int count, float step, float height, float x0, float z0, float kelvin, double mass_kg, double cap_kg) {
    for (int j = 0; j < count; ++j)
      for (int i = 0; i < count; ++i) {
        position.push_back(Vec3{x0 + i * step, height, z0 + j * step});
        area.push_back(step * step);
        temperature.push_back(kelvin);
        wetting.push_back(0);
        max_mass.push_back(texel_units_of_kg(cap_kg, kTestParticleMass));
        mass.push_back(std::min(texel_units_of_kg(mass_kg, kTestParticleMass), max_mass.back()));
      }
  }
  void prepare() { exchange.prepare(exec, air.grid(), position); }

  TexelExchangeView view() {
    return TexelExchangeView{position.data(), area.data(), temperature.data(), wetting.data(), max_mass.data(), mass.data()};
  }
  // Alg. 2 only.
  void exchange_step(float dt) {
    params.dt = dt;
    const AirSnapshot a = air.snapshot();
    std::vector<Vec3> v(a.vapor.size());
    for (int k = 0; k < a.grid.nz; ++k)
      for (int j = 0; j < a.grid.ny; ++j)
        for (int i = 0; i < a.grid.nx; ++i) v[a.grid.cell(i, j, k)] = a.cell_velocity(i, j, k);
    air_units += exchange.exchange(exec, view(), air, v.data(), params);
  }
  // Alg. 2, then the air carries the vapor away.
  void step(float dt) {
    exchange_step(dt);
    air.step(exec, dt);
  }
  TexelMassSum texel_sum() const {
    TexelMassSum s;
    for (TexelMassUnits m : mass) s.add(m);
    return s;
  }
  double texel_kg() const { return texel_sum().kg(params.kg_per_unit); }
};

// The texels' units plus those the air was credited with: constant,
// exactly, if no transfer is lost or made up.
__extension__ typedef __int128 WideUnits;
inline WideUnits water_units(const TexelBox& b) {
  WideUnits s = b.air_units;
  for (TexelMassUnits m : b.mass) s += m;
  return s;
}

}  // namespace dp::test
