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
DP_HD inline float prolongation_weight(int fine, int coarse, int nc, bool open_low, bool open_high) {
  const int near = fine >> 1;
  const int far = (fine & 1) ? near + 1 : near - 1;
  if (coarse == near) {
    if (far < 0) return open_low ? 0.5f : 1.0f;
    if (far >= nc) return open_high ? 0.5f : 1.0f;
    return 0.75f;
  }
  return coarse == far ? 0.25f : 0.0f;
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

// b_coarse = P^T r / 2: the transpose of the prolongation, scaled so that the
// re-discretised coarse operator (cell size 2 dx, unscaled form) sees the
// fine residual's level: A_2h ~ 4 dx^2 (-lap), A_h ~ dx^2 (-lap), and P^T
// sums 8 fine cells.
struct RestrictResidual {
  PoissonLevel fine, coarse;
  const float* r;
  float* b;
  DP_HD void operator()(int I, int J, int K) const {
    const std::size_t c = coarse.index(I, J, K);
    if (!coarse.unknown[c]) {
      b[c] = 0.0f;
      return;
    }
    const bool interior = 2 * I >= 1 && 2 * I + 2 < fine.nx && 2 * J >= 1 && 2 * J + 2 < fine.ny && 2 * K >= 1 &&
                          2 * K + 2 < fine.nz;
    b[c] = 0.5f * (interior ? interior_sum(I, J, K) : boundary_sum(I, J, K));
  }

  // All 4 x 4 x 4 fine cells exist: walk them by offsets, with the axis
  // weights of prolongation_weight (1/4, 3/4, 3/4, 1/4) as constants; the
  // terms and their order are those of boundary_sum.
  DP_HD float interior_sum(int I, int J, int K) const {
    const float w[4] = {0.25f, 0.75f, 0.75f, 0.25f};
    const std::size_t row = static_cast<std::size_t>(fine.nx), slab = row * fine.ny;
    const float* base = r + fine.index(2 * I - 1, 2 * J - 1, 2 * K - 1);
    float s = 0.0f;
    for (int dk = 0; dk < 4; ++dk)
      for (int dj = 0; dj < 4; ++dj) {
        const float wjk = w[dk] * w[dj];
        const float* line = base + dk * slab + dj * row;
        for (int di = 0; di < 4; ++di) s += wjk * w[di] * line[di];
      }
    return s;
  }

  DP_HD float boundary_sum(int I, int J, int K) const {
    float s = 0.0f;
    for (int fk = 2 * K - 1; fk <= 2 * K + 2; ++fk) {
      if (fk < 0 || fk >= fine.nz) continue;
      const float wk = prolongation_weight(coarse, 2, fk, K);
      for (int fj = 2 * J - 1; fj <= 2 * J + 2; ++fj) {
        if (fj < 0 || fj >= fine.ny) continue;
        const float wjk = wk * prolongation_weight(coarse, 1, fj, J);
        for (int fi = 2 * I - 1; fi <= 2 * I + 2; ++fi) {
          if (fi < 0 || fi >= fine.nx) continue;
          s += wjk * prolongation_weight(coarse, 0, fi, I) * r[fine.index(fi, fj, fk)];
        }
      }
    }
    return s;
  }
};

// x_fine += P e_coarse on the fine unknowns, P scaled by ProlongationScale.
struct ProlongAndAdd {
  PoissonLevel coarse, fine;
  const float* scale;
  const float* e;
  float* x;
  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t f = fine.index(i, j, k);
    if (!fine.unknown[f]) return;
    int ci[2], cj[2], ck[2];
    coarse_pair(i, ci);
    coarse_pair(j, cj);
    coarse_pair(k, ck);
    const bool interior = ci[0] >= 1 && ci[0] + 1 < coarse.nx && cj[0] >= 1 && cj[0] + 1 < coarse.ny && ck[0] >= 1 &&
                          ck[0] + 1 < coarse.nz;
    x[f] += scale[f] * (interior ? interior_sum(ci, cj, ck) : boundary_sum(i, j, k));
  }

  // All eight coarse cells exist: the terms and order of boundary_sum,
  // reached by offsets from the nearest coarse cell.
  DP_HD float interior_sum(const int* ci, const int* cj, const int* ck) const {
    const std::ptrdiff_t row = coarse.nx, slab = row * coarse.ny;
    const std::ptrdiff_t d[3] = {ci[1] - ci[0], (cj[1] - cj[0]) * row, (ck[1] - ck[0]) * slab};
    const float* near = e + coarse.index(ci[0], cj[0], ck[0]);
    float s = 0.0f;
    for (int c = 0; c < 2; ++c)
      for (int b = 0; b < 2; ++b)
        for (int a = 0; a < 2; ++a) {
          const float w = (a ? 0.25f : 0.75f) * (b ? 0.25f : 0.75f) * (c ? 0.25f : 0.75f);
          s += w * near[a * d[0] + b * d[1] + c * d[2]];
        }
    return s;
  }

  DP_HD float boundary_sum(int i, int j, int k) const {
    float s = 0.0f;
    for_each_prolongation_term(coarse, i, j, k, [&](float w, std::size_t c) { s += w * e[c]; });
    return s;
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
      nx = (nx + 1) / 2;
      ny = (ny + 1) / 2;
      nz = (nz + 1) / 2;
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
    exec.parallel_for_3d(c.nx, c.ny, c.nz, RestrictResidual{p, view(l + 1), v.tmp.ptr(), Exec::ptr(c.b)});
    cycle(exec, l + 1, Exec::ptr(c.b), c.x.ptr());
    exec.parallel_for_3d(v.nx, v.ny, v.nz, ProlongAndAdd{view(l + 1), p, scale, c.x.ptr(), x});
    smooth(exec, l, b, x, false, kSmoothingSweeps);
  }

  std::vector<Level> levels_;
  DomainFaces faces_;
  bool built_ = false;  // set_unknowns has run since resize
};

}  // namespace dp
