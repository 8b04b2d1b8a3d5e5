#!/usr/bin/env bash
# slurm_test.sh PHONGVK — scripts/slurm/ on a real one-node Slurm cluster that this test starts and
# stops: munged, slurmctld and slurmd from Debian's munge and slurm-wlm, with a key, a slurm.conf
# and every state, log and socket in a temporary folder (nothing of the system's is used or left
# running). A 4-task job array over the 120-frame orbit must give one `phongvk sequence` run's
# bytes (and a contact sheet); then, with block slicing, one task is requeued midway: nothing may
# be missing or partial afterwards, and the frames it had finished must not be rendered again.
# Run by CTest where slurmctld was found (tests/CMakeLists.txt); prints "N passed, N failed".
set -uo pipefail
phongvk="$(realpath "$1")"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
run=$(mktemp -d)
chmod 700 "$run"
passed=0
failed=0
pass() { echo "ok   $1"; passed=$((passed + 1)); }
fail() { echo "FAIL $1"; failed=$((failed + 1)); }

stop() {
  scancel --quiet --user=root 2>/dev/null
  for pid in slurmd slurmctld munged; do [ -f "$run/$pid.pid" ] && kill "$(cat "$run/$pid.pid")" 2>/dev/null; done
  sleep 1
  for pid in slurmd slurmctld munged; do [ -f "$run/$pid.pid" ] && kill -9 "$(cat "$run/$pid.pid")" 2>/dev/null; done
  rm -rf "$run"
}
trap stop EXIT

# ---- the cluster ----
free_port() { /usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
mkdir -p "$run/state" "$run/spool" "$run/log"
head -c 1024 /dev/urandom >"$run/munge.key"
chmod 400 "$run/munge.key"
/usr/sbin/munged --key-file="$run/munge.key" --socket="$run/munge.socket" --pid-file="$run/munged.pid" \
  --log-file="$run/log/munged.log" --seed-file="$run/munged.seed" --force || { echo "munged did not start"; exit 1; }
node=$(hostname)
cat >"$run/slurm.conf" <<CONF
ClusterName=phongvktest
SlurmctldHost=$node(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
AuthType=auth/munge
AuthInfo=socket=$run/munge.socket
CredType=cred/munge
StateSaveLocation=$run/state
SlurmdSpoolDir=$run/spool
SlurmctldPidFile=$run/slurmctld.pid
SlurmdPidFile=$run/slurmd.pid
SlurmctldLogFile=$run/log/slurmctld.log
SlurmdLogFile=$run/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=phongvk Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$run/slurm.conf"
/usr/sbin/slurmctld -i || { echo "slurmctld did not start"; cat "$run/log/slurmctld.log"; exit 1; }
/usr/sbin/slurmd || { echo "slurmd did not start"; cat "$run/log/slurmd.log"; exit 1; }
for _ in $(seq 50); do sinfo -h -o %T 2>/dev/null | grep -q idle && break; sleep 0.2; done
sinfo -h -o %T | grep -q idle || { echo "the node never became idle"; cat "$run/log/slurmd.log"; exit 1; }
echo "cluster up: $(sinfo -h -o '%P %D %T %c CPUs')"

# wait_jobs JOB...: until none of the jobs is queued or running (at most 5 minutes).
wait_jobs() {
  for _ in $(seq 3000); do
    [ -z "$(squeue -h -j "$(IFS=,; echo "$*")" 2>/dev/null)" ] && return 0
    sleep 0.1
  done
  return 1
}

# ---- one run of the whole orbit, to compare with ----
scene="$root/scenes/paper/fig6_orbit_red.json"
opts=(--width 480 --height 320 --samples 16 --shading phong --backend cpu)
"$phongvk" sequence "$scene" -o "$run/one" "${opts[@]}" >/dev/null 2>&1 || { echo "the single run failed"; exit 1; }

# same_frames DIR: every one of the 120 frames equals the single run's, and no temporary file is left.
same_frames() {
  local dir=$1 bad=0
  for f in "$run/one"/frame_*.png; do cmp -s "$f" "$dir/$(basename "$f")" || bad=$((bad + 1)); done
  [ "$bad" -eq 0 ] && [ -z "$(find "$dir" -name '*.tmp*')" ]
}

# ---- a 4-task array, interleaved, then the assembly ----
ids=$(PHONGVK="$phongvk" "$root/scripts/slurm/submit.sh" "$scene" "$run/array" 4 "${opts[@]}")
read -r _ array _ assembly <<<"${ids//,/}"
if wait_jobs "$array" "$assembly" && same_frames "$run/array" && [ -s "$run/array/sheet.png" ]; then
  pass "4-task array: 120 frames byte-identical to one run, contact sheet written"
else
  fail "4-task array ($ids): $(ls "$run/array" | wc -l) files; $(cat "$run"/array/slurm-*.log | tail -5)"
fi

# ---- blocks, one task requeued midway ----
ids=$(PHONGVK="$phongvk" PHONGVK_SLICE=blocks "$root/scripts/slurm/submit.sh" "$scene" "$run/requeued" 4 "${opts[@]}")
read -r _ array _ assembly <<<"${ids//,/}"
block=(0030 0031 0032 0033 0034 0035 0036 0037 0038 0039 0040 0041 0042 0043 0044 0045 0046 0047 0048 0049
       0050 0051 0052 0053 0054 0055 0056 0057 0058 0059)  # task 1's frames
done_before() { local n=0; for k in "${block[@]}"; do [ -f "$run/requeued/frame_$k.png" ] && n=$((n + 1)); done; echo $n; }
for _ in $(seq 3000); do [ "$(done_before)" -ge 3 ] && break; sleep 0.05; done
scontrol requeue "${array}_1"
before=$(done_before)
stamps=$(cd "$run/requeued" && stat -c '%n %Y.%y' frame_00[3-5]*.png 2>/dev/null)
# A requeued task is held back for minutes (its begin time); once it is pending again, it may start now.
for _ in $(seq 300); do
  [ "$(squeue -h -j "${array}_1" -o %T 2>/dev/null)" = PENDING ] && scontrol update jobid="${array}_1" StartTime=now && break
  sleep 0.1
done
if [ "$before" -ge 3 ] && [ "$before" -lt 30 ]; then
  pass "task 1 requeued after $before of its 30 frames"
else
  fail "task 1 was requeued after $before of its 30 frames, not midway"
fi
if wait_jobs "$array" "$assembly" && same_frames "$run/requeued" && [ -s "$run/requeued/sheet.png" ]; then
  pass "after the requeue: 120 frames byte-identical to one run, none partial, sheet written"
else
  fail "after the requeue ($ids): $(ls "$run/requeued" | wc -l) files"
fi
# The frames finished when the requeue was asked for keep their times; the restarted task says how
# many it kept (more may have been finished before the kill took effect).
kept=$(cd "$run/requeued" && stat -c '%n %Y.%y' $(echo "$stamps" | cut -d' ' -f1) 2>/dev/null)
said=$(sed -n 's/^kept \([0-9]*\) frames\{0,1\} an earlier run wrote whole$/\1/p' "$run"/requeued/slurm-*_1.log)
if [ -n "$stamps" ] && [ "$stamps" = "$kept" ] && [ "${said:-0}" -ge "$(echo "$stamps" | wc -l)" ]; then
  pass "the $said frames finished before the requeue took effect were not rendered again"
else
  fail "frames finished before the requeue were rendered again:
$stamps
---
$kept
$(cat "$run"/requeued/slurm-*_1.log | tail -3)"
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
