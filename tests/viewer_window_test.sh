#!/usr/bin/env bash
# The viewer in a real window under Xvfb, driven by a script: screenshots of RGB and spectral
# mode under the narrow blue LED must differ the way the renderer says they do (and two
# screenshots of one mode must not), and the split view with its heat map must come up.
# Usage: viewer_window_test.sh PRISM SCENES_DIR SCRATCH_DIR
set -euo pipefail
prism=$1 scenes=$2 scratch=$3
rm -rf "$scratch"
mkdir -p "$scratch"
cat >"$scratch/script" <<SCRIPT
set mode rgb
frames 3
screenshot $scratch/rgb.png
frames 2
screenshot $scratch/rgb_again.png
set mode jakob-hanika
set strategy rotated
frames 8
screenshot $scratch/spectral.png
set split on
set right.mode rgb
set heat-map on
frames 20
screenshot $scratch/split.png
save-settings $scratch/settings.json
reload-shaders
frames 1
SCRIPT
xvfb-run -a -s "-screen 0 1024x768x24" "$prism" view "$scenes/spheres_blue_led.json" --width 640 --height 400 \
  --script "$scratch/script"
for f in rgb rgb_again spectral split; do [ -s "$scratch/$f.png" ] || { echo "no $f.png" >&2; exit 1; }; done
grep -q '"split": true' "$scratch/settings.json"

# "pixels above ΔE00 1: X %": the share of the window that changed visibly.
share() { "$prism" compare "$1" "$2" | sed -n 's/^pixels above ΔE00 1: \([0-9.]*\) %$/\1/p'; }
same=$(share "$scratch/rgb.png" "$scratch/rgb_again.png")
changed=$(share "$scratch/rgb.png" "$scratch/spectral.png")
echo "RGB vs RGB two frames later: $same % of the window above ΔE00 1 (the frame-time text)"
echo "RGB vs spectral under the blue LED: $changed % of the window above ΔE00 1"
awk -v s="$same" -v c="$changed" 'BEGIN { exit !(s < 1.0 && c > 5.0) }'
