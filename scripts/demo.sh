#!/usr/bin/env bash
# The README's first command: install what is missing, build Release, run Prism's main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# ccache keys on paths relative to the checkout, so that another clone (CI's) reuses the cache.
export CCACHE_BASEDIR="$PWD"
# --fresh: the cache holds only what the preset says (a folder configured by another compiler
# or other options would otherwise keep them, or lose the preset's when CMake drops its cache).
cmake --preset release --fresh >/dev/null
cmake --build --preset release --target prism
exec build/release/app/prism demo "$@"
