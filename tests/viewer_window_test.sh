#!/usr/bin/env bash
# The viewer in a real window under Xvfb, driven by a script. Under the narrow blue LED:
# - the window's screenshots (PNG, interface included) in RGB and in spectral mode differ over a
#   share of the window, and two of one mode two frames apart do not;
# - the left view's tristimulus (EXR) in the two modes differ by the renderer's own measure;
# - the split view's heat map compares the two modes and finds them apart;
# - under the spectral sky, moving the sun (the sky panel's setting) changes the view;
# - in the nebula scene, the palette changes the view and the reference mode does not;
# - a point light's shadows and position, set by the script (the lights panel's controls),
#   change the view;
# - a screenshot or settings file over a file the scene reads or over the script is refused;
# - a heat map that cannot be computed says why; one camera on both sides, or a camera against
#   the eye, is compared.
# Usage: viewer_window_test.sh PRISM SCENES_DIR SCRATCH_DIR
set -euo pipefail
prism=$1 scenes=$2 scratch=$3
rm -rf "$scratch"
mkdir -p "$scratch"
# prism view SCENE [OPTIONS…] in a virtual screen.
view() { xvfb-run -a -s "-screen 0 1024x768x24" "$prism" view "$@"; }
cat >"$scratch/script" <<SCRIPT
set mode rgb
frames 3
screenshot $scratch/rgb.png
screenshot $scratch/rgb.exr
frames 2
screenshot $scratch/rgb_again.png
set mode jakob-hanika
set strategy rotated
frames 8
screenshot $scratch/spectral.png
screenshot $scratch/spectral.exr
set split on
set right.mode rgb
set heat-map on
frames 20
heat-map-stats
screenshot $scratch/split.png
save-settings $scratch/settings.json
reload-shaders
frames 1
SCRIPT
out=$(view "$scenes/spheres_blue_led.json" --width 640 --height 400 --script "$scratch/script")
echo "$out"
for f in rgb.png rgb_again.png spectral.png split.png rgb.exr spectral.exr; do
  [ -s "$scratch/$f" ] || { echo "no $f" >&2; exit 1; }
done
grep -q '"split": true' "$scratch/settings.json"

# "pixels above ΔE00 1: X %" and "CIEDE2000  mean X": what compare says.
share() { "$prism" compare "$1" "$2" | sed -n 's/^pixels above ΔE00 1: \([0-9.]*\) %$/\1/p'; }
mean() { "$prism" compare "$1" "$2" | sed -n 's/^CIEDE2000  mean \([0-9.]*\) .*/\1/p'; }
same=$(share "$scratch/rgb.png" "$scratch/rgb_again.png")
changed=$(share "$scratch/rgb.png" "$scratch/spectral.png")
views=$(mean "$scratch/rgb.exr" "$scratch/spectral.exr")
heat=$(echo "$out" | sed -n 's/^heat map: mean \([0-9.]*\) .*/\1/p')
echo "window, RGB vs RGB two frames later: $same % above ΔE00 1 (the frame-time text)"
echo "window, RGB vs spectral: $changed % above ΔE00 1"
echo "left view's tristimulus, RGB vs spectral: mean ΔE00 $views; the split view's heat map: mean $heat"
[ -n "$same" ] && [ -n "$changed" ] && [ -n "$views" ] && [ -n "$heat" ]
# The gallery measures 2.2 mean ΔE00 between the modes in this scene (`prism demo`, 640×360):
# the viewer must see at least half of it (measured 2.75, heat map 2.50). The bound was 3.0 while
# RGB mode showed negative light under this LED (the gallery measured 6; efb1597 stops RGB mode's
# tristimulus at 0, which brought RGB closer to the spectral image).
awk -v s="$same" -v c="$changed" -v v="$views" -v h="$heat" 'BEGIN { exit !(s < 1.0 && c > 5.0 && v > 1.1 && h > 1.1) }'

# The sky: the sun from 3° to 30° above the horizon, in optimised4 mode.
cat >"$scratch/sky_script" <<SCRIPT
set mode optimised4
frames 2
screenshot $scratch/sky_low.exr
set sky.elevation 30
frames 2
screenshot $scratch/sky_high.exr
SCRIPT
view "$scenes/sunset.json" --width 480 --height 270 --script "$scratch/sky_script"
sky=$(mean "$scratch/sky_low.exr" "$scratch/sky_high.exr")
echo "sunset, sun at 3° vs 30°: mean ΔE00 $sky"
[ -n "$sky" ] && awk -v d="$sky" 'BEGIN { exit !(d > 3.0) }'

# The nebula (its panel drawn every frame): the Hubble palette against natural colour differ; the
# renderer's reference mode (the paper's double integration) against projection does not.
cat >"$scratch/nebula_script" <<SCRIPT
frames 2
screenshot $scratch/nebula_hubble.exr
set nebula.filters cie1931
frames 2
screenshot $scratch/nebula_natural.exr
set mode reference
frames 1
screenshot $scratch/nebula_reference.exr
SCRIPT
view "$scenes/nebula_field.json" --width 160 --height 160 --script "$scratch/nebula_script"
palette=$(mean "$scratch/nebula_hubble.exr" "$scratch/nebula_natural.exr")
method=$(mean "$scratch/nebula_natural.exr" "$scratch/nebula_reference.exr")
echo "nebula, Hubble palette vs natural colour: mean ΔE00 $palette; projection vs reference: mean ΔE00 $method"
[ -n "$palette" ] && [ -n "$method" ] && awk -v p="$palette" -v m="$method" 'BEGIN { exit !(p > 3.0 && m < 0.5) }'

