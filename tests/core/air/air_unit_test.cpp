// Unit checks of the air phase's parts against closed-form answers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "air/vapor_pressure.h"
#include "air_test_setups.h"

namespace dp {
namespace {

// Trilinear interpolation reproduces linear fields exactly, so a uniform
// flow must carry T = a.x + c to a.(x - u t) + c, both semi-Lagrangian and
// MacCormack, wherever the back-traced point lies inside the grid.
void expect_linear_field_translated(AirAdvection scheme) {
  CpuExec exec = test::air_exec();
  AirSettings s = test::quiet_air_box(16);
  s.advection = scheme;
  test::SortedParticles none(exec, {}, s.domain_min, s.domain_max, 0.2f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, none.view());
  const MacGrid& g = air.grid();
  const Vec3 vel{0.3f, -0.2f, 0.1f}, a{2.0f, -1.0f, 0.5f};
  AirSnapshot st = air.snapshot();
  std::fill(st.u.begin(), st.u.end(), vel.x);
  std::fill(st.v.begin(), st.v.end(), vel.y);
  std::fill(st.w.begin(), st.w.end(), vel.z);
  std::vector<float> t(g.cell_count());
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) t[g.cell(i, j, k)] = 300.0f + dot(a, g.cell_center(i, j, k));
  air.set_velocity(st.u, st.v, st.w);
  air.set_temperature(t);
  const float dt = 0.1f;  // 0.5 cells along x
  air.advect_temperature(exec, dt);
  const AirSnapshot end = air.snapshot();
  int checked = 0;
  for (int k = 2; k < g.nz - 2; ++k)
    for (int j = 2; j < g.ny - 2; ++j)
      for (int i = 2; i < g.nx - 2; ++i) {
        const Vec3 x = g.cell_center(i, j, k);
        EXPECT_NEAR(end.temperature[g.cell(i, j, k)], 300.0f + dot(a, x - dt * vel), 2e-4f) << i << " " << j << " " << k;
        ++checked;
      }
  EXPECT_GT(checked, 1000);
}

TEST(air_Advection, SemiLagrangianCarriesLinearFieldExactly) { expect_linear_field_translated(AirAdvection::SemiLagrangian); }
TEST(air_Advection, MacCormackCarriesLinearFieldExactly) { expect_linear_field_translated(AirAdvection::MacCormack); }

// Prolongation along one axis is linear interpolation between coarse cell
// centres of the coarse error extended one cell past each end: mirrored
// across a closed wall (Neumann), negated across an open face (phi = 0 on
// the face). Checked on rows of even and odd length, every pair of ends.
TEST(air_Multigrid, ProlongationExtendsTheErrorAcrossWallsAndOpenFaces) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<float> u(-1, 1);
  for (const int nf : {8, 9, 12})
    for (unsigned mask = 0; mask < 4; ++mask) {
      const int nc = (nf + 1) / 2;
      std::vector<float> e(nc), fine(nf);
      for (float& v : e) v = u(rng);
      DomainFaces faces;
      faces.open_mask = mask;  // bit 0: x low, bit 1: x high
      const ProlongAlong<0, false> pass{Box{{nc, 1, 1}}, Box{{nf, 1, 1}}, faces, e.data(), fine.data(), nullptr, nullptr};
      for (int i = 0; i < nf; ++i) pass(i, 0, 0);
      std::vector<double> extended(nc + 2);  // ghost, e_0 .. e_{nc-1}, ghost
      for (int c = 0; c < nc; ++c) extended[c + 1] = e[c];
      extended[0] = (mask & 1u) ? -e[0] : e[0];
      extended[nc + 1] = (mask & 2u) ? -e[nc - 1] : e[nc - 1];
      for (int i = 0; i < nf; ++i) {
        // Fine centre i + 1/2 at (i + 1/2) / 2 coarse cells; extended[m]'s centre at m - 1/2.
        const double x = (i + 0.5) / 2.0 + 0.5;
        const int left = static_cast<int>(std::floor(x));
        const double w = x - left;
        const double expected = (1 - w) * extended[left] + w * extended[left + 1];
        EXPECT_NEAR(fine[i], expected, 1e-6) << "nf " << nf << ", open mask " << mask << ", fine cell " << i;
      }
    }
}

// Restriction is the transpose of prolongation, halved (R = P^T / 2, the
// halving in its last pass): without that pass's halving the three passes
// give P^T r, so r . P e = (P^T r) . e for random r and e, on boxes of odd
// and even sizes with open faces on both sides of different axes.
TEST(air_Multigrid, RestrictionIsHalfTheTransposeOfProlongation) {
  std::mt19937 rng(43);
  std::uniform_real_distribution<float> u(-1, 1);
  const Box fine{{9, 8, 7}}, coarse{{5, 4, 4}};
  const TransferBoxes boxes{fine, coarse};
  for (const unsigned mask : {0u, 0x3u, 0x6u, 0x39u}) {
    DomainFaces faces;
    faces.open_mask = mask;
    std::vector<float> r(fine.size()), e(coarse.size()), wide(boxes.wide_size()), narrow(boxes.narrow_size());
    std::vector<float> restricted(coarse.size()), prolonged(fine.size());
    for (float& v : r) v = u(rng);
    for (float& v : e) v = u(rng);
    auto run = [](const auto& pass) {
      for (int k = 0; k < pass.out.n[2]; ++k)
        for (int j = 0; j < pass.out.n[1]; ++j)
          for (int i = 0; i < pass.out.n[0]; ++i) pass(i, j, k);
    };
    run(RestrictAlong<0, false>{fine, boxes.coarse_x(), faces, r.data(), wide.data(), nullptr});
    run(RestrictAlong<1, false>{boxes.coarse_x(), boxes.coarse_xy(), faces, wide.data(), narrow.data(), nullptr});
    run(RestrictAlong<2, false>{boxes.coarse_xy(), coarse, faces, narrow.data(), restricted.data(), nullptr});
    run(ProlongAlong<0, false>{coarse, boxes.fine_x(), faces, e.data(), narrow.data(), nullptr, nullptr});
    run(ProlongAlong<1, false>{boxes.fine_x(), boxes.fine_xy(), faces, narrow.data(), wide.data(), nullptr, nullptr});
    run(ProlongAlong<2, false>{boxes.fine_xy(), fine, faces, wide.data(), prolonged.data(), nullptr, nullptr});
    double r_pe = 0, rr_e = 0, scale = 0;
    for (std::size_t n = 0; n < r.size(); ++n) {
      r_pe += static_cast<double>(r[n]) * prolonged[n];
      scale += std::fabs(static_cast<double>(r[n]) * prolonged[n]);
    }
    for (std::size_t n = 0; n < e.size(); ++n) rr_e += static_cast<double>(restricted[n]) * e[n];
    EXPECT_NEAR(r_pe, rr_e, 1e-6 * scale) << "open mask " << mask;
    EXPECT_GT(scale, 10.0);
  }
}

