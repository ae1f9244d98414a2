#!/usr/bin/env bash
# Image-diff regression of the whole pipeline (simulate -> mesh -> render) on
# the cases of tests/regression/cases.tsv. docs/regression.md explains the
# thresholds and how to regenerate the references.
#
#   image-regression.sh check  NAME|all   render NAME and compare with tests/regression/references/NAME.exr
#   image-regression.sh update NAME|all   render NAME and make it the new reference
#   image-regression.sh render NAME OUTDIR [RENDER_SCENE]
#                                          simulate, mesh and render NAME into OUTDIR
#                                          (RENDER_SCENE: another scene file for the render stage only)
#   image-regression.sh compare REF.exr NEW.exr [DIFF.png]
#                                          the comparison alone; exit 0 pass, 1 fail
#
# Environment: DEWPOINT_BIN (the build folder, default ROOT/build),
# REGRESSION_OUT (work folder, default ROOT/out/regression).
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
BIN=${DEWPOINT_BIN:-$ROOT/build}
CASES=$ROOT/tests/regression/cases.tsv
REFERENCES=$ROOT/tests/regression/references
WORK=${REGRESSION_OUT:-$ROOT/out/regression}

# Comparison thresholds. Path-traced images carry Monte Carlo noise, so both
# images are first smoothed by a 5x5 Gaussian (noise falls ~3x, a shifted edge
# or a changed material does not); then a pixel fails when any channel differs
# by more than FAIL_ABS in linear radiance, and the image fails when more than
# FAIL_PERCENT of its pixels fail. The test suite proves both sides: a render
# with another seed passes, a wrong material or a shifted camera fails.
BLUR=5x5
FAIL_ABS=0.02
FAIL_PERCENT=1
WARN_ABS=0.01

die() { echo "image-regression: $*" >&2; exit 2; }

# Prints the fields "scene frame width height spp preset" of case NAME.
case_fields() {
  local name=$1
  [ -f "$CASES" ] || die "$CASES: missing"
  local line
  line=$(awk -F'\t' -v n="$name" '$1 == n { print $2, $3, $4, $5, $6, (NF >= 7 ? $7 : "-") }' "$CASES")
  [ -n "$line" ] || die "$CASES: no case named '$name' (cases: $(case_names | tr '\n' ' '))"
  echo "$line"
}

case_names() { awk -F'\t' '!/^#/ && NF >= 6 { print $1 }' "$CASES"; }

for tool in oiiotool idiff; do
  command -v "$tool" >/dev/null || die "$tool not found (Debian package openimageio-tools)"
done

render_case() {
  local name=$1 out=$2 render_scene=${3:-}
  local scene frame width height spp preset
  read -r scene frame width height spp preset <<<"$(case_fields "$name")"
  local preset_args=()
  [ "$preset" = "-" ] || preset_args=(--preset "$preset")
  scene=$ROOT/$scene
  [ -f "$scene" ] || die "case $name: scene $scene missing"
  render_scene=${render_scene:-$scene}
  for exe in simulate/dewpoint-simulate mesh/dewpoint-mesh render/dewpoint-render; do
    [ -x "$BIN/$exe" ] || die "$BIN/$exe not built (make -C pipelines build, or set DEWPOINT_BIN)"
  done
  mkdir -p "$out"
  # The simulation and its mesh depend only on the scene and the simulator:
  # reuse them when a previous call left them (the sensitivity tests render
  # one frame several ways). Otherwise start from nothing, so that a run that
  # fails cannot leave an earlier run's frames to be rendered. This runs in
  # a command substitution, where set -e does not hold: each stage's failure
  # ends the case here.
  local manifest=$out/frames/manifest.json
  if [ ! -f "$manifest" ] || [ "$manifest" -ot "$scene" ] || [ "$manifest" -ot "$BIN/simulate/dewpoint-simulate" ]; then
    rm -rf "$out/frames" "$out/meshes"
    "$BIN/simulate/dewpoint-simulate" "$scene" -o "$out" --frames "$frame-$frame" "${preset_args[@]}" --quiet ||
      die "case $name: dewpoint-simulate failed"
  fi
  local mesh_file
  mesh_file=$(printf '%s/meshes/liquid.%04d.ply' "$out" "$frame")
  if [ ! -f "$mesh_file" ] || [ "$mesh_file" -ot "$manifest" ] || [ "$mesh_file" -ot "$BIN/mesh/dewpoint-mesh" ]; then
    "$BIN/mesh/dewpoint-mesh" "$out/frames" -o "$out/meshes" --frames "$frame" --quiet || die "case $name: dewpoint-mesh failed"
  fi
  rm -rf "$out/images"
  "$BIN/render/dewpoint-render" "$render_scene" --frames-dir "$out/frames" --meshes-dir "$out/meshes" \
    -o "$out/images" --frames "$frame" --resolution "${width}x${height}" --spp "$spp" --seed "${REGRESSION_SEED:-1}" \
    --aov none --quiet || die "case $name: dewpoint-render failed"
  printf '%s/images/beauty.%04d.exr\n' "$out" "$frame"
}

