#!/usr/bin/env bash
# The main job: install the dependencies, build semimesh (Release, build/), run it on the
# reference case. For now the reference case is the CAD model of the paper's wing (analytic NACA
# 0012 on a wall in its far-field box); the meshing case replaces it when the mesher lands.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target semimesh
./build/apps/semimesh cad-info --backend naca
