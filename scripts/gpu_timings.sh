#!/usr/bin/env bash
# The timings the open issues ask of a real GPU, in one run (each a few seconds there), every
# output kept in OUTDIR:
#   nebula_64.txt, nebula_1024.txt  issue 15: the GPU's double integration (21 λ a step) against
#                                   projection and light–density, 1, 6 and 32 stars, at 64² (with
#                                   the CPU's columns) and 1024² (the march, not launches)
#   prt.json                        issue 14: spectral PRT (m = 8) against RGB-PRT at 1920×1080 on
#                                   the 100k-vertex terrain (techniques.prt.ratio_spectral8_to_rgb_prt)
#   prt_water.json                  PRT under water: the same terrain in Jerlov IB, the water's 16
#                                   wet / 16 dry frame ratio (techniques.water), the PRT pass's nodes
#   spheres.json                    issue 16: the wavelength strategies' frame cost (strategies_16),
#                                   and the frame time against the wavelength count at 1920×1080
#   gpu.txt                         the GL renderer, and nvidia-smi where there is one
# Usage: scripts/gpu_timings.sh PRISM OUTDIR [--quick]
#   PRISM: the prism executable (a build's, or a bundle's: scripts/bundle.sh); --quick: tiny sizes,
#   to check on any machine that the run goes through.
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: scripts/gpu_timings.sh PRISM OUTDIR [--quick]" >&2; exit 2; }
prism=$(command -v "$1") || { echo "gpu_timings: no executable $1" >&2; exit 2; }
prism=$(realpath "$prism")
out=$(realpath -m "$2")
quick=${3:-}
case "$quick" in "" | --quick) ;; *) echo "gpu_timings: unknown option $quick (only --quick)" >&2; exit 2 ;; esac
cd "$(dirname "$0")/.."
mkdir -p "$out"

if [ "$quick" = --quick ]; then
  nebula_repeats=1 nebula_size=16 width=160 height=90 frames=20 rounds=2 wavelengths=4,16
else
  nebula_repeats=9 nebula_size=1024 width=1920 height=1080 frames=600 rounds=30 wavelengths=4,8,16,32,64,128,256
fi

step() { echo "== $1" >&2; }
{
  command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem --format=csv
  uname -a
} >"$out/gpu.txt" 2>&1 || true

step "issue 15: nebula marches, 64x64 (with the CPU's columns)"
"$prism" nebula bench --repeats "$nebula_repeats" | tee "$out/nebula_64.txt"
step "issue 15: nebula marches, ${nebula_size}x${nebula_size}"
"$prism" nebula bench --repeats "$nebula_repeats" --size "$nebula_size" --no-cpu | tee "$out/nebula_$nebula_size.txt"
grep -m1 'GPU:' "$out/nebula_64.txt" >>"$out/gpu.txt"

step "issue 14: spectral PRT against RGB-PRT, ${width}x${height}, 100k vertices"
"$prism" bench bench/scenes/prt_terrain_100k.json --width "$width" --height "$height" --wavelengths 16 \
  --frames "$frames" --rounds "$rounds" --warmup 3 --json >"$out/prt.json"
step "PRT under water, ${width}x${height}, 100k vertices"
"$prism" bench bench/scenes/prt_terrain_100k_water.json --width "$width" --height "$height" --wavelengths 16 \
  --frames "$frames" --rounds "$rounds" --warmup 3 --json >"$out/prt_water.json"
step "issue 16: wavelength strategies and the wavelength count, ${width}x${height}"
"$prism" bench scenes/spheres_d65.json --width "$width" --height "$height" --wavelengths "$wavelengths" \
  --frames "$frames" --rounds "$rounds" --warmup 3 --json >"$out/spheres.json"
echo "wrote $out" >&2
