#pragma once
// Multigrid preconditioner for the pressure CG (McAdams, Sifakis & Teran
// 2010, "A parallel multigrid Poisson solver for fluids simulation on large
// grids"): one V-cycle per CG iteration, levels halved per axis, damped
// Jacobi smoothing with as many sweeps before as after the coarse
// correction, trilinear prolongation and its transpose as restriction, and
// the operator re-discretised on each level (a coarse cell is unknown when
// any of its children is). The cycle is symmetric and positive definite, as
// CG needs. McAdams et al. add extra Gauss-Seidel sweeps near the boundary;
// instead, prolongation here honours the boundary conditions (mirrored at
// closed walls, negated at open faces, extrapolated next to obstacles), which
// keeps the iteration count independent of resolution (docs/paper-map.md,
// departures).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "air/poisson_level.h"

namespace dp {

// A coarse cell is unknown when any of its (up to eight) children is.
struct CoarsenUnknown {
  PoissonLevel fine;
  int nx, ny, nz;
  std::uint8_t* coarse_unknown;
  DP_HD void operator()(std::size_t c) const {
    const int i = static_cast<int>(c % nx), j = static_cast<int>((c / nx) % ny),
              k = static_cast<int>(c / (static_cast<std::size_t>(nx) * ny));
    std::uint8_t any = 0;
    for (int dk = 0; dk < 2; ++dk)
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
          const int fi = 2 * i + di, fj = 2 * j + dj, fk = 2 * k + dk;
          if (fi < fine.nx && fj < fine.ny && fk < fine.nz && fine.unknown[fine.index(fi, fj, fk)]) any = 1;
        }
    coarse_unknown[c] = any;
  }
};

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
};

// The residual the cycle restricts: scale (b - A x), so that restriction
// stays the transpose of the scaled prolongation and the cycle symmetric.
struct ScaledPoissonResidual {
  PoissonLevel level;
  const float* x;
  const float* b;
  const float* scale;
  float* r;
  DP_HD_INLINE void operator()(std::size_t c) const {
    r[c] = keep_if(scale[c] * (b[c] - level.apply(x, c)), level.unknown[c] != 0);
  }
};

// The four fine cells 2C-1 .. 2C+2 that coarse cell C gathers from along one
// axis of nf fine cells, with their prolongation weights (prolongation_weight)
// as restriction's; a fine cell beyond the grid gets weight 0 and the index
// of the nearest one, so that every read stays inside.
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
  // The weighted sum of four values, as a tree: (w0 v0 + w3 v3) + (w1 v1 + w2 v2).
  DP_HD_INLINE float sum(float v0, float v1, float v2, float v3) const {
    return (weight[0] * v0 + weight[3] * v3) + (weight[1] * v1 + weight[2] * v2);
  }
};

// The shapes a transfer between a fine level and the next coarser one
// passes through: one axis at a time is coarsened (restriction) or refined
// (prolongation). Box (X, Y, Z) is stored x fastest.
struct TransferBoxes {
  PoissonLevel fine, coarse;
  // Coarse along x only, then along x and y (restriction's order); fine
  // along x only, then along x and y (prolongation's).
  DP_HD std::size_t coarse_x(int I, int j, int k) const { return (static_cast<std::size_t>(k) * fine.ny + j) * coarse.nx + I; }
  DP_HD std::size_t coarse_xy(int I, int J, int k) const { return (static_cast<std::size_t>(k) * coarse.ny + J) * coarse.nx + I; }
  DP_HD std::size_t fine_x(int i, int J, int K) const { return (static_cast<std::size_t>(K) * coarse.ny + J) * fine.nx + i; }
  DP_HD std::size_t fine_xy(int i, int j, int K) const { return (static_cast<std::size_t>(K) * fine.ny + j) * fine.nx + i; }
  // Values each intermediate box holds: the larger of the two shapes that
  // share a buffer.
  std::size_t wide_size() const {
    const std::size_t r = static_cast<std::size_t>(coarse.nx) * fine.ny * fine.nz;
    const std::size_t p = static_cast<std::size_t>(fine.nx) * fine.ny * coarse.nz;
    return r > p ? r : p;
  }
  std::size_t narrow_size() const {
    const std::size_t r = static_cast<std::size_t>(coarse.nx) * coarse.ny * fine.nz;
    const std::size_t p = static_cast<std::size_t>(fine.nx) * coarse.ny * coarse.nz;
    return r > p ? r : p;
  }
  DP_HD bool open(int axis, int side) const { return coarse.faces.open(axis, side); }
};