// The transfer passes as CpuExec::parallel_for_3d runs them, four points
// at a time (four_along_x) or restriction along x a whole row at a time
// (whole_row), in both of the launcher's copies, against one point at a
// time, bit for bit. The boxes' rows hold groups away from the ends, which
// read every other fine cell (restriction along x) or pair coarse cells
// (prolongation along x) as shuffled lanes, and the ends, which take the
// one-point path; every open-face mask of x changes the end weights; the
// last passes mask by the unknowns and prolongation adds to what is there.
template <class MakePass>
void expect_pass_rows_equal_one(const Box& out, const std::vector<float>& start, const MakePass& make_pass,
                                const char* what) {
  std::vector<float> one = start;
  const auto by_one = make_pass(one.data());
  for (int k = 0; k < out.n[2]; ++k)
    for (int j = 0; j < out.n[1]; ++j)
      for (int i = 0; i < out.n[0]; ++i) by_one(i, j, k);
  for (const CpuIsa isa : {CpuIsa::Baseline, CpuIsa::Avx2}) {
    if (isa == CpuIsa::Avx2 && !cpu_runs_avx2_copy()) continue;
    std::vector<float> rows = start;
    const auto by_rows = make_pass(rows.data());
    static_assert(TakesFourAlongX<decltype(by_rows)>::value || TakesWholeRows<decltype(by_rows)>::value,
                  "the pass has a lane or row path");
    CpuExec(1, isa).parallel_for_3d(out.n[0], out.n[1], out.n[2], by_rows);
    ASSERT_EQ(one.size(), out.size());
    for (std::size_t n = 0; n < one.size(); ++n)
      ASSERT_EQ(std::memcmp(&one[n], &rows[n], sizeof(float)), 0)
          << what << " (" << cpu_isa_name(isa) << "), point " << n << ": " << one[n] << " vs " << rows[n];
  }
}

TEST(air_Multigrid, TransferPassesInRowsAndLanesEqualOnePointBitForBit) {
  std::mt19937 rng(47);
  std::uniform_real_distribution<float> u(-1, 1);
  for (const Box fine : {Box{{2, 5, 6}}, Box{{3, 9, 6}}, Box{{5, 8, 7}}, Box{{21, 9, 6}}, Box{{24, 10, 9}}, Box{{36, 7, 8}}})
    for (const unsigned mask : {0u, 0x1u, 0x2u, 0x3u, 0x3cu}) {
      const Box coarse{{(fine.n[0] + 1) / 2, (fine.n[1] + 1) / 2, (fine.n[2] + 1) / 2}};
      const TransferBoxes boxes{fine, coarse};
      DomainFaces faces;
      faces.open_mask = mask;
      auto random = [&](std::size_t n) {
        std::vector<float> v(n);
        for (float& x : v) x = u(rng);
        return v;
      };
      const std::vector<float> fine_r = random(fine.size()), coarse_x = random(boxes.coarse_x().size()),
                               coarse_xy = random(boxes.coarse_xy().size()), coarse_e = random(coarse.size()),
                               fine_x = random(boxes.fine_x().size()), fine_xy = random(boxes.fine_xy().size()),
                               fine_before = random(fine.size()), scale = random(fine.size());
      std::vector<std::uint8_t> coarse_unknown(coarse.size()), fine_unknown(fine.size());
      for (auto& b : coarse_unknown) b = u(rng) > -0.5f;
      for (auto& b : fine_unknown) b = u(rng) > -0.5f;
      const std::vector<float> zero_coarse_x(boxes.coarse_x().size()), zero_coarse_xy(boxes.coarse_xy().size()),
          zero_coarse(coarse.size()), zero_fine_x(boxes.fine_x().size()), zero_fine_xy(boxes.fine_xy().size());
      expect_pass_rows_equal_one(boxes.coarse_x(), zero_coarse_x, [&](float* t) {
        return RestrictAlong<0, false>{fine, boxes.coarse_x(), faces, fine_r.data(), t, nullptr};
      }, "restriction along x");
      expect_pass_rows_equal_one(boxes.coarse_xy(), zero_coarse_xy, [&](float* t) {
        return RestrictAlong<1, false>{boxes.coarse_x(), boxes.coarse_xy(), faces, coarse_x.data(), t, nullptr};
      }, "restriction along y");
      expect_pass_rows_equal_one(coarse, zero_coarse, [&](float* t) {
        return RestrictAlong<2, true>{boxes.coarse_xy(), coarse, faces, coarse_xy.data(), t, coarse_unknown.data()};
      }, "restriction along z, last");
      expect_pass_rows_equal_one(boxes.fine_x(), zero_fine_x, [&](float* t) {
        return ProlongAlong<0, false>{coarse, boxes.fine_x(), faces, coarse_e.data(), t, nullptr, nullptr};
      }, "prolongation along x");
      expect_pass_rows_equal_one(boxes.fine_xy(), zero_fine_xy, [&](float* t) {
        return ProlongAlong<1, false>{boxes.fine_x(), boxes.fine_xy(), faces, fine_x.data(), t, nullptr, nullptr};
      }, "prolongation along y");
      expect_pass_rows_equal_one(fine, fine_before, [&](float* t) {
        return ProlongAlong<2, true>{boxes.fine_xy(), fine, faces, fine_xy.data(), t, scale.data(), fine_unknown.data()};
      }, "prolongation along z, last");
    }
}

// The one-pass transfers the GPU runs (RestrictWhole, ProlongWhole) against
// the three separable passes the CPU runs, bit for bit: the same terms in
// the same order, on boxes of odd and even sizes down to one cell per axis,
// with every kind of end (closed, open) on each axis, random unknowns and
// a prolongation that adds to what x holds.
TEST(air_Multigrid, WholeTransfersEqualSeparablePassesBitForBit) {
  std::mt19937 rng(53);
  std::uniform_real_distribution<float> u(-1, 1);
  auto run = [](const Box& out, const auto& pass) {
    for (int k = 0; k < out.n[2]; ++k)
      for (int j = 0; j < out.n[1]; ++j)
        for (int i = 0; i < out.n[0]; ++i) pass(i, j, k);
  };
  int compared = 0;
  for (const Box fine : {Box{{1, 2, 3}}, Box{{8, 8, 8}}, Box{{9, 5, 7}}, Box{{16, 11, 6}}})
    for (const unsigned mask : {0u, 0x3u, 0x9u, 0x36u, 0x3fu}) {
      SCOPED_TRACE(::testing::Message() << "fine " << fine.n[0] << "x" << fine.n[1] << "x" << fine.n[2] << ", open mask " << mask);
      const Box coarse{{(fine.n[0] + 1) / 2, (fine.n[1] + 1) / 2, (fine.n[2] + 1) / 2}};
      const TransferBoxes boxes{fine, coarse};
      DomainFaces faces;
      faces.open_mask = mask;
      std::vector<float> r(fine.size()), e(coarse.size()), scale(fine.size()), x(fine.size());
      std::vector<std::uint8_t> coarse_unknown(coarse.size()), fine_unknown(fine.size());
      for (float& v : r) v = u(rng);
      for (float& v : e) v = u(rng);
      for (float& v : scale) v = 1.0f + 0.5f * u(rng);
      for (float& v : x) v = u(rng);
      for (auto& b : coarse_unknown) b = u(rng) > -0.6f;
      for (auto& b : fine_unknown) b = u(rng) > -0.6f;
      std::vector<float> wide(boxes.wide_size()), narrow(boxes.narrow_size());

      std::vector<float> separable(coarse.size(), 7.0f), whole(coarse.size(), -7.0f);
      run(boxes.coarse_x(), RestrictAlong<0, false>{fine, boxes.coarse_x(), faces, r.data(), wide.data(), nullptr});
      run(boxes.coarse_xy(), RestrictAlong<1, false>{boxes.coarse_x(), boxes.coarse_xy(), faces, wide.data(), narrow.data(), nullptr});
      run(coarse, RestrictAlong<2, true>{boxes.coarse_xy(), coarse, faces, narrow.data(), separable.data(), coarse_unknown.data()});
      run(coarse, RestrictWhole{boxes, faces, r.data(), whole.data(), coarse_unknown.data()});
      ASSERT_EQ(std::memcmp(separable.data(), whole.data(), coarse.size() * sizeof(float)), 0) << "restriction";

      std::vector<float> x_separable = x, x_whole = x;
      run(boxes.fine_x(), ProlongAlong<0, false>{coarse, boxes.fine_x(), faces, e.data(), narrow.data(), nullptr, nullptr});
      run(boxes.fine_xy(), ProlongAlong<1, false>{boxes.fine_x(), boxes.fine_xy(), faces, narrow.data(), wide.data(), nullptr, nullptr});
      run(fine, ProlongAlong<2, true>{boxes.fine_xy(), fine, faces, wide.data(), x_separable.data(), scale.data(), fine_unknown.data()});
      run(fine, ProlongWhole{boxes, faces, e.data(), x_whole.data(), scale.data(), fine_unknown.data()});
      ASSERT_EQ(std::memcmp(x_separable.data(), x_whole.data(), fine.size() * sizeof(float)), 0) << "prolongation";
      EXPECT_NE(x_whole, x);  // the correction was added somewhere
      ++compared;
    }
  EXPECT_EQ(compared, 20);
}

