#!/usr/bin/env bash
# The GPU bundle (pipelines/gpu-bundle.sh) runs where none of our packages
# are: a minimal Debian 12 (debootstrap --variant=minbase, no -dev package,
# nothing of ours), entered by chroot. There its dewpoint-simulate, on the
# CPU, must write the same frames, byte for byte, as the build it was packed
# from writes here; its gpu test binaries must load and run; asking for
# --device cuda without a GPU must be a clear error. So a bundle with a
# library left behind, a wrong RUNPATH or a path into this build fails here,
# on a machine without a GPU, not on the lent one.
#
#   relocation_test.sh SOURCE_DIR BUILD_DIR
#
# The chroot is made once (about 90 s and 200 MB, from deb.debian.org) and kept
# in $DEWPOINT_CHROOT (default /var/cache/dewpoint/bookworm-minbase). Skips
# (exit 77), saying why, where it cannot be made: not root, no debootstrap,
# no network, or a build without the CUDA backend.
set -euo pipefail
SRC=$(realpath "$1")
BUILD=$(realpath "$2")
CHROOT=${DEWPOINT_CHROOT:-/var/cache/dewpoint/bookworm-minbase}
skip() { echo "relocation_test: SKIPPED: $*"; exit 77; }
fail() { echo "relocation_test: FAILED: $*" >&2; exit 1; }

[ "$(id -u)" -eq 0 ] || skip "chroot needs root"
grep -q '^DEWPOINT_BUILT_CUDA:INTERNAL=ON' "$BUILD/CMakeCache.txt" || skip "$BUILD has no CUDA backend, so no GPU bundle"
if [ ! -f "$CHROOT/.dewpoint-complete" ]; then
  command -v debootstrap >/dev/null || skip "debootstrap not installed (pipelines/install-deps.sh installs it)"
  rm -rf "$CHROOT"
  mkdir -p "$(dirname "$CHROOT")"
  echo "relocation_test: making a minimal Debian 12 in $CHROOT (once)"
  debootstrap --variant=minbase bookworm "$CHROOT" http://deb.debian.org/debian > "$CHROOT.log" 2>&1 ||
    skip "debootstrap failed (no network?); see $CHROOT.log"
  touch "$CHROOT/.dewpoint-complete"
fi
# Nothing of ours, nor any -dev package, in the chroot.
if chroot "$CHROOT" dpkg-query -W -f='${Package}\n' | grep -E -- '-dev$|openvdb|openexr|assimp|openimageio|libtbb|libstb|libgomp'; then
  fail "$CHROOT holds packages the bundle should bring itself (above)"
fi

# The same absolute paths inside the chroot and out, so that the manifests'
# scene paths agree too.
W=/tmp/dewpoint-relocation.$$
INSIDE=$CHROOT$W
# The loader finds $ORIGIN, where the bundle's RUNPATH points, through
# /proc/self/exe: every real machine has /proc, a bare chroot does not.
mountpoint -q "$CHROOT/proc" || mount -t proc proc "$CHROOT/proc" || skip "cannot mount /proc in $CHROOT"
trap 'umount "$CHROOT/proc" 2>/dev/null; rm -rf "$W" "$INSIDE"' EXIT
mkdir -p "$W" "$INSIDE"
"$SRC/pipelines/gpu-bundle.sh" --build "$BUILD" --out "$W/dewpoint-gpu.tar.xz"
tar -C "$INSIDE" -xJf "$W/dewpoint-gpu.tar.xz"
cp -r "$SRC/assets" "$W/assets"
cp -r "$SRC/assets" "$INSIDE/assets"
in_chroot() { chroot "$CHROOT" /usr/bin/env -i PATH=/usr/bin:/bin HOME=/tmp OMP_WAIT_POLICY=PASSIVE "$@"; }

# Every library a binary loads comes from the bundle or from glibc.
for f in "$INSIDE"/dewpoint-gpu/bin/*; do
  name=$(basename "$f")
  libs=$(in_chroot /usr/bin/ldd "$W/dewpoint-gpu/bin/$name")
  ! grep -q "not found" <<<"$libs" || fail "$name: $(grep 'not found' <<<"$libs" | tr '\n' ' ')"
  outside=$(awk '/=> \// { print $3 }' <<<"$libs" | sed 's|/bin/\.\./lib/|/lib/|' | grep -v "^$W/dewpoint-gpu/lib/" |
            grep -Ev '/(ld-linux[^/]*|lib(c|m|mvec|pthread|dl|rt|resolv|util)\.so[^/]*)$' || true)
  [ -z "$outside" ] || fail "$name loads libraries from outside the bundle: $outside"
done

# Frames from the bundle in the chroot against frames from the build here:
# particles, surface textures (max-mass image included) and the air grid.
shots=("drop preview 0-2" "sca_logo_tex preview 0-1")
for shot in "${shots[@]}"; do
  read -r scene preset frames <<<"$shot"
  args=("$W/assets/scenes/$scene.json" --preset "$preset" --frames "$frames" --device cpu --threads 2 --quiet)
  OMP_WAIT_POLICY=PASSIVE "$BUILD/simulate/dewpoint-simulate" "${args[@]}" -o "$W/here/$scene"
  in_chroot "$W/dewpoint-gpu/bin/dewpoint-simulate" "${args[@]}" -o "$W/there/$scene"
  here=$W/here/$scene/frames
  there=$INSIDE/there/$scene/frames
  compared=$(python3 "$SRC/tests/bundle/same_frames.py" "$here" "$there") || fail "$scene: the bundle's frames differ from the build's"
  echo "relocation_test: $scene $preset frames $frames: $compared files the same bytes (VDB UUIDs and wall-clock times aside)"
done

# The gpu test binaries load and run in the chroot (no GPU there: they skip,
# which is a pass).
for f in "$INSIDE"/dewpoint-gpu/bin/*; do
  name=$(basename "$f")
  case "$name" in dewpoint-*) continue ;; esac
  in_chroot "$W/dewpoint-gpu/bin/$name" --gtest_brief=1 > "$W/$name.log" 2>&1 || { cat "$W/$name.log"; fail "$name failed in the chroot"; }
  echo "relocation_test: $name: $(grep -E '^\[  PASSED  \]|SKIPPED \]' "$W/$name.log" | head -2 | tr '\n' ' ')"
done

# --device cuda where there is no GPU: a clear error, not a fallback.
set +e
message=$(in_chroot "$W/dewpoint-gpu/bin/dewpoint-simulate" "$W/assets/scenes/drop.json" -o "$W/cuda" --preset preview --frames 0-0 --device cuda 2>&1)
code=$?
set -e
if nvidia-smi >/dev/null 2>&1; then
  echo "relocation_test: a GPU is present here; --device cuda exited $code"
else
  [ $code -ne 0 ] || fail "--device cuda without a GPU exited 0"
  grep -qi "cuda\|gpu" <<<"$message" || fail "--device cuda without a GPU: the message names neither CUDA nor a GPU: $message"
  echo "relocation_test: --device cuda without a GPU: exit $code, '$message'"
fi
echo "relocation_test: passed"
