#!/usr/bin/env bash
# Packs the CUDA-enabled simulator, the GPU benchmarks and the gpu-labelled
# test binaries of a build with every shared library they load, for a machine
# that has a GPU but none of our Debian packages (the lent H100/H200; docs/gpu.md).
#
#   pipelines/gpu-bundle.sh [--build DIR] [--out FILE]
#
# DIR (default build/) must be a full build configured with the CUDA backend
# (the default wherever nvcc exists). FILE defaults to .carry/dewpoint-gpu.tar.xz.
# The bundle unpacks to dewpoint-gpu/{bin,lib,BUNDLE.txt}: each binary finds
# its libraries through RUNPATH $ORIGIN/../lib, each library its own through
# $ORIGIN, so it runs from wherever it is unpacked. glibc (libc, libm, the
# loader, ...) and the CUDA driver (libcuda) are not packed: they are the
# host's, and a newer glibc runs what Debian 12's built.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD=$ROOT/build
OUTFILE=$ROOT/.carry/dewpoint-gpu.tar.xz
LIMIT_MIB=40
while [ $# -gt 0 ]; do
  case "$1" in
    --build) BUILD=$(realpath "$2"); shift 2 ;;
    --out) OUTFILE=$(realpath -m "$2"); shift 2 ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) echo "gpu-bundle: unknown argument '$1' (expected --build DIR or --out FILE)" >&2; exit 2 ;;
  esac
done

die() { echo "gpu-bundle: $*" >&2; exit 1; }
command -v patchelf >/dev/null || die "patchelf not found; install the Debian package 'patchelf' (pipelines/install-deps.sh)"
[ -f "$BUILD/CMakeCache.txt" ] || die "$BUILD is not a CMake build folder (make -C pipelines build)"
grep -q '^DEWPOINT_CORE_ONLY:BOOL=OFF' "$BUILD/CMakeCache.txt" ||
  die "$BUILD is a core-only build; the bundle needs the full one (dewpoint-simulate)"
grep -q '^DEWPOINT_BUILT_CUDA:INTERNAL=ON' "$BUILD/CMakeCache.txt" ||
  die "$BUILD was configured without the CUDA backend (nvcc not found, or -DDEWPOINT_CUDA=OFF)"

# What goes in: the simulator, the core benchmarks, every test binary that
# holds a gpu-labelled test (ctest's own list, so a new one is not forgotten).
programs=("$BUILD/simulate/dewpoint-simulate")
for b in dam-break air coupling surface; do programs+=("$BUILD/simulate/dewpoint-bench-$b"); done
mapfile -t gpu_tests < <(cd "$BUILD" && ctest -L gpu --show-only=json-v1 | python3 -c '
import json, sys
seen = []
for test in json.load(sys.stdin)["tests"]:
    if test.get("command") and test["command"][0] not in seen:
        seen.append(test["command"][0])
print("\n".join(seen))')
[ ${#gpu_tests[@]} -gt 0 ] || die "ctest lists no gpu-labelled test in $BUILD"
programs+=("${gpu_tests[@]}")
for p in "${programs[@]}"; do [ -x "$p" ] || die "$p is missing; build first (cmake --build $BUILD)"; done

STAGE=$(mktemp -d)
trap 'rm -rf "$STAGE"' EXIT
B=$STAGE/dewpoint-gpu
mkdir -p "$B/bin" "$B/lib"

# The host's own: glibc's libraries and loader, and the GPU driver.
host_library() {
  case "$(basename "$1")" in
    ld-linux*|libc.so*|libm.so*|libmvec.so*|libpthread.so*|libdl.so*|librt.so*|libresolv.so*|libutil.so*|libcuda.so*|linux-vdso*) return 0 ;;
    *) return 1 ;;
  esac
}
for p in "${programs[@]}"; do
  cp "$p" "$B/bin/"
  # ldd resolves the whole closure as the loader would on this machine.
  ldd "$p" | awk '/=> \// { print $3 }' | while read -r lib; do
    host_library "$lib" && continue
    [ -e "$B/lib/$(basename "$lib")" ] || cp -L "$lib" "$B/lib/"
  done
done
for f in "$B"/bin/*; do patchelf --set-rpath '$ORIGIN/../lib' "$f"; done
for f in "$B"/lib/*; do patchelf --set-rpath '$ORIGIN' "$f"; done

# Unused libraries would be dead weight; strip what debug symbols our own
# binaries carry (Debian's libraries come stripped).
strip --strip-unneeded "$B"/bin/* 2>/dev/null || true
{
  echo "dewpoint GPU bundle"
  echo "commit: $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo unknown)$(git -C "$ROOT" diff --quiet HEAD 2>/dev/null || echo ' (with uncommitted changes)')"
  echo "built: $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(. /etc/os-release && echo "$PRETTY_NAME"), glibc $(ldd --version | head -1 | awk '{print $NF}')"
  nvcc=$(grep '^DEWPOINT_BUILT_NVCC:' "$BUILD/CMakeCache.txt" | cut -d= -f2)
  echo "nvcc: $nvcc, $("$nvcc" --version | grep -i release)"
  echo "architectures: $(grep '^DEWPOINT_BUILT_CUDA_ARCHITECTURES:' "$BUILD/CMakeCache.txt" | cut -d= -f2)"
  echo "gpu tests: $(cd "$B/bin" && for t in "${gpu_tests[@]}"; do basename "$t"; done | tr '\n' ' ')"
  echo "needs from the host: glibc >= 2.36, the NVIDIA driver (libcuda.so.1) for --device cuda"
  echo "files:"
  (cd "$B" && find bin lib -type f | sort | xargs sha256sum)
} > "$B/BUNDLE.txt"

mkdir -p "$(dirname "$OUTFILE")"
tar -C "$STAGE" -cf - dewpoint-gpu | xz -T0 -6 > "$OUTFILE.tmp$$"
mv "$OUTFILE.tmp$$" "$OUTFILE"
unpacked=$(du -sm "$B" | cut -f1)
packed=$(( $(stat -c %s "$OUTFILE") / 1048576 ))
echo "gpu-bundle: $OUTFILE: ${#programs[@]} programs, $(ls "$B/lib" | wc -l) libraries, ${unpacked} MiB unpacked, ${packed} MiB packed"
[ "$packed" -le "$LIMIT_MIB" ] || die "$OUTFILE is ${packed} MiB packed, over the ${LIMIT_MIB} MiB the device tool leaves room for"
