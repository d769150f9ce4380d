#!/usr/bin/env bash
# The bad-input corpus, tests/bad_input/cases.txt: each line `EXIT | ARGS | FRAGMENT` is a prism
# command that must exit with EXIT (1: bad input or environment; 2: a malformed command line; 70,
# a bug, never), print exactly one line on stderr, `prism: error: …` containing FRAGMENT, and
# leave its output folder empty (nothing half-written). ARGS are words separated by spaces, with
# {F} for tests/bad_input/files, {S} for scenes/, {Z} for fuzz/corpus/ and {O} for an empty folder
# made for the case; leading NAME=VALUE words are the command's environment. Lines starting with
# # and blank lines are skipped. Prints every case that fails, then a count. PART/PARTS (say 1/2)
# runs every PARTS-th case from the PART-th on, so that ctest runs the corpus's parts side by side.
# Usage: bad_input_test.sh PRISM CASES FILES SCENES FUZZ_CORPUS SCRATCH [PART/PARTS]
set -uo pipefail
prism=$1 cases=$2 files=$3 scenes=$4 corpus=$5 scratch=$6 share=${7:-1/1}
part=${share%/*} parts=${share#*/}
rm -rf "$scratch" && mkdir -p "$scratch"
export PRISM_CACHE_DIR=${PRISM_CACHE_DIR:-$scratch/cache}
total=0 failed=0 line_number=0 seen=0
while IFS= read -r line || [ -n "$line" ]; do
  line_number=$((line_number + 1))
  [[ -z "$line" || "$line" == \#* ]] && continue
  seen=$((seen + 1))
  [ $(((seen - 1) % parts + 1)) = "$part" ] || continue
  total=$((total + 1))
  if ! [[ "$line" =~ ^([^|]*[^|\ ])\ \|\ ([^|]*[^|\ ])\ \|(\ (.*))?$ ]]; then
    echo "$cases:$line_number: not EXIT | ARGS | FRAGMENT"
    failed=$((failed + 1))
    continue
  fi
  expected=${BASH_REMATCH[1]} words=${BASH_REMATCH[2]} fragment=${BASH_REMATCH[4]}
  out="$scratch/case_$line_number"
  mkdir -p "$out/o"
  words=${words//\{F\}/$files}
  words=${words//\{S\}/$scenes}
  words=${words//\{Z\}/$corpus}
  words=${words//\{O\}/$out/o}
  read -r -a argv <<<"$words"
  env_words=()
  while [ ${#argv[@]} -gt 0 ] && [[ "${argv[0]}" =~ ^[A-Z_]+= ]]; do env_words+=("${argv[0]}"); argv=("${argv[@]:1}"); done
  env "${env_words[@]}" timeout 120 "$prism" "${argv[@]}" >"$out/stdout" 2>"$out/stderr" </dev/null
  status=$?
  stderr_lines=$(wc -l <"$out/stderr")
  first=$(head -n 1 "$out/stderr")
  left=$(find "$out/o" -mindepth 1 | head -n 3)
  why=""
  [ "$status" = "$expected" ] || why="exit $status, expected $expected"
  [ "$stderr_lines" = 1 ] || why="${why:+$why; }$stderr_lines lines on stderr"
  [[ "$first" == "prism: error: "* ]] || why="${why:+$why; }stderr does not start with 'prism: error: '"
  [[ -n "$fragment" && "$first" == *"$fragment"* ]] || why="${why:+$why; }message lacks '$fragment'"
  [ -z "$left" ] || why="${why:+$why; }left behind: $left"
  if [ -n "$why" ]; then
    failed=$((failed + 1))
    echo "$cases:$line_number: prism ${argv[*]}: $why"
    echo "    stderr: $(head -c 400 "$out/stderr" | tr '\n' '|')"
  fi
done <"$cases"
echo "bad input (part $share): $((total - failed)) of $total cases give their one-line error and exit code"
[ "$total" -gt 0 ] && [ "$failed" = 0 ]
