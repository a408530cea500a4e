#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian 12 packages this project builds, tests and runs with. Idempotent: only
# missing packages are installed, so a second run returns in a moment. Needs root (or sudo).
# python3-jsonschema, lib3mf-dev, desktop-file-utils, appstream, shared-mime-info: the independent
# validators and readers the tests check --json reports, 3MF files and the desktop files with;
# zsh and fish parse their completion scripts.
set -euo pipefail

packages=(
  cmake g++ make pkg-config ccache clang-format clang-tidy help2man dpkg-dev
  libopenvdb-dev libboost-iostreams-dev libimath-dev libtbb-dev libblosc-dev zlib1g-dev
  libgdcm-dev libgdcm-tools
  libvtk9-dev libopenexr-dev
  libglfw3-dev libglm-dev libimgui-dev
  xvfb xauth libgl1-mesa-dri
  libcli11-dev nlohmann-json3-dev
  pybind11-dev python3-dev python3-numpy
  libgtest-dev libgmock-dev libbenchmark-dev libtinygltf-dev
  mricron-data libcgal-demo python3-jsonschema lib3mf-dev
  desktop-file-utils appstream shared-mime-info zsh fish
)

# --sanitizers: also what scripts/sanitizer-tree.sh builds with (clang and its sanitizer and
# libFuzzer runtimes).
if [[ ${1:-} == --sanitizers ]]; then packages+=(clang libclang-rt-14-dev); fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=()
if [[ $(id -u) != 0 ]]; then sudo=(sudo); fi
echo "install-deps: installing ${missing[*]}"
"${sudo[@]}" apt-get update -q
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
