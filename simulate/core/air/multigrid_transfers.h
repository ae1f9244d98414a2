#pragma once
// The grid transfers of the multigrid preconditioner (multigrid_mcadams2010.h):
// trilinear prolongation of a coarse correction to the next finer level, and
// restriction, half its transpose. Each comes as three separable passes, one
// per axis, which the CPU vectorises, and as one whole pass, which the GPU
// runs as one launch instead of three; both add the same terms in the same
// order, so they give the same bits.
#include <cstddef>
#include <cstdint>

#include "air/poisson_level.h"
#include "air/sample_lanes.h"

namespace dp {

// Weight of coarse cell `coarse` in the trilinear prolongation to cell-centred
// fine cell `fine`, along one axis of `nc` coarse cells: fine cell 2I takes
// 3/4 of coarse I and 1/4 of I-1, fine 2I+1 3/4 of I and 1/4 of I+1. Where
// that second coarse cell lies beyond the grid, the error there is taken as
// the mirror of the near cell's across a closed wall (Neumann: the near cell
// gets weight 1) and as its negative across an open face (phi = 0 on the
// face: weight 1/2). Treating it as zero instead, as if every wall were
// open, halved the correction next to the walls and cost CG twice the
// iterations (docs/benchmarks.md, air step).
// Written as selects without branches, so that the transfer passes, which
// call it per point, still vectorise.
DP_HD_INLINE float prolongation_weight(int fine, int coarse, int nc, bool open_low, bool open_high) {
  const int near = fine >> 1;
  const int far = near + 2 * (fine & 1) - 1;
  const bool below = far < 0, above = far >= nc;
  const float edge = (below ? open_low : open_high) ? 0.5f : 1.0f;
  const float near_weight = (below | above) ? edge : 0.75f;
  return coarse == near ? near_weight : (coarse == far ? 0.25f : 0.0f);
}

// prolongation_weight along one axis of the coarse level's grid.
DP_HD inline float prolongation_weight(const PoissonLevel& coarse, int axis, int fine, int coarse_index) {
  const int nc = axis == 0 ? coarse.nx : (axis == 1 ? coarse.ny : coarse.nz);
  return prolongation_weight(fine, coarse_index, nc, coarse.faces.open(axis, 0), coarse.faces.open(axis, 1));
}

// The near and far coarse cell of fine cell `fine` along one axis (the far
// one may lie outside the grid).
DP_HD inline void coarse_pair(int fine, int* pair) {
  pair[0] = fine >> 1;
  pair[1] = (fine & 1) ? pair[0] + 1 : pair[0] - 1;
}

// Calls f(weight, coarse cell index) for each coarse cell inside the grid
// that fine cell (i, j, k) takes a share of, in a fixed order.
template <class F>
DP_HD void for_each_prolongation_term(const PoissonLevel& coarse, int i, int j, int k, const F& f) {
  int ci[2], cj[2], ck[2];
  coarse_pair(i, ci);
  coarse_pair(j, cj);
  coarse_pair(k, ck);
  for (int c = 0; c < 2; ++c) {
    if (ck[c] < 0 || ck[c] >= coarse.nz) continue;
    const float wk = prolongation_weight(coarse, 2, k, ck[c]);
    for (int b = 0; b < 2; ++b) {
      if (cj[b] < 0 || cj[b] >= coarse.ny) continue;
      const float wjk = wk * prolongation_weight(coarse, 1, j, cj[b]);
      for (int a = 0; a < 2; ++a) {
        if (ci[a] < 0 || ci[a] >= coarse.nx) continue;
        f(wjk * prolongation_weight(coarse, 0, i, ci[a]), coarse.index(ci[a], cj[b], ck[c]));
      }
    }
  }
}

// Per fine cell, the prolongation's weights over all coarse cells in the grid
// divided by those over the unknown ones: a coarse cell that is no unknown
// (all its children rigid or liquid) holds no error, and weighting it in as
// zero would pull the correction next to an obstacle towards zero, as if the
// obstacle were open. Scaling the rest up extrapolates instead (Neumann, as
// the obstacle's faces are); 1 away from obstacles.
struct ProlongationScale {
  PoissonLevel fine, coarse;
  float* scale;
  DP_HD void operator()(int i, int j, int k) const {
    float all = 0.0f, unknown = 0.0f;
    for_each_prolongation_term(coarse, i, j, k, [&](float w, std::size_t c) {
      all += w;
      if (coarse.unknown[c]) unknown += w;
    });
    // An unknown fine cell's own coarse cell is unknown, so `unknown` > 0 there.
    scale[fine.index(i, j, k)] = unknown > 0.0f ? all / unknown : 0.0f;
  }

#if !defined(__CUDA_ARCH__)
  // Cells 0 .. n - 1 of fine row (j, k) (CpuExec::parallel_for_3d): the
  // coarse rows the row draws on and their y and z weights are found once;
  // per cell only the two x terms of each remain. The same terms in the
  // same order as for_each_prolongation_term, so the same bits.
  DP_HOST_INLINE void whole_row(int n, int j, int k) const {
    int cj[2], ck[2];
    coarse_pair(j, cj);
    coarse_pair(k, ck);
    float wjk[4];
    const std::uint8_t* coarse_row[4];
    int rows = 0;
    for (int c = 0; c < 2; ++c) {
      if (ck[c] < 0 || ck[c] >= coarse.nz) continue;
      const float wk = prolongation_weight(coarse, 2, k, ck[c]);
      for (int b = 0; b < 2; ++b) {
        if (cj[b] < 0 || cj[b] >= coarse.ny) continue;
        wjk[rows] = wk * prolongation_weight(coarse, 1, j, cj[b]);
        coarse_row[rows++] = coarse.unknown + coarse.index(0, cj[b], ck[c]);
      }
    }
    const bool open_low = coarse.faces.open(0, 0), open_high = coarse.faces.open(0, 1);
    float* out = scale + fine.index(0, j, k);
    for (int i = 0; i < n; ++i) {
      int ci[2];  // near, then far, as for_each_prolongation_term takes them
      coarse_pair(i, ci);
      bool inside[2];
      float wi[2];
      for (int a = 0; a < 2; ++a) {
        inside[a] = ci[a] >= 0 && ci[a] < coarse.nx;
        wi[a] = prolongation_weight(i, ci[a], coarse.nx, open_low, open_high);
      }
      float all = 0.0f, unknown = 0.0f;
      for (int r = 0; r < rows; ++r)
        for (int a = 0; a < 2; ++a) {
          if (!inside[a]) continue;
          const float w = wjk[r] * wi[a];
          all += w;
          if (coarse_row[r][ci[a]]) unknown += w;
        }
      out[i] = unknown > 0.0f ? all / unknown : 0.0f;
    }
  }
#endif
};

// The four fine cells 2C-1 .. 2C+2 that coarse cell C gathers from along one
// axis of nf fine cells, each with the weight the prolongation gives C in
// it (prolongation_weight), which makes restriction its transpose; a fine
// cell beyond the grid gets weight 0 and the index of the nearest one, so
// that every read stays inside.
struct RestrictionAxis {
  int fine[4];
  float weight[4];
  DP_HD_INLINE static RestrictionAxis at(int coarse, int nf, int nc, bool open_low, bool open_high) {
    RestrictionAxis a;
    for (int d = 0; d < 4; ++d) {
      const int f = 2 * coarse - 1 + d;
      const bool inside = (f >= 0) & (f < nf);
      a.fine[d] = f < 0 ? 0 : (f < nf ? f : nf - 1);
      a.weight[d] = inside ? prolongation_weight(f, coarse, nc, open_low, open_high) : 0.0f;
    }
    return a;
  }
  // The weighted sum of four values (or of four lanes of each), as a tree:
  // (w0 v0 + w3 v3) + (w1 v1 + w2 v2).
  template <class V>
  DP_HD_INLINE V sum(V v0, V v1, V v2, V v3) const {
    return (weight[0] * v0 + weight[3] * v3) + (weight[1] * v1 + weight[2] * v2);
  }
};

// nx x ny x nz values, x fastest: a level, or one of the boxes a transfer
// between levels passes through, coarsened or refined one axis at a time.
struct Box {
  int n[3];
  DP_HD std::size_t index(int i, int j, int k) const { return (static_cast<std::size_t>(k) * n[1] + j) * n[0] + i; }
  DP_HD std::size_t size() const { return static_cast<std::size_t>(n[0]) * n[1] * n[2]; }
  // This box with `count` values along `axis`.
  DP_HD Box with(int axis, int count) const {
    Box b = *this;
    b.n[axis] = count;
    return b;
  }
};

// Index in `box` of point (i, j, k) with its coordinate along Axis replaced.
template <int Axis>
DP_HD_INLINE std::size_t index_along(const Box& box, int i, int j, int k, int along) {
  return box.index(Axis == 0 ? along : i, Axis == 1 ? along : j, Axis == 2 ? along : k);
}

// b_coarse = P^T r / 2: the transpose of the prolongation, scaled so that the
// re-discretised coarse operator (cell size 2 dx, unscaled form) sees the
// fine residual's level: A_2h ~ 4 dx^2 (-lap), A_h ~ dx^2 (-lap), and P^T
// sums 8 fine cells. P is separable, so restriction is three passes, along
// x, y and z, each summing four values as a tree. One pass of 64-term sums
// per coarse cell took as long as five Jacobi sweeps: each sum a chain of
// additions waiting on the one before, and no pass that vectorised.
// `in` has the fine count along Axis, `out` the coarse one; the Last pass
// writes b, halved, on the coarse unknowns and 0 elsewhere.
template <int Axis, bool Last>
struct RestrictAlong {
  Box in, out;
  DomainFaces faces;
  const float* source;
  float* target;
  const std::uint8_t* coarse_unknown;  // Last only
  DP_HD void operator()(int i, int j, int k) const {
    const RestrictionAxis a = axis_at(i, j, k);
    const float sum = a.sum(source[index_along<Axis>(in, i, j, k, a.fine[0])], source[index_along<Axis>(in, i, j, k, a.fine[1])],
                            source[index_along<Axis>(in, i, j, k, a.fine[2])], source[index_along<Axis>(in, i, j, k, a.fine[3])]);
    const std::size_t c = out.index(i, j, k);
    if constexpr (Last) target[c] = keep_if(0.5f * sum, coarse_unknown[c] != 0);
    else target[c] = sum;
  }

#if !defined(__CUDA_ARCH__)
  // Coarse points (i .. i + 3, j, k) as SSE lanes (CpuExec::parallel_for_3d),
  // the same operations in the same order as one by one: along y and z the
  // four read contiguous fine rows with one weight set.
  template <int A = Axis, std::enable_if_t<A != 0, int> = 0>
  DP_HOST_INLINE void four_along_x(int i, int j, int k) const {
    using L = FourLanes;
    const RestrictionAxis a = axis_at(i, j, k);
    L::Value v[4];
    for (int d = 0; d < 4; ++d) v[d] = L::load_row(source + index_along<Axis>(in, i, j, k, a.fine[d]));
    const L::Value sum = a.sum(v[0], v[1], v[2], v[3]);
    const std::size_t c = out.index(i, j, k);
    if constexpr (Last) L::store(target + c, L::keep_where(0.5f * sum, coarse_unknown + c));
    else L::store(target + c, sum);
  }
  bool lanes_fit() const { return true; }

