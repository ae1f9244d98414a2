#pragma once
// The rigid-surface textures of a simulation (paper Sec. 4.3, 4.4, 5.2) on
// one backend: static texel data and the texel <-> rigid particle
// neighbourhoods, built once (rigids are static); each step, the texel
// temperatures from the rigid particles (Eq. 7) and the wetting history
// from the liquid particles. The evaporation / condensation coupling
// (Alg. 2, Sec. 6.2) reads and changes the mass textures held here.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend/sorted_runs.h"
#include "simulation.h"
#include "simulation_state.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/neighbor_list.h"
#include "sph/uniform_grid.h"
#include "surface/seeding_points.h"
#include "surface/texel_temperature_bonet2002.h"
#include "surface/wetting_history_wang2005.h"

namespace dp {

template <class Exec>
class SurfaceTextures {
 public:
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

  // One rigid's textures on the device.
  struct Texture {
    SurfaceTextureSetup setup;   // the static textures, host copy
    SeedingPoints seeds;         // host copy
    Buffer<Vec3> position, normal;
    Buffer<float> area;
    Buffer<TexelMassUnits> max_mass;  // m_t^max in units
    Buffer<TexelMassUnits> mass;      // m_t
    Buffer<float> temperature;        // T_t (K)
    Buffer<float> wetting;            // [0, 1]
    Buffer<Vec3> seed_position, seed_normal;
    Buffer<std::uint32_t> seed_texel_offset, seed_texel_index;
    NeighborListBuffers<Exec> rigid_neighbours;  // texel -> sorted rigid particles within h
    Buffer<float> rigid_weight;                  // Eq. 7's V_k W-bar_tk per neighbour-list entry
    // The sorted indices of this texture's own rigid's particles, the only
    // ones Eq. 7 weighs, and their temperatures at the last interpolation.
    Buffer<std::uint32_t> own_particle;
    Buffer<float> seen_temperature;
    bool interpolated = false;
    // The liquid grid's cells that hold texels and each texel's entry among
    // them (wetting history); built on the first step.
    SortedRuns<Exec> liquid_cells;
    Buffer<std::uint32_t> liquid_cell_slot;
    UniformGrid liquid_grid{};  // the grid those cells are of

    std::size_t size() const { return setup.texels.size(); }
    NeighborList rigid_list() const { return NeighborList{Exec::ptr(rigid_neighbours.offset), Exec::ptr(rigid_neighbours.index)}; }
  };

  // Builds the static data; `rigid_order[i]` is the setup index of sorted
  // rigid particle i. Throws std::invalid_argument on an inconsistent setup.
  void prepare(const Exec& exec, const SimulationSetup& setup, const GridView& rigid, const Buffer<std::uint32_t>& rigid_order,
               const Buffer<float>& rigid_volume, const Buffer<float>& rigid_temperature) {
    kernel_ = CubicSplineKernel::with_support(setup.support_radius());
    kg_per_unit_ = kg_per_texel_unit(setup.particle_mass());
    contact_radius_ = kWettingContactSpacings * setup.particle_spacing;
    textures_.clear();
    textures_.resize(setup.surfaces.size());
    for (std::size_t i = 0; i < setup.surfaces.size(); ++i) {
      const SurfaceTextureSetup& s = setup.surfaces[i];
      check(s, i, setup.rigid_position.size());
      Texture& tex = textures_[i];
      tex.setup = s;
      tex.seeds = make_seeding_points(s.texels, setup.particle_spacing);
      upload_static(tex, setup.particle_mass());
      tex.rigid_neighbours.build(exec, tex.position, rigid, kernel_.h);
      tex.rigid_weight.resize(tex.rigid_neighbours.index.size());
      exec.parallel_for(tex.size(), ComputeTexelWeights{tex.rigid_list(), Exec::ptr(tex.position), rigid.position,
                                                        Exec::ptr(rigid_volume), Exec::ptr(rigid_order),
                                                        static_cast<std::uint32_t>(s.rigid_first),
                                                        static_cast<std::uint32_t>(s.rigid_count), kernel_,
                                                        Exec::ptr(tex.rigid_weight)});
      tex.own_particle = own_particles(rigid_order, static_cast<std::uint32_t>(s.rigid_first), static_cast<std::uint32_t>(s.rigid_count));
    }
    interpolate_temperatures(exec, rigid_temperature);
  }

  // Alg. 1 line 14 (rigid particles -> texels, Eq. 7) and the wetting
  // history of this step's liquid particles.
  void step(const Exec& exec, float dt, const Buffer<float>& rigid_temperature, const GridView& liquid,
            std::size_t liquid_count) {
    interpolate_temperatures(exec, rigid_temperature);
    record_wetting(exec, dt, liquid, liquid_count);
  }