// Every layout of the V-cycle's passes (CycleLayout: separable or whole
// transfers; none, some or all of the levels handed to in_one_block, which
// on the CPU runs them on the calling thread) gives the same z = M^-1 r,
// bit for bit, on a grid with obstacles and an open face: the layouts move
// launches, never arithmetic, which is what lets the GPU take its own.
TEST(air_Multigrid, CycleLayoutsGiveTheSameBits) {
  CpuExec exec = test::air_exec();
  const test::PoissonProblem p = test::random_poisson_problem(59);
  MultigridPreconditioner<CpuExec> hierarchy;
  hierarchy.resize(p.n[0], p.n[1], p.n[2], p.faces);
  ASSERT_EQ(hierarchy.level_count(), 4);
  const std::vector<float> reference = test::one_v_cycle(exec, p, CycleLayout{});
  double norm = 0;
  for (float v : reference) norm += std::fabs(v);
  EXPECT_GT(norm, 1.0);
  for (const bool whole : {false, true})
    for (const std::size_t one_block : {std::size_t{0}, std::size_t{125}, std::size_t{810}, std::size_t{6120}, p.cells()}) {
      const std::vector<float> z = test::one_v_cycle(exec, p, CycleLayout{whole, one_block});
      EXPECT_EQ(std::memcmp(z.data(), reference.data(), p.cells() * sizeof(float)), 0)
          << "whole transfers " << whole << ", one block from " << one_block << " cells";
    }
}

// The corner search (clamped lower corner and weight) against its
// definition with floor in double precision, one lane, four and eight: offsets on
// and next to cell boundaries, beyond both ends, and far beyond (where a
// truncation to int would overflow), on lattices of 1, 2 and 5 points.
TEST(air_Sampling, CornerSearchMatchesFloorAndClamp) {
  const float offsets[] = {-3e9f, -1e6f, -2.5f, -1.0f, -0.5f, -1e-7f, 0.0f, 1e-7f, 0.49999997f, 0.5f, 1.0f,
                           3.9999998f, 4.0f, 4.5f, 1e6f, 3e9f, std::numeric_limits<float>::infinity(),
                           -std::numeric_limits<float>::infinity()};
  int checked = 0;
  for (const int n : {1, 2, 5})
    for (const int base : {-3, 0, 1, 4})
      for (const float offset : offsets) {
        const double whole = std::floor(static_cast<double>(offset));
        const double at = base + whole;
        int i;
        float t;
        if (at < 0) {
          i = 0;
          t = 0.0f;
        } else if (at >= n - 1) {
          i = n > 1 ? n - 2 : 0;
          t = n > 1 ? 1.0f : 0.0f;
        } else {
          i = static_cast<int>(at);
          t = offset - static_cast<float>(whole);
        }
        const auto one = CornerOf<OneLane<float>>::locate(base, offset, n);
        EXPECT_EQ(one.i, i) << "n " << n << ", base " << base << ", offset " << offset;
        EXPECT_EQ(one.t, t) << "n " << n << ", base " << base << ", offset " << offset;
        EXPECT_EQ(one.step, n > 1 ? 1 : 0);
        const auto four = CornerOf<FourLanes>::locate(FourLanes::ints(base), FourLanes::reals(offset), n);
        for (int l = 0; l < 4; ++l) {
          EXPECT_EQ(four.i[l], i) << "lane " << l << ", n " << n << ", base " << base << ", offset " << offset;
          EXPECT_EQ(four.t[l], t) << "lane " << l << ", n " << n << ", base " << base << ", offset " << offset;
        }
        const auto eight = CornerOf<EightLanes>::locate(EightLanes::ints(base), EightLanes::reals(offset), n);
        for (int l = 0; l < 8; ++l) {
          EXPECT_EQ(eight.i[l], i) << "lane " << l << " of 8, n " << n << ", base " << base << ", offset " << offset;
          EXPECT_EQ(eight.t[l], t) << "lane " << l << " of 8, n " << n << ", base " << base << ", offset " << offset;
        }
        ++checked;
      }
  EXPECT_EQ(checked, 3 * 4 * 18);
}

// The CPU's lane back-traces (sample_lanes.h), as CpuExec runs them, four
// at a time in the baseline copy, eight and then four in the AVX2 copy,
// against the one-point trace on the same fields, bit for bit, on every
// lattice of a MAC grid: rows that end in whole groups and rows with points
// left over, a random flow fast enough (up to 6 cells per step, forwards
// and backwards as MacCormack traces) that traces leave the grid and are
// clamped, and velocities of 0 and -0 at some faces.
template <int Points>
void expect_lanes_equal_one(const FaceVelocity& vel, const Lattice<float>& source, float c, CpuIsa isa) {
  static_assert(TakesEightAlongX<AdvectSemiLagrangian<float, Points>>::value, "the CPU launcher must find the lanes");
  std::vector<float> one(source.size()), lanes(source.size());
  const AdvectSemiLagrangian<float, Points> by_one{source, vel, c, one.data()};
  const AdvectSemiLagrangian<float, Points> by_lanes{source, vel, c, lanes.data()};
  ASSERT_TRUE(by_lanes.lanes_fit());
  CpuExec(1, isa).parallel_for_3d(source.nx, source.ny, source.nz, by_lanes);
  for (int k = 0; k < source.nz; ++k)
    for (int j = 0; j < source.ny; ++j)
      for (int i = 0; i < source.nx; ++i) by_one(i, j, k);
  for (std::size_t n = 0; n < one.size(); ++n)
    ASSERT_EQ(std::memcmp(&one[n], &lanes[n], sizeof(float)), 0)
        << cpu_isa_name(isa) << ", lattice " << Points << ", point " << n << ": " << one[n] << " vs " << lanes[n];
}

