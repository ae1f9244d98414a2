#pragma once
// Preconditioned conjugate gradients (Hestenes & Stiefel 1952) for the
// pressure Poisson equation, every vector operation a launcher call so it
// runs on either backend. Vectors are float; dot products are summed in
// double in the backends' fixed blocked order, so iterates do not depend on
// thread count. When no cell touches an open face the system is singular
// (pressure is defined up to a constant): the right-hand side and each
// preconditioned residual are then made mean-free over the unknowns.
#include <cmath>
#include <cstdint>

#include "air/multigrid_mcadams2010.h"

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
struct SubtractWhere {
  float value;
  const std::uint8_t* mask;
  float* a;
  DP_HD void operator()(std::size_t i) const { a[i] = mask[i] ? a[i] - value : 0.0f; }
};
// x += alpha d and r -= alpha q, one pass over both.
struct StepIterateAndResidual {
  float alpha;
  const float* d;
  const float* q;
  float* x;
  float* r;
  DP_HD void operator()(std::size_t i) const {
    x[i] += alpha * d[i];
    r[i] += -alpha * q[i];
  }
};
// d = z + s d
struct Xpay {
  const float* z;
  float s;
  float* d;
  DP_HD void operator()(std::size_t i) const { d[i] = z[i] + s * d[i]; }
};

template <class Exec>
class PoissonPcg {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

 public:
  void resize(int nx, int ny, int nz, DomainFaces faces) {
    const std::size_t n = static_cast<std::size_t>(nx) * ny * nz;
    for (auto* b : {&r_, &z_, &d_, &q_}) b->resize(n);
    multigrid_.resize(nx, ny, nz, faces);
    singular_ = !faces.any_open();
  }

  void set_unknowns(const Exec& exec, const Buffer<std::uint8_t>& unknown) { multigrid_.set_unknowns(exec, unknown); }
  const MultigridPreconditioner<Exec>& preconditioner() const { return multigrid_; }
  MultigridPreconditioner<Exec>& preconditioner() { return multigrid_; }

  // Solves A x = b from the guess in x. b may be changed (made mean-free).
  PcgResult solve(const Exec& exec, Buffer<float>& b, Buffer<float>& x, float tolerance, int max_iterations) {
    const PoissonLevel a = multigrid_.view(0);
    const std::size_t n = b.size();
    if (singular_) remove_mean(exec, b);
    const double b_norm = std::sqrt(exec.sum(n, ProductOf{Exec::ptr(b), Exec::ptr(b)}));
    PcgResult result;
    if (b_norm == 0.0) {
      exec.parallel_for(n, ClearFloats{Exec::ptr(x)});
      return result;
    }
    exec.parallel_for(n, PoissonResidual{a, Exec::ptr(x), Exec::ptr(b), Exec::ptr(r_)});
    double r_norm = std::sqrt(exec.sum(n, ProductOf{Exec::ptr(r_), Exec::ptr(r_)}));
    result.relative_residual = static_cast<float>(r_norm / b_norm);
    if (r_norm <= tolerance * b_norm) return result;
    precondition(exec);
    exec.parallel_for(n, Xpay{Exec::ptr(z_), 0.0f, Exec::ptr(d_)});
    double rz = exec.sum(n, ProductOf{Exec::ptr(r_), Exec::ptr(z_)});
    while (result.iterations < max_iterations) {
      exec.parallel_for(n, ApplyPoisson{a, Exec::ptr(d_), Exec::ptr(q_)});
      const double dq = exec.sum(n, ProductOf{Exec::ptr(d_), Exec::ptr(q_)});
      if (!(dq > 0.0)) break;  // converged to rounding
      const float alpha = static_cast<float>(rz / dq);
      exec.parallel_for(n, StepIterateAndResidual{alpha, Exec::ptr(d_), Exec::ptr(q_), Exec::ptr(x), Exec::ptr(r_)});
      ++result.iterations;
      r_norm = std::sqrt(exec.sum(n, ProductOf{Exec::ptr(r_), Exec::ptr(r_)}));
      result.relative_residual = static_cast<float>(r_norm / b_norm);
      if (r_norm <= tolerance * b_norm) break;
      precondition(exec);
      const double rz_next = exec.sum(n, ProductOf{Exec::ptr(r_), Exec::ptr(z_)});
      exec.parallel_for(n, Xpay{Exec::ptr(z_), static_cast<float>(rz_next / rz), Exec::ptr(d_)});
      rz = rz_next;
    }
    return result;
  }

 private:
  void precondition(const Exec& exec) {
    multigrid_.apply(exec, r_, z_);
    if (singular_) remove_mean(exec, z_);
  }

  void remove_mean(const Exec& exec, Buffer<float>& v) {
    const std::uint8_t* mask = Exec::ptr(multigrid_.unknowns());
    const double count = exec.sum(v.size(), CountWhere{mask});
    if (count == 0) return;
    const double mean = exec.sum(v.size(), ValueWhere{Exec::ptr(v), mask}) / count;
    exec.parallel_for(v.size(), SubtractWhere{static_cast<float>(mean), mask, Exec::ptr(v)});
  }

  MultigridPreconditioner<Exec> multigrid_;
  Buffer<float> r_, z_, d_, q_;
  bool singular_ = false;
};

}  // namespace dp
