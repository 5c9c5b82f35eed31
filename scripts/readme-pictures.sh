#!/usr/bin/env bash
# The README's pictures of the paper's case: meshes it with --pictures (MSH binary only, the fastest
# writer; a few minutes) and copies the chosen pictures into docs/pictures/ under the names the
# README uses. An SVG larger than 150 kB (the wake cut holds thousands of curved elements) is
# turned into a PNG at most 1000 x 800 pixels with rsvg-convert (Debian librsvg2-bin), so the repository
# stays small. Commit docs/pictures/ afterwards.
#
#   scripts/readme-pictures.sh [CONFIG]     (default: examples/naca0012_wing.toml)
set -euo pipefail
cd "$(dirname "$0")/.."

config=${1:-examples/naca0012_wing.toml}
work=out/readme_pictures
# picture suffix written by `semimesh run --pictures` -> name in docs/pictures/ (without extension)
pictures=(
  "_cut:h_type_cut"
  "_cut_le:h_type_leading_edge"
  "_cut_te:h_type_trailing_edge"
  "_cut_junction:h_type_junction"
  "_cut_wake:h_type_wake"
  "_body_planform:h_type_surface_planform"
  "_body_front:h_type_surface_front"
  "_quality:h_type_quality"
)
max_svg_bytes=150000

[ -x build/apps/semimesh ] || cmake --build build -j"$(nproc)" --target semimesh
command -v rsvg-convert >/dev/null || { echo "readme-pictures: needs rsvg-convert (apt-get install librsvg2-bin)" >&2; exit 1; }
rm -rf "$work"
./build/apps/semimesh run "$config" -o "$work" --pictures --set 'output.formats=["msh41-binary"]' --set output.basename='"case"'

mkdir -p docs/pictures
for entry in "${pictures[@]}"; do
  suffix=${entry%%:*} name=${entry#*:}
  svg="$work/case$suffix.svg"
  [ -f "$svg" ] || { echo "readme-pictures: $svg not written (this case has no such block): skipped"; continue; }
  rm -f "docs/pictures/$name.svg" "docs/pictures/$name.png"
  if [ "$(stat -c %s "$svg")" -gt "$max_svg_bytes" ]; then
    rsvg-convert --keep-aspect-ratio -w 1000 -h 800 -o "docs/pictures/$name.png" "$svg"
    echo "readme-pictures: docs/pictures/$name.png (from $(stat -c %s "$svg")-byte $svg)"
  else
    cp "$svg" "docs/pictures/$name.svg"
    echo "readme-pictures: docs/pictures/$name.svg"
  fi
done
