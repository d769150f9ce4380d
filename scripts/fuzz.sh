#!/usr/bin/env bash
# Fuzzes one of Prism's loaders with libFuzzer for SECONDS (clang, ASan + UBSan; the `fuzz`
# preset): scripts/fuzz.sh TARGET SECONDS [JOBS]. TARGET is a file fuzz/TARGET_fuzz.cpp
# (scene_json, scene_set, gltf, spectrum_csv, image, exr, upsampling_table, view_settings).
# New inputs that reach new code go to build/fuzz/corpus/TARGET (the saved corpus, fuzz/corpus/
# TARGET, is read, never written: copy what is worth keeping there, e.g. with -merge=1); a crash
# is written to build/fuzz/crashes/ and ends the run with libFuzzer's non-zero status. Prints
# libFuzzer's final statistics (executions per second, coverage). Installs what is missing
# (scripts/install-deps.sh: clang and its libFuzzer runtime among the rest).
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: scripts/fuzz.sh TARGET SECONDS [JOBS]" >&2; exit 2; }
target=$1 seconds=$2 jobs=${3:-1}
[ -f "fuzz/${target}_fuzz.cpp" ] || { echo "scripts/fuzz.sh: no fuzz target '$target' (fuzz/*_fuzz.cpp)" >&2; exit 2; }
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || { echo "scripts/fuzz.sh: SECONDS must be a positive integer, not '$seconds'" >&2; exit 2; }
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "scripts/fuzz.sh: JOBS must be a positive integer, not '$jobs'" >&2; exit 2; }

scripts/install-deps.sh
export CCACHE_BASEDIR="$PWD"
cmake --preset fuzz --fresh >/dev/null  # the cache holds only what the preset says
cmake --build --preset fuzz --target "${target}_fuzz"

work=build/fuzz/corpus/$target
mkdir -p "$work" build/fuzz/crashes
dict=()
case $target in
  scene_json|scene_set|gltf|view_settings) dict=(-dict=fuzz/dict/json.dict) ;;
esac
parallel=()
# More than one job: libFuzzer's workers, each logging to build/fuzz/fuzz-N.log.
[ "$jobs" -gt 1 ] && parallel=(-jobs="$jobs" -workers="$jobs")
# Every loader's limits (core/json_schema.h, the README's "Limits and errors") keep one input's
# work small; 4 GB of memory and 10 s an input are libFuzzer's signs of unbounded work.
exec "build/fuzz/fuzz/${target}_fuzz" "$work" "fuzz/corpus/$target" "${dict[@]}" "${parallel[@]}" \
  -max_total_time="$seconds" -rss_limit_mb=4096 -timeout=10 \
  -max_len=65536 -artifact_prefix=build/fuzz/crashes/ -print_final_stats=1
