#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Blender's Cycles bake of BenchNormalMapBaker's mesh pair, the baseline of vtkNormalMapBaker's
# table in BENCHMARKS.md: writes the two meshes with $BUILD_DIR/bin/BenchNormalMapBaker, then
# times the bake step (Testing/Benchmarks/BlenderBake.py) at 1024^2 and 2048^2 on 1 and 2
# threads, $RUNS runs each (default 3), and prints every time and the median.
# Blender is an optional tool, not a dependency: apt-get install blender (Debian 12: 3.4.1).
# The meshes and the baked maps go to $BAKE_DIR if set (and stay there), else to a temporary
# folder that is removed at the end.
set -euo pipefail
# --help prints the comment above and does nothing else.
if [[ "${1-}" == --help || "${1-}" == -h ]]; then
  sed -n '4,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"
  exit 0
fi
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$src/build}"
blender="${BLENDER:-blender}"
runs="${RUNS:-3}"
script="$src/Testing/Benchmarks/BlenderBake.py"

if ! command -v "$blender" > /dev/null; then
  echo "Blender not found: install it (apt-get install blender) or set BLENDER." >&2
  exit 1
fi
bench="$build/bin/BenchNormalMapBaker"
if [ ! -x "$bench" ]; then
  echo "$bench not found: cmake --build $build --target BenchNormalMapBaker" >&2
  exit 1
fi

if [ -n "${BAKE_DIR:-}" ]; then
  folder="$BAKE_DIR"
  mkdir -p "$folder"
else
  folder="$(mktemp -d)"
  trap 'rm -rf "$folder"' EXIT
fi
SURFACEDETAIL_BAKE_MESHES="$folder" "$bench"

"$blender" --version | head -n 1
echo "load average: $(cut -d ' ' -f 1-3 /proc/loadavg)"
printf '| map | threads | runs (s) | median (s) |\n|---|---:|---|---:|\n'
for size in 1024 2048; do
  for threads in 1 2; do
    times=()
    for _ in $(seq "$runs"); do
      line="$("$blender" -b --factory-startup -noaudio --python "$script" \
        -- "$folder" "$size" "$threads" 2>&1 | grep '^BlenderBake ')" || {
        echo "Blender did not bake ($size, $threads threads)." >&2
        exit 1
      }
      times+=("$(echo "$line" | awk '{ print $NF }')")
    done
    median="$(printf '%s\n' "${times[@]}" | sort -g | sed -n "$(((runs + 1) / 2))p")"
    printf '| %s² | %s | %s | %s |\n' "$size" "$threads" "${times[*]}" "$median"
  done
done
