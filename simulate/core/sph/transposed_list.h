#pragma once
// A neighbour list seen from its other side: for each particle b of the set
// the list points into, the query particles whose lists hold b, ascending.
// Both sets are sorted into one grid whose cells are the support radius
// wide, so these are exactly the particles a walk of the queries' grid
// around b finds (gather_near), in the walk's order: the cells' adjacency
// and the distance test are symmetric, and a walk meets sorted particles in
// ascending order. The CPU builds it in two passes over the list's pairs
// instead of walking the grid for every particle of the set: the glass's
// 90K rigid particles have 0.19M liquid pairs among them, and most have
// none.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/neighbor_list.h"

namespace dp {

class TransposedList {
 public:
  // `list` holds, for each of `queries` particles, indices below `targets`.
  NeighborList build(const NeighborList& list, std::size_t queries, std::size_t targets) {
    offset_.assign(targets + 1, 0);
    const std::uint32_t pairs = list.offset[queries] - list.offset[0];
    for (std::uint32_t k = list.offset[0]; k < list.offset[queries]; ++k) ++offset_[list.index[k] + 1];
    for (std::size_t b = 0; b < targets; ++b) offset_[b + 1] += offset_[b];
    index_.resize(pairs);
    next_.assign(offset_.begin(), offset_.end() - 1);
    for (std::size_t i = 0; i < queries; ++i)
      for (std::uint32_t k = list.offset[i]; k < list.offset[i + 1]; ++k) index_[next_[list.index[k]]++] = static_cast<std::uint32_t>(i);
    return NeighborList{offset_.data(), index_.data()};
  }

 private:
  std::vector<std::uint32_t> offset_, index_, next_;
};

}  // namespace dp
