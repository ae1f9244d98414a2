// Linked when the CUDA backend is not built.
#include "backend/device.h"

namespace dp {
int cuda_device_count(std::string* why) {
  if (why) *why = "this dewpoint was built without the CUDA backend (configure with -DDEWPOINT_CUDA=ON where nvcc exists)";
  return 0;
}
}  // namespace dp
