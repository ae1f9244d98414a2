#pragma once
// Support for the gpu-labelled agreement tests: particle sets sorted on the
// GPU with host copies, and a fixture that skips, saying why, where no GPU
// is present. Included by .cu test files only.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "backend/cuda_exec.cuh"
#include "backend/device.h"
#include "sph/particle_grid.h"

namespace dp::test {

// One particle set sorted on the GPU, with a host copy of its grid for
// running the same functors on the host.
struct DeviceSet {
  ParticleGrid<CudaExec> grid;
  CudaExec::Buffer<Vec3> position;  // sorted
  std::vector<Vec3> host_position;
  std::vector<std::uint32_t> host_order, host_begin;

  void build(const CudaExec& exec, const std::vector<Vec3>& p, const UniformGrid& g) {
    grid.grid = g;
    CudaExec::Buffer<Vec3> unsorted;
    CudaExec::upload(unsorted, p);
    position.resize(p.size());
    grid.sort(exec, unsorted);
    exec.parallel_for(p.size(), Gather<Vec3>{CudaExec::ptr(grid.order), CudaExec::ptr(unsorted), CudaExec::ptr(position)});
    grid.find_ranges(exec);
    host_position = CudaExec::download(position);
    host_order = CudaExec::download(grid.order);
    host_begin = CudaExec::download(grid.cell_begin);
  }
  GridView device_view() const { return grid.view(position); }
  GridView host_view() const { return GridView{grid.grid, host_begin.data(), host_begin.data() + 1, host_position.data()}; }
  template <class T>
  std::vector<T> to_sorted(const std::vector<T>& v) const {
    std::vector<T> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[host_order[i]];
    return out;
  }
};

class RequiresGpu : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (cuda_device_count(&why) == 0) GTEST_SKIP() << "no GPU: " << why;
  }
};

}  // namespace dp::test
