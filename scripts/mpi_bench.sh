#!/usr/bin/env bash
# What compositing one scene across processes costs (phongvk render --mpi): for 2, 3 and 4
# processes (oversubscribed on a 2-core machine) and three image sizes, the median over ROUNDS runs
# (default 5) of the key reduction (MPI_Allreduce, MPI_MIN on 8 bytes a pixel) and the colour
# reduction to rank 0 (MPI_Reduce, MPI_BOR on 3 bytes a pixel), each timed from a barrier, and the
# bytes each rank sends into them. Prints a Markdown table (docs/DISTRIBUTED.md quotes one).
#   scripts/mpi_bench.sh [PHONGVK] [ROUNDS]
# Needs Open MPI (`bash scripts/setup.sh --test`) and a phongvk built with it (scripts/test.sh's build/).
set -euo pipefail
cd "$(dirname "$0")/.."
phongvk=${1:-build/phongvk}
rounds=${2:-5}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl=self,tcp OMPI_MCA_btl_tcp_if_include=lo OMPI_MCA_oob_tcp_if_include=lo
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
echo "| processes | image | keys MB per rank | keys ms (median) | colours MB per rank | colours ms (median) |"
echo "|--:|--:|--:|--:|--:|--:|"
for size in 640x480 1385x923 3840x2160; do
  for np in 2 3 4; do
    : >"$out/keys"; : >"$out/colors"
    for _ in $(seq "$rounds"); do
      line=$(mpirun -np "$np" --oversubscribe "$phongvk" render scenes/paper/fig3_two_lights.json --backend cpu \
             --width "${size%x*}" --height "${size#*x}" -o "$out/x.png" --mpi)
      sed -n 's/.*composite keys \([0-9.]*\) ms.*/\1/p' <<<"$line" >>"$out/keys"
      sed -n 's/.*colours \([0-9.]*\) ms.*/\1/p' <<<"$line" >>"$out/colors"
      keyBytes=$(sed -n 's/.*MPI_MIN, \([0-9]*\) bytes.*/\1/p' <<<"$line")
      colorBytes=$(sed -n 's/.*MPI_BOR, \([0-9]*\) bytes.*/\1/p' <<<"$line")
    done
    printf '| %d | %s | %s | %s | %s | %s |\n' "$np" "$size" "$(awk "BEGIN {printf \"%.1f\", $keyBytes / 1e6}")" \
      "$(median <"$out/keys")" "$(awk "BEGIN {printf \"%.1f\", $colorBytes / 1e6}")" "$(median <"$out/colors")"
  done
done
