#!/usr/bin/env bash
# mpi_render_test.sh PHONGVK — `mpirun -np N phongvk render SCENE -o OUT --mpi` gives the bytes of
# one process's render, for N = 2 and 3 (oversubscribed on a 2-core machine), on both backends:
# a scene of several objects (its shares cut through objects) and one large mesh split by
# triangle ranges, in Gouraud and Phong shading; with --rgba, --depth, --ids and --normals (.npy
# and .png) every file is the bytes of one process's. Run by CTest (tests/CMakeLists.txt) where MPI
# was found; prints one line per case and "N passed, N failed".
set -uo pipefail
phongvk=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Open MPI refuses to start as root unless told; CI runs as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Its shared-memory transport wants more room in /dev/shm than containers give; TCP on loopback
# stays on this machine.
export OMPI_MCA_btl=self,tcp OMPI_MCA_btl_tcp_if_include=lo OMPI_MCA_oob_tcp_if_include=lo

cat >"$tmp/mesh.json" <<'JSON'
{"camera": {"position": [0, -3, 1], "look_at": [0, 0, 0], "width": 320, "height": 240},
 "lights": [{"position": [-1, -2, 2]}],
 "objects": [{"shape": "icosphere", "center": [0, 0, 0], "radius": 1, "subdivide": 5,
              "material": {"color": [0.3, 0.6, 0.9]}}]}
JSON

passed=0
failed=0
check() {  # check NAME SCENE NP ARGS...: one process against NP processes
  local name=$1 scene=$2 np=$3
  shift 3
  if ! "$phongvk" render "$scene" -o "$tmp/one.png" "$@" >"$tmp/log" 2>&1 ||
     ! mpirun -np "$np" --oversubscribe "$phongvk" render "$scene" -o "$tmp/many.png" --mpi "$@" >>"$tmp/log" 2>&1; then
    echo "FAIL $name: a render failed"; cat "$tmp/log"; failed=$((failed + 1)); return
  fi
  if cmp -s "$tmp/one.png" "$tmp/many.png"; then
    echo "ok   $name"; passed=$((passed + 1))
  else
    echo "FAIL $name: the composited PNG differs from one process's"; failed=$((failed + 1))
  fi
  rm -f "$tmp/one.png" "$tmp/many.png"
}

# check_outputs NAME SCENE NP ARGS...: the same with every output file, each compared with cmp.
check_outputs() {
  local name=$1 scene=$2 np=$3 file differs=""
  shift 3
  local one=(-o "$tmp/one.png" --rgba --depth "$tmp/one_depth.npy" --ids "$tmp/one_ids.png"
             --normals "$tmp/one_normals.npy")
  local many=(-o "$tmp/many.png" --rgba --depth "$tmp/many_depth.npy" --ids "$tmp/many_ids.png"
              --normals "$tmp/many_normals.npy")
  if ! "$phongvk" render "$scene" "${one[@]}" "$@" >"$tmp/log" 2>&1 ||
     ! mpirun -np "$np" --oversubscribe "$phongvk" render "$scene" "${many[@]}" --mpi "$@" >>"$tmp/log" 2>&1; then
    echo "FAIL $name: a render failed"; cat "$tmp/log"; failed=$((failed + 1)); return
  fi
  for file in .png _depth.npy _ids.png _normals.npy; do
    cmp -s "$tmp/one$file" "$tmp/many$file" || differs="$differs $file"
  done
  if [ -z "$differs" ]; then
    echo "ok   $name"; passed=$((passed + 1))
  else
    echo "FAIL $name: the composited file(s)$differs differ from one process's"; failed=$((failed + 1))
  fi
  rm -f "$tmp"/one*.png "$tmp"/one*.npy "$tmp"/many*.png "$tmp"/many*.npy
}

for np in 2 3; do
  for backend in gpu cpu; do
    check "fig3 (2 objects), $np processes, $backend" scenes/paper/fig3_two_lights.json "$np" --backend "$backend" --width 480 --height 320
    check "floor_and_walls (5 objects), $np processes, $backend, phong" scenes/floor_and_walls.json "$np" --backend "$backend" --shading phong
    check "one 20k-triangle mesh, $np processes, $backend" "$tmp/mesh.json" "$np" --backend "$backend"
    check_outputs "basic (6 objects), $np processes, $backend, --rgba --depth --ids --normals" scenes/basic.json "$np" \
      --backend "$backend" --width 480 --height 320
    check_outputs "directional (3 objects), $np processes, $backend, phong, outputs" scenes/directional.json "$np" \
      --backend "$backend" --shading phong
  done
done
# A failure on one rank ends the whole job with its message and exit code, never a hang.
out=$(mpirun -np 2 --oversubscribe "$phongvk" render scenes/basic.json -o "$tmp/x.png" --mpi --samples 4 2>&1)
code=$?
if [ "$code" -ne 0 ] && [[ "$out" == *"--mpi composites one sample per pixel"* ]] && [ ! -e "$tmp/x.png" ]; then
  echo "ok   a bad option ends every rank with the message"; passed=$((passed + 1))
else
  echo "FAIL a bad option: exit $code, $out"; failed=$((failed + 1))
fi
# More than one sample per pixel is refused with the outputs too, before any file is written.
out=$(mpirun -np 2 --oversubscribe "$phongvk" render scenes/basic.json -o "$tmp/x.png" --mpi --samples 4 --rgba \
      --depth "$tmp/d.npy" --ids "$tmp/i.png" --normals "$tmp/n.npy" 2>&1)
code=$?
if [ "$code" -ne 0 ] && [[ "$out" == *"--mpi composites one sample per pixel: render.samples (or --samples) must be 1"* ]] &&
   [ -z "$(ls "$tmp"/*.png "$tmp"/*.npy 2>/dev/null)" ]; then
  echo "ok   --samples 4 with the outputs is refused"; passed=$((passed + 1))
else
  echo "FAIL --samples 4 with the outputs: exit $code, $out"; failed=$((failed + 1))
fi
# So are the graphics backend (no keys) and an --ids PNG for more objects than 16 bits hold.
out=$(mpirun -np 2 --oversubscribe "$phongvk" render scenes/basic.json -o "$tmp/x.png" --mpi --backend graphics 2>&1)
code=$?
if [ "$code" -ne 0 ] && [[ "$out" == *"the graphics backend does not have"* ]] && [ ! -e "$tmp/x.png" ]; then
  echo "ok   the graphics backend is refused"; passed=$((passed + 1))
else
  echo "FAIL the graphics backend: exit $code, $out"; failed=$((failed + 1))
fi
python3 -c 'import json; print(json.dumps({"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "width": 8, "height": 6},
  "objects": [{"shape": "cube", "size": 0.001}] * 65535}))' >"$tmp/many.json"
out=$(mpirun -np 2 --oversubscribe "$phongvk" render "$tmp/many.json" -o "$tmp/x.png" --mpi --ids "$tmp/i.png" 2>&1)
code=$?
if [ "$code" -ne 0 ] && [[ "$out" == *"a 16-bit PNG holds at most 65534 objects' ids, the scene has 65535"* ]] &&
   [ ! -e "$tmp/x.png" ] && [ ! -e "$tmp/i.png" ]; then
  echo "ok   an --ids PNG for 65535 objects is refused"; passed=$((passed + 1))
else
  echo "FAIL an --ids PNG for 65535 objects: exit $code, $out"; failed=$((failed + 1))
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
