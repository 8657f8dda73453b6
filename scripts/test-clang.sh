#!/usr/bin/env bash
# The portability check that CI runs after the README's test command: builds SurfaceDetail
# with clang (in $BUILD_DIR, default build-clang/ in the source tree) and runs every test.
# The hot loops have GCC-only vector code (vector extensions with __builtin_shuffle) with
# plain fallbacks; clang builds the fallbacks, in its AVX-512 build too, so this run is
# what tests them. Clang must also build the module without a warning.
set -euo pipefail
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export BUILD_DIR="${BUILD_DIR:-$src/build-clang}"
export CC=clang CXX=clang++
export CMAKE_ARGS="${CMAKE_ARGS:-} -DCMAKE_COMPILE_WARNING_AS_ERROR=ON"
exec bash "$src/scripts/test.sh" "$@"