TEST(air_Advection, LanesEqualOneLaneBitForBit) {
  MacGrid g;
  g.dx = 0.1f;
  // The u lattice's rows (16) end in whole groups of four and eight, the
  // cells' (15) and the v and w lattices' rows take eight, four, then three
  // one by one.
  g.nx = 15;
  g.ny = 10;
  g.nz = 7;
  std::mt19937 rng(29);
  std::uniform_real_distribution<float> speed(-6.0f, 6.0f), value(-1.0f, 1.0f);
  std::vector<float> u(g.face_count(0)), v(g.face_count(1)), w(g.face_count(2)), t(g.cell_count());
  for (auto* f : {&u, &v, &w})
    for (std::size_t n = 0; n < f->size(); ++n) (*f)[n] = n % 11 == 0 ? 0.0f : (n % 13 == 0 ? -0.0f : speed(rng));
  for (float& x : t) x = value(rng);
  const FaceVelocity vel = face_velocity(g, u.data(), v.data(), w.data());
  std::vector<CpuIsa> copies{CpuIsa::Baseline};
  if (cpu_runs_avx2_copy()) copies.push_back(CpuIsa::Avx2);
  for (const CpuIsa isa : copies)
    for (const float c : {0.1f / g.dx, -0.1f / g.dx}) {  // dt / dx: up to 6 cells per step
      expect_lanes_equal_one<kCellCentres>(vel, cell_lattice(g, t.data()), c, isa);
      expect_lanes_equal_one<0>(vel, vel.u, c, isa);
      expect_lanes_equal_one<1>(vel, vel.v, c, isa);
      expect_lanes_equal_one<2>(vel, vel.w, c, isa);
    }
}

// A grid of n[0] x n[1] x n[2] cells, the rest as MacGrid's defaults.
MacGrid grid_of_size(const int (&n)[3]) {
  MacGrid g;
  g.nx = n[0];
  g.ny = n[1];
  g.nz = n[2];
  return g;
}

// The CPU launcher hands the vapor flux whole rows (ComputeVaporFlux::
// whole_row), which decide once per row what lies on the domain and which
// neighbours lie inside; against the face-by-face flux, bit for bit, in
// both of the launcher's copies: grids down to one cell per axis (rows with
// no inner faces), every kind of cell, random open faces, flow both ways
// with faces at 0 and -0, and equal neighbours (the limiter's zero slope).
TEST(air_VaporTransport, FluxRowsEqualFaceByFaceBitForBit) {
  std::mt19937 rng(83);
  std::uniform_real_distribution<float> speed(-3.0f, 3.0f), unit(0.0f, 1.0f);
  const int sizes[][3] = {{1, 3, 2}, {2, 2, 3}, {3, 4, 1}, {4, 3, 3}, {5, 1, 4}, {9, 6, 5}};
  int compared = 0;
  for (const auto& n : sizes) {
    MacGrid g = grid_of_size(n);
    g.dx = 0.1f;
    std::vector<double> vapor(g.cell_count());
    for (std::size_t c = 0; c < vapor.size(); ++c) vapor[c] = c % 5 == 0 && c > 0 ? vapor[c - 1] : 0.03 * unit(rng);
    std::vector<std::uint8_t> kind(g.cell_count());
    for (auto& k : kind) {
      const float x = unit(rng);
      k = x < 0.7f ? kAirCell : (x < 0.8f ? kInflowCell : (x < 0.9f ? kSolidCell : kLiquidCell));
    }
    DomainFaces faces;
    faces.open_mask = static_cast<unsigned>(rng()) & 0x3fu;
    const VaporFaceFlux flux{CellKinds{g, kind.data(), faces}, vapor.data(), 0.011, 0.02f};
    const auto face_by_face_equals_rows = [&](auto axis) {
      constexpr int a = decltype(axis)::value;
      std::vector<float> u(g.face_count(a));
      for (std::size_t f = 0; f < u.size(); ++f) u[f] = f % 7 == 0 ? 0.0f : (f % 11 == 0 ? -0.0f : speed(rng));
      std::vector<double> one(u.size(), -1.0);
      const ComputeVaporFlux<a> by_face{flux, u.data(), one.data()};
      for (int k = 0; k < g.face_n(a, 2); ++k)
        for (int j = 0; j < g.face_n(a, 1); ++j)
          for (int i = 0; i < g.face_n(a, 0); ++i) by_face(i, j, k);
      for (const CpuIsa isa : {CpuIsa::Baseline, CpuIsa::Avx2}) {
        if (isa == CpuIsa::Avx2 && !cpu_runs_avx2_copy()) continue;
        std::vector<double> rows(u.size(), -1.0);
        CpuExec(1, isa).parallel_for_3d(g.face_n(a, 0), g.face_n(a, 1), g.face_n(a, 2),
                                        ComputeVaporFlux<a>{flux, u.data(), rows.data()});
        for (std::size_t f = 0; f < u.size(); ++f)
          ASSERT_EQ(std::memcmp(&one[f], &rows[f], sizeof(double)), 0)
              << "axis " << a << " (" << cpu_isa_name(isa) << "), grid " << g.nx << "x" << g.ny << "x" << g.nz << ", face "
              << f << ": " << one[f] << " vs " << rows[f];
        ++compared;
      }
    };
    static_assert(TakesWholeRows<ComputeVaporFlux<0>>::value, "the CPU launcher must find the rows");
    face_by_face_equals_rows(std::integral_constant<int, 0>{});
    face_by_face_equals_rows(std::integral_constant<int, 1>{});
    face_by_face_equals_rows(std::integral_constant<int, 2>{});
  }
  EXPECT_GE(compared, 18);
}

// A row's largest outflow speed, taken on the speeds' bits as integers
// (CellOutflowSpeed::row_max), against the float comparison over its cells,
// bit for bit: faces at +-0, +-inf and NaN among random speeds (a NaN face
// counts as no outflow). Then the CPU launcher's max_3d, which takes the rows
// through row_max, against the float maximum over every cell.
TEST(air_VaporTransport, RowOutflowSpeedIsTheFloatMaximum) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<float> speed(-3.0f, 3.0f), unit(0.0f, 1.0f);
  const float specials[] = {0.0f, -0.0f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()};
  const int sizes[][3] = {{1, 1, 1}, {5, 3, 2}, {17, 4, 3}};
  for (const auto& n : sizes) {
    const MacGrid g = grid_of_size(n);
    std::vector<float> u[3];
    for (int a = 0; a < 3; ++a) {
      u[a].resize(g.face_count(a));
      for (float& x : u[a]) x = unit(rng) < 0.1f ? specials[rng() % 5] : speed(rng);
    }
    const CellOutflowSpeed outflow{g, u[0].data(), u[1].data(), u[2].data()};
    float grid_largest = 0.0f;
    for (int k = 0; k < g.nz; ++k)
      for (int j = 0; j < g.ny; ++j) {
        float expected = 0.0f;
        for (int i = 0; i < g.nx; ++i) {
          const float s = outflow(i, j, k);
          if (s > expected) expected = s;
        }
        const float found = outflow.row_max(g.nx, j, k);
        ASSERT_EQ(std::memcmp(&expected, &found, sizeof found), 0) << "row j=" << j << " k=" << k << ": " << found << " vs " << expected;
        if (expected > grid_largest) grid_largest = expected;
      }
    for (int threads : {1, 2}) EXPECT_EQ(CpuExec(threads).max_3d(g.nx, g.ny, g.nz, outflow, 0.0f), grid_largest);
  }
}

