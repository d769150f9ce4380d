#!/usr/bin/env bash
# Prism's batch work on a real Slurm cluster of one node, from Debian's packages (slurmctld,
# slurmd, slurm-client, munge): the test starts munged, slurmctld and slurmd in a folder of its
# own (local_cluster.sh: its own munge key and socket, a generated slurm.conf on free ports,
# this machine's CPUs) and stops them at the end, failed or not. Every job goes through `prism cluster script`, as a
# user's would:
#   1. an 8-task reference array by rows and its merge job: bit-identical to the single-process
#      render with the same seed (cmp of the EXR files, image and variance); the array submitted
#      again skips every task and merges the same bytes;
#   2. a 4-task split by path indices: within 1e-6 relative per pixel of it;
#   3. a 2-task `validate --quick --only` sweep of two experiments (a sphere scene, a nebula) and
#      its --collect: results.json and index.html the same bytes as one process's;
#   4. a 16³ upsampling table as 4 tasks by columns and its merge: the same bytes as `prism lut`;
#      a PRT transfer bake as 3 tasks by vertices and its merge into the cache: the same bytes as
#      `prism prt bake`'s cached file;
#   5. one array task killed mid-run (scancel): no part left behind, the merge job cancelled with
#      it; that task alone submitted again: the image of the undisturbed render.
# Usage: slurm_cluster_test.sh PRISM MAX_RELATIVE_DIFFERENCE SCENES
# Needs root (munged and slurmd run as the user who runs them, and slurmd as root to start jobs):
# skipped (exit 77) otherwise.
set -euo pipefail
prism=$1 maxrel=$2 scenes=$3

if [ "$(id -u)" -ne 0 ]; then
  echo "SKIP: the Slurm test starts slurmd, which must run as root (run the tests as root, as CI does)"
  exit 77
fi
for tool in munged mungekey slurmctld slurmd sbatch squeue scancel scontrol sinfo; do
  command -v "$tool" >/dev/null || { echo "FAIL: $tool is missing (scripts/install-deps.sh installs it)"; exit 1; }
done

