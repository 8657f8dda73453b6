# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Helpers that add SurfaceDetail's tests in one line each.
#
#   surfacedetail_add_gtest(<exe> SOURCES <src>... [MODULES <module>...] [LABELS <label>]
#                           [FIXTURES_REQUIRED <fixture>] [SANITIZER_ENVIRONMENT <var=value>])
#     A GoogleTest program; every TEST in it becomes its own ctest test.
#     SANITIZER_ENVIRONMENT: one variable set for its tests in the AddressSanitizer build only.
#
#   surfacedetail_add_image_test(<TestName> [SOURCES <src>...] [EXECUTABLE <exe>]
#                                [MODULES <module>...] [ARGS <arg>...]
#                                [BASELINE <name>] [EXPECT_MISMATCH])
#     A rendering regression test. The program renders and calls
#     SurfaceDetailImageComparison::RegressionTest (Testing/Cxx/SurfaceDetailImageComparison.h,
#     strict per-pixel comparison); ctest passes it
#       -V Testing/Baseline/<BASELINE or TestName>.png  -T <build>/Testing/Temporary
#     A missing baseline fails the test and leaves the candidate image in
#     <build>/Testing/Temporary. SOURCES builds <exe> (default <TestName>); EXECUTABLE reuses
#     a program built by an earlier call, so one program can serve many scenes via ARGS.
#     EXPECT_MISMATCH turns the test around: it passes only if the comparison fails (used
#     to prove that the harness catches a wrong picture).
#
# Floating-point exceptions stay off in these programs: Mesa's llvmpipe raises SIGFPE.

# Programs that render run without LeakSanitizer in the AddressSanitizer build: Mesa unloads
# its driver at exit, and the driver's leaked caches then have no module to be named by (and
# so suppressed); unwinding slowly enough to reach a named frame makes llvmpipe's runs take
# minutes. AddressSanitizer and UBSan stay on.
set(surfacedetail_rendering_asan_options "ASAN_OPTIONS=detect_leaks=0")

set(surfacedetail_baseline_dir "${PROJECT_SOURCE_DIR}/Testing/Baseline")
set(surfacedetail_temporary_dir "${CMAKE_BINARY_DIR}/Testing/Temporary")
file(MAKE_DIRECTORY "${surfacedetail_temporary_dir}")

function(_surfacedetail_add_program exe)
  cmake_parse_arguments(arg "" "" "SOURCES;MODULES;LIBRARIES" ${ARGN})
  add_executable(${exe} ${arg_SOURCES})
  target_link_libraries(${exe} PRIVATE ${arg_MODULES} ${arg_LIBRARIES})
  target_include_directories(${exe} PRIVATE "${PROJECT_SOURCE_DIR}/Testing/Cxx")
  target_compile_options(${exe} PRIVATE ${SURFACEDETAIL_WARNING_FLAGS})
  target_compile_definitions(${exe} PRIVATE
    "SURFACEDETAIL_DATA_DIR=\"${PROJECT_SOURCE_DIR}/Data\""
    "SURFACEDETAIL_TEMP_DIR=\"${surfacedetail_temporary_dir}\"")
  if(arg_MODULES)
    vtk_module_autoinit(TARGETS ${exe} MODULES ${arg_MODULES})
  endif()
endfunction()

function(surfacedetail_add_gtest exe)
  cmake_parse_arguments(arg "" "LABELS;FIXTURES_REQUIRED;SANITIZER_ENVIRONMENT"
    "SOURCES;MODULES;LIBRARIES"
    ${ARGN})
  _surfacedetail_add_program(${exe} SOURCES ${arg_SOURCES} MODULES ${arg_MODULES}
    LIBRARIES GTest::gtest GTest::gtest_main ${arg_LIBRARIES})
  # gtest_discover_tests flattens PROPERTIES into name/value pairs, so every value must be a
  # single word (a list would shift the pairs and lose what follows): one label per program.
  if(arg_LABELS)
    set(properties LABELS ${arg_LABELS})
  else()
    set(properties LABELS unit)
  endif()
  if(arg_FIXTURES_REQUIRED)
    list(APPEND properties FIXTURES_REQUIRED ${arg_FIXTURES_REQUIRED})
  endif()
  if(SURFACEDETAIL_SANITIZE_ADDRESS AND arg_LABELS STREQUAL "rendering")
    list(APPEND properties ENVIRONMENT ${surfacedetail_rendering_asan_options})
  elseif(SURFACEDETAIL_SANITIZE_ADDRESS AND arg_SANITIZER_ENVIRONMENT)
    list(APPEND properties ENVIRONMENT ${arg_SANITIZER_ENVIRONMENT})
  endif()
  gtest_discover_tests(${exe}
    DISCOVERY_MODE PRE_TEST
    DISCOVERY_TIMEOUT 60
    PROPERTIES ${properties})
endfunction()

function(surfacedetail_add_image_test name)
  cmake_parse_arguments(arg "EXPECT_MISMATCH" "EXECUTABLE;BASELINE"
    "SOURCES;MODULES;ARGS" ${ARGN})
  if(NOT arg_EXECUTABLE)
    set(arg_EXECUTABLE ${name})
  endif()
  if(NOT arg_BASELINE)
    set(arg_BASELINE ${name})
  endif()
  if(arg_SOURCES)
    _surfacedetail_add_program(${arg_EXECUTABLE} SOURCES ${arg_SOURCES}
      MODULES VTK::RenderingOpenGL2 VTK::InteractionStyle VTK::IOImage VTK::ImagingCore
      ${arg_MODULES})
  endif()
  add_test(NAME ${name}
    COMMAND ${arg_EXECUTABLE} ${arg_ARGS}
      -V "${surfacedetail_baseline_dir}/${arg_BASELINE}.png"
      -T "${surfacedetail_temporary_dir}")
  set_tests_properties(${name} PROPERTIES LABELS "image" SKIP_RETURN_CODE 125)
  if(SURFACEDETAIL_SANITIZE_ADDRESS)
    set_tests_properties(${name} PROPERTIES ENVIRONMENT ${surfacedetail_rendering_asan_options})
  endif()
  if(arg_EXPECT_MISMATCH)
    set_tests_properties(${name} PROPERTIES PASS_REGULAR_EXPRESSION "Failed Image Test")
  else()
    set_tests_properties(${name} PROPERTIES
      FAIL_REGULAR_EXPRESSION "Failed Image Test;ImageNotFound;ERROR:")
  endif()
endfunction()
