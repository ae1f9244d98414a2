#pragma once
// Preconditioned conjugate gradients (Hestenes & Stiefel 1952) for the
// pressure Poisson equation, every vector operation a launcher call so it
// runs on either backend. Vectors are float; dot products are summed in
// double in the backends' fixed blocked order, so iterates do not depend on
// thread count. When no cell touches an open face the system is singular
// (pressure is defined up to a constant): the right-hand side and each
// preconditioned residual are then made mean-free over the unknowns.
//
// The iteration's scalars (ρ = r·z, d·q, r·r) stay where the vectors are
// and the kernels read them there, so on the GPU an iteration needs no host
// round trip: the iterations between two convergence checks run as
// recorded graphs. What is done with a scalar alone (the convergence test,
// β) runs after its sum, in the sum's launch. An iteration that finds the
// solve converged (or at its cap) sets a flag that freezes x, r and d in
// the iterations after it, so the result is that of checking after every
// iteration, on both backends.
//
// Where a check is a round trip (Exec::kIterationsPerCheck > 1), the first
// check comes after as many iterations as the last solve took: the solves
// of consecutive steps start from the last pressure and take about as many
// iterations, and every iteration run past convergence costs its launches
// however little it does. After that first check, one iteration per check.
#include <cmath>
#include <cstdint>

#include "air/multigrid_mcadams2010.h"
#include "backend/blocked_sum.h"

namespace dp {

struct PcgResult {
  int iterations = 0;
  float relative_residual = 0;  // |r|_2 / |b|_2 at the end
};

struct ProductOf {
  const float* a;
  const float* b;
  DP_HD double operator()(std::size_t i) const { return static_cast<double>(a[i]) * b[i]; }
};
struct ValueWhere {
  const float* a;
  const std::uint8_t* mask;
  DP_HD double operator()(std::size_t i) const { return mask[i] ? a[i] : 0.0f; }
};
struct CountWhere {
  const std::uint8_t* mask;
  DP_HD double operator()(std::size_t i) const { return mask[i] ? 1.0 : 0.0; }
};
// a -= sum / count on the mask (a mean read where it was summed), 0 elsewhere;
// nothing when the mask is empty.
struct SubtractMeanWhere {
  const double* sum;
  const double* count;
  const std::uint8_t* mask;
  float* a;
  DP_HD void operator()(std::size_t i) const {
    if (!(*count > 0)) return;
    const float mean = static_cast<float>(*sum / *count);
    a[i] = mask[i] ? a[i] - mean : 0.0f;
  }
};
// d = z + s d
struct Xpay {
  const float* z;
  float s;
  float* d;
  DP_HD void operator()(std::size_t i) const { d[i] = z[i] + s * d[i]; }
};

// The iteration's scalars and state, in one small buffer of doubles.
struct PcgScalars {
  enum : int {
    kRho,
    kDq,
    kRr,
    kRhoNext,
    kBeta,
    kBNorm,
    kTolerance,
    kMeanSum,
    kMeanCount,
    kStopped,
    kIterations,
    kMaxIterations,
    kCount
  };
  double* s;
  DP_HD bool stopped() const { return s[kStopped] != 0.0; }
};

// x += alpha d and r -= alpha q with alpha = rho / (d.q), one pass over both;
// nothing once stopped, or when d.q is not positive (converged to rounding).
struct StepIterateAndResidual {
  PcgScalars p;
  const float* d;
  const float* q;
  float* x;
  float* r;
  // Selects, not an early return, and the quotient taken whether it is used
  // or not (g++ will not move a division out of a branch): so the CPU's
  // loop vectorises. A quotient that is not used may be inf or NaN.
  DP_HD void operator()(std::size_t i) const {
    const bool steps = !p.stopped() & (p.s[PcgScalars::kDq] > 0.0);
    const float alpha = static_cast<float>(p.s[PcgScalars::kRho] / p.s[PcgScalars::kDq]);
    const float xi = x[i], ri = r[i];
    x[i] = steps ? xi + alpha * d[i] : xi;
    r[i] = steps ? ri + -alpha * q[i] : ri;
  }
};

// q = A d, returning d.q for a sum: the operator and the dot product in one
// pass (the launchers' sums call f once per element, so it may write it);
// as a plain kernel it only writes q.
struct ApplyPoissonAndDot {
  PoissonLevel level;
  const float* d;
  float* q;
  DP_HD double operator()(std::size_t i) const {
    const float qi = level.apply(d, i);
    q[i] = qi;
    return static_cast<double>(d[i]) * qi;
  }
};

// StepIterateAndResidual, returning r.r of the stepped residual for a sum.
struct StepAndResidualNorm {
  StepIterateAndResidual step;
  DP_HD double operator()(std::size_t i) const {
    step(i);
    return static_cast<double>(step.r[i]) * step.r[i];
  }
};

// After the step's r.r: counts it, and stops on d.q <= 0, on |r| <= tol |b|,
// or at the iteration cap (one thread).
struct CountIterationAndTest {
  PcgScalars p;
  DP_HD void operator()(std::size_t) const {
    double* s = p.s;
    if (p.stopped()) return;
    if (!(s[PcgScalars::kDq] > 0.0)) {
      s[PcgScalars::kStopped] = 1.0;
      return;
    }
    s[PcgScalars::kIterations] += 1.0;
    if (sqrt(s[PcgScalars::kRr]) <= s[PcgScalars::kTolerance] * s[PcgScalars::kBNorm] ||
        s[PcgScalars::kIterations] >= s[PcgScalars::kMaxIterations])
      s[PcgScalars::kStopped] = 1.0;
  }
};

// After rho_next = r.z: beta = rho_next / rho, and rho_next becomes rho
// (one thread); nothing once stopped.
struct AdvanceRho {
  PcgScalars p;
  DP_HD void operator()(std::size_t) const {
    if (p.stopped()) return;
    p.s[PcgScalars::kBeta] = p.s[PcgScalars::kRhoNext] / p.s[PcgScalars::kRho];
    p.s[PcgScalars::kRho] = p.s[PcgScalars::kRhoNext];
  }
};

// d = z + beta d; nothing once stopped.
struct UpdateDirection {
  PcgScalars p;
  const float* z;
  float* d;
  DP_HD void operator()(std::size_t i) const {
    if (p.stopped()) return;
    d[i] = z[i] + static_cast<float>(p.s[PcgScalars::kBeta]) * d[i];
  }
};

// Starts an iteration loop: the norms and the cap where the kernels read them.
struct StartIterations {
  PcgScalars p;
  double b_norm;
  double tolerance;
  int max_iterations;
  DP_HD void operator()(std::size_t) const {
    p.s[PcgScalars::kBNorm] = b_norm;
    p.s[PcgScalars::kTolerance] = tolerance;
    p.s[PcgScalars::kMaxIterations] = max_iterations;
    p.s[PcgScalars::kIterations] = 0.0;
    p.s[PcgScalars::kStopped] = max_iterations > 0 ? 0.0 : 1.0;
  }
};

template <class Exec>
class PoissonPcg {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

