#include <cuda_runtime.h>

#include "backend/device.h"

namespace dp {
int cuda_device_count(std::string* why) {
  int count = 0;
  cudaError_t err = cudaGetDeviceCount(&count);
  if (err != cudaSuccess) {
    if (why) *why = std::string("no usable CUDA GPU: ") + cudaGetErrorString(err);
    cudaGetLastError();  // clear the sticky error so later queries start clean
    return 0;
  }
  if (count == 0 && why) *why = "no CUDA GPU is present on this machine";
  return count;
}
}  // namespace dp
