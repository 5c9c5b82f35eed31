#!/usr/bin/env bash
# Installs the Debian 12 packages that semimesh needs to build and test, when any is missing.
# Idempotent: installs nothing when everything is present. Needs root (or sudo) for apt-get.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libtbb-dev          # OCCT's CMake export names libtbb.so
  libeigen3-dev libgtest-dev libgmock-dev libfmt-dev
  libtomlplusplus-dev libcli11-dev libpugixml-dev libzip-dev
  zlib1g-dev                                    # compressed Nektar++ output (one zlib stream per array)
  libdeflate-dev                                # compressed VTU (independent 64 KiB zlib blocks)
  libtet1.5-dev libcgal-dev libgmp-dev libmpfr-dev
  python3 python3-numpy python3-gmsh python3-vtk9 python3-meshio
  librsvg2-bin                                  # scripts/readme-pictures.sh: large SVG pictures to PNG
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
