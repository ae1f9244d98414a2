#pragma once
// The particle path force of Algorithm 1, line 19. The paper names it and
// says what it is for — the wetting history "allows for a realistic
// rendering of particle paths down surfaces" (Sec. 6.2) — but gives no
// formula. Our definition follows the affinity idea of Wang, Mucha & Turk
// 2005 ("Water drops on surfaces"): a drop next to a wetter part of a
// surface is drawn towards it, so later drops run along earlier paths.
//
// Each boundary particle k carries the wetting history of the texels around
// it, W_k in [0, 1]. A liquid particle i feels Akinci 2013's adhesion form
// (Eq. 6 of Akinci et al., the kernel A that holds liquid to walls) weighted
// by how much wetter each boundary particle is than the average around i:
//   a_i = -beta_path sum_k Psi_k (W_k - W_i) A(r_ik) x_ik / r_ik,
//   W_i = sum_k Psi_k A(r_ik) W_k / sum_k Psi_k A(r_ik),   Psi_k = rho0 V_k.
// On a uniformly wet (or dry) surface every W_k - W_i is 0 and the force
// vanishes: a wet wall does not hold the liquid harder, the paper's step is
// unchanged; only a difference in wetting pulls, along the surface towards
// the wetter side. beta_path has the units of the rigids' adhesion beta.
//
// W_k is the transpose of Eq. 7's interpolation: texel t takes its
// temperature from particles k with weights w_tk; particle k takes back the
// area-weighted average of its texels' wetting with weights A_t w_tk,
//   W_k = sum_t A_t w_tk wet_t / sum_t A_t w_tk.
// Rigids are static, so this transposed list is built once, on the host.
#include <cstdint>
#include <vector>

#include "backend/host_device.h"
#include "sph/surface_tension_akinci2013.h"
#include "sph/uniform_grid.h"
#include "surface/surface_textures.h"

namespace dp {

// Rigid particle k -> its texels of one texture:
// texel[offset[k], offset[k + 1]) with weight A_t w_tk.
struct RigidTexelList {
  std::vector<std::uint32_t> offset, texel;
  std::vector<float> weight;
};

// Transposes one texture's texel -> rigid-particle list (`texel_offset`,
// `rigid_index` over sorted rigid particles, Eq. 7 weights `eq7_weight`) into
// a rigid -> texel list over all `rigid_count` sorted rigid particles.
// Entries of weight 0 (particles of another rigid) are dropped. Texels are
// visited in order, so each particle's entries are in texel order: the
// gather's sums do not depend on the thread count.
inline RigidTexelList transpose_texel_rigid_list(const std::vector<std::uint32_t>& texel_offset,
                                                 const std::vector<std::uint32_t>& rigid_index,
                                                 const std::vector<float>& eq7_weight, const std::vector<float>& texel_area,
                                                 std::size_t rigid_count) {
  RigidTexelList list;
  list.offset.assign(rigid_count + 1, 0);
  const std::size_t texels = texel_offset.empty() ? 0 : texel_offset.size() - 1;
  for (std::size_t t = 0; t < texels; ++t)
    for (std::uint32_t e = texel_offset[t]; e < texel_offset[t + 1]; ++e)
      if (eq7_weight[e] > 0.0f) ++list.offset[rigid_index[e] + 1];
  for (std::size_t k = 0; k < rigid_count; ++k) list.offset[k + 1] += list.offset[k];
  list.texel.resize(list.offset[rigid_count]);
  list.weight.resize(list.offset[rigid_count]);
  std::vector<std::uint32_t> fill(list.offset.begin(), list.offset.end() - 1);
  for (std::size_t t = 0; t < texels; ++t)
    for (std::uint32_t e = texel_offset[t]; e < texel_offset[t + 1]; ++e) {
      if (!(eq7_weight[e] > 0.0f)) continue;
      const std::uint32_t slot = fill[rigid_index[e]]++;
      list.texel[slot] = static_cast<std::uint32_t>(t);
      list.weight[slot] = texel_area[t] * eq7_weight[e];
    }
  return list;
}

// W_k for the rigid particles that have texels of this texture; the others
// keep what they have (0, or another texture's value: a particle belongs to
// one rigid and so to one texture).
struct GatherRigidWetting {
  const std::uint32_t* offset;
  const std::uint32_t* texel;
  const float* weight;
  const float* texel_wetting;
  float* rigid_wetting;