// b_coarse = P^T r / 2: the transpose of the prolongation, scaled so that the
// re-discretised coarse operator (cell size 2 dx, unscaled form) sees the
// fine residual's level: A_2h ~ 4 dx^2 (-lap), A_h ~ dx^2 (-lap), and P^T
// sums 8 fine cells. P is separable, so restriction is three passes, along
// x, y and z, each summing four values as a tree. One pass of 64-term sums
// per coarse cell took as long as five Jacobi sweeps: each sum a chain of
// additions waiting on the one before, and no pass that vectorised.
struct RestrictAlongX {
  TransferBoxes box;
  const float* r;  // fine
  float* out;      // coarse_x
  DP_HD void operator()(int I, int j, int k) const {
    const RestrictionAxis x = RestrictionAxis::at(I, box.fine.nx, box.coarse.nx, box.open(0, 0), box.open(0, 1));
    const float* row = r + box.fine.index(0, j, k);
    out[box.coarse_x(I, j, k)] = x.sum(row[x.fine[0]], row[x.fine[1]], row[x.fine[2]], row[x.fine[3]]);
  }
};

struct RestrictAlongY {
  TransferBoxes box;
  const float* in;  // coarse_x
  float* out;       // coarse_xy
  DP_HD void operator()(int I, int J, int k) const {
    const RestrictionAxis y = RestrictionAxis::at(J, box.fine.ny, box.coarse.ny, box.open(1, 0), box.open(1, 1));
    out[box.coarse_xy(I, J, k)] = y.sum(in[box.coarse_x(I, y.fine[0], k)], in[box.coarse_x(I, y.fine[1], k)],
                                        in[box.coarse_x(I, y.fine[2], k)], in[box.coarse_x(I, y.fine[3], k)]);
  }
};

// The last pass writes b on the coarse unknowns and 0 elsewhere.
struct RestrictAlongZ {
  TransferBoxes box;
  const float* in;  // coarse_xy
  float* b;         // coarse
  DP_HD void operator()(int I, int J, int K) const {
    const RestrictionAxis z = RestrictionAxis::at(K, box.fine.nz, box.coarse.nz, box.open(2, 0), box.open(2, 1));
    const std::size_t c = box.coarse.index(I, J, K);
    const float sum = z.sum(in[box.coarse_xy(I, J, z.fine[0])], in[box.coarse_xy(I, J, z.fine[1])],
                            in[box.coarse_xy(I, J, z.fine[2])], in[box.coarse_xy(I, J, z.fine[3])]);
    b[c] = keep_if(0.5f * sum, box.coarse.unknown[c] != 0);
  }
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
                            far_inside ? 0.25f : 0.0f};
  }
  DP_HD_INLINE float lerp(float near_value, float far_value) const { return w_near * near_value + w_far * far_value; }
};

// x_fine += P e_coarse on the fine unknowns, P scaled by ProlongationScale:
// like restriction, three separable passes, along x, y, then z.
struct ProlongAlongX {
  TransferBoxes box;
  const float* e;  // coarse
  float* out;      // fine_x
  DP_HD void operator()(int i, int J, int K) const {
    const ProlongationAxis x = ProlongationAxis::at(i, box.coarse.nx, box.open(0, 0), box.open(0, 1));
    const float* row = e + box.coarse.index(0, J, K);
    out[box.fine_x(i, J, K)] = x.lerp(row[x.near], row[x.far]);
  }
};

struct ProlongAlongY {
  TransferBoxes box;
  const float* in;  // fine_x
  float* out;       // fine_xy
  DP_HD void operator()(int i, int j, int K) const {
    const ProlongationAxis y = ProlongationAxis::at(j, box.coarse.ny, box.open(1, 0), box.open(1, 1));
    out[box.fine_xy(i, j, K)] = y.lerp(in[box.fine_x(i, y.near, K)], in[box.fine_x(i, y.far, K)]);
  }
};

