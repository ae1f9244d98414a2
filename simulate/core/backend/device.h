#pragma once
// Run-time choice of backend (--device cpu|cuda, --threads N).
#include <stdexcept>
#include <string>

#include "backend/cpu_isa.h"

namespace dp {

enum class Device { Cpu, Cuda };

struct ExecutionConfig {
  Device device = Device::Cpu;
  int threads = 0;  // CPU threads; 0 = all hardware threads
  CpuIsa cpu_isa = detect_cpu_isa();  // the CPU loops' copy (cpu_isa.h); the same bits either way
};

Device parse_device(const std::string& name);  // throws std::invalid_argument
const char* device_name(Device d);

// Number of usable CUDA devices. When zero, `why` says why (not built with
// CUDA, no driver, no GPU), for error messages that name the cause.
int cuda_device_count(std::string* why);

// Resolves threads = 0 to the hardware thread count.
int resolve_thread_count(int requested);

}  // namespace dp
