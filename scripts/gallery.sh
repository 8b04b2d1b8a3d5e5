#!/usr/bin/env bash
# Regenerates docs/gallery/ from scenes/paper/: a still for each Fig. 1 scene and a contact sheet
# for each sequence (Figs. 2-7), then the shading modes and samples side by side
# (scenes/shading/), and prints how long each took. See docs/gallery.md.
#
#   scripts/gallery.sh                      # builds build/ if needed, renders on the GPU backend
#   BUILD_DIR=build-rel BACKEND=cpu scripts/gallery.sh
#
# Sizes are kept small so the committed PNGs stay at a few hundred KB in all and the whole run
# takes seconds on a 2-core machine with lavapipe: stills at 360x240; sequences rendered at
# 240x160, every 10th frame of a 120-frame sequence (12 frames), box-filtered to 120 px wide
# thumbnails. The frames themselves go to a temporary folder and are deleted. The committed PNGs
# are written at the smallest PNG level (12): the same pixels as any level.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
backend="${BACKEND:-gpu}"
cd "$root"

out=docs/gallery
frames="$(mktemp -d)"
trap 'rm -rf "$frames"' EXIT
mkdir -p "$out"

# Incremental: configures once, then rebuilds only what changed (usually nothing). The build's
# output is shown only if it fails. A fresh configure leaves the tests out, as the README's render
# command does, so `bash scripts/setup.sh` is enough (scripts/test.sh turns them back on).
build_phongvk() {
  if [[ ! -f "$build/CMakeCache.txt" ]]; then
    cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHONGVK_TESTS=OFF || return
  fi
  cmake --build "$build" -j2 --target phongvk
}
build_phongvk >"$frames/build.log" 2>&1 || { cat "$frames/build.log" >&2; exit 1; }
phongvk="$build/phongvk"

now_ms() { echo $(( $(date +%s%N) / 1000000 )); }

# timed IMAGE SCENE COMMAND...: runs the command quietly and prints one line for the gallery table.
timed() {
  local image="$1" scene="$2"
  shift 2
  local start
  start="$(now_ms)"
  "$@" >/dev/null 2>"$frames/stderr" || { cat "$frames/stderr" >&2; exit 1; }
  local ms=$(( $(now_ms) - start ))
  printf '%-38s %3d.%03d s  %s\n' "$image" $((ms / 1000)) $((ms % 1000)) "$scene"
}

still() {
  local name="$1"
  timed "$out/$name.png" "scenes/paper/$name.json" \
    "$phongvk" render "scenes/paper/$name.json" -o "$out/$name.png" --width 360 --height 240 --backend "$backend" --png-level 12
}

# sheet NAME RANGE: a contact sheet of the frames RANGE selects (--frames syntax).
sheet() {
  local name="$1" range="$2"
  timed "$out/$name.png" "scenes/paper/$name.json --frames $range" \
    "$phongvk" sequence "scenes/paper/$name.json" -o "$frames/$name" --frames "$range" \
    --width 240 --height 160 --sheet "$out/$name.png" --thumb-width 120 --backend "$backend" --png-level 12
}

# modes NAME: the six frames of scenes/shading/NAME.json (one scene, one render option each)
# side by side at the scene's own size.
modes() {
  local name="$1"
  timed "$out/shading_$name.png" "scenes/shading/$name.json" \
    "$phongvk" sequence "scenes/shading/$name.json" -o "$frames/$name" --sheet "$out/shading_$name.png" \
    --thumb-width 360 --backend "$backend" --png-level 12
}

total_start="$(now_ms)"
echo "phongvk gallery: $backend backend, $("$phongvk" devices 2>/dev/null | grep -m1 usable || echo 'no Vulkan device')"
for object in cube cylinder cone polyhedron; do still "fig1_$object"; done
sheet fig2_light_colours :
sheet fig3_two_lights 0:120:10
sheet fig4_ka_sweep 0:120:10
sheet fig5_ks_sweep 0:120:10
sheet fig6_orbit_red 0:120:10
sheet fig7_orbit_white_red 0:120:10
modes modes
modes samples
# model NAME FILE [OPTIONS...]: a still of a model file or scene at 360x240, with 4 samples per pixel
# (textures seen from far away need them: there are no mipmaps).
model() {
  local name="$1" file="$2"
  shift 2
  timed "$out/textured_$name.png" "$file" \
    "$phongvk" render "$file" -o "$out/textured_$name.png" --width 360 --height 240 --samples 4 --backend "$backend" --png-level 12 "$@"
}
model scene scenes/textured.json
model box /usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb
model spider /usr/share/assimp/models/OBJ/spider.obj
# lit NAME: a still of scenes/NAME.json (spot lights, shadows, a glTF file's own lights) at 360x240,
# 4 samples per pixel, Phong shading.
lit() {
  local name="$1"
  timed "$out/lights_$name.png" "scenes/$name.json" \
    "$phongvk" render "scenes/$name.json" -o "$out/lights_$name.png" --width 360 --height 240 --samples 4 \
    --shading phong --backend "$backend" --png-level 12
}
lit spot_light
lit shadows
lit file_lights
total_ms=$(( $(now_ms) - total_start ))
echo "total: $((total_ms / 1000)).$(printf '%03d' $((total_ms % 1000))) s, $(du -ch "$out"/*.png | tail -1 | cut -f1) of PNG in $out"