// Diffusion in whole rows (DiffuseExplicit::whole_row), as the CPU launcher
// runs it in both copies, against cell by cell, bit for bit, for float
// (temperature) and double (vapor): grids down to one cell per axis, every
// kind of cell, negative values and -0.
template <class T>
void expect_diffusion_rows_equal_cell_by_cell(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), value(-2.0f, 2.0f);
  const int sizes[][3] = {{1, 1, 1}, {1, 3, 2}, {2, 2, 3}, {3, 4, 1}, {7, 5, 4}};
  for (const auto& n : sizes) {
    const MacGrid g = grid_of_size(n);
    std::vector<T> in(g.cell_count());
    for (std::size_t c = 0; c < in.size(); ++c) in[c] = c % 9 == 4 ? T(-0.0) : static_cast<T>(value(rng));
    std::vector<std::uint8_t> kind(g.cell_count());
    for (auto& k : kind) {
      const float x = unit(rng);
      k = x < 0.7f ? kAirCell : (x < 0.8f ? kInflowCell : (x < 0.9f ? kSolidCell : kLiquidCell));
    }
    // Closed, the top open (the scenes'), and every face open.
    for (const unsigned open_mask : {0u, 1u << 3, 63u}) {
      const CellKinds cells{g, kind.data(), DomainFaces{open_mask}};
      std::vector<T> one(in.size());
      const DiffuseExplicit<T> by_cell{cells, in.data(), 0.15, T(0.5), one.data()};
      for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
          for (int i = 0; i < g.nx; ++i) by_cell(i, j, k);
      for (const CpuIsa isa : {CpuIsa::Baseline, CpuIsa::Avx2}) {
        if (isa == CpuIsa::Avx2 && !cpu_runs_avx2_copy()) continue;
        std::vector<T> rows(in.size());
        CpuExec(1, isa).parallel_for_3d(g.nx, g.ny, g.nz, DiffuseExplicit<T>{cells, in.data(), 0.15, T(0.5), rows.data()});
        for (std::size_t c = 0; c < in.size(); ++c)
          ASSERT_EQ(std::memcmp(&one[c], &rows[c], sizeof(T)), 0) << sizeof(T) << "-byte values (" << cpu_isa_name(isa) << "), grid "
                                                                   << g.nx << "x" << g.ny << "x" << g.nz << ", cell " << c
                                                                   << ", open faces " << open_mask;
      }
    }
  }
}

TEST(air_Diffusion, RowsEqualCellByCellBitForBit) {
  static_assert(TakesWholeRows<DiffuseExplicit<float>>::value, "the CPU launcher must find the rows");
  std::mt19937 rng(97);
  expect_diffusion_rows_equal_cell_by_cell<float>(rng);
  expect_diffusion_rows_equal_cell_by_cell<double>(rng);
}

// The cell forces added to the faces in whole rows (AddCellForceToFaces::
// whole_row), in both of the launcher's copies, against face by face, bit
// for bit, on grids down to one cell per axis.
TEST(air_Forces, FaceRowsEqualFaceByFaceBitForBit) {
  static_assert(TakesWholeRows<AddCellForceToFaces<0>>::value, "the CPU launcher must find the rows");
  std::mt19937 rng(61);
  std::uniform_real_distribution<float> value(-3.0f, 3.0f);
  const int sizes[][3] = {{1, 1, 1}, {2, 3, 1}, {3, 1, 2}, {7, 4, 5}};
  for (const auto& n : sizes) {
    const MacGrid g = grid_of_size(n);
    std::vector<Vec3> force(g.cell_count());
    for (Vec3& f : force) f = Vec3{value(rng), value(rng), value(rng)};
    const auto rows_equal_faces = [&](auto axis) {
      constexpr int a = decltype(axis)::value;
      std::vector<float> start(g.face_count(a));
      for (float& x : start) x = value(rng);
      std::vector<float> one = start;
      const AddCellForceToFaces<a> by_face{g, force.data(), 0.01f, one.data()};
      for (int k = 0; k < g.face_n(a, 2); ++k)
        for (int j = 0; j < g.face_n(a, 1); ++j)
          for (int i = 0; i < g.face_n(a, 0); ++i) by_face(i, j, k);
      for (const CpuIsa isa : {CpuIsa::Baseline, CpuIsa::Avx2}) {
        if (isa == CpuIsa::Avx2 && !cpu_runs_avx2_copy()) continue;
        std::vector<float> rows = start;
        CpuExec(1, isa).parallel_for_3d(g.face_n(a, 0), g.face_n(a, 1), g.face_n(a, 2),
                                        AddCellForceToFaces<a>{g, force.data(), 0.01f, rows.data()});
        for (std::size_t f = 0; f < one.size(); ++f)
          ASSERT_EQ(std::memcmp(&one[f], &rows[f], sizeof(float)), 0)
              << "axis " << a << " (" << cpu_isa_name(isa) << "), grid " << g.nx << "x" << g.ny << "x" << g.nz << ", face " << f;
      }
    };
    rows_equal_faces(std::integral_constant<int, 0>{});
    rows_equal_faces(std::integral_constant<int, 1>{});
    rows_equal_faces(std::integral_constant<int, 2>{});
  }
}

