#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Install what is missing, build, and run every test (unit, accuracy, stress, image) with
# ctest under a virtual X server (Mesa llvmpipe).
set -euo pipefail
# --help prints the comment above and does nothing else.
if [[ "${1-}" == --help || "${1-}" == -h ]]; then
  sed -n '4,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"
  exit 0
fi
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export BUILD_DIR="${BUILD_DIR:-$src/build}"
bash "$src/scripts/build.sh"

cd "$BUILD_DIR"
# -noreset: by default Xvfb resets when its last client disconnects, and a test starting
# during that reset cannot connect ("bad X server connection") when tests run in parallel.
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  ctest --output-on-failure --timeout 600 -j "$(nproc)" "$@"
