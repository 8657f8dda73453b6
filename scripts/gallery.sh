#!/usr/bin/env bash
# The main job: install what is missing, build, and render the gallery of example scenes
# (the seed scenes) as PNG images into $BUILD_DIR/gallery.
set -euo pipefail
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export BUILD_DIR="${BUILD_DIR:-$src/build}"
bash "$src/scripts/build.sh"

out="$BUILD_DIR/gallery"
mkdir -p "$out"
count=0
while read -r example; do
  [ -n "$example" ] || continue
  echo "gallery: $example"
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$BUILD_DIR/bin/$example" "$out"
  count=$((count + 1))
done < "$BUILD_DIR/gallery-examples.txt"
echo "gallery: $count scenes rendered into $out"
ls -1 "$out"
