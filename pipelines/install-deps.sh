#!/usr/bin/env bash
# Installs dewpoint's build and run dependencies from Debian packages
# (clang and its runtime only for the libFuzzer targets, `make fuzz`; Slurm,
# munge and python3 for the render farm, pipelines/farm; jq and assimp-utils
# for its test, which checks the farm's files with tools that are not ours;
# libopenvdb-tools (vdb_print), openimageio-tools and assimp-utils for the
# readers test, tests/cli/readers_cli_test.cpp;
# python3-vtk9 and python3-numpy to read dewpoint-simulate --paraview's
# files back with VTK's own readers (tests/cli/paraview_series_test.py);
# blender to open a shot in it, pipelines/blender/import_shot.py, and for
# its headless test, tests/cli/blender_import_test.py (about 200 MB);
# gnuplot, the DejaVu fonts and python3 for `make figures` and
# pipelines/make-assets.py; patchelf for the GPU bundle, pipelines/gpu-bundle.sh,
# and debootstrap for its test in a minimal Debian, tests/bundle).
# Idempotent: when everything is present it prints nothing and returns at once.
set -euo pipefail

packages=(
  cmake ninja-build g++ make pkg-config
  libeigen3-dev nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev
  libtbb-dev libassimp-dev libembree-dev libopenimageio-dev openimageio-tools jq
  libopenexr-dev libstb-dev libopenvdb-dev libboost-iostreams-dev libcgal-dev libboost-dev zlib1g-dev
  clang libclang-rt-14-dev libomp-dev
  slurm-wlm munge python3 assimp-utils libopenvdb-tools python3-vtk9 python3-numpy
  gnuplot-nox fonts-dejavu-core
  blender
  patchelf debootstrap
)

# The CPU backend compiles CCCL's Thrust with g++. It comes with the CUDA
# toolkit (/usr/local/cuda); without one, Debian's own Thrust/CUB serve.
if [ ! -f /usr/local/cuda/include/cccl/thrust/sort.h ] && [ -z "${CUDA_PATH:-}" ]; then
  packages+=(libthrust-dev libcub-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}; run this script as root (apt-get needs it)" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