  std::size_t count() const { return textures_.size(); }
  Texture& texture(std::size_t i) { return textures_[i]; }
  const Texture& texture(std::size_t i) const { return textures_[i]; }
  double kg_per_unit() const { return kg_per_unit_; }

  // The textures' dynamic part, per rigid (simulation_state.h).
  std::vector<SurfaceState> states() const {
    std::vector<SurfaceState> out;
    for (const Texture& tex : textures_)
      out.push_back(SurfaceState{Exec::download(tex.mass), Exec::download(tex.temperature), Exec::download(tex.wetting)});
    return out;
  }
  // Throws std::invalid_argument when the count or sizes are not these textures'.
  void restore(const std::vector<SurfaceState>& states) {
    if (states.size() != textures_.size()) throw std::invalid_argument("surface state: number of textured rigids differs");
    for (std::size_t i = 0; i < textures_.size(); ++i) {
      const SurfaceState& s = states[i];
      Texture& tex = textures_[i];
      const std::size_t n = tex.size();
      if (s.mass_units.size() != n || s.temperature.size() != n || s.wetting.size() != n)
        throw std::invalid_argument("surface state: texel count of rigid " + std::to_string(i) + " differs");
      Exec::upload(tex.mass, s.mass_units);
      Exec::upload(tex.temperature, s.temperature);
      Exec::upload(tex.wetting, s.wetting);
      tex.interpolated = false;
    }
  }

  std::vector<SurfaceSnapshot> snapshots() const {
    std::vector<SurfaceSnapshot> out;
    for (const Texture& tex : textures_) {
      SurfaceSnapshot s;
      s.width = tex.setup.texels.width;
      s.height = tex.setup.texels.height;
      s.pixel = tex.setup.texels.pixel;
      s.max_mass = tex.setup.texels.max_mass;
      s.kg_per_unit = kg_per_unit_;
      s.mass_units = Exec::download(tex.mass);
      s.temperature = Exec::download(tex.temperature);
      s.wetting = Exec::download(tex.wetting);
      out.push_back(std::move(s));
    }
    return out;
  }

 private:
  static void check(const SurfaceTextureSetup& s, std::size_t i, std::size_t rigid_particles) {
    const TexelGeometry& g = s.texels;
    const std::string which = "surface texture " + std::to_string(i);
    if (g.width <= 0 || g.height <= 0) throw std::invalid_argument(which + ": resolution must be positive");
    const std::size_t n = g.size();
    if (g.position.size() != n || g.normal.size() != n || g.area.size() != n || g.max_mass.size() != n)
      throw std::invalid_argument(which + ": texel arrays differ in length");
    for (std::uint32_t p : g.pixel)
      if (p >= static_cast<std::size_t>(g.width) * g.height) throw std::invalid_argument(which + ": pixel index outside the atlas");
    if (s.rigid_first + s.rigid_count > rigid_particles) throw std::invalid_argument(which + ": rigid particle range out of bounds");
    if (!(s.wetting_decay >= 0)) throw std::invalid_argument(which + ": wetting decay time must be non-negative");
    if (!s.initial_wetting.empty() && s.initial_wetting.size() != n)
      throw std::invalid_argument(which + ": initial wetting has " + std::to_string(s.initial_wetting.size()) + " entries, expected " +
                                  std::to_string(n));
  }

  void upload_static(Texture& tex, float particle_mass) {
    const TexelGeometry& g = tex.setup.texels;
    const std::size_t n = g.size();
    std::vector<TexelMassUnits> max_units(n), mass(n);
    for (std::size_t t = 0; t < n; ++t) {
      max_units[t] = texel_units_of_kg(g.max_mass[t], particle_mass);
      const double initial = std::fmin(static_cast<double>(tex.setup.initial_mass_per_area) * g.area[t], g.max_mass[t]);
      mass[t] = std::min(texel_units_of_kg(initial, particle_mass), max_units[t]);
    }
    Exec::upload(tex.position, g.position);
    Exec::upload(tex.normal, g.normal);
    Exec::upload(tex.area, g.area);
    Exec::upload(tex.max_mass, max_units);
    Exec::upload(tex.mass, mass);
    Exec::upload(tex.temperature, std::vector<float>(n, tex.setup.initial_temperature));
    Exec::upload(tex.wetting, tex.setup.initial_wetting.size() == n ? tex.setup.initial_wetting : std::vector<float>(n, 0.0f));
    Exec::upload(tex.seed_position, tex.seeds.position);
    Exec::upload(tex.seed_normal, tex.seeds.normal);
    Exec::upload(tex.seed_texel_offset, tex.seeds.texel_offset);
    Exec::upload(tex.seed_texel_index, tex.seeds.texel_index);
  }

