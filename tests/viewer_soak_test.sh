#!/usr/bin/env bash
# PRISM_SOAK_FRAMES frames (5 000 unless set; CI runs those, a longer soak sets e.g. 100 000) of
# the viewer under Xvfb with settings changing every 10 frames, a resize every 100 and the split
# view toggled every 250. The viewer's `soak` fails by itself when any kind of GL object is not
# back to its count, or when the heap in use or the anonymous resident memory (the allocator's
# free pages given back first) grew by more than 500 bytes a frame (2.5 MB over 5 000 frames)
# once the driver's caches have warmed up (a first 1 000-frame round, which goes through every
# combination of the changing settings, not bounded). Prints the numbers, failing or not.
# llvmpipe rasterises in the calling thread (LP_NUM_THREADS=0): its rasteriser threads held 9 MB
# of heap at one count and not at the next (a sun's four 256² shadow cascades in flight), which
# failed the bound without any memory of Prism's growing; in the calling thread, none.
# Usage: viewer_soak_test.sh PRISM SCENES_DIR SCRATCH_DIR
set -euo pipefail
prism=$1 scenes=$2 scratch=$3
frames=${PRISM_SOAK_FRAMES:-5000}
[[ "$frames" =~ ^[1-9][0-9]*$ ]] || { echo "viewer_soak_test.sh: PRISM_SOAK_FRAMES must be a positive integer, not '$frames'" >&2; exit 2; }
bound_mb=$(awk -v n="$frames" 'BEGIN { printf "%g", n * 500 / 1e6 }')
mkdir -p "$scratch"
printf 'set shadow-map-size 256\nset right.shadow-map-size 256\nframes 2\nsoak 1000\nsoak %s %s\n' "$frames" "$bound_mb" >"$scratch/soak"
rc=0
out=$(LP_NUM_THREADS=0 xvfb-run -a -s "-screen 0 1024x768x24" "$prism" view "$scenes/spheres_blue_led.json" --width 160 --height 120 \
        --script "$scratch/soak" 2>&1) || rc=$?
echo "$out"
[ "$rc" = 0 ] && [ "$(echo "$out" | grep -c '^soak: GL objects')" = 2 ] && [ "$(echo "$out" | grep -c '^soak: heap in use')" = 2 ]