  // Along x, a whole coarse row n long (CpuExec::parallel_for_3d): coarse
  // cells 1 .. n - 2 read fine cells 2i - 1 .. 2i + 2, all inside, with the
  // one weight set 1/4, 3/4, 3/4, 1/4, in a loop g++ vectorises; the two
  // end cells, whose weights depend on the walls, go one by one.
  template <int A = Axis, std::enable_if_t<A == 0, int> = 0>
  DP_HOST_INLINE void whole_row(int n, int j, int k) const {
    static_assert(!Last, "the last pass runs along z");
    (*this)(0, j, k);
    if (n > 2) {
      const RestrictionAxis a = axis_at(1, j, k);
      restrict_inner_row(source + in.index(0, j, k), target + out.index(0, j, k), n - 1, a.weight);
    }
    if (n > 1) (*this)(n - 1, j, k);
  }
#endif

 private:
  DP_HD_INLINE RestrictionAxis axis_at(int i, int j, int k) const {
    const int at[3] = {i, j, k};
    return RestrictionAxis::at(at[Axis], in.n[Axis], out.n[Axis], faces.open(Axis, 0), faces.open(Axis, 1));
  }
#if !defined(__CUDA_ARCH__)
  // out[i] for i = 1 .. end - 1 from fine row `fine`, as RestrictionAxis::sum
  // orders the terms; restrict parameters, so no overlap test per call.
  DP_HOST_INLINE static void restrict_inner_row(const float* __restrict fine, float* __restrict out, int end, const float* w) {
    const float w0 = w[0], w1 = w[1], w2 = w[2], w3 = w[3];
    for (int i = 1; i < end; ++i) out[i] = (w0 * fine[2 * i - 1] + w3 * fine[2 * i + 2]) + (w1 * fine[2 * i] + w2 * fine[2 * i + 1]);
  }
#endif
};

// The two coarse cells fine cell `fine` takes a share of along one axis, near
// and far, with their prolongation_weight; where the far one lies beyond
// the grid it gets weight 0 and the near one's index.
struct ProlongationAxis {
  int near, far;
  float w_near, w_far;
  DP_HD_INLINE static ProlongationAxis at(int fine, int nc, bool open_low, bool open_high) {
    int pair[2];
    coarse_pair(fine, pair);
    const bool far_inside = (pair[1] >= 0) & (pair[1] < nc);
    return ProlongationAxis{pair[0], far_inside ? pair[1] : pair[0], prolongation_weight(fine, pair[0], nc, open_low, open_high),
                            far_inside ? prolongation_weight(fine, pair[1], nc, open_low, open_high) : 0.0f};
  }
  template <class V>
  DP_HD_INLINE V lerp(V near_value, V far_value) const { return w_near * near_value + w_far * far_value; }
};

// x_fine += P e_coarse on the fine unknowns, P scaled by ProlongationScale:
// like restriction, three separable passes, along x, y, then z. `in` has
// the coarse count along Axis, `out` the fine one; the Last pass adds to x,
// +0 where the fine cell is no unknown (x holds +0 there).
template <int Axis, bool Last>
struct ProlongAlong {
  Box in, out;
  DomainFaces faces;
  const float* source;
  float* target;
  const float* scale;                // Last only
  const std::uint8_t* fine_unknown;  // Last only
  DP_HD void operator()(int i, int j, int k) const {
    const ProlongationAxis a = axis_at(i, j, k);
    const float e = a.lerp(source[index_along<Axis>(in, i, j, k, a.near)], source[index_along<Axis>(in, i, j, k, a.far)]);
    const std::size_t f = out.index(i, j, k);
    if constexpr (Last) target[f] += keep_if(scale[f] * e, fine_unknown[f] != 0);
    else target[f] = e;
  }

#if !defined(__CUDA_ARCH__)
  // Fine points (i .. i + 3, j, k) as SSE lanes, as RestrictAlong's. Along
  // x, from even i, they take coarse cells i/2 - 1 .. i/2 + 2: near ones
  // i/2, i/2, i/2 + 1, i/2 + 1 and far ones i/2 - 1, i/2 + 1, i/2, i/2 + 2,
  // with the weights 3/4 and 1/4 only where all of these lie inside.
  DP_HOST_INLINE void four_along_x(int i, int j, int k) const {
    using L = FourLanes;
    const int c = i / 2;
    if (Axis == 0 && !(i % 2 == 0 && c >= 1 && c + 2 < in.n[0])) {
      for (int l = 0; l < L::kCount; ++l) (*this)(i + l, j, k);
      return;
    }
    const ProlongationAxis a = axis_at(i, j, k);
    L::Value e;
    if constexpr (Axis == 0) {
      const L::Value coarse = L::load_row(source + in.index(c - 1, j, k));
      e = a.lerp(L::pick<1, 1, 2, 2>(coarse, coarse), L::pick<0, 2, 1, 3>(coarse, coarse));
    } else {
      e = a.lerp(L::load_row(source + index_along<Axis>(in, i, j, k, a.near)),
                 L::load_row(source + index_along<Axis>(in, i, j, k, a.far)));
    }
    const std::size_t f = out.index(i, j, k);
    if constexpr (Last) L::store(target + f, L::load_row(target + f) + L::keep_where(L::load_row(scale + f) * e, fine_unknown + f));
    else L::store(target + f, e);
  }
  bool lanes_fit() const { return true; }
#endif

