#!/usr/bin/env bash
#SBATCH --job-name=phongvk-assemble
#SBATCH --cpus-per-task=1
# The job after a job array of render_array.sh (submit.sh makes it depend on the array's success):
# the contact sheet of every frame, taken from the files (phongvk sequence --skip-existing renders
# none again; one still missing would be rendered here), and an MP4 when ffmpeg is installed.
# Same environment as render_array.sh.
set -euo pipefail
# shellcheck disable=SC2086
"$PHONGVK" sequence "$PHONGVK_SCENE" -o "$PHONGVK_OUT" --skip-existing --sheet "$PHONGVK_OUT/sheet.png" ${PHONGVK_ARGS:-}
if command -v ffmpeg >/dev/null; then
  ffmpeg -loglevel error -y -framerate 30 -pattern_type glob -i "$PHONGVK_OUT/frame_*.png" \
    -vf "pad=ceil(iw/2)*2:ceil(ih/2)*2" -pix_fmt yuv420p "$PHONGVK_OUT/sequence.mp4"
  echo "wrote $PHONGVK_OUT/sequence.mp4"
fi