// Adds +0 where the fine cell is no unknown (x holds +0 there).
struct ProlongAlongZAndAdd {
  TransferBoxes box;
  const float* scale;
  const float* in;  // fine_xy
  float* x;         // fine
  DP_HD void operator()(int i, int j, int k) const {
    const ProlongationAxis z = ProlongationAxis::at(k, box.coarse.nz, box.open(2, 0), box.open(2, 1));
    const std::size_t f = box.fine.index(i, j, k);
    const float e = z.lerp(in[box.fine_xy(i, j, z.near)], in[box.fine_xy(i, j, z.far)]);
    x[f] += keep_if(scale[f] * e, box.fine.unknown[f] != 0);
  }
};

struct CopyBytes {
  const std::uint8_t* in;
  std::uint8_t* out;
  DP_HD void operator()(std::size_t i) const { out[i] = in[i]; }
};

struct BytesDiffer {
  const std::uint8_t* a;
  const std::uint8_t* b;
  DP_HD bool operator()(std::size_t i) const { return a[i] != b[i]; }
};

struct ClearFloats {
  float* x;
  DP_HD void operator()(std::size_t i) const { x[i] = 0.0f; }
};


template <class Exec>
class MultigridPreconditioner {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

 public:
  static constexpr int kSmoothingSweeps = 2;   // before and after the coarse correction; even (JacobiSweeps)
  static constexpr int kCoarsestSweeps = 40;   // Jacobi from zero on the coarsest level
  static constexpr float kOmega = 2.0f / 3.0f;
  static_assert(kSmoothingSweeps % 2 == 0, "post-smoothing starts from a guess: JacobiSweeps needs an even count");

  // Builds the hierarchy's shapes; call `set_unknowns` whenever the cells change.
  void resize(int nx, int ny, int nz, DomainFaces faces) {
    levels_.clear();
    for (;;) {
      Level l;
      l.nx = nx;
      l.ny = ny;
      l.nz = nz;
      const std::size_t n = static_cast<std::size_t>(nx) * ny * nz;
      l.unknown.resize(n);
      l.stencil.resize(n);
      l.diagonal.resize(n);
      const std::size_t slab = static_cast<std::size_t>(nx) * ny;  // PoissonLevel::slab of this level
      l.tmp.resize(n, slab);
      if (!levels_.empty()) {  // the finest level works in the caller's r and z
        l.x.resize(n, slab);
        l.b.resize(n);
      }
      levels_.push_back(std::move(l));
      // Halve while every axis keeps at least four cells.
      if (nx < 8 || ny < 8 || nz < 8) break;
      levels_.back().prolongation_scale.resize(n);
      const PoissonLevel fine_shape{nx, ny, nz, nullptr, faces, nullptr, nullptr};
      nx = (nx + 1) / 2;
      ny = (ny + 1) / 2;
      nz = (nz + 1) / 2;
      const TransferBoxes box{fine_shape, PoissonLevel{nx, ny, nz, nullptr, faces, nullptr, nullptr}};
      levels_.back().transfer_wide.resize(box.wide_size());
      levels_.back().transfer_narrow.resize(box.narrow_size());
    }
    faces_ = faces;
    built_ = false;
  }

  int level_count() const { return static_cast<int>(levels_.size()); }
  const Buffer<std::uint8_t>& unknowns() const { return levels_[0].unknown; }

  // Level 0's unknowns are copied; coarser ones follow by coarsening. The
  // cells change only where liquid moves between them, so most steps find
  // the hierarchy already built for them.
  void set_unknowns(const Exec& exec, const Buffer<std::uint8_t>& fine_unknown) {
    const std::size_t n = fine_unknown.size();
    if (built_ && exec.find_first(n, BytesDiffer{Exec::ptr(fine_unknown), Exec::ptr(levels_[0].unknown)}) == n) return;
    // Copied in place: a recorded solve (CUDA graph) holds these buffers' addresses.
    exec.parallel_for(n, CopyBytes{Exec::ptr(fine_unknown), Exec::ptr(levels_[0].unknown)});
    for (std::size_t l = 0; l < levels_.size(); ++l) {
      Level& c = levels_[l];
      if (l > 0) exec.parallel_for(c.unknown.size(), CoarsenUnknown{view(l - 1), c.nx, c.ny, c.nz, Exec::ptr(c.unknown)});
      exec.parallel_for(c.unknown.size(), BuildPoissonStencil{view(l), Exec::ptr(c.stencil), Exec::ptr(c.diagonal)});
    }
    for (std::size_t l = 0; l + 1 < levels_.size(); ++l) {
      Level& f = levels_[l];
      exec.parallel_for_3d(f.nx, f.ny, f.nz, ProlongationScale{view(l), view(l + 1), Exec::ptr(f.prolongation_scale)});
    }
    built_ = true;
  }