// The face boundary conditions in whole rows (EnforceFaceVelocity::
// whole_row), in both of the launcher's copies, against face by face, bit
// for bit: every kind of cell, two inflows, random open domain faces, and
// free faces holding -0 and NaN, which must come through untouched.
TEST(air_Boundaries, FaceRowsEqualFaceByFaceBitForBit) {
  static_assert(TakesWholeRows<EnforceFaceVelocity<1>>::value, "the CPU launcher must find the rows");
  std::mt19937 rng(71);
  std::uniform_real_distribution<float> value(-3.0f, 3.0f);
  const std::vector<float> table[3] = {{0.0f, 1.5f, -0.5f}, {0.0f, -2.0f, 0.25f}, {0.0f, 0.75f, -0.0f}};
  const int sizes[][3] = {{1, 1, 1}, {2, 3, 1}, {3, 1, 2}, {7, 4, 5}};
  for (const auto& n : sizes) {
    const MacGrid g = grid_of_size(n);
    std::vector<std::uint8_t> kind(g.cell_count()), inflow_of(g.cell_count());
    for (std::size_t c = 0; c < kind.size(); ++c) {
      kind[c] = static_cast<std::uint8_t>(rng() % 4);
      inflow_of[c] = kind[c] == kInflowCell ? static_cast<std::uint8_t>(1 + rng() % 2) : 0;
    }
    DomainFaces faces;
    faces.open_mask = rng() % 64;
    const CellKinds cells{g, kind.data(), faces};
    const auto rows_equal_faces = [&](auto axis) {
      constexpr int a = decltype(axis)::value;
      const std::size_t count = g.face_count(a);
      std::vector<float> start(count);
      for (std::size_t f = 0; f < count; ++f)
        start[f] = f % 7 == 3 ? -0.0f : (f % 11 == 5 ? std::numeric_limits<float>::quiet_NaN() : value(rng));
      std::vector<float> one = start, one_value(count, 9.0f);
      std::vector<std::uint8_t> one_prescribed(count, 7);
      const EnforceFaceVelocity<a> by_face{cells, inflow_of.data(), table[a].data(), one.data(), one_prescribed.data(), one_value.data()};
      for (int k = 0; k < g.face_n(a, 2); ++k)
        for (int j = 0; j < g.face_n(a, 1); ++j)
          for (int i = 0; i < g.face_n(a, 0); ++i) by_face(i, j, k);
      for (const CpuIsa isa : {CpuIsa::Baseline, CpuIsa::Avx2}) {
        if (isa == CpuIsa::Avx2 && !cpu_runs_avx2_copy()) continue;
        std::vector<float> rows = start, rows_value(count, 9.0f);
        std::vector<std::uint8_t> rows_prescribed(count, 7);
        CpuExec(1, isa).parallel_for_3d(
            g.face_n(a, 0), g.face_n(a, 1), g.face_n(a, 2),
            EnforceFaceVelocity<a>{cells, inflow_of.data(), table[a].data(), rows.data(), rows_prescribed.data(), rows_value.data()});
        for (std::size_t f = 0; f < count; ++f) {
          SCOPED_TRACE(::testing::Message() << "axis " << a << " (" << cpu_isa_name(isa) << "), grid " << g.nx << "x" << g.ny
                                            << "x" << g.nz << ", face " << f);
          ASSERT_EQ(std::memcmp(&one[f], &rows[f], sizeof(float)), 0);
          ASSERT_EQ(std::memcmp(&one_value[f], &rows_value[f], sizeof(float)), 0);
          ASSERT_EQ(one_prescribed[f], rows_prescribed[f]);
        }
      }
    };
    rows_equal_faces(std::integral_constant<int, 0>{});
    rows_equal_faces(std::integral_constant<int, 1>{});
    rows_equal_faces(std::integral_constant<int, 2>{});
  }
}

// CG needs a symmetric positive definite preconditioner: y.M x = x.M y and
// x.M x > 0 for random x, y, on a grid with obstacles and an open face.
TEST(air_Multigrid, VCycleIsSymmetricPositiveDefinite) {
  CpuExec exec = test::air_exec();
  const int nx = 20, ny = 17, nz = 12;
  std::vector<std::uint8_t> unknown(nx * ny * nz, 1);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1, 1);
  for (auto& c : unknown) c = u(rng) > -0.8f;  // one cell in ten a wall
  DomainFaces faces;
  faces.open_mask = 1u << 3;
  MultigridPreconditioner<CpuExec> mg;
  mg.resize(nx, ny, nz, faces);
  ASSERT_GE(mg.level_count(), 2);
  mg.set_unknowns(exec, unknown);
  for (int trial = 0; trial < 3; ++trial) {
    std::vector<float> x(unknown.size()), y(unknown.size());
    PaddedField<CpuExec> mx_field, my_field;
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i] = unknown[i] ? u(rng) : 0.0f;
      y[i] = unknown[i] ? u(rng) : 0.0f;
    }
    mg.apply(exec, x, mx_field);
    mg.apply(exec, y, my_field);
    const float* mx = mx_field.ptr();
    const float* my = my_field.ptr();
    double ymx = 0, xmy = 0, xmx = 0, norm = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      ymx += static_cast<double>(y[i]) * mx[i];
      xmy += static_cast<double>(x[i]) * my[i];
      xmx += static_cast<double>(x[i]) * mx[i];
      norm += std::fabs(static_cast<double>(y[i]) * mx[i]);
    }
    EXPECT_NEAR(ymx, xmy, 1e-5 * norm);
    EXPECT_GT(xmx, 0.0);
  }
}

// Multigrid's defining property (Brandt 1977; Trottenberg, Oosterlee &
// Schüller, "Multigrid", 2001, ch. 2): the work to reach a tolerance does not
// grow with the resolution, and MGPCG (McAdams et al. 2010, Table 1) needs
// about ten iterations on fluid domains with obstacles. Here: closed walls,
// one open face, a solid floor and a solid block, a random right-hand side,
// from x = 0 to 1e-6. A cycle that let the coarse correction vanish at walls
// or obstacles needed 18 iterations at 32^3 and more at 64^3.
int iterations_to_1e6(int n) {
  CpuExec exec = test::air_exec();
  const std::size_t cells = static_cast<std::size_t>(n) * n * n;
  std::vector<std::uint8_t> unknown(cells, 1);
  const auto at = [n](int i, int j, int k) { return (static_cast<std::size_t>(k) * n + j) * n + i; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const bool floor = j < n / 10;
        const bool block = i >= n / 2 && i < 2 * n / 3 && j >= n / 4 && j < n / 2 && k >= n / 3 && k < n / 2;
        if (floor || block) unknown[at(i, j, k)] = 0;
      }
  DomainFaces faces;
  faces.open_mask = 1u << 3;  // y max
  PoissonPcg<CpuExec> pcg;
  pcg.resize(n, n, n, faces);
  pcg.set_unknowns(exec, unknown);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<float> b(cells), x(cells, 0.0f);
  for (std::size_t c = 0; c < cells; ++c) b[c] = unknown[c] ? u(rng) : 0.0f;
  const PcgResult r = pcg.solve(exec, b, x, 1e-6f, 100);
  EXPECT_LE(r.relative_residual, 1e-6f);
  return r.iterations;
}

// The stencil on a padded field (unconditional loads, masked) against the
// guarded form on the same values, bit for bit: walls, an open face,
// obstacles, isolated cells, negative zeros in x and NaN in the padding,
// which must never be selected.
TEST(air_Poisson, PaddedStencilEqualsTheGuardedOneBitForBit) {
  const int nx = 9, ny = 7, nz = 6;
  const std::size_t n = static_cast<std::size_t>(nx) * ny * nz;
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<std::uint8_t> unknown(n), stencil(n), diagonal(n);
  for (auto& c : unknown) c = u(rng) > -0.6f;
  DomainFaces faces;
  faces.open_mask = 1u << 1;  // x max
  PoissonLevel level{nx, ny, nz, unknown.data(), faces, nullptr, nullptr};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) BuildPoissonStencil{level, stencil.data(), diagonal.data()}(i, j, k);
  level.stencil = stencil.data();
  level.diagonal = diagonal.data();
  PaddedField<CpuExec> x;
  x.resize(n, level.slab());
  float* padded = x.ptr();
  for (std::size_t i = 0; i < level.slab(); ++i) padded[-1 - static_cast<std::ptrdiff_t>(i)] = padded[n + i] = std::nanf("");
  std::vector<float> plain(n);
  for (std::size_t c = 0; c < n; ++c) plain[c] = padded[c] = (c % 5 == 0) ? -0.0f : u(rng);
  std::size_t unknowns = 0;
  for (std::size_t c = 0; c < n; ++c) {
    const float a = level.apply(padded, c), b = level.apply_unpadded(plain.data(), c);
    EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "cell " << c << ": " << a << " vs " << b;
    unknowns += unknown[c];
  }
  EXPECT_GT(unknowns, n / 2);
  EXPECT_LT(unknowns, n);
}

