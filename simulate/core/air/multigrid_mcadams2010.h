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
#include <type_traits>
#include <vector>

#include "air/poisson_level.h"
#include "air/cycle_layout.h"
#include "air/multigrid_transfers.h"
#include "backend/host_device.h"

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

// One level of the hierarchy as the cycle's passes see it: views, with no
// buffer of its own, so that a GPU kernel can take the levels as a
// parameter (VCycleFrom).
struct CycleLevel {
  PoissonLevel poisson;
  float* x;       // the level's correction, padded; null on the finest, which works in the caller's z
  float* b;       // its right-hand side, the restricted residual; null on the finest (the caller's r)
  float* tmp;     // padded: the Jacobi sweeps' other vector, and the residual restricted from it
  const float* prolongation_scale;  // ProlongationScale toward the next coarser level; null on the coarsest
  float* wide;    // the separable transfers' intermediates (TransferBoxes); null on the coarsest
  float* narrow;
};

// The V-cycle over levels first .. count - 1 of a hierarchy (finest first):
// on each level but the coarsest, Jacobi sweeps from zero, the scaled
// residual restricted to the next level, the cycle there, its correction
// prolonged back and sweeps again; on the coarsest, sweeps only. Written
// against any executor with parallel_for, parallel_for_3d and
// parallel_sweeps: the backends' launchers, and a GPU thread block's
// (BlockExec) inside one kernel.
struct VCycle {
  static constexpr int kMaxLevels = 16;        // halving 2^16 cells per axis down to 4
  static constexpr int kSmoothingSweeps = 2;   // before and after the coarse correction; even (JacobiSweeps)
  static constexpr int kCoarsestSweeps = 40;   // Jacobi from zero on the coarsest level
  static constexpr float kOmega = 2.0f / 3.0f;
  static_assert(kSmoothingSweeps % 2 == 0, "post-smoothing starts from a guess: JacobiSweeps needs an even count");

  CycleLevel levels[kMaxLevels];
  int count;
  DomainFaces faces;
  bool whole_transfers;

  // Solves level first's A x = b approximately; b and x are that level's
  // (the caller's r and z on the finest).
  DP_EXEC_TEMPLATE template <class E>
  DP_HD void run(const E& exec, int first, const float* b, float* x) const {
    const int c = count - 1;
    run_above(exec, first, c, b, x, CoarsestSweeps{this, rhs(c, first, b), solution(c, first, x)});
  }

  // The same with levels `split` .. count - 1 handed to `below(exec)`,
  // whose result lands in level split's x.
  DP_EXEC_TEMPLATE template <class E, class Below>
  DP_HD void run_above(const E& exec, int first, int split, const float* b, float* x, const Below& below) const {
    for (int l = first; l < split; ++l) descend(exec, l, rhs(l, first, b), solution(l, first, x));
    below(exec);
    for (int l = split - 1; l >= first; --l) ascend(exec, l, rhs(l, first, b), solution(l, first, x));
  }


 private:
  // The coarsest level's sweeps, as run_above's `below`.
  struct CoarsestSweeps {
    const VCycle* cycle;
    const float* b;
    float* x;
    DP_EXEC_TEMPLATE template <class E>
    DP_HD void operator()(const E& exec) const { cycle->smooth(exec, cycle->count - 1, b, x, true, kCoarsestSweeps); }
  };

  DP_HD const float* rhs(int l, int first, const float* b) const { return l == first ? b : levels[l].b; }
  DP_HD float* solution(int l, int first, float* x) const { return l == first ? x : levels[l].x; }
  DP_HD Box box(int l) const { return Box{{levels[l].poisson.nx, levels[l].poisson.ny, levels[l].poisson.nz}}; }

  // Pre-smoothing on level l and its residual restricted to level l + 1's b.
  DP_EXEC_TEMPLATE template <class E>
  DP_HD void descend(const E& exec, int l, const float* b, float* x) const {
    const CycleLevel& v = levels[l];
    const CycleLevel& c = levels[l + 1];
    smooth(exec, l, b, x, true, kSmoothingSweeps);
    exec.parallel_for(v.poisson.size(), ScaledPoissonResidual{v.poisson, x, b, v.prolongation_scale, v.tmp});
    const TransferBoxes boxes{box(l), box(l + 1)};
    if (whole_transfers) {
      run_pass(exec, boxes.coarse, RestrictWhole{boxes, faces, v.tmp, c.b, c.poisson.unknown});
      return;
    }
    run_pass(exec, boxes.coarse_x(), RestrictAlong<0, false>{boxes.fine, boxes.coarse_x(), faces, v.tmp, v.wide, nullptr});
    run_pass(exec, boxes.coarse_xy(), RestrictAlong<1, false>{boxes.coarse_x(), boxes.coarse_xy(), faces, v.wide, v.narrow, nullptr});
    run_pass(exec, boxes.coarse, RestrictAlong<2, true>{boxes.coarse_xy(), boxes.coarse, faces, v.narrow, c.b, c.poisson.unknown});
  }

  // Level l + 1's correction prolonged into level l's x, and post-smoothing.
  DP_EXEC_TEMPLATE template <class E>
  DP_HD void ascend(const E& exec, int l, const float* b, float* x) const {
    const CycleLevel& v = levels[l];
    const CycleLevel& c = levels[l + 1];
    const TransferBoxes boxes{box(l), box(l + 1)};
    const float* scale = v.prolongation_scale;
    if (whole_transfers) {
      run_pass(exec, boxes.fine, ProlongWhole{boxes, faces, c.x, x, scale, v.poisson.unknown});
    } else {
      run_pass(exec, boxes.fine_x(), ProlongAlong<0, false>{boxes.coarse, boxes.fine_x(), faces, c.x, v.narrow, nullptr, nullptr});
      run_pass(exec, boxes.fine_xy(), ProlongAlong<1, false>{boxes.fine_x(), boxes.fine_xy(), faces, v.narrow, v.wide, nullptr, nullptr});
      run_pass(exec, boxes.fine, ProlongAlong<2, true>{boxes.fine_xy(), boxes.fine, faces, v.wide, x, scale, v.poisson.unknown});
    }
    smooth(exec, l, b, x, false, kSmoothingSweeps);
  }

