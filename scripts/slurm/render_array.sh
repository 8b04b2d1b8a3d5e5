#!/usr/bin/env bash
#SBATCH --job-name=phongvk-frames
#SBATCH --cpus-per-task=1
# One task of a Slurm job array that renders a sequence's frames (submit.sh submits it). Task k of
# n takes frames k, k+n, k+2n, ... (PHONGVK_SLICE=interleaved, the default: every task gets early
# and late frames alike) or the k-th of n contiguous blocks (PHONGVK_SLICE=blocks). Frames a task
# wrote whole before it was killed or requeued are kept (phongvk sequence --skip-existing: frames
# are written whole, a temporary file renamed), so a restart renders only what is missing.
# From the environment (submit.sh exports them): PHONGVK (the command), PHONGVK_SCENE, PHONGVK_OUT,
# PHONGVK_SLICE, PHONGVK_ARGS (more `phongvk sequence` options, split at spaces).
set -euo pipefail
task=$((${SLURM_ARRAY_TASK_ID:?run this as a task of a Slurm job array} - ${SLURM_ARRAY_TASK_MIN:-0}))
tasks=${SLURM_ARRAY_TASK_COUNT:?run this as a task of a Slurm job array}
case "${PHONGVK_SLICE:-interleaved}" in
  interleaved) frames="$task::$tasks" ;;
  blocks)
    count=$(/usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1])).get("animate", {}).get("frames", 1))' \
            "$PHONGVK_SCENE")
    frames="$((count * task / tasks)):$((count * (task + 1) / tasks))" ;;
  *) echo "PHONGVK_SLICE must be interleaved or blocks, got '$PHONGVK_SLICE'" >&2; exit 2 ;;
esac
# An empty block (more tasks than frames) has nothing to do.
[[ "$frames" =~ ^([0-9]+):([0-9]+)$ ]] && [ "${BASH_REMATCH[1]}" -ge "${BASH_REMATCH[2]}" ] && exit 0
# shellcheck disable=SC2086  # PHONGVK_ARGS is a list of options
exec "$PHONGVK" sequence "$PHONGVK_SCENE" -o "$PHONGVK_OUT" --frames "$frames" --skip-existing ${PHONGVK_ARGS:-}
