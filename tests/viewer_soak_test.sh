#!/usr/bin/env bash
# 10 000 frames of the viewer under Xvfb with settings changing every 10 frames, a resize every
# 100 and the split view toggled every 250. The viewer's `soak` fails by itself when any kind of
# GL object is not back to its count, or when the heap in use or the anonymous resident memory
# (the allocator's free pages given back first) grew by more than 5 MB once the driver's caches
# have warmed up (a first 2 000-frame round, not bounded). Prints the numbers,
# failing or not.
# Usage: viewer_soak_test.sh PRISM SCENES_DIR SCRATCH_DIR
set -euo pipefail
prism=$1 scenes=$2 scratch=$3
mkdir -p "$scratch"
printf 'set shadow-map-size 256\nset right.shadow-map-size 256\nframes 2\nsoak 2000\nsoak 10000 5\n' >"$scratch/soak"
rc=0
out=$(xvfb-run -a -s "-screen 0 1024x768x24" "$prism" view "$scenes/spheres_blue_led.json" --width 160 --height 120 \
        --script "$scratch/soak" 2>&1) || rc=$?
echo "$out"
[ "$rc" = 0 ] && [ "$(echo "$out" | grep -c '^soak: GL objects')" = 2 ] && [ "$(echo "$out" | grep -c '^soak: heap in use')" = 2 ]
