#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# The run-time-against-error study (Testing/Benchmarks/SurfaceDetailStudy.cxx): builds the
# program alone and runs it under a virtual X server (Mesa llvmpipe). Writes the CSVs, the
# Markdown tables and one plot per scene to Documentation/study (or $STUDY_OUT), every rendered
# picture to $BUILD_DIR/study-images, and the machine it ran on to machine.txt.
# Extra arguments go to the program (e.g. --rounds 31, --scenes wall-70).
set -euo pipefail
# --help prints the comment above and does nothing else.
if [[ "${1-}" == --help || "${1-}" == -h ]]; then
  sed -n '4,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"
  exit 0
fi
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$src/build}"
out="${STUDY_OUT:-$src/Documentation/study}"

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
# Only this program and what it links: the study is meant to run on small shared machines.
cmake --build "$build" --target SurfaceDetailStudy -j "${JOBS:-2}"

mkdir -p "$out"
{
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  lscpu | grep -E '^(Model name|CPU\(s\)|Thread\(s\) per core|CPU max MHz|BogoMIPS)' | sed 's/  */ /g'
  echo "vector extensions: $(grep -o -w -E 'avx2|avx512f' /proc/cpuinfo | sort -u | tr '\n' ' ')"
  echo "command: scripts/study.sh $*"
} > "$out/machine.txt"
start=$(date +%s)
# -noreset: Xvfb must not reset when a window closes (the program opens one per scene and plot).
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  "$build/bin/SurfaceDetailStudy" --out "$out" --images "$build/study-images" "$@"
echo "wall time: $(( $(date +%s) - start )) s" >> "$out/machine.txt"
cat "$out/machine.txt"
