#!/usr/bin/env bash
# A relocatable Prism for a machine that has none of its Debian libraries (a lent GPU machine, a
# cluster node): the install (bin/prism; share/prism/ with data, shaders and the example scenes,
# which prism finds beside its executable, core/data_files.h) and, in lib/, every shared library
# prism loads but the C library's, the C++ runtime's and the GL/EGL loaders' (which come with the
# machine's driver), packed into OUT.tar.xz. Use it there as
#   mkdir -p DIR && tar -xJf OUT.tar.xz -C DIR && LD_LIBRARY_PATH=DIR/lib DIR/bin/prism …
# The machine's own C++ runtime must be GCC 12's libstdc++ or newer (Debian 12's, which prism links).
# Usage: scripts/bundle.sh OUT.tar.xz [BUILD_DIR]   (BUILD_DIR: build/release, already built)
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: scripts/bundle.sh OUT.tar.xz [BUILD_DIR]" >&2; exit 2; }
out=$(realpath -m "$1")
build=$(realpath -m "${2:-$(dirname "$0")/../build/release}")
cd "$(dirname "$0")/.."
[ -x "$build/app/prism" ] || { echo "bundle: $build/app/prism is missing: build it first" >&2; exit 1; }

stage=$(mktemp -d)
trap 'rm -rf "$stage" "$out.tmp"' EXIT
cmake --install "$build" --prefix "$stage" >/dev/null
rm -rf "${stage:?}/include" "${stage:?}/lib"  # the layers' headers and archives: for building, not running
mkdir -p "$stage/lib"
libraries=$(ldd "$stage/bin/prism")
if grep -q 'not found' <<<"$libraries"; then
  echo "bundle: prism needs libraries this machine lacks:" >&2
  grep 'not found' <<<"$libraries" >&2
  exit 1
fi
awk '$3 ~ /^\// { print $3 }' <<<"$libraries" | while read -r lib; do
  case "$(basename "$lib")" in
    libc.so* | libm.so* | libmvec.so* | libpthread.so* | libdl.so* | librt.so* | libresolv.so* | ld-linux*) ;;
    libstdc++.so* | libgcc_s.so*) ;;
    libGL.so* | libEGL.so* | libOpenGL.so* | libGLX.so* | libGLdispatch.so* | libGLES*) ;;
    *) cp -L "$lib" "$stage/lib/" ;;
  esac
done
tar -C "$stage" -I 'xz -T0' -cf "$out.tmp" .
mv "$out.tmp" "$out"
echo "wrote $out ($(du -h "$out" | cut -f1); $(find "$stage/lib" -type f | wc -l) libraries)"
