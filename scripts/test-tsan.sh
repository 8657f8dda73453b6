#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# A stage of CI: the threaded sources and filters under ThreadSanitizer. Builds, with clang and
# -fsanitize=thread in $BUILD_DIR (default build-tsan/ in the source tree), only what the
# tests of the threaded code need: the thread-count stress test and the unit and accuracy
# tests of vtkParametricSurfaceSource, vtkDisplacementMapFilter, vtkMikkTSpaceTangents,
# vtkHeightMapToNormalMap and vtkNormalMapBaker (no rendering, examples, Python, MPI or
# benchmarks). Any data race stops the test that found it, and so the stage.
#
# The tests run on VTK's STDThread SMP backend (VTK_SMP_BACKEND_IN_USE). Debian's VTK uses TBB
# by default, and TBB hands work to its threads through its own atomics inside libtbb, which is
# not instrumented: ThreadSanitizer cannot see that a task started after the data it reads was
# written, and would report every parallel loop. STDThread starts its threads and waits for
# them with std::thread and std::mutex, which ThreadSanitizer follows, so nothing needs to be
# suppressed; the same functors run either way (vtkSMPTools::For), and the stress test checks
# that TBB gives the same bits in the ordinary build.
set -euo pipefail
# --help prints the comment above and does nothing else.
if [[ "${1-}" == --help || "${1-}" == -h ]]; then
  sed -n '4,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"
  exit 0
fi
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$src/build-tsan}"
export CC=clang CXX=clang++

bash "$src/scripts/install-deps.sh"
# Optimised, so that the threaded loops run as they do in a release build, with the frame
# pointers and line tables that make the reports readable.
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSURFACEDETAIL_SANITIZE=thread \
  -DSURFACEDETAIL_BUILD_BENCHMARKS=OFF -DSURFACEDETAIL_BUILD_EXAMPLES=OFF \
  -DSURFACEDETAIL_BUILD_FUZZERS=OFF -DSURFACEDETAIL_WRAP_PYTHON=OFF -DSURFACEDETAIL_USE_MPI=OFF \
  -DCMAKE_COMPILE_WARNING_AS_ERROR=ON ${CMAKE_ARGS:-}

programs=(
  TestSurfaceDetailThreadCounts
  TestParametricSurfaceSource TestParametricSurfaceAccuracy
  TestParametricSurfaceSourceTextureTransform
  TestDisplacementMapFilter TestDisplacementMapFilterAccuracy TestDisplacementMapFilterParametric
  TestDisplacementMapFilterHardEdges TestDisplacementMapFilterClosedForms
  TestDisplacementMapFilterInput TestDisplacementMapFilterPrecision
  TestDisplacementMapFilterNormals TestDisplacementMapFilterTriplanar
  TestMikkTSpaceTangents TestMikkTSpaceTangentsHardEdges
  TestHeightMapToNormalMap TestHeightMapToNormalMapKernels
  TestNormalMapBaker TestNormalMapBakerRayReach
)
cmake --build "$build" -j "$(nproc)" --target "${programs[@]}"

# Their GoogleTest suites (each program's tests are named Suite.Test in ctest).
suites=(
  SurfaceDetailThreadCounts
  ParametricSurfaceSource ParametricSurfaceAccuracy ParametricSurfaceSourceTextureTransform
  DisplacementMapFilter DisplacementMapFilterAccuracy DisplacementMapFilterParametric
  DisplacementMapFilterHardEdges DisplacementMapFilterClosedForms
  vtkDisplacementMapFilterTriplanar
  vtkMikkTSpaceTangents MikkTSpaceTangentsHardEdges
  TestHeightMapToNormalMap HeightMapToNormalMapKernels
  NormalMapBaker NormalMapBakerRayReach
)
regex="^($(IFS='|'; echo "${suites[*]}"))\\."

export VTK_SMP_BACKEND_IN_USE=STDThread
# halt_on_error: the first race fails the test (its report is in the ctest output);
# second_deadlock_stack: both stacks of a lock-order inversion.
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:history_size=4"
cd "$build"
ctest --output-on-failure --timeout 900 -j "$(nproc)" -R "$regex" "$@"
