#!/usr/bin/env bash
# The README's scaling of a split reference render ("On a cluster (Slurm)"), measured on this
# machine's one-node Slurm cluster (tests/slurm/local_cluster.sh, started and stopped here): one
# render submitted by `prism cluster script reference` as 1 task and as 2 tasks of one CPU each,
# the wall time from `bash SCRIPT` to the merged image (the merge job done), best of ROUNDS; then
# Amdahl's law from it: T(n) = T(1)·(s + (1 − s)/n), so the serial fraction s = 2·T(2)/T(1) − 1,
# and the speed-up at 100 tasks (one per node) 1/(s + (1 − s)/100). Also the same pipeline for a
# render of no work (8×8 pixels, one path, 1 task): the fixed cost of scheduling the array and the
# merge after it, starting prism, loading the scene and merging, which is most of s at this size.
# SPLIT is rows (the default: --tile) or samples (--samples: every task the same work).
# Usage (as root, after a Release build): scripts/slurm_scaling.sh [PRISM] [ROUNDS] [SPLIT]
set -euo pipefail
cd "$(dirname "$0")/.."
prism=$(realpath "${1:-build/release/app/prism}")
rounds=${2:-2}
split=${3:-rows}
source tests/slurm/local_cluster.sh
T=$(mktemp -d /tmp/prism-scaling.XXXXXX)
trap 'stop_local_cluster "$T"; rm -rf "$T"' EXIT
start_local_cluster "$T"

WORK=(reference scenes/spheres_d65.json --width 320 --height 180 --spp 384 --transport global --seed 1)
NOTHING=(reference scenes/spheres_d65.json --width 8 --height 8 --spp 1 --seed 1)
echo "render: prism ${WORK[*]}, split by $split"
# Seconds from submission until the merge job has left the queue (polled every 0.1 s).
wall() {
  local tasks=$1 dir=$T/run-$1-$2 start line finish
  "$prism" cluster script "${R[@]}" --tasks "$tasks" --split "$split" -o "$dir/image.exr" >"$dir.sh"
  start=$(date +%s.%N)
  line=$(bash "$dir.sh")
  finish=${line##* }
  while [ -n "$(squeue -h -j "$finish" 2>/dev/null)" ]; do sleep 0.1; done
  scontrol show job "$finish" | grep -q JobState=COMPLETED || { echo "merge job $finish failed" >&2; exit 1; }
  awk -v start="$start" -v end="$(date +%s.%N)" 'BEGIN { printf "%.2f", end - start }'
}
best() {
  local tasks=$1 best="" t
  for round in $(seq "$rounds"); do
    t=$(wall "$tasks" "$round")
    echo "  $tasks task(s), round $round: $t s" >&2
    best=$(awk -v best="$best" -v t="$t" 'BEGIN { print (best == "" || t + 0 < best + 0) ? t : best }')
  done
  echo "$best"
}
R=("${NOTHING[@]}")
t0=$(best 1)
R=("${WORK[@]}")
rm -rf "$T"/run-*
t1=$(best 1)
t2=$(best 2)
"$prism" compare "$T/run-1-1/image.exr" "$T/run-2-1/image.exr" --json | grep -q '"max_delta_e": 0.0,' ||
  { echo "1 and 2 tasks gave different images" >&2; exit 1; }
awk -v t0="$t0" -v t1="$t1" -v t2="$t2" -v cpus="$(nproc)" 'BEGIN {
  printf "no work (8x8, 1 path, 1 task): %.1f s\n", t0
  s = 2 * t2 / t1 - 1
  printf "1 task: %.1f s, 2 tasks: %.1f s (%d CPUs): speed-up %.2f, efficiency %.0f %%\n", t1, t2, cpus, t1 / t2, 50 * t1 / t2
  printf "serial fraction s = 2·T2/T1 − 1 = %.3f; Amdahl at 100 tasks: speed-up %.1f (efficiency %.0f %%), T(100) = %.1f s\n",
         s, 1 / (s + (1 - s) / 100), 1 / (s + (1 - s) / 100), t1 * (s + (1 - s) / 100)
  printf "the fixed cost as the serial part instead: T(2) = %.1f s predicted, T(100) = %.1f s\n", t0 + (t1 - t0) / 2, t0 + (t1 - t0) / 100
}'
