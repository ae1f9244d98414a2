#!/usr/bin/env bash
# The GPU benchmarks of docs/benchmarks.md, after pipelines/gpu-check.sh has
# built build-gpu on the GPU machine. Each line of output is one benchmark's
# report; LOG (default: stdout) collects them.
set -uo pipefail
cd "$(dirname "$0")/.."
B=${DEWPOINT_BENCH_BIN:-build-gpu/simulate}
run() { echo "### $*"; "$@" 2>&1; echo "### exit $?"; }
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader || true
run $B/dewpoint-bench-dam-break --device cuda --particles 100000 --steps 20 --warmup 5
run $B/dewpoint-bench-dam-break --device cuda --particles 1000000 --steps 10 --warmup 3
# Both solvers late in the collapse (docs/benchmarks.md, "Both solvers against SPlisHSPlasH").
run $B/dewpoint-bench-dam-break --device cuda --particles 100000 --steps 20 --warmup-until 0.38
run $B/dewpoint-bench-dam-break --device cuda --particles 100000 --steps 20 --warmup-until 0.38 --method dfsph
# Glass scale (issue #3): 177K liquid + 80K rigid particles, paper Table 1 Glass 174K + 89K; target <= 5 ms per step.
run $B/dewpoint-bench-dam-break --device cuda --particles 182000 --steps 20 --warmup 5
run $B/dewpoint-bench-air --device cuda --resolution 64 --steps 20 --warmup 5
# The pressure V-cycle's layouts on this GPU (docs/benchmarks.md, "Air step on
# the GPU: one V-cycle, fewer launches"), and where the step's time goes.
run $B/dewpoint-bench-air --device cuda --resolution 64 --steps 20 --warmup 5 --cycle-layout separable
run $B/dewpoint-bench-air --device cuda --resolution 64 --steps 20 --warmup 5 --cycle-layout whole
run $B/dewpoint-bench-air --device cuda --resolution 64 --steps 20 --warmup 5 --parts 1
run $B/dewpoint-bench-air --device cuda --resolution 128 --steps 10 --warmup 3
run $B/dewpoint-bench-coupling --device cuda --steps 10
run $B/dewpoint-bench-coupling --device cuda --rigid-particles 28000 --texels 1024 --liquid 135 --steps 5
run $B/dewpoint-bench-surface --device cuda --steps 20
run $B/dewpoint-bench-surface --device cuda --rigid-particles 28000 --texels 1024 --liquid 135 --steps 10
# The same on the machine's CPU threads, for the ratio on one machine.
run $B/dewpoint-bench-dam-break --device cpu --particles 100000 --steps 10 --warmup 3
run $B/dewpoint-bench-air --device cpu --resolution 64 --steps 10 --warmup 3
