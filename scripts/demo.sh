#!/usr/bin/env bash
# The README's first command: install what is missing, build Release, run Prism's main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target prism
exec build/release/app/prism demo "$@"
