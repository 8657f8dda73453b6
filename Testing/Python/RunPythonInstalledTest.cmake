# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Run by ctest (TestPythonImportInstalled): installs the build tree into a scratch prefix and
# runs TestPythonImport.py against that prefix alone. Neither PYTHONPATH's build-tree folder
# nor LD_LIBRARY_PATH is set: the installed modules must find their libraries by themselves.
foreach(var BUILD_DIR SOURCE_DIR PREFIX PYTHON PYTHON_DESTINATION)
  if(NOT ${var})
    message(FATAL_ERROR "RunPythonInstalledTest.cmake needs -D ${var}=...")
  endif()
endforeach()

file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
  OUTPUT_QUIET RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "TestPythonImportInstalled: the install failed (${result})")
endif()

set(site "${PREFIX}/${PYTHON_DESTINATION}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env --unset=LD_LIBRARY_PATH "PYTHONPATH=${site}"
    "${PYTHON}" "${SOURCE_DIR}/Testing/Python/TestPythonImport.py" "${SOURCE_DIR}" "${site}"
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "TestPythonImportInstalled: the installed package failed (${result})")
endif()
