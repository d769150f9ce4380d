#!/usr/bin/env bash
# Installs the Debian packages Prism builds and tests with, and only those that are missing.
# As root it runs apt-get; otherwise it prints the exact apt-get line and stops (exit 1).
set -euo pipefail

packages=(
  cmake ninja-build pkg-config g++ ccache  # g++: the C++ runtime, and the compiler of the install test's consumers
  clang libclang-rt-dev  # every preset's compiler; the ASan, UBSan and libFuzzer runtimes
  libcli11-dev nlohmann-json3-dev libfmt-dev libeigen3-dev libglm-dev libcsv-dev libstb-dev zlib1g-dev
  libopenexr-dev libtinygltf-dev libembree-dev libnlopt-cxx-dev
  libgtest-dev libbenchmark-dev glslang-tools
  libepoxy-dev libegl-dev libgl-dev libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri libglfw3-dev
  libimgui-dev xvfb xauth
  slurmctld slurmd slurm-client munge  # the one-node cluster of tests/slurm
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = installed ] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

line="apt-get install -y --no-install-recommends ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "prism: missing Debian packages; run as root:" >&2
  echo "  apt-get update && $line" >&2
  exit 1
fi
echo "prism: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
# shellcheck disable=SC2086
apt-get install -y -qq --no-install-recommends ${missing[*]} >/dev/null
