#!/usr/bin/env bash
# Proves the image-diff thresholds of pipelines/image-regression.sh on the
# demo case against its committed reference: Monte Carlo noise alone (another
# seed) passes; a visibly wrong image (the water given the tray's diffuse
# material, the camera moved 3 cm sideways) fails.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
REGRESS=$ROOT/pipelines/image-regression.sh
REF=$ROOT/tests/regression/references/demo.exr
WORK=$(mktemp -d "${TMPDIR:-/tmp}/dewpoint-sensitivity.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
SCENES=$ROOT/assets/scenes

# A variant of the demo scene for the render stage; mesh paths made absolute
# so that the copy may live elsewhere.
variant() {
  jq --arg d "$SCENES" '.simulation.rigids |= map(.mesh = ($d + "/" + .mesh))' "$SCENES/demo.json" | jq "$1" > "$2"
}
variant '.render.liquid_material = "tray"' "$WORK/diffuse_water.json"
variant '.render.camera.position_m[0] += 0.03' "$WORK/shifted_camera.json"

expect() {
  local want=$1 what=$2 image=$3
  if "$REGRESS" compare "$REF" "$image"; then got=pass; else got=fail; fi
  echo "sensitivity: $what: $got (expected $want)"
  [ "$got" = "$want" ]
}

status=0
image=$(REGRESSION_SEED=7 "$REGRESS" render demo "$WORK/run" | tail -1)
expect pass "another seed" "$image" || status=1
image=$("$REGRESS" render demo "$WORK/run" "$WORK/diffuse_water.json" | tail -1)
expect fail "water with the tray's diffuse material" "$image" || status=1
image=$("$REGRESS" render demo "$WORK/run" "$WORK/shifted_camera.json" | tail -1)
expect fail "camera moved 3 cm" "$image" || status=1
exit $status
