#!/usr/bin/env bash
# The GLSL half of "one formula, two compilers": every shaders/shared/*.glsl must compile as
# GLSL 4.50 after prelude.glsl (the C++ half is compiled by the build itself). A deliberately
# broken file must fail, so that this test can fail. A file that builds on others names them on
# a "// Requires: a.glsl b.glsl" line; they are included first (from shared/, or, for stand-ins
# of accessors a file expects its includer to define, from tests/glsl_stubs/). A file specialised
# by defines names them on a "// Variants: A B" line; it is compiled once without them and once
# with all of them, so that every branch is checked.
# Usage: glsl_compile_test.sh GLSLANG_VALIDATOR SHARED_DIR SCRATCH_DIR
set -euo pipefail
validator=$1 shared=$2 scratch=$3
mkdir -p "$scratch"
stubs=$(cd "$(dirname "$0")" && pwd)/glsl_stubs

compile() {  # compile FILE [-DNAME...]: wraps FILE in a compute shader and validates it
  local file=$1; shift
  local wrapper=$scratch/$(basename "$file")$(printf '%s' "$@" | tr -c 'A-Za-z0-9_' '_').comp
  {
    echo '#version 450'
    echo '#extension GL_GOOGLE_include_directive : require'
    echo '#include "prelude.glsl"'
    local dep
    for dep in $(sed -n 's|^// Requires: ||p' "$shared/$file" 2>/dev/null); do
      echo "#include \"$dep\""
    done
    echo "#include \"$file\""
    echo 'layout(local_size_x = 1) in;'
    echo 'void main() {}'
  } >"$wrapper"
  # -G (OpenGL SPIR-V target): glslang resolves #include only when generating SPIR-V.
  "$validator" -G "$@" -I"$shared" -I"$stubs" -I"$scratch" "$wrapper" -o "$wrapper.spv"
}

status=0
for file in "$shared"/*.glsl; do
  name=$(basename "$file")
  [ "$name" = prelude.glsl ] && continue
  if compile "$name" >"$scratch/$name.log" 2>&1; then
    echo "ok    $name"
  else
    echo "FAIL  $name"; cat "$scratch/$name.log"; status=1
  fi
  variants=$(sed -n 's|^// Variants: ||p' "$file")
  [ -n "$variants" ] || continue
  defines=()
  for v in $variants; do defines+=("-D$v"); done
  if compile "$name" "${defines[@]}" >"$scratch/$name.variants.log" 2>&1; then
    echo "ok    $name ($variants)"
  else
    echo "FAIL  $name ($variants)"; cat "$scratch/$name.variants.log"; status=1
  fi
done

echo 'PRISM_INLINE float broken(float x) { return x * vec2(1.0f); }' >"$scratch/broken_control.glsl"
if compile broken_control.glsl >/dev/null 2>&1; then
  echo "FAIL  the negative control compiled: the validator checks nothing"; status=1
fi
exit $status