  // Eq. 7 is a fixed linear map of the temperatures of a texture's own
  // rigid (other rigids' particles have weight 0): when none of them changed
  // since its last interpolation (a rigid held at its temperature, or no heat
  // reaching it), neither do its texels'. The check is per texture: SCA
  // Logo's 4 degC mirror is held, but the tray it stands in warms, and a
  // check over all rigid particles re-interpolated the mirror's 1M texels
  // whenever the tray changed (14 ms of a 17 ms Heat step).
  void interpolate_temperatures(const Exec& exec, const Buffer<float>& rigid_temperature) {
    for (Texture& tex : textures_) {
      const std::size_t n = tex.own_particle.size();
      const DifferentAt differs{Exec::ptr(rigid_temperature), Exec::ptr(tex.own_particle), Exec::ptr(tex.seen_temperature)};
      if (tex.interpolated && exec.find_first(n, differs) == n) continue;
      tex.seen_temperature.resize(n);
      exec.parallel_for(n, GatherAt{Exec::ptr(rigid_temperature), Exec::ptr(tex.own_particle), Exec::ptr(tex.seen_temperature)});
      tex.interpolated = true;
      exec.parallel_for(tex.size(), InterpolateTexelTemperature{tex.rigid_list(), Exec::ptr(tex.rigid_weight),
                                                                Exec::ptr(rigid_temperature), Exec::ptr(tex.temperature)});
    }
  }

  // The sorted indices i whose setup index rigid_order[i] lies in
  // [first, first + count), ascending.
  static Buffer<std::uint32_t> own_particles(const Buffer<std::uint32_t>& rigid_order, std::uint32_t first, std::uint32_t count) {
    const std::vector<std::uint32_t> order = Exec::download(rigid_order);
    std::vector<std::uint32_t> own;
    own.reserve(count);
    for (std::size_t i = 0; i < order.size(); ++i)
      if (of_rigid(order[i], first, count)) own.push_back(static_cast<std::uint32_t>(i));
    Buffer<std::uint32_t> out;
    Exec::upload(out, own);
    return out;
  }

  void record_wetting(const Exec& exec, float dt, const GridView& liquid, std::size_t liquid_count) {
    if (textures_.empty()) return;
    for (Texture& tex : textures_) {
      if (tex.size() == 0) continue;
      if (tex.liquid_cell_slot.size() != tex.size() || !same_grid(tex.liquid_grid, liquid.grid)) find_liquid_cells(exec, tex, liquid.grid);
      near_liquid_.resize(tex.liquid_cells.count);
      exec.parallel_for(tex.liquid_cells.count, MarkCellsNearLiquid{liquid, Exec::ptr(near_liquid_), Exec::ptr(tex.liquid_cells.key)});
      const float decay = tex.setup.wetting_decay;
      const float dry = decay > 0 ? std::exp(-dt / decay) : 0.0f;
      // Without liquid nothing touches; the history only fades.
      const float r = liquid_count > 0 ? contact_radius_ : -1.0f;
      exec.parallel_for(tex.size(), RecordWetting{liquid, Exec::ptr(near_liquid_), Exec::ptr(tex.position), Exec::ptr(tex.normal),
                                                  r, dry, Exec::ptr(tex.wetting), Exec::ptr(tex.liquid_cell_slot)});
    }
  }

  static bool same_grid(const UniformGrid& h, const UniformGrid& g) {
    return g.origin.x == h.origin.x && g.origin.y == h.origin.y && g.origin.z == h.origin.z && g.cell_size == h.cell_size &&
           g.nx == h.nx && g.ny == h.ny && g.nz == h.nz;
  }

  void find_liquid_cells(const Exec& exec, Texture& tex, const UniformGrid& g) {
    const std::size_t n = tex.size();
    Buffer<std::uint32_t> key(n), texel(n);
    exec.parallel_for(n, ComputeCellKeys{g, Exec::ptr(tex.position), Exec::ptr(key), Exec::ptr(texel)});
    exec.sort_by_key(key, texel);
    tex.liquid_cells.build(exec, key);
    tex.liquid_cell_slot.resize(n);
    exec.parallel_for(tex.liquid_cells.count, TexelSlotOfRun{Exec::ptr(tex.liquid_cells.begin), Exec::ptr(texel),
                                                             Exec::ptr(tex.liquid_cell_slot)});
    tex.liquid_grid = g;
  }

  std::vector<Texture> textures_;
  Buffer<std::uint8_t> near_liquid_;  // per listed cell of one texture, this step
  CubicSplineKernel kernel_{};
  double kg_per_unit_ = 0;
  float contact_radius_ = 0;
};

}  // namespace dp
