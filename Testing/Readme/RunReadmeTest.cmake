# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Run by ctest (TestReadmeProgram, TestReadmePythonProgram): the README's first program, taken
# from README.md exactly as printed, run against an installed SurfaceDetail as a user would
# run it, its picture compared with Testing/Baseline/TestReadmeProgram.png.
#
# Each code block to run follows a line "<!-- ctest: <file name> -->" in the README.
# LANGUAGE CXX: writes the blocks first.cxx and CMakeLists.txt into a project, configures it
# with CMAKE_PREFIX_PATH at a scratch install of BUILD_DIR, builds it and runs it.
# LANGUAGE Python: runs the block first.py with PYTHON, the installed package on PYTHONPATH.
foreach(var LANGUAGE README BUILD_DIR SCRATCH_DIR COMPARE BASELINE)
  if(NOT ${var})
    message(FATAL_ERROR "RunReadmeTest.cmake needs -D ${var}=...")
  endif()
endforeach()

file(READ "${README}" readme)
# The code block that follows the marker for <name>, written to <folder>/<name>.
function(extract_block name folder)
  set(marker "<!-- ctest: ${name} -->")
  string(FIND "${readme}" "${marker}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "README.md has no block marked '${marker}'")
  endif()
  string(LENGTH "${marker}" length)
  math(EXPR at "${at} + ${length}")
  string(SUBSTRING "${readme}" ${at} -1 rest)
  # The fence line opens the block; the next line that is a fence closes it.
  if(NOT rest MATCHES "^[ \t]*\n```[a-z]*\n")
    message(FATAL_ERROR "the marker '${marker}' is not followed by a code block")
  endif()
  string(LENGTH "${CMAKE_MATCH_0}" open)
  string(SUBSTRING "${rest}" ${open} -1 rest)
  string(FIND "${rest}" "\n```" close)
  if(close EQUAL -1)
    message(FATAL_ERROR "the block marked '${marker}' is not closed")
  endif()
  math(EXPR close "${close} + 1")
  string(SUBSTRING "${rest}" 0 ${close} block)
  file(WRITE "${folder}/${name}" "${block}")
endfunction()

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${step} failed (${result}): ${ARGN}")
  endif()
endfunction()

file(REMOVE_RECURSE "${SCRATCH_DIR}")
set(prefix "${SCRATCH_DIR}/prefix")
set(project "${SCRATCH_DIR}/project")
set(work "${SCRATCH_DIR}/run")
file(MAKE_DIRECTORY "${project}" "${work}" "${SCRATCH_DIR}/compare")
run(install "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")

if(LANGUAGE STREQUAL "CXX")
  extract_block(first.cxx "${project}")
  extract_block(CMakeLists.txt "${project}")
  run(configure "${CMAKE_COMMAND}" -S "${project}" -B "${project}/build" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}"
    "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_C_COMPILER=${C_COMPILER}"
    "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}")
  run(build "${CMAKE_COMMAND}" --build "${project}/build")
  execute_process(COMMAND "${project}/build/first" WORKING_DIRECTORY "${work}"
    RESULT_VARIABLE result)
elseif(LANGUAGE STREQUAL "Python")
  extract_block(first.py "${project}")
  set(ENV{PYTHONPATH} "${prefix}/${PYTHON_DESTINATION}")
  set(ENV{PYTHONDONTWRITEBYTECODE} 1)
  execute_process(COMMAND "${PYTHON}" "${project}/first.py" WORKING_DIRECTORY "${work}"
    RESULT_VARIABLE result)
else()
  message(FATAL_ERROR "LANGUAGE is CXX or Python, not '${LANGUAGE}'")
endif()
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the README's program failed (${result})")
endif()
run(compare "${COMPARE}" "${work}/donut.png" -V "${BASELINE}" -T "${SCRATCH_DIR}/compare")
message(STATUS "the README's program runs as printed and draws the baseline")
