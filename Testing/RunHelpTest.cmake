# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Run by ctest for each program and script (Testing/CMakeLists.txt): runs COMMAND --help in an
# empty WORK_DIR and fails unless it exits with 0, prints its usage on standard output and
# leaves the folder empty (a program asked for help renders, computes and writes nothing).
foreach(var COMMAND WORK_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "RunHelpTest.cmake needs -D ${var}=...")
  endif()
endforeach()
string(REPLACE "|" ";" COMMAND "${COMMAND}")

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
execute_process(COMMAND ${COMMAND} --help
  WORKING_DIRECTORY "${WORK_DIR}"
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors TIMEOUT 60)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "--help exited with ${result}: ${output}${errors}")
endif()
string(STRIP "${output}" output)
if(output STREQUAL "")
  message(FATAL_ERROR "--help printed nothing on standard output")
endif()
if(USAGE_REGEX AND NOT output MATCHES "${USAGE_REGEX}")
  message(FATAL_ERROR "--help printed no line matching '${USAGE_REGEX}':\n${output}")
endif()
file(GLOB_RECURSE written LIST_DIRECTORIES true "${WORK_DIR}/*")
if(written)
  message(FATAL_ERROR "--help wrote into the folder it ran in: ${written}")
endif()
message(STATUS "answers --help:\n${output}")