  DP_HD void operator()(std::size_t k) const {
    float sum = 0.0f, norm = 0.0f;
    for (std::uint32_t e = offset[k]; e < offset[k + 1]; ++e) {
      sum += weight[e] * texel_wetting[texel[e]];
      norm += weight[e];
    }
    if (norm > 0.0f) rigid_wetting[k] = sum / norm;
  }
};

// a_i of the definition above, added to the step's other non-pressure
// accelerations.
struct AddPathAcceleration {
  const Vec3* liquid_position;  // sorted
  GridView rigid;               // boundary particles, sorted
  const float* rigid_volume;    // V_k
  const float* rigid_wetting;   // W_k
  float support;                // h
  float rest_density;           // rho0
  float path_adhesion;          // beta_path
  Vec3* acceleration;

  DP_HD void operator()(std::size_t i) const {
    const Vec3 xi = liquid_position[i];
    const float h2 = support * support;
    const AkinciAdhesionKernel adhesion = AkinciAdhesionKernel::with_support(support);
    float weighted = 0.0f, norm = 0.0f;
    rigid.for_each_near(xi, [&](std::uint32_t k) {
      const float r2 = length_squared(xi - rigid.position[k]);
      if (r2 >= h2 || r2 <= 0.0f) return;
      const float w = rest_density * rigid_volume[k] * adhesion.A(sqrtf(r2));
      weighted += w * rigid_wetting[k];
      norm += w;
    });
    if (!(norm > 0.0f)) return;
    const float local = weighted / norm;
    Vec3 a{};
    rigid.for_each_near(xi, [&](std::uint32_t k) {
      const Vec3 xik = xi - rigid.position[k];
      const float r2 = length_squared(xik);
      if (r2 >= h2 || r2 <= 0.0f) return;
      const float r = sqrtf(r2);
      a -= (path_adhesion * rest_density * rigid_volume[k] * (rigid_wetting[k] - local) * adhesion.A(r) / r) * xik;
    });
    acceleration[i] += a;
  }
};

// The path force's state on a backend: the transposed lists (static) and
// the adhesion coefficients of this step.
template <class Exec>
class ParticlePathForce {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

 public:
  bool active() const { return active_; }

  void prepare(const SurfaceTextures<Exec>& surfaces, std::size_t rigid_count, float path_adhesion) {
    const std::size_t m = rigid_count;
    active_ = path_adhesion > 0.0f && surfaces.count() > 0 && m > 0;
    if (!active_) return;
    path_adhesion_ = path_adhesion;
    lists_.resize(surfaces.count());
    for (std::size_t r = 0; r < surfaces.count(); ++r) {
      const auto& tex = surfaces.texture(r);
      const RigidTexelList list = transpose_texel_rigid_list(
          Exec::download(tex.rigid_neighbours.offset), Exec::download(tex.rigid_neighbours.index),
          Exec::download(tex.rigid_weight), Exec::download(tex.area), m);
      Exec::upload(lists_[r].offset, list.offset);
      Exec::upload(lists_[r].texel, list.texel);
      Exec::upload(lists_[r].weight, list.weight);
    }
    Exec::upload(rigid_wetting_, std::vector<float>(m, 0.0f));
  }

  // Adds a_i to `acceleration` of the n liquid particles, from the wetting
  // history of this step (recorded before, Alg. 1 line 14).
  void apply(const Exec& exec, const SurfaceTextures<Exec>& surfaces, const GridView& rigid, const Buffer<float>& rigid_volume,
             const Vec3* liquid_position, std::size_t n, float support, float rest_density, Vec3* acceleration) {
    if (!active_) return;
    const std::size_t m = rigid_volume.size();
    for (std::size_t r = 0; r < surfaces.count(); ++r)
      exec.parallel_for(m, GatherRigidWetting{Exec::ptr(lists_[r].offset), Exec::ptr(lists_[r].texel), Exec::ptr(lists_[r].weight),
                                              Exec::ptr(surfaces.texture(r).wetting), Exec::ptr(rigid_wetting_)});
    exec.parallel_for(n, AddPathAcceleration{liquid_position, rigid, Exec::ptr(rigid_volume), Exec::ptr(rigid_wetting_), support,
                                             rest_density, path_adhesion_, acceleration});
  }

 private:
  struct Lists {
    Buffer<std::uint32_t> offset, texel;
    Buffer<float> weight;
  };
  bool active_ = false;
  float path_adhesion_ = 0.0f;
  std::vector<Lists> lists_;
  Buffer<float> rigid_wetting_;
};

}  // namespace dp