  // z = M^-1 r, one V-cycle; z padded for the finest level (padding()).
  void apply(const Exec& exec, const Buffer<float>& r, PaddedField<Exec>& z) {
    // Never while recording: sizes are set by then.
    if (z.size() != r.size() || z.padding() < padding()) z.resize(r.size(), padding());
    cycle(exec, 0, Exec::ptr(r), z.ptr());
  }

  // The padding a finest-level field needs (PaddedField).
  std::size_t padding() const { return view(0).slab(); }

  PoissonLevel view(std::size_t l) const {
    const Level& v = levels_[l];
    return PoissonLevel{v.nx, v.ny, v.nz, Exec::ptr(v.unknown), faces_, Exec::ptr(v.stencil), Exec::ptr(v.diagonal)};
  }

 private:
  struct Level {
    int nx = 0, ny = 0, nz = 0;
    Buffer<std::uint8_t> unknown, stencil, diagonal;
    PaddedField<Exec> x, tmp;  // read by the stencil
    Buffer<float> b;
    Buffer<float> prolongation_scale;  // levels with a coarser one
    Buffer<float> transfer_wide, transfer_narrow;  // likewise: TransferBoxes' intermediates
  };

  // Damped Jacobi sweeps on level l's A x = b; from zero, or (an even number
  // of sweeps) from the guess in x. The coarsest level's many sweeps are one
  // launcher call (one GPU launch); on the others each pass is a plain
  // kernel, which the CPU vectorises.
  void smooth(const Exec& exec, std::size_t l, const float* b, float* x, bool from_zero, int sweeps) {
    Level& v = levels_[l];
    const std::size_t n = v.tmp.size();
    const JacobiSweeps passes{view(l), b, kOmega, from_zero, sweeps, x, v.tmp.ptr()};
    if (l + 1 == levels_.size()) {
      exec.parallel_sweeps(n, sweeps, passes);
      return;
    }
    for (int s = 0; s < sweeps; ++s) {
      if (passes.starts_from_zero(s)) exec.parallel_for(n, passes.from_zero_pass(s));
      else exec.parallel_for(n, passes.sweep_pass(s));
    }
  }

  // Solves level l's A x = b approximately: smooth, correct from the
  // coarser level, smooth again; the coarsest level is only smoothed.
  void cycle(const Exec& exec, std::size_t l, const float* b, float* x) {
    Level& v = levels_[l];
    if (l + 1 == levels_.size()) {
      smooth(exec, l, b, x, true, kCoarsestSweeps);
      return;
    }
    smooth(exec, l, b, x, true, kSmoothingSweeps);
    const PoissonLevel p = view(l);
    const float* scale = Exec::ptr(v.prolongation_scale);
    exec.parallel_for(v.tmp.size(), ScaledPoissonResidual{p, x, b, scale, v.tmp.ptr()});
    Level& c = levels_[l + 1];
    const TransferBoxes box{p, view(l + 1)};
    float* wide = Exec::ptr(v.transfer_wide);
    float* narrow = Exec::ptr(v.transfer_narrow);
    exec.parallel_for_3d(c.nx, v.ny, v.nz, RestrictAlongX{box, v.tmp.ptr(), wide});
    exec.parallel_for_3d(c.nx, c.ny, v.nz, RestrictAlongY{box, wide, narrow});
    exec.parallel_for_3d(c.nx, c.ny, c.nz, RestrictAlongZ{box, narrow, Exec::ptr(c.b)});
    cycle(exec, l + 1, Exec::ptr(c.b), c.x.ptr());
    exec.parallel_for_3d(v.nx, c.ny, c.nz, ProlongAlongX{box, c.x.ptr(), narrow});
    exec.parallel_for_3d(v.nx, v.ny, c.nz, ProlongAlongY{box, narrow, wide});
    exec.parallel_for_3d(v.nx, v.ny, v.nz, ProlongAlongZAndAdd{box, scale, wide, x});
    smooth(exec, l, b, x, false, kSmoothingSweeps);
  }

  std::vector<Level> levels_;
  DomainFaces faces_;
  bool built_ = false;  // set_unknowns has run since resize
};

}  // namespace dp
