#pragma once
// Dynamic particle adjustment (paper Sec. 6.3, Eq. 18), after the merging and
// mass redistribution of Winchenbach et al. 2017: particles drift towards the
// full weight w = 1 by merging with a neighbour when w_i + w_j <= 1 and by
// evening out their weights with a neighbour otherwise.
//
// Pairs are formed without atomics: every live particle names its best
// partner under one strict order on pairs (ranks_before), and a pair exists
// only where two particles name each other. A particle is thus in at most one
// pair, and the globally best qualifying pair always names itself from both
// ends, so every round makes progress. Each kernel gathers and writes only
// its own element; the result does not depend on thread count.
//
// Weights are integer mass units (mass_units.h), so a merge or a
// redistribution moves whole units and total mass is conserved exactly.
// Position, velocity, temperature and the extra attributes are intensive
// (per unit mass) and are blended with the units as weights (Eq. 18), which
// conserves momentum, centre of mass and heat up to float rounding.
#include <cstddef>
#include <cstdint>

#include "backend/host_device.h"
#include "math/vec3.h"
#include "sph/mass_units.h"
#include "sph/uniform_grid.h"

namespace dp {

inline constexpr std::uint32_t kNoPartner = 0xffffffffu;

// Read-only view of the adaptive particle arrays. `extra` holds extra_count
// attributes, attribute-major: attribute a of particle i is extra[a * size + i].
struct AdaptiveSource {
  const Vec3* position;
  const Vec3* velocity;
  const float* temperature;
  const MassUnits* units;
  const std::uint32_t* id;
  const float* extra;
  std::size_t size;
  std::size_t extra_count;
};

// Writable view of the same layout.
struct AdaptiveTarget {
  Vec3* position;
  Vec3* velocity;
  float* temperature;
  MassUnits* units;
  std::uint32_t* id;
  float* extra;
  std::size_t size;
  std::size_t extra_count;
};

// Merging comes before redistribution: it brings a small particle to the
// target size and lowers the particle count, redistribution only evens out.
enum class PairKind : int { Merge = 0, Redistribute = 1, None = 2 };

enum class PairRole : int { None, MergeSurvivor, MergeAbsorbed, Giver, Receiver };

DP_HD inline bool merge_fits(MassUnits a, MassUnits b) {
  return static_cast<std::uint64_t>(a) + b <= kFullParticleUnits;
}

// The units the larger particle hands to the smaller so that both end at the
// mean weight; the odd unit of an odd difference stays with the larger one.
DP_HD inline MassUnits redistributed_units(MassUnits larger, MassUnits smaller) { return (larger - smaller) / 2; }

// What two live particles may do together. Only pairs with a small particle
// (below `small_units`) take part: particles near the target size are left
// alone. The rule is symmetric in (a, b), which the mutual choice relies on.
DP_HD inline PairKind pair_kind(MassUnits a, MassUnits b, MassUnits small_units) {
  MassUnits lo = a < b ? a : b, hi = a < b ? b : a;
  if (lo == 0 || lo >= small_units) return PairKind::None;
  if (merge_fits(a, b)) return PairKind::Merge;
  return redistributed_units(hi, lo) > 0 ? PairKind::Redistribute : PairKind::None;
}

// A candidate pair in the one strict order shared by both of its ends: kind,
// then squared distance, then the pair's indices. Both ends compute the same
// squared distance bit for bit (x_i - x_j is the exact negation of x_j - x_i).
struct PairRank {
  PairKind kind;
  float distance2;
  std::uint32_t lo, hi;
};

DP_HD inline PairRank rank_of_pair(PairKind kind, float distance2, std::uint32_t i, std::uint32_t j) {
  return PairRank{kind, distance2, i < j ? i : j, i < j ? j : i};
}

DP_HD inline bool ranks_before(const PairRank& a, const PairRank& b) {
  if (a.kind != b.kind) return static_cast<int>(a.kind) < static_cast<int>(b.kind);
  if (a.distance2 != b.distance2) return a.distance2 < b.distance2;
  if (a.lo != b.lo) return a.lo < b.lo;
  return a.hi < b.hi;
}

// partner[i] = the best qualifying neighbour within the search radius, or
// kNoPartner. `particles` must be the grid view of the same (sorted) arrays.
struct ChooseAdaptivityPartner {
  GridView particles;
  const MassUnits* units;
  MassUnits small_units;
  float radius2;
  std::uint32_t* partner;
  DP_HD void operator()(std::size_t i) const {
    const std::uint32_t self = static_cast<std::uint32_t>(i);
    const MassUnits ui = units[i];
    const Vec3 xi = particles.position[i];
    PairRank best{PairKind::None, 0.0f, 0, 0};
    std::uint32_t chosen = kNoPartner;
    if (ui > 0) {
      particles.for_each_near(xi, [&](std::uint32_t j) {
        if (j == self) return;
        const PairKind kind = pair_kind(ui, units[j], small_units);
        if (kind == PairKind::None) return;
        const float d2 = length_squared(xi - particles.position[j]);
        if (!(d2 <= radius2)) return;  // also rejects NaN
        const PairRank rank = rank_of_pair(kind, d2, self, j);
        if (chosen == kNoPartner || ranks_before(rank, best)) {
          best = rank;
          chosen = j;
        }
      });
    }
    partner[i] = chosen;
  }
};

// Particle i's part in this round's pairing. Survivor of a merge is the lower
// index, so that exactly one of the two carries the merged state.
DP_HD inline PairRole pair_role(std::size_t i, const std::uint32_t* partner, const MassUnits* units) {
  const std::uint32_t j = partner[i];
  if (j == kNoPartner || partner[j] != static_cast<std::uint32_t>(i)) return PairRole::None;
  if (merge_fits(units[i], units[j])) return i < j ? PairRole::MergeSurvivor : PairRole::MergeAbsorbed;
  return units[i] > units[j] ? PairRole::Giver : PairRole::Receiver;
}

// Weight of `part` in a blend over `total` units. Units are below 2^25, so
// the float conversion loses at most one part in 2^24.
DP_HD inline float share_of(MassUnits part, MassUnits total) {
  return static_cast<float>(part) / static_cast<float>(total);
}

// Eq. 18 written as a step from a towards b: a + t (b - a) with t = w_b / w_n
// stays between a and b and is exact where a == b.
DP_HD inline float blend(float a, float b, float t) { return a + t * (b - a); }
DP_HD inline Vec3 blend(Vec3 a, Vec3 b, float t) { return a + t * (b - a); }

DP_HD inline void copy_particle(const AdaptiveSource& in, std::size_t from, const AdaptiveTarget& out, std::size_t to) {
  out.position[to] = in.position[from];
  out.velocity[to] = in.velocity[from];
  out.temperature[to] = in.temperature[from];
  out.units[to] = in.units[from];
  out.id[to] = in.id[from];
  for (std::size_t a = 0; a < in.extra_count; ++a) out.extra[a * out.size + to] = in.extra[a * in.size + from];
}

// Particle i takes `added` units carrying the state of particle j: its
// intensive quantities become the unit-weighted means (Eq. 18).
DP_HD inline void absorb_units(const AdaptiveSource& in, std::size_t i, std::size_t j, MassUnits added,
                               const AdaptiveTarget& out) {
  const MassUnits total = in.units[i] + added;
  const float t = share_of(added, total);
  out.position[i] = blend(in.position[i], in.position[j], t);
  out.velocity[i] = blend(in.velocity[i], in.velocity[j], t);
  out.temperature[i] = blend(in.temperature[i], in.temperature[j], t);
  out.units[i] = total;
  for (std::size_t a = 0; a < in.extra_count; ++a)
    out.extra[a * out.size + i] = blend(in.extra[a * in.size + i], in.extra[a * in.size + j], t);
}

// The new state of particle i after this round's pairing, from the old state
// of i and its partner. `out` must not alias `in`. Absorbed particles are
// left with zero units, for RemoveEmpty to drop.
struct ApplyAdaptivityPairs {
  AdaptiveSource in;
  const std::uint32_t* partner;
  AdaptiveTarget out;
  DP_HD void operator()(std::size_t i) const {
    copy_particle(in, i, out, i);
    const std::uint32_t j = partner[i];
    switch (pair_role(i, partner, in.units)) {
      case PairRole::None:
        break;
      case PairRole::MergeSurvivor:
        absorb_units(in, i, j, in.units[j], out);
        // The merged particle continues the heavier one's identity, so that
        // a tracked droplet keeps its id when it swallows a small one.
        if (in.units[j] > in.units[i]) out.id[i] = in.id[j];
        break;
      case PairRole::MergeAbsorbed:
        out.units[i] = 0;
        break;
      case PairRole::Giver:
        out.units[i] = in.units[i] - redistributed_units(in.units[i], in.units[j]);
        break;
      case PairRole::Receiver:
        absorb_units(in, i, j, redistributed_units(in.units[j], in.units[i]), out);
        break;
    }
  }
};

// 1 where particle i has a role `role` this round, for counting with sum().
struct HasPairRole {
  const std::uint32_t* partner;
  const MassUnits* units;
  PairRole role;
  DP_HD double operator()(std::size_t i) const { return pair_role(i, partner, units) == role ? 1.0 : 0.0; }
};

struct UnitsAt {
  const MassUnits* units;
  DP_HD double operator()(std::size_t i) const { return static_cast<double>(units[i]); }
};

struct FlagAt {
  const std::uint32_t* flag;
  DP_HD double operator()(std::size_t i) const { return static_cast<double>(flag[i]); }
};

// live[i] = 1 where particle i still carries mass.
struct MarkLive {
  const MassUnits* units;
  std::uint32_t* live;
  DP_HD void operator()(std::size_t i) const { live[i] = units[i] > 0 ? 1u : 0u; }
};

// For output slot k of a compaction, the index of the k-th live particle:
// with `live_before` the exclusive scan of the live flags, it is the last
// index whose count of live predecessors is <= k. A binary search keeps the
// compaction a pure gather.
struct SourceOfLive {
  const std::uint32_t* live_before;
  std::size_t n;
  std::uint32_t* source;
  DP_HD void operator()(std::size_t k) const {
    std::size_t lo = 0, hi = n;  // first index with live_before > k lies in [lo, hi]
    while (lo < hi) {
      std::size_t mid = lo + (hi - lo) / 2;
      if (live_before[mid] <= k)
        lo = mid + 1;
      else
        hi = mid;
    }
    source[k] = static_cast<std::uint32_t>(lo - 1);
  }
};

// out[k] = in[source[k]] for every array, extra attributes included; used
// both to sort particles into grid order and to compact them.
struct GatherParticles {
  AdaptiveSource in;
  const std::uint32_t* source;
  AdaptiveTarget out;
  DP_HD void operator()(std::size_t k) const { copy_particle(in, source[k], out, k); }
};

}  // namespace dp
