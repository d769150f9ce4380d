#!/usr/bin/env bash
# 10 000 frames of the viewer under Xvfb with settings changing every 10 frames, a resize every
# 100 and the split view toggled every 250: the live GL objects must end where they started and
# resident memory must stay flat (within 5 MB) once the driver's caches have warmed up (a first
# 2 000-frame round). Prints the numbers.
# Usage: viewer_soak_test.sh PRISM SCENES_DIR SCRATCH_DIR
set -euo pipefail
prism=$1 scenes=$2 scratch=$3
mkdir -p "$scratch"
printf 'set shadow-map-size 256\nset right.shadow-map-size 256\nframes 2\nsoak 2000\nsoak 10000\n' >"$scratch/soak"
out=$(xvfb-run -a -s "-screen 0 1024x768x24" "$prism" view "$scenes/spheres_blue_led.json" --width 160 --height 120 \
        --script "$scratch/soak")
echo "$out"
last_objects=$(echo "$out" | grep '^soak: GL objects' | tail -1)
last_memory=$(echo "$out" | grep '^soak: resident memory' | tail -1)
before=$(echo "$last_objects" | sed -n 's/^soak: GL objects \([0-9]*\) -> \([0-9]*\) .*/\1/p')
after=$(echo "$last_objects" | sed -n 's/^soak: GL objects \([0-9]*\) -> \([0-9]*\) .*/\2/p')
[ -n "$before" ] && [ "$before" = "$after" ] || { echo "GL objects not flat: $last_objects" >&2; exit 1; }
echo "$last_memory" | awk '{ if (!($7 - $4 <= 5.0)) { print "resident memory grew: " $0 > "/dev/stderr"; exit 1 } }'
