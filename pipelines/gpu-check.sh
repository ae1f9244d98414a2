#!/usr/bin/env bash
# The GPU checks, for a machine with a CUDA GPU but no Debian packages (the
# lent H100/H200 machines): builds only the simulator core with CUDA and runs
# the gpu-labelled tests (CUDA against the CPU reference) and the core tests.
#
# GoogleTest travels as source: on the packaged machine run
#   pipelines/gpu-check.sh --prepare      (copies /usr/src/googletest to .carry/)
# then on the GPU machine, with .carry carried along:
#   pipelines/gpu-check.sh
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--prepare" ]; then
  mkdir -p .carry && rm -rf .carry/googletest && cp -r /usr/src/googletest .carry/googletest
  echo "gpu-check: GoogleTest source in .carry/googletest; carry .carry to the GPU machine"
  exit 0
fi
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader || true
cmake -S . -B build-gpu -G Ninja -DDEWPOINT_CORE_ONLY=ON -DDEWPOINT_CUDA=ON \
  -DDEWPOINT_GTEST_SOURCE="$PWD/.carry/googletest" -DCMAKE_BUILD_TYPE=Release
cmake --build build-gpu -j "$(nproc)"
cd build-gpu && ctest --output-on-failure -V -L "gpu|unit"
