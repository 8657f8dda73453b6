#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Fuzzes each libFuzzer target of the sanitizer build (scripts/test-sanitizers.sh builds them
# into $BUILD_DIR, default build-sanitizers/) for a bounded time: FUZZ_SECONDS (default 60)
# each, starting from Testing/Fuzz/corpus/<target>. New inputs go to a scratch corpus in the
# build tree, never into the repository. A crash stops the run and leaves its input in
# $BUILD_DIR/fuzz-artifacts: fix the bug, then add that input to the target's corpus folder so
# that ctest replays it from then on.
set -euo pipefail
# --help prints the comment above and does nothing else.
if [[ "${1-}" == --help || "${1-}" == -h ]]; then
  sed -n '4,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"
  exit 0
fi
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$src/build-sanitizers}"
seconds="${FUZZ_SECONDS:-60}"
export LSAN_OPTIONS="suppressions=$src/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
mkdir -p "$build/fuzz-artifacts"
for target in FuzzDisplacementMapFilter FuzzHeightMapToNormalMap FuzzMikkTSpaceTangents \
  FuzzOIIOImageReader; do
  scratch="$build/fuzz-corpus/$target"
  mkdir -p "$scratch"
  echo "fuzz: $target for $seconds s"
  # The reader's target leaks inside OpenImageIO on truncated PNGs (scripts/lsan.supp), and
  # naming that needs slow unwinding, too slow to fuzz with: no leak checks for it here (its
  # corpus replay in ctest has them).
  leaks=1
  [ "$target" = FuzzOIIOImageReader ] && leaks=0
  ASAN_OPTIONS="detect_leaks=$leaks" "$build/bin/$target" -detect_leaks="$leaks" \
    -max_total_time="$seconds" -print_final_stats=1 -max_len=4096 \
    -artifact_prefix="$build/fuzz-artifacts/$target-" "$scratch" \
    "$src/Testing/Fuzz/corpus/$target" 2>&1 | grep -E '^(#[0-9]+ +DONE|Done|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY)' || true
  if ls "$build/fuzz-artifacts/$target-"* >/dev/null 2>&1; then
    echo "fuzz: $target failed; inputs in $build/fuzz-artifacts" >&2
    exit 1
  fi
done
echo "fuzz: no target failed"