 public:
  void resize(int nx, int ny, int nz, DomainFaces faces) {
    const std::size_t n = static_cast<std::size_t>(nx) * ny * nz;
    for (auto* b : {&r_, &q_}) b->resize(n);
    partial_.assign(sum_scratch_count(n), 0.0);  // zero-filled, as sum_into needs
    scalars_.resize(PcgScalars::kCount);
    multigrid_.resize(nx, ny, nz, faces);
    for (auto* b : {&z_, &d_}) b->resize(n, multigrid_.padding());
    singular_ = !faces.any_open();
    for (auto& r : iterations_) r.reset();
    last_iterations_ = 0;
  }

  void set_unknowns(const Exec& exec, const Buffer<std::uint8_t>& unknown) { multigrid_.set_unknowns(exec, unknown); }
  const MultigridPreconditioner<Exec>& preconditioner() const { return multigrid_; }
  MultigridPreconditioner<Exec>& preconditioner() { return multigrid_; }

  // Solves A x = b from the guess in x. b may be changed (made mean-free).
  PcgResult solve(const Exec& exec, Buffer<float>& b, Buffer<float>& x, float tolerance, int max_iterations) {
    const PoissonLevel a = multigrid_.view(0);
    const std::size_t n = b.size();
    if (singular_) remove_mean(exec, Exec::ptr(b));
    const double b_norm = std::sqrt(exec.sum(n, ProductOf{Exec::ptr(b), Exec::ptr(b)}));
    PcgResult result;
    if (b_norm == 0.0) {
      exec.parallel_for(n, ClearFloats{Exec::ptr(x)});
      return result;
    }
    exec.parallel_for(n, PoissonResidual{a, Exec::ptr(x), Exec::ptr(b), Exec::ptr(r_)});
    const double r_norm = std::sqrt(exec.sum(n, ProductOf{Exec::ptr(r_), Exec::ptr(r_)}));
    result.relative_residual = static_cast<float>(r_norm / b_norm);
    if (r_norm <= tolerance * b_norm) return result;
    precondition(exec);
    exec.parallel_for(n, Xpay{z_.ptr(), 0.0f, d_.ptr()});
    const PcgScalars p = scalars();
    exec.sum_into(n, ProductOf{Exec::ptr(r_), z_.ptr()}, Exec::ptr(partial_), p.s + PcgScalars::kRho,
                  StartIterations{p, b_norm, static_cast<double>(tolerance), max_iterations});
    if (Exec::ptr(x) != recorded_x_) {  // the recordings bake x in
      for (auto& r : iterations_) r.reset();
      recorded_x_ = Exec::ptr(x);
    }
    const bool predicts = Exec::kIterationsPerCheck > 1 && last_iterations_ > 0;
    int before_check = predicts ? last_iterations_ : Exec::kIterationsPerCheck;
    for (;;) {
      run_iterations(exec, Exec::ptr(x), before_check);
      if (Exec::download_one(scalars_, PcgScalars::kStopped) != 0.0) break;
      before_check = predicts ? 1 : Exec::kIterationsPerCheck;
    }
    const std::vector<double> s = Exec::download(scalars_);
    result.iterations = static_cast<int>(s[PcgScalars::kIterations]);
    if (result.iterations > 0) result.relative_residual = static_cast<float>(std::sqrt(s[PcgScalars::kRr]) / b_norm);
    last_iterations_ = result.iterations;
    return result;
  }

