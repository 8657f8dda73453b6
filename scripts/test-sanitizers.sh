#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# The second stage of CI: every test again, built by clang with AddressSanitizer and
# UndefinedBehaviorSanitizer (in $BUILD_DIR, default build-sanitizers/ in the source tree),
# warnings as errors. Undefined behaviour stops the program; LeakSanitizer reports leaks at
# exit, except inside Mesa and X (scripts/lsan.supp says which and why).
set -euo pipefail
# --help prints the comment above and does nothing else.
if [[ "${1-}" == --help || "${1-}" == -h ]]; then
  sed -n '4,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"
  exit 0
fi
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export BUILD_DIR="${BUILD_DIR:-$src/build-sanitizers}"
export CC=clang CXX=clang++
# Optimised, so that the threaded loops run as they do in a release build, with the frame
# pointers and line tables that make the reports readable.
export CMAKE_ARGS="${CMAKE_ARGS:-} -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSURFACEDETAIL_SANITIZE=address \
  -DSURFACEDETAIL_BUILD_BENCHMARKS=OFF -DSURFACEDETAIL_BUILD_EXAMPLES=OFF \
  -DCMAKE_COMPILE_WARNING_AS_ERROR=ON -DSURFACEDETAIL_WRAP_PYTHON=OFF"
# No Python wrapping here: an AddressSanitizer-built extension module cannot be loaded by
# /usr/bin/python3, which is not built with the sanitizer runtime.
# allocator_may_return_null: an allocation beyond memory fails as it does outside ASan (malloc
# returns null), so that the code's own handling of it is what gets tested.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:allocator_may_return_null=1"
export LSAN_OPTIONS="suppressions=$src/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
exec bash "$src/scripts/test.sh" "$@"
