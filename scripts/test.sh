#!/usr/bin/env bash
# The README's second command (and CI's only step): install what is missing, then build and run
# every test twice, in Release and under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# ccache keys on paths relative to the checkout, so that another clone (CI's) reuses the cache.
export CCACHE_BASEDIR="$PWD"

werror=OFF
[ -n "${CI:-}" ] && werror=ON

for preset in release asan; do
  echo "== $preset: configure, build, test"
  # --fresh: the cache holds only what the preset and this line say (a folder configured by
  # another compiler or other options would otherwise keep them, or lose the preset's when CMake
  # drops its cache on a change of compiler).
  cmake --preset "$preset" --fresh -DPRISM_WERROR=$werror >/dev/null
  cmake --build --preset "$preset"
  ctest --preset "$preset"
done
