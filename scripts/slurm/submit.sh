#!/usr/bin/env bash
# Renders an animated scene's frames on a Slurm cluster: a job array of TASKS tasks
# (render_array.sh), then, once every task succeeded, one job that makes the contact sheet and a
# video (assemble.sh). Prints the two job ids. The frames are byte for byte those of one
# `phongvk sequence` run; a task that is requeued or restarted keeps the frames it finished.
#
#   scripts/slurm/submit.sh SCENE OUT_DIR TASKS [phongvk sequence options...]
#   PHONGVK_SLICE=blocks scripts/slurm/submit.sh scenes/paper/fig7_orbit_white_red.json frames/ 8 --width 640 --height 480
#
# PHONGVK names the phongvk command (default: the one on PATH, else this checkout's build/phongvk);
# every node must reach it, the scene and OUT_DIR at the same paths (a shared file system). Options
# for sbatch go in SBATCH_* environment variables (SBATCH_PARTITION, SBATCH_TIMELIMIT, ...).
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 SCENE OUT_DIR TASKS [phongvk sequence options...]" >&2
  exit 2
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
scene="$(realpath "$1")"
out="$(realpath -m "$2")"
tasks=$3
shift 3
phongvk="${PHONGVK:-$(command -v phongvk || echo "$here/../../build/phongvk")}"
mkdir -p "$out"
export PHONGVK="$(realpath "$phongvk")" PHONGVK_SCENE="$scene" PHONGVK_OUT="$out" PHONGVK_ARGS="$*"
export PHONGVK_SLICE="${PHONGVK_SLICE:-interleaved}"
array=$(sbatch --parsable --array="0-$((tasks - 1))" --export=ALL --output="$out/slurm-%A_%a.log" "$here/render_array.sh")
array=${array%%;*}
assembly=$(sbatch --parsable --dependency="afterok:$array" --export=ALL --output="$out/slurm-%j-assemble.log" \
           "$here/assemble.sh")
echo "array $array, assembly ${assembly%%;*}"
