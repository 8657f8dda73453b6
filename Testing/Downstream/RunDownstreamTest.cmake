# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Run by ctest (TestDownstreamFindPackage) with -D BUILD_DIR=... -D SOURCE_DIR=...
# -D SCRATCH_DIR=... -D GENERATOR=... -D CXX_COMPILER=... -D C_COMPILER=...
# [-D LINK_FLAGS=...] (the sanitizers' runtime, when SurfaceDetail was built with them):
# installs SurfaceDetail's build tree into a scratch prefix, then configures, builds and
# runs Testing/Downstream against that prefix alone.
foreach(var BUILD_DIR SOURCE_DIR SCRATCH_DIR GENERATOR)
  if(NOT ${var})
    message(FATAL_ERROR "RunDownstreamTest.cmake needs -D ${var}=...")
  endif()
endforeach()

file(REMOVE_RECURSE "${SCRATCH_DIR}")
file(MAKE_DIRECTORY "${SCRATCH_DIR}")
set(prefix "${SCRATCH_DIR}/prefix")
set(build "${SCRATCH_DIR}/build")

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "TestDownstreamFindPackage: ${step} failed (${result})")
  endif()
endfunction()

run(install "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
run(configure "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Testing/Downstream" -B "${build}"
  -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_C_COMPILER=${C_COMPILER}"
  "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}")
run(build "${CMAKE_COMMAND}" --build "${build}")
run(run "${build}/downstream" "${SCRATCH_DIR}")
message(STATUS "TestDownstreamFindPackage: the installed package works")
