#!/usr/bin/env bash
# End-to-end test of the render farm (docs/farm.md) on a one-node Slurm
# cluster started for it: a tiny shot is submitted and every frame checked
# with tools that are not dewpoint's (assimp reads the meshes, oiiotool the
# images, Slurm's own records say which array tasks ran); then a damaged
# image and a deleted mesh must be all that a second submission redoes; then
# a mesh task that cannot write its mesh must cancel its own render task and
# no other. Exit 77 (ctest: skipped) only when Slurm cannot start here.
#   farm_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail

source_dir=$1
build_dir=$2
farm="$source_dir/pipelines/farm"
scene="$source_dir/tests/farm/tiny.json"
work=$(mktemp -d /tmp/dewpoint-farm-test.XXXXXX)
cluster="$work/slurm"
out="$work/out"
frames=(0 1 2 3)

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "ok: $*"; }

cleanup() {
  local status=$?
  "$farm/local-cluster.sh" stop "$cluster" || true
  if [ "$status" -ne 0 ] && [ "$status" -ne 77 ]; then
    echo "--- job logs ($out/logs) ---"
    tail -n 20 "$out"/logs/*.log 2>/dev/null || true
    echo "--- slurm logs ---"
    tail -n 20 "$cluster"/log/*.log 2>/dev/null || true
  fi
  rm -rf "$work"
}
trap cleanup EXIT
# A signal (ctest's timeout, Ctrl-C) ends the script through exit, so the
# cluster is stopped then too.
trap 'exit 143' TERM
trap 'exit 130' INT

# Ports nobody listens on, so a cluster that already runs here is no obstacle.
free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
DEWPOINT_SLURMCTLD_PORT=$(free_port)
DEWPOINT_SLURMD_PORT=$(free_port)
while [ "$DEWPOINT_SLURMD_PORT" = "$DEWPOINT_SLURMCTLD_PORT" ]; do DEWPOINT_SLURMD_PORT=$(free_port); done
export DEWPOINT_SLURMCTLD_PORT DEWPOINT_SLURMD_PORT
if ! "$farm/local-cluster.sh" start "$cluster" >"$work/cluster-start.log" 2>&1; then
  echo "SKIPPED: a local Slurm cluster cannot start here:"
  cat "$work/cluster-start.log"
  exit 77
fi
export SLURM_CONF="$cluster/slurm.conf" DEWPOINT_BIN="$build_dir"

file() { printf '%s/%s.%04d.%s' "$1" "$2" "$3" "$4"; }

# Submits and waits until every job it printed has left the queue.
submit_and_wait() {
  "$farm/submit" "$scene" -o "$out" | tee "$work/submit.out"
  local ids deadline=$((SECONDS + 150))
  ids=$(awk '/^submitted/ { print $4 }' "$work/submit.out" | paste -sd,)
  [ -n "$ids" ] || return 0
  while [ -n "$(squeue -h -j "$ids" 2>/dev/null)" ]; do
    [ $SECONDS -lt $deadline ] || { squeue; echo "jobs $ids still queued after 150 s"; return 1; }
    sleep 1
  done
}

# The job id submit printed for a stage (the Nth such line).
job_of() { awk -v s="$1" '$1 == "submitted" && $2 == s { print $4 }' "$work/submit.out" | sed -n "${2:-1}p"; }

# "TASK STATE" for every task of an array job, from Slurm's records.
task_states() {
  scontrol -o show job "$1" | grep -o 'ArrayTaskId=[0-9]* .*JobState=[A-Z_]*' |
    sed -E 's/ArrayTaskId=([0-9]+) .*JobState=([A-Z_]+)/\1 \2/' | sort -n
}
job_state() { scontrol -o show job "$1" | grep -o 'JobState=[A-Z_]*' | head -n1 | cut -d= -f2; }
expect_tasks() {  # JOB "TASK STATE; ..." description
  local got
  got=$(task_states "$1" | paste -sd';' | sed 's/;/; /g')
  [ "$got" = "$2" ] && pass "$3: $got" || fail "$3: expected '$2', Slurm has '$got'"
}

# A mesh is sound when assimp loads it and finds the triangles and vertices
# its sidecar reports; an image when oiiotool reads every pixel at the
# scene's resolution.
mesh_sound() {
  local ply json info
  ply=$(file "$out/meshes" liquid "$1" ply)
  json=$(file "$out/meshes" liquid "$1" json)
  info=$(assimp info "$ply" 2>&1) || return 1
  [ "$(grep -o '^Vertices: *[0-9]*' <<<"$info" | grep -o '[0-9]*$')" = "$(jq .vertices "$json")" ] &&
    [ "$(grep -o '^Faces: *[0-9]*' <<<"$info" | grep -o '[0-9]*$')" = "$(jq .triangles "$json")" ] &&
    [ "$(jq .triangles "$json")" -gt 100 ]
}
image_sound() {
  local exr info
  exr=$(file "$out/images" beauty "$1" exr)
  info=$(oiiotool --info "$exr" --printstats "$(file "$out/images" beauty "$1" png)" --printstats 2>&1) || return 1
  [ "$(grep -cE 'beauty\.[0-9]{4}\.(exr|png) *: *64 x +36,' <<<"$info")" -eq 2 ]
}
check_all_frames() {
  local f
  for f in "${frames[@]}"; do
    mesh_sound "$f" && pass "$1: mesh $f sound (assimp)" || fail "$1: mesh $f missing or unsound"
    image_sound "$f" && pass "$1: image $f sound (oiiotool)" || fail "$1: image $f missing or unsound"
  done
}
mtimes() {  # the modification times of every mesh and image file, one per line
  stat -c '%n %Y.%y' "$out"/meshes/liquid.* "$out"/images/beauty.* | sort
}

echo "== 1. the whole shot"
start=$SECONDS
submit_and_wait
echo "first submission done in $((SECONDS - start)) s"
expect_tasks "$(job_of mesh)" "0 COMPLETED; 1 COMPLETED; 2 COMPLETED; 3 COMPLETED" "mesh array"
expect_tasks "$(job_of render)" "0 COMPLETED; 1 COMPLETED; 2 COMPLETED; 3 COMPLETED" "render array"
[ "$(job_state "$(job_of simulate)")" = COMPLETED ] && pass "simulate completed" || fail "simulate did not complete"
check_all_frames "first run"
sheet="$out/figures/contact-sheet.0000-0003.png"
oiiotool "$sheet" --printstats >/dev/null 2>&1 && pass "contact sheet readable" || fail "no contact sheet $sheet"

echo "== 2. a truncated image and a deleted mesh"
exr2=$(file "$out/images" beauty 2 exr)
truncate -s $(($(stat -c %s "$exr2") / 2)) "$exr2"
rm "$(file "$out/meshes" liquid 1 ply)"
before=$(mtimes)
sleep 1.1  # so that a rewritten file has a later mtime even on coarse clocks
submit_and_wait
grep -q '^submitted simulate' "$work/submit.out" && fail "simulate resubmitted" || pass "simulate not resubmitted"
expect_tasks "$(job_of mesh)" "1 COMPLETED" "mesh array redoes only frame 1"
expect_tasks "$(job_of render 1)" "1 COMPLETED" "render array after the mesh: only frame 1"
expect_tasks "$(job_of render 2)" "2 COMPLETED" "render array of sound meshes: only frame 2"
after=$(mtimes)
changed=$(diff <(echo "$before") <(echo "$after") | awk '/^>/ { print $2 }' | xargs -r -n1 basename | sort -u | paste -sd' ' || true)
expected="beauty.0001.exr beauty.0001.json beauty.0001.png beauty.0002.exr beauty.0002.json beauty.0002.png liquid.0001.json liquid.0001.ply"
[ "$changed" = "$expected" ] && pass "only frames 1 and 2 rewritten" || fail "rewritten files: '$changed', expected '$expected'"
check_all_frames "after the resubmission"

echo "== 3. up to date: nothing to submit"
submit_and_wait
grep -q '^submitted' "$work/submit.out" && fail "a sound shot was resubmitted" || pass "nothing resubmitted"

echo "== 4. a mesh task that fails"
# Meshes 1-3 are redone; frame 2's cannot be written because a folder holds
# its name. Its render task must be cancelled, renders 1 and 3 must run.
rm "$(file "$out/meshes" liquid 1 ply)" "$(file "$out/meshes" liquid 3 ply)" "$(file "$out/meshes" liquid 2 ply)"
mkdir "$(file "$out/meshes" liquid 2 ply)"
submit_and_wait
expect_tasks "$(job_of mesh)" "1 COMPLETED; 2 FAILED; 3 COMPLETED" "mesh array with frame 2 failing"
expect_tasks "$(job_of render)" "1 COMPLETED; 2 CANCELLED; 3 COMPLETED" "render array: only frame 2 cancelled"
[ "$(job_state "$(job_of contact-sheet)")" = FAILED ] && pass "contact sheet job reports the failure" ||
  fail "contact sheet job state $(job_state "$(job_of contact-sheet)"), expected FAILED"
missing="$out/figures/contact-sheet.0000-0003.missing.txt"
[ "$(cat "$missing" 2>/dev/null)" = 2 ] && pass "missing frames listed: 2" || fail "missing frames list: '$(cat "$missing" 2>/dev/null)'"
why=$(grep -h "cannot move the finished file into place" "$out/logs/farm-tiny-mesh.$(job_of mesh)_2.log" || true)
[ -n "$why" ] && pass "the mesh log says why: $why" || fail "the failed mesh task's log does not say why"

echo "== 5. the folder removed, the next submission completes the shot"
rmdir "$(file "$out/meshes" liquid 2 ply)"
submit_and_wait
expect_tasks "$(job_of mesh)" "2 COMPLETED" "mesh array redoes frame 2 only"
check_all_frames "after recovery"
[ ! -e "$missing" ] && pass "no frame missing from the contact sheet" || fail "$missing still there"

echo "total $SECONDS s, $failures failure(s)"
[ "$failures" -eq 0 ]