# A point light alone (the sun at 0 lux) brought near the spheres: its shadows turned on, then the
# light moved (the conductors' point light has "shadows": false in the scene file).
cat >"$scratch/lights_script" <<SCRIPT
set mode jakob-hanika
set light.0.intensity 0
set light.1.position -1,1.5,1.5
frames 1
screenshot $scratch/lamp_unshadowed.exr
set light.1.shadows on
frames 1
screenshot $scratch/lamp_shadowed.exr
set light.1.position 1.5,1.5,1.5
frames 1
screenshot $scratch/lamp_moved.exr
SCRIPT
view "$scenes/conductors_d65.json" --width 320 --height 180 --script "$scratch/lights_script"
shadowed=$(share "$scratch/lamp_unshadowed.exr" "$scratch/lamp_shadowed.exr")
moved=$(share "$scratch/lamp_shadowed.exr" "$scratch/lamp_moved.exr")
echo "conductors, the point light's shadows on: $shadowed % above ΔE00 1; the light moved: $moved %"
[ -n "$shadowed" ] && [ -n "$moved" ] && awk -v s="$shadowed" -v m="$moved" 'BEGIN { exit !(s > 1.0 && m > 1.0) }'

# Files the script writes over what the viewer reads, refused before the first frame (they were
# written, exit 0): a screenshot over the scene's texture, the settings over the script itself;
# and a settings file that never ends, refused rather than read until memory ran out.
mkdir -p "$scratch/own/models"
cp "$scenes/textured_gltf.json" "$scratch/own/"
cp "$scenes"/models/tiles* "$scratch/own/models/"
texture=$scratch/own/models/tiles_base_colour.png
before=$(md5sum <"$texture")
# view_error SCRIPT_TEXT NEEDLE: the run fails with NEEDLE in its one error line.
view_error() {
  printf '%s\n' "$1" >"$scratch/own/script.json"
  local err
  if err=$(view "$scratch/own/textured_gltf.json" --width 64 --height 48 --script "$scratch/own/script.json" 2>&1); then
    echo "'$1': exit 0" >&2
    exit 1
  fi
  grep -qF "$2" <<<"$err" || { echo "'$1': $err" >&2; exit 1; }
}
view_error "frames 1
screenshot $texture" "script.json:2: $texture: is also a file the scene reads"
[ "$(md5sum <"$texture")" = "$before" ]
# (the script named .json, as settings are: another name is refused for its extension first)
view_error "save-settings $scratch/own/script.json" "script.json:1: $scratch/own/script.json: is also the script"
grep -q '^save-settings' "$scratch/own/script.json"
view_error "load-settings /dev/zero" "script.json:1: /dev/zero: not a regular file"
# The rehearsal: a bad value, a light the scene lacks, a missing settings file fail at their lines
# before a screenshot above them is written (it was, then the error came).
for bad in "set mode bogus|script.json:2: mode: expected" "set light.9.intensity 5|script.json:2: light index: expected" \
           "load-settings $scratch/own/none.json|script.json:2: $scratch/own/none.json"; do
  rm -f "$scratch/own/early.png"
  view_error "screenshot $scratch/own/early.png
${bad%%|*}" "${bad#*|}"
  [ ! -e "$scratch/own/early.png" ] || { echo "'${bad%%|*}': the screenshot above it was written" >&2; exit 1; }
done
# A heat map that cannot be computed (CIE 1964 on both sides) says why at heat-map-stats: it said
# only "no heat map yet (set split on, heat-map on, frames N)", the steps the script had taken.
view_error "set observer cie1964
set split on
set right.mode jakob-hanika
set right.observer cie1964
set heat-map on
frames 16
heat-map-stats" "script.json:7: no heat map: the heat map compares CIE 1931 XYZ"
# One camera on both sides is compared through its matrix, as `prism compare` takes two of its
# frames (a camera's RGB was refused).
camera=$(view "$scratch/own/textured_gltf.json" --width 64 --height 48 --script <(printf '%s\n' "set observer nikon_d850" \
  "set split on" "set right.mode jakob-hanika" "set right.observer nikon_d850" "set right.strategy uniform" "set heat-map on" frames\ 16 heat-map-stats))
grep -q '^heat map: mean' <<<"$camera" || { echo "one camera's heat map: $camera" >&2; exit 1; }
# A camera against the eye, all else the same: each side through its own matrix (CIE 1931 has none),
# which maps the camera's own colour error — under 5 ΔE00 (1.8 measured) and not 0 (one camera's
# RGB taken as XYZ read 26.6 against the eye on the D65 spheres). It was refused.
eye=$(view "$scratch/own/textured_gltf.json" --width 64 --height 48 --script <(printf '%s\n' "set observer nikon_d850" \
  "set strategy uniform" "set split on" "set right.mode jakob-hanika" "set right.observer cie1931" \
  "set right.strategy uniform" "set heat-map on" frames\ 16 heat-map-stats))
mean=$(sed -n 's/^heat map: mean \([0-9.]*\) .*/\1/p' <<<"$eye")
awk -v m="$mean" 'BEGIN { exit !(m > 0.2 && m < 5) }' || { echo "a camera against the eye: $eye" >&2; exit 1; }
# A settings file the script saves before loading it is taken as it, not refused as missing.
view "$scratch/own/textured_gltf.json" --width 64 --height 48 --script <(printf 'save-settings %s\nload-settings %s\n' \
  "$scratch/own/saved.json" "$scratch/own/saved.json") >/dev/null
echo "outputs over the scene's files and the script refused; /dev/zero refused"
