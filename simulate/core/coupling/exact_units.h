#pragma once
// Integer helpers for mass transfers in texel mass units
// (surface/texel_mass_units.h): every transfer of the coupling is a whole
// number of units, computed once and applied to both sides, so the liquid
// and texel stores change by exactly what the air is credited with.
#include <cstdint>

#include "backend/host_device.h"
#include "surface/texel_mass_units.h"

namespace dp {

// Transfers are kept below 2^62 units (2^30 particles' mass), far above any
// step's exchange, so sums of eight of them cannot overflow 64 bits.
inline constexpr double kMaxTransferUnits = 4.6116860184273879e18;

// kg -> whole texel units, rounded down (a transfer never exceeds its rate).
DP_HD inline TexelMassUnits transfer_units_of_kg(double kg, double kg_per_unit) {
  const double u = kg / kg_per_unit;
  if (!(u > 0)) return 0;
  // Below 2^63: the signed conversion gives the same integer, in one instruction.
  return static_cast<TexelMassUnits>(static_cast<std::int64_t>(u < kMaxTransferUnits ? u : kMaxTransferUnits));
}

// floor(x * num / den) exactly, for num <= den: the scaled transfers of
// Alg. 2 then never add up to more than `num` (the sum of floors is at most
// the floor of the sum). 128-bit products: nvcc and g++ both have them.
// For num < den the quotient is below x and fits 64 bits, so on x86-64 one
// divq of the 128-bit product by den gives it; g++ calls the general
// 128-by-128-bit __udivti3 instead, which was 9 % of a 1024^2 texture's
// scene (SCA Logo Tex). Both give the floor, so the same units.
DP_HD inline TexelMassUnits scale_units(TexelMassUnits x, TexelMassUnits num, TexelMassUnits den) {
  if (den == 0 || num >= den) return x;
  __extension__ typedef unsigned __int128 Wide;
  const Wide product = static_cast<Wide>(x) * num;
#if defined(__x86_64__) && !defined(__CUDA_ARCH__)
  std::uint64_t quotient = static_cast<std::uint64_t>(product), high = static_cast<std::uint64_t>(product >> 64);
  __asm__("divq %[den]" : "+a"(quotient), "+d"(high) : [den] "rm"(den) : "cc");
  return quotient;
#else
  return static_cast<TexelMassUnits>(product / den);
#endif
}

// scale_units for many x and one num / den: the quotient estimated in
// double precision, then made exact with two 128-bit products. Below 2^51
// the estimate is off by less than 0.4 (three roundings of 2^-53 each), so
// it truncates to the floor or next to it, and one compare corrects it;
// above, it divides. The same units as scale_units, without a division per
// pair (a cell scales up to thousands of its pairs' condensation).
class UnitScale {
 public:
  DP_HD UnitScale(TexelMassUnits num, TexelMassUnits den)
      : num_(num), den_(den), ratio_(den > 0 ? static_cast<double>(num) / static_cast<double>(den) : 1.0) {}

  DP_HD TexelMassUnits operator()(TexelMassUnits x) const {
    if (den_ == 0 || num_ >= den_) return x;
    const double estimate = static_cast<double>(x) * ratio_;
    if (!(estimate < 0x1p51)) return scale_units(x, num_, den_);
    __extension__ typedef unsigned __int128 Wide;
    const TexelMassUnits q = static_cast<TexelMassUnits>(static_cast<std::int64_t>(estimate));
    const Wide product = static_cast<Wide>(x) * num_, below = static_cast<Wide>(q) * den_;
    if (below > product) return q - 1;
    if (product - below >= den_) return q + 1;
    return q;
  }

 private:
  TexelMassUnits num_, den_;
  double ratio_;
};

// Signed units split in two halves that a double-accumulating sum adds
// exactly (each block and total below 2^53): the low 24 bits and the rest.
struct SignedUnitsLow {
  const std::int64_t* v;
  DP_HD double operator()(std::size_t i) const {
    const std::int64_t x = v[i];
    const std::int64_t m = x < 0 ? -x : x;
    return static_cast<double>(x < 0 ? -(m & 0xFFFFFF) : (m & 0xFFFFFF));
  }
};
struct SignedUnitsHigh {
  const std::int64_t* v;
  DP_HD double operator()(std::size_t i) const {
    const std::int64_t x = v[i];
    const std::int64_t m = x < 0 ? -x : x;
    return static_cast<double>(x < 0 ? -(m >> 24) : (m >> 24));
  }
};

// The exact sum of n signed unit counts on either backend.
template <class Exec>
std::int64_t exact_units_sum(const Exec& exec, std::size_t n, const std::int64_t* v) {
  const double lo = exec.sum(n, SignedUnitsLow{v}), hi = exec.sum(n, SignedUnitsHigh{v});
  return static_cast<std::int64_t>(hi) * (std::int64_t{1} << 24) + static_cast<std::int64_t>(lo);
}

}  // namespace dp
