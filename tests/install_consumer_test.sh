#!/usr/bin/env bash
# Installs the build into a scratch prefix, builds tests/consumer against it with
# find_package(Prism), runs it on the installed data, and checks that the installed prism
# binary reads the data installed beside it.
# Usage: install_consumer_test.sh SOURCE_DIR BUILD_DIR SCRATCH_DIR
set -euo pipefail
source_dir=$1 build_dir=$2 scratch=$3
rm -rf "$scratch"
prefix=$scratch/prefix
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
cmake -S "$source_dir/tests/consumer" -B "$scratch/build" -G Ninja \
      -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$scratch/build" >/dev/null
output=$(PRISM_DATA_DIR="$prefix/share/prism/data" "$scratch/build/consumer")
echo "$output"
[ "$output" = "D65 xy 0.3127 0.3290" ]

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
