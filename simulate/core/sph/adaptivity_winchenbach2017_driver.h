#pragma once
// Host side of the dynamic particle adjustment (paper Sec. 6.3, Alg. 1 line
// 18): rounds of sort into the grid, mutual partner choice, merge or
// redistribution, and removal of emptied particles. Written against the
// backend interface only, so the same code runs on CpuExec and CudaExec.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "sph/adaptivity_winchenbach2017.h"
#include "sph/mass_units.h"
#include "sph/particle_grid.h"

namespace dp {

// The per-particle state that survives a merge or redistribution. `extra`
// carries any further intensive attributes of the caller, attribute-major
// (attribute a of particle i at extra[a * size() + i]), blended like the
// temperature.
template <class Exec>
struct AdaptiveParticles {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

  Buffer<Vec3> position, velocity;
  Buffer<float> temperature;
  Buffer<MassUnits> units;
  Buffer<std::uint32_t> id;
  Buffer<float> extra;
  std::size_t extra_count = 0;

  std::size_t size() const { return units.size(); }

  bool sizes_agree() const {
    const std::size_t n = size();
    return position.size() == n && velocity.size() == n && temperature.size() == n && id.size() == n &&
           extra.size() == n * extra_count;
  }

  void resize(std::size_t n, std::size_t extra_attributes) {
    position.resize(n);
    velocity.resize(n);
    temperature.resize(n);
    units.resize(n);
    id.resize(n);
    extra.resize(n * extra_attributes);
    extra_count = extra_attributes;
  }

  void swap(AdaptiveParticles& other) {
    position.swap(other.position);
    velocity.swap(other.velocity);
    temperature.swap(other.temperature);
    units.swap(other.units);
    id.swap(other.id);
    extra.swap(other.extra);
    std::swap(extra_count, other.extra_count);
  }

  AdaptiveSource source() const {
    return AdaptiveSource{Exec::ptr(position), Exec::ptr(velocity), Exec::ptr(temperature), Exec::ptr(units),
                          Exec::ptr(id),       Exec::ptr(extra),    size(),                 extra_count};
  }
  AdaptiveTarget target() {
    return AdaptiveTarget{Exec::ptr(position), Exec::ptr(velocity), Exec::ptr(temperature), Exec::ptr(units),
                          Exec::ptr(id),       Exec::ptr(extra),    size(),                 extra_count};
  }
};

struct AdaptivityParameters {
  // Partners lie within this distance; at most the grid's cell size. The
  // support radius h is the natural choice: partners are SPH neighbours.
  float search_radius = 0;
  // Only pairs with a particle below this weight merge or redistribute. At
  // 0.5 every pairing lifts the small particle to at least 0.5 (a merge of
  // two below 0.5 stays <= 1, a redistribution ends at the mean > 0.5), so a
  // particle is adjusted once and nothing oscillates.
  float small_weight = 0.5f;
  // Pairing rounds per call; each round costs one sort. Stops early once a
  // round forms no pair.
  int max_rounds = 1;
};

struct AdaptivityResult {
  int rounds = 0;                       // rounds that formed at least one pair
  std::size_t merges = 0;               // merged pairs
  std::size_t redistributions = 0;      // pairs that evened out their weights
  std::size_t removed_particles = 0;    // particles dropped with zero units
  std::int64_t removed_units = 0;       // units lost by the call: 0 unless a kernel breaks conservation
};

template <class Exec>
class MassAdaptivity {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

 public:
  // `grid` needs a cell size of at least the search radius.
  explicit MassAdaptivity(const UniformGrid& grid) { grid_.grid = grid; }