// The hierarchy's per-cell set-up in whole rows (BuildPoissonStencil and
// ProlongationScale, whole_row), in both of the launcher's copies, against
// cell by cell, bit for bit: levels down to one cell per axis, odd sizes
// (a coarse level of (n + 1) / 2), random unknowns and open domain faces.
TEST(air_Multigrid, SetUpRowsEqualCellByCellBitForBit) {
  static_assert(TakesWholeRows<BuildPoissonStencil>::value && TakesWholeRows<ProlongationScale>::value,
                "the CPU launcher must find the rows");
  std::mt19937 rng(83);
  const int sizes[][3] = {{1, 1, 1}, {2, 3, 1}, {3, 1, 2}, {9, 6, 7}, {16, 8, 9}};
  for (const auto& n : sizes) {
    const int cn[3] = {(n[0] + 1) / 2, (n[1] + 1) / 2, (n[2] + 1) / 2};
    const std::size_t fine_count = static_cast<std::size_t>(n[0]) * n[1] * n[2];
    const std::size_t coarse_count = static_cast<std::size_t>(cn[0]) * cn[1] * cn[2];
    std::vector<std::uint8_t> fine_unknown(fine_count), coarse_unknown(coarse_count);
    for (auto& u : fine_unknown) u = rng() % 5 != 0;
    for (auto& u : coarse_unknown) u = rng() % 4 != 0;
    DomainFaces faces;
    faces.open_mask = rng() % 64;
    const PoissonLevel fine{n[0], n[1], n[2], fine_unknown.data(), faces, nullptr, nullptr};
    const PoissonLevel coarse{cn[0], cn[1], cn[2], coarse_unknown.data(), faces, nullptr, nullptr};
    std::vector<std::uint8_t> stencil(fine_count, 0xAB), diagonal(fine_count, 0xAB);
    std::vector<float> scale(fine_count, -1.0f);
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          BuildPoissonStencil{fine, stencil.data(), diagonal.data()}(i, j, k);
          ProlongationScale{fine, coarse, scale.data()}(i, j, k);
        }
    for (const CpuIsa isa : {CpuIsa::Baseline, CpuIsa::Avx2}) {
      if (isa == CpuIsa::Avx2 && !cpu_runs_avx2_copy()) continue;
      SCOPED_TRACE(::testing::Message() << cpu_isa_name(isa) << ", grid " << n[0] << "x" << n[1] << "x" << n[2]);
      std::vector<std::uint8_t> row_stencil(fine_count, 0xCD), row_diagonal(fine_count, 0xCD);
      std::vector<float> row_scale(fine_count, -2.0f);
      const CpuExec exec(1, isa);
      exec.parallel_for_3d(n[0], n[1], n[2], BuildPoissonStencil{fine, row_stencil.data(), row_diagonal.data()});
      exec.parallel_for_3d(n[0], n[1], n[2], ProlongationScale{fine, coarse, row_scale.data()});
      EXPECT_EQ(row_stencil, stencil);
      EXPECT_EQ(row_diagonal, diagonal);
      EXPECT_EQ(std::memcmp(row_scale.data(), scale.data(), fine_count * sizeof(float)), 0);
    }
  }
}

TEST(air_Multigrid, IterationsDoNotGrowWithResolution) {
  const int coarse = iterations_to_1e6(32), fine = iterations_to_1e6(64);
  RecordProperty("iterations_32", coarse);
  RecordProperty("iterations_64", fine);
  EXPECT_LE(coarse, 12);
  EXPECT_LE(fine, 12);
  EXPECT_LE(fine, coarse + 1);
}

// The hierarchy is rebuilt only when the unknowns change: a solver that saw
// other cells before solves a new set exactly as one built for it alone
// (bit for bit), and setting the same cells again changes nothing.
TEST(air_Multigrid, NewUnknownsRebuildTheHierarchy) {
  CpuExec exec = test::air_exec();
  const int n = 24;
  const std::size_t cells = static_cast<std::size_t>(n) * n * n;
  DomainFaces faces;
  faces.open_mask = 1u << 3;
  const auto with_block = [&](int lo, int hi) {
    std::vector<std::uint8_t> unknown(cells, 1);
    for (int k = lo; k < hi; ++k)
      for (int j = lo; j < hi; ++j)
        for (int i = lo; i < hi; ++i) unknown[(static_cast<std::size_t>(k) * n + j) * n + i] = 0;
    return unknown;
  };
  const std::vector<std::uint8_t> first = with_block(4, 10), second = with_block(12, 20);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<float> b(cells);
  for (std::size_t c = 0; c < cells; ++c) b[c] = second[c] ? u(rng) : 0.0f;
  const auto solve = [&](PoissonPcg<CpuExec>& pcg) {
    std::vector<float> rhs = b, x(cells, 0.0f);
    pcg.solve(exec, rhs, x, 1e-6f, 100);
    return x;
  };

  PoissonPcg<CpuExec> fresh;
  fresh.resize(n, n, n, faces);
  fresh.set_unknowns(exec, second);
  const std::vector<float> expected = solve(fresh);

  PoissonPcg<CpuExec> reused;
  reused.resize(n, n, n, faces);
  reused.set_unknowns(exec, first);
  solve(reused);
  reused.set_unknowns(exec, second);
  EXPECT_EQ(solve(reused), expected);
  reused.set_unknowns(exec, second);
  EXPECT_EQ(solve(reused), expected);
}

// CpuExec as a backend whose convergence check is a round trip, like the
// GPU's: it checks every four iterations, or, once a solve is done, after
// as many iterations as that solve took.
struct CpuExecCheckingRarely : CpuExec {
  using CpuExec::CpuExec;
  static constexpr int kIterationsPerCheck = 4;
};

