#!/usr/bin/env bash
# The main job: install the dependencies, build semimesh (Release, build/) and mesh the paper's case:
# a NACA 0012 wing (chord 1, squared-off trailing edge) standing on a wall, far field about 10 chords
# away, with the paper's H-type near field (wall layer, junction, a wake block of hexes standing a gap
# above the wall layer), curved at order 4 and split into 5 layers with ratio 2. Writes the mesh
# (MSH 4.1, VTU, Nektar++ XML) and report.json into out/naca0012_wing/.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"  # as scripts/test.sh, which shares build/
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON  # as scripts/test.sh: less compile time
cmake --build build -j"$(nproc)" --target semimesh
./build/apps/semimesh run examples/naca0012_wing.toml -o out/naca0012_wing
