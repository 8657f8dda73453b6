#!/usr/bin/env bash
# Install what is missing, build, and run every test (unit, accuracy, stress, image) with
# ctest under a virtual X server (Mesa llvmpipe).
set -euo pipefail
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export BUILD_DIR="${BUILD_DIR:-$src/build}"
bash "$src/scripts/build.sh"

cd "$BUILD_DIR"
xvfb-run -a -s "-screen 0 1280x1024x24" \
  ctest --output-on-failure --timeout 600 -j "$(nproc)" "$@"
