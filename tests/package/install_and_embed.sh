#!/usr/bin/env bash
# The library as an installed package: `cmake --install` the build into a fresh prefix, then build
# examples/embed against it (find_package(semimesh)) and run it: it must write a valid mesh and
# report its progress to the end.
#   install_and_embed.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$source/examples/embed" -B "$work/embed" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/embed" -j2 > "$work/build.log"
"$work/embed/embed" "$work/wing.msh" 2> "$work/embed.err"
cat "$work/embed.err" >&2
test -s "$work/wing.msh"
# Its progress callback (semimesh/progress.hpp, installed) saw curving and certification to the end.
grep -q "progress 100%" "$work/embed.err" || { echo "embed: no progress reported to 100%" >&2; exit 1; }
# The installed tree is self-contained: no header is taken from the source tree.
if grep -rq "$source/[a-z_]*/include" "$work/prefix/lib/cmake/semimesh/"; then
  echo "the installed package refers to the source tree" >&2
  exit 1
fi
echo "embed: built against $work/prefix and ran"
