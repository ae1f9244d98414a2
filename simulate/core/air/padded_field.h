#pragma once
// A vector with room to read past both ends, for stencils that load their
// neighbours unconditionally (air/poisson_level.h, the vorticity passes).
#include <cstddef>
#include <vector>

namespace dp {

// A level's vector that the stencil may read up to one slab (nx ny values)
// before its first and after its last value: PoissonLevel::apply then loads
// all six neighbours unconditionally and selects, which the CPU vectorises
// (a sweep 2.8 times faster than loads behind bit tests, same values). The
// padding is allocated, never written; what it holds is never selected.
template <class Exec, class T = float>
class PaddedField {
 public:
  void resize(std::size_t n, std::size_t pad) {
    n_ = n;
    pad_ = pad;
    storage_.resize(n + 2 * pad);
  }
  std::size_t size() const { return n_; }
  std::size_t padding() const { return pad_; }
  T* ptr() { return Exec::ptr(storage_) + pad_; }
  const T* ptr() const { return Exec::ptr(storage_) + pad_; }
  // The n values, copied to the host.
  std::vector<T> download() const {
    const std::vector<T> all = Exec::download(storage_);
    return std::vector<T>(all.begin() + static_cast<std::ptrdiff_t>(pad_), all.begin() + static_cast<std::ptrdiff_t>(pad_ + n_));
  }

 private:
  typename Exec::template Buffer<T> storage_;
  std::size_t n_ = 0, pad_ = 0;
};

}  // namespace dp
