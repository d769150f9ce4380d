#!/usr/bin/env bash
# The timings the open issues ask of a real GPU, in one run, every output kept in OUTDIR. Lent GPU
# time is short and comes once, so each step has its own time limit, a failed or overlong step
# does not stop the next, and the steps run most-wanted first:
#   nebula_64.txt    issue 15: the GPU's double integration (21 λ a step) against projection and
#                    light–density, 1, 6 and 32 stars, at 64² (with the CPU's columns)
#   prt.json         issue 14: spectral PRT (m = 8) against RGB-PRT at 1920×1080 on the
#                    100k-vertex terrain (techniques.prt.ratio_spectral8_to_rgb_prt)
#   spheres.json     issue 16: the wavelength strategies' frame cost (strategies_16), and the
#                    frame time against the wavelength count at 1920×1080
#   nebula_1024.txt  issue 15 at 1024², where the march and not the launches is timed
#   prt_water.json   PRT under water: the same terrain in Jerlov IB (techniques.water)
#   gpu.txt          the GL renderer, and nvidia-smi where there is one
#   steps.txt        each step's exit status and seconds (124: its time limit)
# Usage: scripts/gpu_timings.sh PRISM OUTDIR [--quick]
#   PRISM: the prism executable (a build's, or a bundle's: scripts/bundle.sh); --quick: tiny sizes,
#   to check on any machine that the run goes through. Exits 1 if any step failed.
set -uo pipefail
[ $# -ge 2 ] || { echo "usage: scripts/gpu_timings.sh PRISM OUTDIR [--quick]" >&2; exit 2; }
prism=$(command -v "$1") || { echo "gpu_timings: no executable $1" >&2; exit 2; }
prism=$(realpath "$prism")
out=$(realpath -m "$2")
quick=${3:-}
case "$quick" in "" | --quick) ;; *) echo "gpu_timings: unknown option $quick (only --quick)" >&2; exit 2 ;; esac
cd "$(dirname "$0")/.." || exit 2
mkdir -p "$out" || exit 2

if [ "$quick" = --quick ]; then
  nebula_repeats=1 nebula_size=16 width=160 height=90 frames=20 rounds=2 wavelengths=4,16
  water_frames=20 water_rounds=2
  limit_nebula=300 limit_bench=300 limit_large=300
else
  nebula_repeats=9 nebula_size=1024 width=1920 height=1080 frames=240 rounds=20 wavelengths=4,8,16,32,64
  water_frames=60 water_rounds=10  # its 81-node sums: 240 frames × 20 rounds passed 60 s on an H200
  limit_nebula=90 limit_bench=110 limit_large=90
fi

{
  command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem --format=csv
  uname -a
} >"$out/gpu.txt" 2>&1
: >"$out/steps.txt"
failed=0
# step NAME LIMIT_S OUTFILE COMMAND…: COMMAND's stdout to OUTDIR/OUTFILE (through a temporary
# file: a step cut off leaves no half-written output, and no earlier run's output stays to pass
# for this one's), its status and time to steps.txt; a text output is shown too.
step() {
  local name=$1 limit=$2 file=$3 start status
  shift 3
  echo "== $name (at most ${limit} s)" >&2
  start=$SECONDS
  rm -f "$out/$file"
  timeout -k 10 "$limit" "$@" >"$out/$file.tmp"
  status=$?
  if [ "$status" -eq 0 ]; then mv "$out/$file.tmp" "$out/$file"; else rm -f "$out/$file.tmp"; failed=1; fi
  case "$file" in *.txt) [ -f "$out/$file" ] && cat "$out/$file" >&2 ;; esac
  echo "$name: exit $status, $((SECONDS - start)) s" | tee -a "$out/steps.txt" >&2
}
sizes=(--width "$width" --height "$height" --warmup 3 --json)

step "issue 15: nebula marches, 64x64 (with the CPU's columns)" "$limit_nebula" nebula_64.txt \
  "$prism" nebula bench --repeats "$nebula_repeats"
step "issue 14: spectral PRT against RGB-PRT, ${width}x${height}, 100k vertices" "$limit_bench" prt.json \
  "$prism" bench bench/scenes/prt_terrain_100k.json "${sizes[@]}" --frames "$frames" --rounds "$rounds" --wavelengths 16
step "issue 16: wavelength strategies and the wavelength count, ${width}x${height}" "$limit_bench" spheres.json \
  "$prism" bench scenes/spheres_d65.json "${sizes[@]}" --frames "$frames" --rounds "$rounds" --wavelengths "$wavelengths"
step "issue 15: nebula marches, ${nebula_size}x${nebula_size}" "$limit_large" "nebula_$nebula_size.txt" \
  "$prism" nebula bench --repeats "$nebula_repeats" --size "$nebula_size" --no-cpu
step "PRT under water, ${width}x${height}, 100k vertices" "$limit_large" prt_water.json \
  "$prism" bench bench/scenes/prt_terrain_100k_water.json "${sizes[@]}" --frames "$water_frames" --rounds "$water_rounds" \
  --wavelengths 16
grep -m1 'GPU:' "$out/nebula_64.txt" >>"$out/gpu.txt" 2>/dev/null
echo "wrote $out" >&2
exit "$failed"