compare_images() {
  local ref=$1 new=$2 diff=${3:-}
  [ -f "$ref" ] || die "$ref: no reference (create it with: $0 update NAME)"
  [ -f "$new" ] || die "$new: missing"
  local tmp
  tmp=$(mktemp -d)
  oiiotool "$ref" --ch R,G,B --blur "$BLUR" -d float -o "$tmp/ref.exr"
  oiiotool "$new" --ch R,G,B --blur "$BLUR" -d float -o "$tmp/new.exr"
  local rc=0
  echo "  $ref vs $new (after a $BLUR blur):"
  idiff -fail "$FAIL_ABS" -failpercent "$FAIL_PERCENT" -warn "$WARN_ABS" -warnpercent 100 \
    "$tmp/ref.exr" "$tmp/new.exr" | grep -v '^Comparing' | sed 's/^/  /' || rc=$?
  if [ -n "$diff" ]; then
    # The difference, 10x brighter, to look at when a comparison fails.
    oiiotool "$tmp/ref.exr" "$tmp/new.exr" --absdiff --mulc 10 --colorconvert linear sRGB -d uint8 -o "$diff"
  fi
  rm -rf "$tmp"
  # idiff: 0 identical or within -fail, 1 warning, 2 failure, 3+ size or file errors.
  [ "$rc" -le 1 ]
}

check_case() {
  local name=$1
  local new
  new=$(render_case "$name" "$WORK/$name" | tail -1)
  echo "image-regression: $name"
  if compare_images "$REFERENCES/$name.exr" "$new" "$WORK/$name/diff.png"; then
    echo "image-regression: $name passed"
  else
    echo "image-regression: $name FAILED (10x difference image: $WORK/$name/diff.png)"
    return 1
  fi
}

update_case() {
  local name=$1
  local new
  new=$(render_case "$name" "$WORK/$name" | tail -1)
  mkdir -p "$REFERENCES"
  # Half floats keep the references small; the thresholds are far above their precision.
  oiiotool "$new" --ch R,G,B -d half --compression zip -o "$REFERENCES/$name.exr"
  echo "image-regression: $REFERENCES/$name.exr updated"
}

each_case() {
  local action=$1 which=$2 failed=0
  if [ "$which" = all ]; then
    for n in $(case_names); do "$action" "$n" || failed=1; done
  else
    "$action" "$which" || failed=1
  fi
  return $failed
}

command=${1:-}
case "$command" in
  check)   [ $# -eq 2 ] || die "usage: $0 check NAME|all"; each_case check_case "$2" ;;
  update)  [ $# -eq 2 ] || die "usage: $0 update NAME|all"; each_case update_case "$2" ;;
  render)  [ $# -ge 3 ] || die "usage: $0 render NAME OUTDIR [RENDER_SCENE]"; render_case "$2" "$3" "${4:-}" ;;
  compare) [ $# -ge 3 ] || die "usage: $0 compare REF NEW [DIFF.png]"; compare_images "$2" "$3" "${4:-}" ;;
  *) die "usage: $0 check|update|render|compare ... (see the head of this file)" ;;
esac
