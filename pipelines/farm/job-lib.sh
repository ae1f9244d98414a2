# shellcheck shell=bash
# Sourced by the farm's job scripts (pipelines/farm/*.sbatch). Slurm runs a
# copy of the script from its spool folder, so the submitter exports where
# this file (DEWPOINT_FARM) and the executables (DEWPOINT_BIN) are.

# The path of dewpoint-NAME: a build tree (BIN/NAME/dewpoint-NAME) or an
# installed, flat folder (BIN/dewpoint-NAME).
dewpoint_exe() {
  local name=$1 bin=${DEWPOINT_BIN:?DEWPOINT_BIN is not set: the folder of the dewpoint build or installed executables}
  local candidate
  for candidate in "$bin/$name/dewpoint-$name" "$bin/dewpoint-$name"; do
    if [ -x "$candidate" ]; then
      echo "$candidate"
      return 0
    fi
  done
  echo "job: dewpoint-$name not found in DEWPOINT_BIN=$bin (looked for $bin/$name/dewpoint-$name and $bin/dewpoint-$name)" >&2
  return 1
}

# Tasks are not confined to their CPUs on every cluster (task/none), so a
# stage uses as many threads as the task was given, not all the node has.
job_threads() {
  echo "${SLURM_CPUS_PER_TASK:-1}"
}

# The array task id is the frame index.
array_frame() {
  if [ -z "${SLURM_ARRAY_TASK_ID:-}" ]; then
    echo "job: this script runs as a job array, one task per frame (sbatch --array=FRAMES)" >&2
    return 1
  fi
  echo "$SLURM_ARRAY_TASK_ID"
}

frame_file() {
  printf '%s.%04d.%s' "$1" "$2" "$3"
}
