#!/usr/bin/env bash
# mpi_render_test.sh PHONGVK — `mpirun -np N phongvk render SCENE -o OUT --mpi` gives the bytes of
# one process's render, for N = 2 and 3 (oversubscribed on a 2-core machine), on both backends:
# a scene of several objects (its shares cut through objects) and one large mesh split by
# triangle ranges, in Gouraud and Phong shading. Run by CTest (tests/CMakeLists.txt) where MPI was
# found; prints one line per case and "N passed, N failed".
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

for np in 2 3; do
  for backend in gpu cpu; do
    check "fig3 (2 objects), $np processes, $backend" scenes/paper/fig3_two_lights.json "$np" --backend "$backend" --width 480 --height 320
    check "floor_and_walls (5 objects), $np processes, $backend, phong" scenes/floor_and_walls.json "$np" --backend "$backend" --shading phong
    check "one 20k-triangle mesh, $np processes, $backend" "$tmp/mesh.json" "$np" --backend "$backend"
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
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
