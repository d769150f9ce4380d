#!/usr/bin/env bash
# Installs the build into a scratch prefix and uses it the way other projects would:
# tests/consumer_spectral links only prism::spectral (no GL needed) and runs on the installed
# data; tests/consumer_gpu links prism::gpu and runs an installed shared shader on llvmpipe;
# tests/consumer_render links prism::render and renders an installed scene with the installed
# shaders; tests/consumer_reference links prism::reference (no GL) and traces that scene;
# tests/consumer_atmosphere links prism::atmosphere_fit (NLopt) and fits a tiny sky.
# Then checks that the installed prism binary reads the data installed beside it.
# Usage: install_consumer_test.sh SOURCE_DIR BUILD_DIR SCRATCH_DIR
set -euo pipefail
source_dir=$1 build_dir=$2 scratch=$3
rm -rf "$scratch"
prefix=$scratch/prefix
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
for consumer in spectral gpu render reference atmosphere; do
  cmake -S "$source_dir/tests/consumer_$consumer" -B "$scratch/build_$consumer" -G Ninja \
        -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$scratch/build_$consumer" >/dev/null
done
output=$(PRISM_DATA_DIR="$prefix/share/prism/data" "$scratch/build_spectral/consumer")
echo "$output"
[ "$output" = "D65 xy 0.3127 0.3290" ]
output=$("$scratch/build_gpu/gpu_consumer")
echo "$output"
[ "$output" = "pcgHash(0) = 129708002" ]
output=$(PRISM_DATA_DIR="$prefix/share/prism/data" PRISM_SHADER_DIR="$prefix/share/prism/shaders" \
         "$scratch/build_render/render_consumer")
echo "$output"
[ "$output" = "rendered 32x18, mostly geometry" ]
output=$(PRISM_DATA_DIR="$prefix/share/prism/data" "$scratch/build_reference/reference_consumer")
echo "$output"
[ "$output" = "traced 32x18, mostly geometry" ]
output=$(PRISM_DATA_DIR="$prefix/share/prism/data" "$scratch/build_atmosphere/atmosphere_consumer")
echo "$output"
[ "$output" = "fitted within 1, shipped within 1" ]

# The installed binary must use its own data: remove one file there and watch it say so.
rm "$prefix/share/prism/data/illuminants_F.csv"
if err=$(env -u PRISM_DATA_DIR "$prefix/bin/prism" colour xyz --illuminant F2 2>&1); then
  echo "installed prism did not read its installed data" >&2
  exit 1
fi
echo "$err"
case "$err" in
  *"$prefix/share/prism/data/illuminants_F.csv: data file not found"*) ;;
  *) echo "unexpected error: $err" >&2; exit 1 ;;
esac