  // Removes the particles that end with zero units, including any that came
  // in with zero units. Once a round has run, the particles are in grid order
  // (stable within a cell); the caller's other per-particle buffers are stale.
  AdaptivityResult adapt(const Exec& exec, AdaptiveParticles<Exec>& particles, const AdaptivityParameters& params) {
    if (!(params.search_radius > 0.0f) || params.search_radius > grid_.grid.cell_size)
      throw std::invalid_argument("adaptivity: search radius must be positive and at most the grid cell size");
    if (!particles.sizes_agree())
      throw std::invalid_argument("adaptivity: particle arrays differ in length (extra must hold extra_count per particle)");
    AdaptivityResult result;
    const double units_before = total_units(exec, particles);
    const MassUnits small_units = units_of_weight(params.small_weight);
    const float radius2 = params.search_radius * params.search_radius;
    for (int round = 0; round < params.max_rounds && particles.size() > 1; ++round) {
      sort_into_cells(exec, particles);
      const std::size_t n = particles.size();
      partner_.resize(n);
      exec.parallel_for(n, ChooseAdaptivityPartner{grid_.view(particles.position), Exec::ptr(particles.units),
                                                   small_units, radius2, Exec::ptr(partner_)});
      const std::size_t merges = count_role(exec, particles, PairRole::MergeSurvivor);
      const std::size_t redistributions = count_role(exec, particles, PairRole::Receiver);
      if (merges + redistributions == 0) break;
      scratch_.resize(n, particles.extra_count);
      exec.parallel_for(n, ApplyAdaptivityPairs{particles.source(), Exec::ptr(partner_), scratch_.target()});
      particles.swap(scratch_);
      result.removed_particles += remove_empty(exec, particles);
      result.merges += merges;
      result.redistributions += redistributions;
      ++result.rounds;
    }
    result.removed_particles += remove_empty(exec, particles);
    result.removed_units = static_cast<std::int64_t>(units_before - total_units(exec, particles));
    return result;
  }

  // Drops particles with zero units, keeping the order of the others;
  // returns how many were dropped.
  std::size_t remove_empty(const Exec& exec, AdaptiveParticles<Exec>& particles) {
    const std::size_t n = particles.size();
    live_.resize(n);
    exec.parallel_for(n, MarkLive{Exec::ptr(particles.units), Exec::ptr(live_)});
    const std::size_t kept = static_cast<std::size_t>(exec.sum(n, FlagAt{Exec::ptr(live_)}));
    if (kept == n) return 0;
    exec.exclusive_scan(live_, live_before_);
    source_.resize(kept);
    exec.parallel_for(kept, SourceOfLive{Exec::ptr(live_before_), n, Exec::ptr(source_)});
    gather_into_scratch(exec, particles, source_, kept);
    return n - kept;
  }

 private:
  static MassUnits units_of_weight(float weight) {
    const float clamped = weight < 0.0f ? 0.0f : (weight > 1.0f ? 1.0f : weight);
    return static_cast<MassUnits>(static_cast<double>(clamped) * kFullParticleUnits);
  }

  static double total_units(const Exec& exec, const AdaptiveParticles<Exec>& particles) {
    return exec.sum(particles.size(), UnitsAt{Exec::ptr(particles.units)});
  }

  std::size_t count_role(const Exec& exec, const AdaptiveParticles<Exec>& particles, PairRole role) const {
    return static_cast<std::size_t>(
        exec.sum(particles.size(), HasPairRole{Exec::ptr(partner_), Exec::ptr(particles.units), role}));
  }

  // Partners are searched in the grid, which needs the particles themselves
  // in cell order; the step's own sort is stale by the time adaptivity runs.
  void sort_into_cells(const Exec& exec, AdaptiveParticles<Exec>& particles) {
    grid_.sort(exec, particles.position);
    gather_into_scratch(exec, particles, grid_.order, particles.size());
    grid_.find_ranges(exec);
  }

  void gather_into_scratch(const Exec& exec, AdaptiveParticles<Exec>& particles, const Buffer<std::uint32_t>& source,
                           std::size_t count) {
    scratch_.resize(count, particles.extra_count);
    exec.parallel_for(count, GatherParticles{particles.source(), Exec::ptr(source), scratch_.target()});
    particles.swap(scratch_);
  }

  ParticleGrid<Exec> grid_;
  AdaptiveParticles<Exec> scratch_;
  Buffer<std::uint32_t> partner_, live_, live_before_, source_;
};

// One-off form of MassAdaptivity::adapt, for callers without a persistent
// instance (its buffers are allocated per call).
template <class Exec>
AdaptivityResult adapt_particle_masses(const Exec& exec, AdaptiveParticles<Exec>& particles, const UniformGrid& grid,
                                       const AdaptivityParameters& params) {
  MassAdaptivity<Exec> adaptivity(grid);
  return adaptivity.adapt(exec, particles, params);
}

}  // namespace dp