  // Damped Jacobi sweeps on level l's A x = b; from zero, or (an even number
  // of sweeps) from the guess in x. The coarsest level's many sweeps are one
  // launcher call (one GPU launch); on the others each pass is a plain
  // kernel, which the CPU vectorises.
  DP_EXEC_TEMPLATE template <class E>
  DP_HD void smooth(const E& exec, int l, const float* b, float* x, bool from_zero, int sweeps) const {
    const CycleLevel& v = levels[l];
    const std::size_t n = v.poisson.size();
    const JacobiSweeps passes{v.poisson, b, kOmega, from_zero, sweeps, x, v.tmp};
    if (l + 1 == count) {
      exec.parallel_sweeps(n, sweeps, passes);
      return;
    }
    for (int s = 0; s < sweeps; ++s) {
      if (passes.starts_from_zero(s)) exec.parallel_for(n, passes.from_zero_pass(s));
      else exec.parallel_for(n, passes.sweep_pass(s));
    }
  }

  // One pass of a transfer, a point per value it writes.
  DP_EXEC_TEMPLATE template <class E, class Pass>
  DP_HD static void run_pass(const E& exec, const Box& out, const Pass& pass) {
    exec.parallel_for_3d(out.n[0], out.n[1], out.n[2], pass);
  }
};

// The cycle from level `first` down, with that level's b and x, on the
// executor it is handed: a functor for Exec::in_one_block, which holds the
// cycle by value (a kernel's parameter).
struct VCycleFrom {
  VCycle cycle;
  int first;
  const float* b;
  float* x;
  DP_EXEC_TEMPLATE template <class E>
  DP_HD void operator()(const E& exec) const { cycle.run(exec, first, b, x); }
};

// VCycle::run_above's `below` that hands the levels from some level down
// to Exec::in_one_block.
struct InOneBlock {
  VCycleFrom below;
  template <class Exec>
  void operator()(const Exec& exec) const { exec.in_one_block(below); }
};

template <class Exec>
class MultigridPreconditioner {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

 public:
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
      if (nx < 8 || ny < 8 || nz < 8 || levels_.size() == static_cast<std::size_t>(VCycle::kMaxLevels)) break;
      levels_.back().prolongation_scale.resize(n);
      const Box fine{{nx, ny, nz}};
      nx = (nx + 1) / 2;
      ny = (ny + 1) / 2;
      nz = (nz + 1) / 2;
      const TransferBoxes boxes{fine, Box{{nx, ny, nz}}};
      levels_.back().transfer_wide.resize(boxes.wide_size());
      levels_.back().transfer_narrow.resize(boxes.narrow_size());
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
      exec.parallel_for_3d(c.nx, c.ny, c.nz, BuildPoissonStencil{view(l), Exec::ptr(c.stencil), Exec::ptr(c.diagonal)});
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
    const VCycle cycle = cycle_views();
    const int split = first_level_in_one_block();
    if (split >= cycle.count) {
      cycle.run(exec, 0, Exec::ptr(r), z.ptr());
      return;
    }
    // The block's top level works in r and z when it is the finest.
    const float* block_b = split == 0 ? Exec::ptr(r) : cycle.levels[split].b;
    float* block_x = split == 0 ? z.ptr() : cycle.levels[split].x;
    cycle.run_above(exec, 0, split, Exec::ptr(r), z.ptr(), InOneBlock{VCycleFrom{cycle, split, block_b, block_x}});
  }

  // How the cycle's passes are laid out: the backend's by default
  // (layout_); the same arithmetic in every layout.
  void set_layout(const CycleLayout& layout) { layout_ = layout; }
  const CycleLayout& layout() const { return layout_; }

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

  // The hierarchy's levels as the cycle sees them; level 0's b and x are
  // the caller's.
  VCycle cycle_views() {
    VCycle v{};
    v.count = static_cast<int>(levels_.size());
    v.faces = faces_;
    v.whole_transfers = layout_.whole_transfers;
    for (std::size_t l = 0; l < levels_.size(); ++l) {
      Level& s = levels_[l];
      const bool coarsest = l + 1 == levels_.size();
      v.levels[l] = CycleLevel{view(l), l > 0 ? s.x.ptr() : nullptr, l > 0 ? Exec::ptr(s.b) : nullptr, s.tmp.ptr(),
                               coarsest ? nullptr : Exec::ptr(s.prolongation_scale), coarsest ? nullptr : Exec::ptr(s.transfer_wide),
                               coarsest ? nullptr : Exec::ptr(s.transfer_narrow)};
    }
    return v;
  }

  // The first level that CycleLayout::one_block_cells puts in one block, or
  // the level count.
  int first_level_in_one_block() const {
    if (layout_.one_block_cells == 0) return static_cast<int>(levels_.size());
    int l = 0;
    while (l < static_cast<int>(levels_.size()) && levels_[l].unknown.size() > layout_.one_block_cells) ++l;
    return l;
  }

  std::vector<Level> levels_;
  DomainFaces faces_;
  // Whole transfers where a pass costs a launch; levels of at most
  // kOneBlockElements cells in one block.
  CycleLayout layout_{Exec::kPassCostsALaunch, Exec::kOneBlockElements};
  bool built_ = false;  // set_unknowns has run since resize
};

}  // namespace dp