 private:
  DP_HD_INLINE ProlongationAxis axis_at(int i, int j, int k) const {
    const int at[3] = {i, j, k};
    return ProlongationAxis::at(at[Axis], in.n[Axis], faces.open(Axis, 0), faces.open(Axis, 1));
  }
};

// The boxes of one transfer between a fine level and the next coarser one.
struct TransferBoxes {
  Box fine, coarse;
  DP_HD Box coarse_x() const { return fine.with(0, coarse.n[0]); }    // restriction, after x
  DP_HD Box coarse_xy() const { return coarse_x().with(1, coarse.n[1]); }
  DP_HD Box fine_x() const { return coarse.with(0, fine.n[0]); }      // prolongation, after x
  DP_HD Box fine_xy() const { return fine_x().with(1, fine.n[1]); }
  // Two buffers serve both transfers: "wide" holds coarse_x, then fine_xy;
  // "narrow" coarse_xy, then fine_x.
  std::size_t wide_size() const { return coarse_x().size() > fine_xy().size() ? coarse_x().size() : fine_xy().size(); }
  std::size_t narrow_size() const { return coarse_xy().size() > fine_x().size() ? coarse_xy().size() : fine_x().size(); }
};

// Restriction as one pass, a point per coarse cell: the 4 x 4 x 4 fine
// residuals it gathers, summed along x, then the four x sums along y, then
// the four y sums along z, each as RestrictionAxis::sum, which is what the
// three RestrictAlong passes compute, term for term. For the GPU, where a
// pass over a coarse level is mostly its launch.
struct RestrictWhole {
  TransferBoxes boxes;
  DomainFaces faces;
  const float* fine;  // scaled residual, boxes.fine
  float* b;           // boxes.coarse: halved on the coarse unknowns, 0 elsewhere
  const std::uint8_t* coarse_unknown;
  DP_HD void operator()(int i, int j, int k) const {
    const RestrictionAxis ax = axis_at(0, i), ay = axis_at(1, j), az = axis_at(2, k);
    float along_y[4];
    for (int dz = 0; dz < 4; ++dz) {
      float along_x[4];
      for (int dy = 0; dy < 4; ++dy) {
        const float* row = fine + boxes.fine.index(0, ay.fine[dy], az.fine[dz]);
        along_x[dy] = ax.sum(row[ax.fine[0]], row[ax.fine[1]], row[ax.fine[2]], row[ax.fine[3]]);
      }
      along_y[dz] = ay.sum(along_x[0], along_x[1], along_x[2], along_x[3]);
    }
    const std::size_t c = boxes.coarse.index(i, j, k);
    b[c] = keep_if(0.5f * az.sum(along_y[0], along_y[1], along_y[2], along_y[3]), coarse_unknown[c] != 0);
  }

