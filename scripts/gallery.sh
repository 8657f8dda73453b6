#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# The main job: install what is missing, build, render the gallery of example scenes
# as PNG images into $BUILD_DIR/gallery, and write $BUILD_DIR/gallery/index.html, a
# page that shows every picture with its caption.
set -euo pipefail
# --help prints the comment above and does nothing else.
if [[ "${1-}" == --help || "${1-}" == -h ]]; then
  sed -n '4,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"
  exit 0
fi
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export BUILD_DIR="${BUILD_DIR:-$src/build}"
bash "$src/scripts/build.sh"

out="$BUILD_DIR/gallery"
rm -rf "$out"
mkdir -p "$out"

html_escape() {
  local s="$1"
  s="${s//&/&amp;}"
  s="${s//</&lt;}"
  s="${s//>/&gt;}"
  printf '%s' "$s"
}

figures=""
count=0
# gallery-examples.txt (written by Examples/Cxx/CMakeLists.txt): name, a tab, the caption.
while IFS=$'\t' read -r example caption; do
  [ -n "$example" ] || continue
  echo "gallery: $example"
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$BUILD_DIR/bin/$example" "$out"
  if [ ! -f "$out/$example.png" ]; then
    echo "gallery: $example wrote no $example.png" >&2
    exit 1
  fi
  sources="Examples/Cxx/$example.cxx"
  if [ -f "$src/Examples/Python/$example.py" ]; then
    sources="$sources, Examples/Python/$example.py"
  fi
  figures+="<figure id=\"$example\">
  <a href=\"$example.png\"><img src=\"$example.png\" alt=\"$example\"></a>
  <figcaption><b>$example</b>: $(html_escape "$caption") <span class=\"source\">($sources)</span></figcaption>
</figure>
"
  count=$((count + 1))
done < "$BUILD_DIR/gallery-examples.txt"

cat > "$out/index.html" <<HTML
<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>SurfaceDetail gallery</title>
<style>
  body { font-family: sans-serif; background: #1e2026; color: #e8e8e8; margin: 2em; }
  figure { margin: 0 0 2.5em 0; }
  img { max-width: 100%; border: 1px solid #444; }
  figcaption { max-width: 60em; margin-top: 0.5em; line-height: 1.4; }
  .source { color: #9aa; }
  a { color: inherit; }
</style>
</head>
<body>
<h1>SurfaceDetail gallery</h1>
<p>$count scenes, each rendered by its example program (Mesa llvmpipe under
Xvfb). Each is also an image test: <code>ctest -R TestExample</code>.</p>
$figures</body>
</html>
HTML
echo "gallery: $count scenes rendered into $out; open $out/index.html"