// An iteration after convergence (or the cap) changes nothing, so when the
// solver checks does not change what it returns: warm-started solves whose
// iteration counts go up and down (so that the count taken from the last
// solve is too many, then too few) give the same x, bit for bit, and the
// same counts and residuals as checking after every iteration.
TEST(air_Pcg, CheckingRarelyGivesWhatCheckingEveryIterationGives) {
  const int n = 20;
  const std::size_t cells = static_cast<std::size_t>(n) * n * n;
  DomainFaces faces;
  faces.open_mask = 1u << 3;  // y max
  std::vector<std::uint8_t> unknown(cells, 1);
  for (int k = 5; k < 11; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 3; i < 13; ++i) unknown[(static_cast<std::size_t>(k) * n + j) * n + i] = 0;
  CpuExec every_exec(1);
  CpuExecCheckingRarely rarely_exec(1);
  PoissonPcg<CpuExec> every;
  PoissonPcg<CpuExecCheckingRarely> rarely;
  every.resize(n, n, n, faces);
  rarely.resize(n, n, n, faces);
  every.set_unknowns(every_exec, unknown);
  rarely.set_unknowns(rarely_exec, unknown);
  std::vector<float> x_every(cells, 0.0f), x_rarely(cells, 0.0f);
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<int> counts;
  for (float tolerance : {1e-2f, 1e-6f, 1e-3f, 1e-6f, 1e-4f, 1e-6f, 1e-6f}) {
    SCOPED_TRACE(tolerance);
    std::vector<float> b(cells);
    for (std::size_t c = 0; c < cells; ++c) b[c] = unknown[c] ? u(rng) : 0.0f;
    std::vector<float> b_rarely = b;
    const PcgResult r_every = every.solve(every_exec, b, x_every, tolerance, 100);
    const PcgResult r_rarely = rarely.solve(rarely_exec, b_rarely, x_rarely, tolerance, 100);
    EXPECT_EQ(r_rarely.iterations, r_every.iterations);
    EXPECT_EQ(r_rarely.relative_residual, r_every.relative_residual);
    EXPECT_EQ(x_rarely, x_every);
    EXPECT_LE(r_every.relative_residual, tolerance);
    counts.push_back(r_every.iterations);
  }
  bool rises = false, falls = false;
  for (std::size_t s = 1; s < counts.size(); ++s) {
    rises |= counts[s] > counts[s - 1];
    falls |= counts[s] < counts[s - 1];
  }
  EXPECT_TRUE(rises && falls) << "the counts never went both ways";
}

// Alg. 1 line 7: a cell holding a rigid particle is solid, one holding a
// liquid particle liquid, an inflow's cells inflow, the rest air.
TEST(air_Classification, CellsTakeTheKindOfWhatTheyHold) {
  CpuExec exec = test::air_exec();
  AirSettings s = test::quiet_air_box(10);  // dx = 0.1
  AirInflow in;
  in.box_min = Vec3{0.0f, 0.0f, 0.0f};
  in.box_max = Vec3{0.2f, 0.1f, 0.1f};  // cell centres (0.05, 0.05, 0.05) and (0.15, 0.05, 0.05)
  s.inflows.push_back(in);
  test::SortedParticles rigid(exec, {Vec3{0.55f, 0.55f, 0.55f}}, s.domain_min, s.domain_max, 0.04f);
  test::SortedParticles liquid(exec, {Vec3{0.31f, 0.72f, 0.99f}, Vec3{0.56f, 0.51f, 0.59f}, Vec3{0.12f, 0.02f, 0.03f}},
                               s.domain_min, s.domain_max, 0.04f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, rigid.view());
  air.classify(exec, liquid.positions());
  const AirSnapshot a = air.snapshot();
  const MacGrid& g = a.grid;
  int counts[4] = {0, 0, 0, 0};
  for (auto k : a.kind) ++counts[k];
  EXPECT_EQ(a.kind[g.cell(5, 5, 5)], kSolidCell);  // rigid wins over the liquid particle there
  EXPECT_EQ(a.kind[g.cell(3, 7, 9)], kLiquidCell);
  EXPECT_EQ(a.kind[g.cell(0, 0, 0)], kInflowCell);  // inflow wins over the liquid particle there
  EXPECT_EQ(a.kind[g.cell(1, 0, 0)], kInflowCell);
  EXPECT_EQ(counts[kSolidCell], 1);
  EXPECT_EQ(counts[kLiquidCell], 1);
  EXPECT_EQ(counts[kInflowCell], 2);
  EXPECT_EQ(counts[kAirCell], 1000 - 4);
}

// The per-step scatter (MarkLiquidCells) against the per-cell gather it
// replaced: a cell is liquid exactly when any_particle_in_box finds a liquid
// particle in it, here for particles scattered at random, on cell faces and
// corners (where float rounding decides which span holds them), and outside
// the grid. 3 threads, so that cells marked from several threads are seen.
TEST(air_Classification, LiquidCellsAreThoseTheBoxSearchFinds) {
  CpuExec exec(3);
  AirSettings s = test::quiet_air_box(12);  // dx = 1/12, a spacing float does not hold exactly
  s.domain_min = Vec3{0.3f, -0.7f, 0.1f};   // an origin that the cell bounds round against
  s.domain_max = s.domain_min + Vec3{1, 1, 1};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-0.05f, 1.05f);
  std::uniform_int_distribution<int> face(0, 12);
  std::vector<Vec3> points;
  for (int n = 0; n < 3000; ++n) points.push_back(s.domain_min + Vec3{u(rng), u(rng), u(rng)});
  const float dx = 1.0f / 12.0f;
  for (int n = 0; n < 1500; ++n) {
    Vec3 p = s.domain_min + Vec3{u(rng), u(rng), u(rng)};
    p.x = s.domain_min.x + dx * static_cast<float>(face(rng));  // on an x face, as the box test's lo is formed
    if (n % 2) p.y = s.domain_min.y + dx * static_cast<float>(face(rng)) + dx;  // on a y face, as hi is
    if (n % 3 == 0) p.z = std::nextafter(s.domain_min.z + dx * static_cast<float>(face(rng)), 0.0f);
    points.push_back(p);
  }
  test::SortedParticles liquid(exec, points, s.domain_min, s.domain_max, 0.04f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, test::SortedParticles(exec, {}, s.domain_min, s.domain_max, 0.04f).view());
  air.classify(exec, liquid.positions());
  const AirSnapshot a = air.snapshot();
  const MacGrid& g = a.grid;
  const GridView view = liquid.view();
  int liquid_cells = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const Vec3 lo = g.origin + g.dx * Vec3{static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)};
        const bool found = any_particle_in_box(view, lo, lo + Vec3{g.dx, g.dx, g.dx});
        ASSERT_EQ(a.kind[g.cell(i, j, k)], found ? kLiquidCell : kAirCell) << "cell " << i << " " << j << " " << k;
        liquid_cells += found;
      }
  EXPECT_GT(liquid_cells, 1000);
  EXPECT_LT(liquid_cells, 1728);
}

// Eq. 11 against the IAPWS-95 saturation pressures of water (0 C: 611.2 Pa,
// 20 C: 2339.2 Pa, 50 C: 12352 Pa), which Magnus' fit follows within half a
// percent; Eq. 10 with it: saturated air at 20 C holds 17.3 g/m^3.
TEST(air_VaporPressure, SaturatedAirAt20CHolds17GramsPerCubicMetre) {
  EXPECT_NEAR(magnus_saturation_pressure(0.0), 611.2, 0.005 * 611.2);
  EXPECT_NEAR(magnus_saturation_pressure(20.0), 2339.2, 0.005 * 2339.2);
  EXPECT_NEAR(magnus_saturation_pressure(50.0), 12352.0, 0.005 * 12352.0);
  EXPECT_NEAR(vapor_density_at_humidity(1.0, 293.15), 0.0173, 0.0002);
  EXPECT_NEAR(vapor_pressure(vapor_density_at_humidity(0.5, 293.15), 293.15), 0.5 * magnus_saturation_pressure(20.0), 1e-9);
}

}  // namespace
}  // namespace dp