 private:
  DP_HD_INLINE RestrictionAxis axis_at(int axis, int coarse) const {
    return RestrictionAxis::at(coarse, boxes.fine.n[axis], boxes.coarse.n[axis], faces.open(axis, 0), faces.open(axis, 1));
  }
};

// Prolongation as one pass, a point per fine cell: the 2 x 2 x 2 coarse
// values it takes, interpolated along x, then y, then z, as the three
// ProlongAlong passes do, term for term; added to x on the fine unknowns.
struct ProlongWhole {
  TransferBoxes boxes;
  DomainFaces faces;
  const float* coarse;  // the coarse correction, boxes.coarse
  float* x;             // boxes.fine
  const float* scale;
  const std::uint8_t* fine_unknown;
  DP_HD void operator()(int i, int j, int k) const {
    const ProlongationAxis ax = axis_at(0, i), ay = axis_at(1, j), az = axis_at(2, k);
    const int y[2] = {ay.near, ay.far}, z[2] = {az.near, az.far};
    float along_y[2];
    for (int dz = 0; dz < 2; ++dz) {
      float along_x[2];
      for (int dy = 0; dy < 2; ++dy) {
        const float* row = coarse + boxes.coarse.index(0, y[dy], z[dz]);
        along_x[dy] = ax.lerp(row[ax.near], row[ax.far]);
      }
      along_y[dz] = ay.lerp(along_x[0], along_x[1]);
    }
    const std::size_t f = boxes.fine.index(i, j, k);
    x[f] += keep_if(scale[f] * az.lerp(along_y[0], along_y[1]), fine_unknown[f] != 0);
  }

 private:
  DP_HD_INLINE ProlongationAxis axis_at(int axis, int fine_index) const {
    return ProlongationAxis::at(fine_index, boxes.coarse.n[axis], faces.open(axis, 0), faces.open(axis, 1));
  }
};

}  // namespace dp
