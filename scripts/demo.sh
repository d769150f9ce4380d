#!/usr/bin/env bash
# The README's first command: install what is missing, build Release, run Prism's main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# ccache keys on paths relative to the checkout, so that another clone (CI's) reuses the cache.
export CCACHE_BASEDIR="$PWD"
cmake --preset release >/dev/null
cmake --build --preset release --target prism
exec build/release/app/prism demo "$@"
