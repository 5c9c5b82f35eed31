#!/usr/bin/env bash
# Installs the dependencies, builds (Release, build/) and runs the test suite (docs/testing.md).
#   scripts/test.sh          the default tier: every test not labelled `long` (what CI runs)
#   scripts/test.sh --long   everything: the default tier, the long end-to-end certifications
#                            (CTest label `long`) and the benchmarks' build
set -euo pipefail
cd "$(dirname "$0")/.."

long=0
for arg in "$@"; do
  case "$arg" in
    --long) long=1 ;;
    -h|--help) sed -n '2,5p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "test.sh: unknown option '$arg' (known: --long)" >&2; exit 1 ;;
  esac
done

scripts/install-deps.sh
# The benchmarks (bench/) print figures and are no test: built with --long only.
bench=OFF
if [ "$long" = 1 ]; then bench=ON; fi
# Ninja for a new build folder (an existing one keeps its generator): it compiles any ready file
# while Make waits for each library to be finished before starting the next.
export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"
# Unity builds (CMake compiles a target's files in batches of 8): each batch parses the shared
# headers (Eigen, GoogleTest, OpenCASCADE) once instead of once per file, about a third less
# compile CPU from a clean tree (docs/testing.md). Every target must therefore compile both ways:
# no two files of one target may define the same name in an anonymous namespace.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON -DSEMIMESH_BUILD_BENCH="$bench"
cmake --build build -j"$(nproc)"

# CTest starts the longest tests first when it knows their times: from the last run in this build
# folder, else from the times measured on 2 cores and kept in tests/ctest_cost_data.txt.
mkdir -p build/Testing/Temporary
if [ ! -s build/Testing/Temporary/CTestCostData.txt ]; then
  cp tests/ctest_cost_data.txt build/Testing/Temporary/CTestCostData.txt
fi
cd build
if [ "$long" = 1 ]; then
  ctest --output-on-failure -j2
else
  ctest --output-on-failure -j2 --label-exclude long
fi