 private:
  PcgScalars scalars() { return PcgScalars{Exec::ptr(scalars_)}; }

  // `count` iterations as replays of the recordings of 4, 2 and 1 iterations.
  void run_iterations(const Exec& exec, float* x, int count) {
    for (int r = kRecordings - 1; r >= 0; --r)
      for (const int length = 1 << r; count >= length; count -= length)
        exec.replay(iterations_[r], [&] {
          for (int k = 0; k < length; ++k) iterate(exec, x);
        });
  }

  // One CG iteration; launches only, nothing waits for the device.
  void iterate(const Exec& exec, float* x) {
    const std::size_t n = r_.size();
    const PcgScalars p = scalars();
    double* partial = Exec::ptr(partial_);
    const ApplyPoissonAndDot apply{multigrid_.view(0), d_.ptr(), Exec::ptr(q_)};
    const StepIterateAndResidual step{p, d_.ptr(), Exec::ptr(q_), x, Exec::ptr(r_)};
    const CountIterationAndTest count_and_test{p};
    if constexpr (Exec::kFusesPassesIntoSums) {
      exec.sum_into(n, apply, partial, p.s + PcgScalars::kDq);
      exec.sum_into(n, StepAndResidualNorm{step}, partial, p.s + PcgScalars::kRr, count_and_test);
    } else {  // the same values, each pass with a thread per element
      exec.parallel_for(n, apply);
      exec.sum_into(n, ProductOf{d_.ptr(), Exec::ptr(q_)}, partial, p.s + PcgScalars::kDq);
      exec.parallel_for(n, step);
      exec.sum_into(n, ProductOf{Exec::ptr(r_), Exec::ptr(r_)}, partial, p.s + PcgScalars::kRr, count_and_test);
    }
    precondition(exec);
    exec.sum_into(n, ProductOf{Exec::ptr(r_), z_.ptr()}, partial, p.s + PcgScalars::kRhoNext, AdvanceRho{p});
    exec.parallel_for(n, UpdateDirection{p, z_.ptr(), d_.ptr()});
  }

  void precondition(const Exec& exec) {
    multigrid_.apply(exec, r_, z_);
    if (singular_) remove_mean(exec, z_.ptr());
  }

  // v -= mean of v over the unknowns; on the device, without a round trip.
  void remove_mean(const Exec& exec, float* v) {
    const std::size_t n = r_.size();
    const std::uint8_t* mask = Exec::ptr(multigrid_.unknowns());
    const PcgScalars p = scalars();
    exec.sum_into(n, CountWhere{mask}, Exec::ptr(partial_), p.s + PcgScalars::kMeanCount);
    exec.sum_into(n, ValueWhere{v, mask}, Exec::ptr(partial_), p.s + PcgScalars::kMeanSum);
    exec.parallel_for(n, SubtractMeanWhere{p.s + PcgScalars::kMeanSum, p.s + PcgScalars::kMeanCount, mask, v});
  }

  MultigridPreconditioner<Exec> multigrid_;
  Buffer<float> r_, q_;
  PaddedField<Exec> z_, d_;  // read by the stencil
  Buffer<double> partial_, scalars_;
  static constexpr int kRecordings = 3;
  typename Exec::Recording iterations_[kRecordings];  // 1, 2 and 4 iterations
  const float* recorded_x_ = nullptr;
  int last_iterations_ = 0;
  bool singular_ = false;
};

}  // namespace dp
