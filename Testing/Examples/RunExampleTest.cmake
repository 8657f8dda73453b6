# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Run by ctest for each example (Testing/Examples/CMakeLists.txt): runs COMMAND with a fresh
# OUTPUT_DIR as its last argument, then compares OUTPUT_DIR/IMAGE with BASELINE by the strict
# comparison (COMPARE, SurfaceDetailCompareImage), which leaves the candidate and the
# difference in TEMPORARY_DIR when they differ.
foreach(var COMMAND OUTPUT_DIR IMAGE COMPARE BASELINE TEMPORARY_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "RunExampleTest.cmake needs -D ${var}=...")
  endif()
endforeach()
string(REPLACE "|" ";" COMMAND "${COMMAND}")

file(REMOVE_RECURSE "${OUTPUT_DIR}")
file(MAKE_DIRECTORY "${OUTPUT_DIR}" "${TEMPORARY_DIR}")
execute_process(COMMAND ${COMMAND} "${OUTPUT_DIR}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the example failed (${result}): ${COMMAND}")
endif()
execute_process(
  COMMAND "${COMPARE}" "${OUTPUT_DIR}/${IMAGE}" -V "${BASELINE}" -T "${TEMPORARY_DIR}"
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the picture differs from ${BASELINE}")
endif()