source "$(dirname "$0")/local_cluster.sh"
T=$(mktemp -d /tmp/prism-slurm.XXXXXX)
started=$SECONDS
finish_test() {
  local status=$?
  if [ $status -ne 0 ]; then
    echo "== the daemons' logs and the jobs' output (the test failed)"
    tail -n 20 "$T"/*.log 2>/dev/null || true
    tail -n 5 "$T"/*/*.parts/*.out "$T"/validate/parts/*.out 2>/dev/null || true
  fi
  stop_local_cluster "$T"
  rm -rf "$T"
  exit $status
}
trap finish_test EXIT
fail() { echo "FAIL: $*"; exit 1; }

echo "== starting munged, slurmctld and slurmd in $T"
start_local_cluster "$T" || fail "the cluster did not start"
echo "   up after $((SECONDS - started)) s: $(sinfo -h -o '%D node, %c CPUs, state %t')"

# Submits a script of `prism cluster script` (ARGS: task indices to submit again); sets $array, $finish.
submit() {
  local line
  line=$(bash "$@")
  read -r _ array _ finish <<<"$line"
  [ -n "$finish" ] || fail "$1 printed \"$line\", not the two job ids"
}
# Waits until job $1 has left the queue and prints its state.
job_state() {
  for _ in $(seq 1500); do [ -z "$(squeue -h -j "$1" 2>/dev/null)" ] && break; sleep 0.2; done
  scontrol show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | sort -u | tr '\n' ' ' | sed 's/ $//'
}
expect_completed() {
  local state
  state=$(job_state "$1")
  [ "$state" = COMPLETED ] || fail "$2: job $1 ended $state"
}

R=(reference "$scenes/spheres_d65.json" --width 64 --height 48 --spp 16 --seed 7 --transport global)
echo "== the single-process render"
"$prism" "${R[@]}" -o "$T/single.exr" --variance "$T/single-variance.exr" 2>/dev/null

echo "== 1. 8 tasks by rows, then merge"
"$prism" cluster script "${R[@]}" --tasks 8 -o "$T/tiles/image.exr" --variance "$T/tiles/variance.exr" >"$T/tiles.sh"
grep -q -- '--array=0-7' "$T/tiles.sh" || fail "no --array=0-7 in the script"
submit "$T/tiles.sh"
expect_completed "$finish" "the merge of 8 row tasks"
expect_completed "$array" "the 8 row tasks"
cmp "$T/single.exr" "$T/tiles/image.exr" || fail "8 row tasks merged are not the single-process render"
cmp "$T/single-variance.exr" "$T/tiles/variance.exr" || fail "their variance is not the single-process render's"
echo "   bit-identical to the single-process render (image and variance)"
submit "$T/tiles.sh"
expect_completed "$finish" "the merge of the array submitted again"
skipped=$(grep -l "complete (rows .*), skipped" "$T"/tiles/image.exr.parts/prism-reference-"$array"_*.out | wc -l)
[ "$skipped" -eq 8 ] || fail "submitted again, $skipped of 8 tasks skipped their complete part"
cmp "$T/single.exr" "$T/tiles/image.exr" || fail "merging again changed the image"
echo "   submitted again: 8 of 8 tasks skipped, the same image merged"

echo "== 2. 4 tasks by path indices, then merge"
"$prism" cluster script "${R[@]}" --tasks 4 --split samples -o "$T/samples/image.exr" >"$T/samples.sh"
submit "$T/samples.sh"
expect_completed "$finish" "the merge of 4 path-index tasks"
difference=$("$maxrel" "$T/single.exr" "$T/samples/image.exr")
awk -v d="$difference" 'BEGIN { exit !(d <= 1e-6) }' || fail "4 path-index tasks differ from the single-process render by $difference relative"
echo "   largest relative difference from the single-process render: $difference"

echo "== 3. validate --quick --only (two experiments) as 2 tasks, then --collect"
V=(validate --quick --only spheres_d65,nebula_natural)
"$prism" "${V[@]}" -o "$T/validated" >"$T/validated.log" 2>&1 || { tail -n 5 "$T/validated.log"; fail "prism ${V[*]} failed"; }
"$prism" cluster script "${V[@]}" --tasks 2 -o "$T/validate" >"$T/validate.sh"
# A part an earlier sweep into the same folder left, split otherwise: the collect job takes its own
# split's (it failed on an experiment in both).
mkdir -p "$T/validate/parts"
printf '{"format": "prism-validate-part 1", "identity": {}, "experiments": ["spheres_d65"], "results": []}\n' \
  >"$T/validate/parts/task-0-of-3.json"
submit "$T/validate.sh"
expect_completed "$finish" "validate --collect after 2 tasks"
for file in results.json index.html; do
  cmp "$T/validated/$file" "$T/validate/$file" || fail "the sweep's $file is not one process's"
done
echo "   results.json and index.html: the same bytes as one process's"

echo "== 4. an upsampling table as 4 tasks by columns, then merge"
"$prism" lut --gamut rec2020 --res 16 -o "$T/single.prismlut" >/dev/null 2>&1
"$prism" cluster script lut --gamut rec2020 --res 16 --tasks 4 -o "$T/lut/table.prismlut" >"$T/lut.sh"
submit "$T/lut.sh"
expect_completed "$finish" "the merge of 4 column tasks"
cmp "$T/single.prismlut" "$T/lut/table.prismlut" || fail "4 column tasks merged are not prism lut's table"
echo "   the same bytes as prism lut's table"
P=(prt bake "$scenes/spheres_d65.json" --samples 64)
PRISM_CACHE_DIR="$T/prt-single" "$prism" "${P[@]}" >/dev/null 2>&1
"$prism" cluster script prt "${P[@]:2}" --tasks 3 --cache "$T/prt-cluster" >"$T/prt.sh"
submit "$T/prt.sh"
expect_completed "$finish" "the merge of 3 vertex tasks"
single_bake=$(ls "$T"/prt-single/prt/transfer-*.bin)
cmp "$single_bake" "$T/prt-cluster/prt/$(basename "$single_bake")" || fail "3 vertex tasks merged are not prism prt bake's transfer"
echo "   a PRT bake as 3 tasks by vertices, merged into the cache: the same bytes as prism prt bake's"

echo "== 5. a task killed mid-run, then only it submitted again"
K=(reference "$scenes/spheres_d65.json" --width 64 --height 48 --spp 768 --seed 11)
"$prism" "${K[@]}" -o "$T/undisturbed.exr" 2>/dev/null
"$prism" cluster script "${K[@]}" --tasks 4 -o "$T/kill/image.exr" >"$T/kill.sh"
submit "$T/kill.sh"
log="$T/kill/image.exr.parts/prism-reference-${array}_2.out"
for _ in $(seq 2400); do [ -s "$log" ] && break; sleep 0.05; done  # tracing has begun: its bar is in the log
[ -s "$log" ] || fail "task 2 did not start"
scancel "${array}_2"
[ "$(job_state "${array}_2")" = CANCELLED ] || fail "task 2 was not cancelled"
[ "$(job_state "$finish")" = CANCELLED ] || fail "the merge job outlived a cancelled task"
if compgen -G "$T/kill/image.exr.parts/part-2-of-4.exr*" >/dev/null; then
  fail "the killed task left $(ls "$T"/kill/image.exr.parts/part-2-of-4.exr*)"
fi
job_state "$array" >/dev/null  # the other tasks have ended
ls "$T/kill/image.exr.parts"/part-*-of-4.exr | grep -c part- | grep -qx 3 || fail "the other 3 parts are not all there"
echo "   killed while tracing: no part 2, merge cancelled, 3 parts kept"
submit "$T/kill.sh" 2
expect_completed "$finish" "the merge after task 2 again"
expect_completed "$array" "task 2 again"
cmp "$T/undisturbed.exr" "$T/kill/image.exr" || fail "after the kill and task 2 again, the image is not the undisturbed render's"
echo "   task 2 again, merged: bit-identical to the undisturbed render"
echo "PASS in $((SECONDS - started)) s"
