# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Installs the reference MikkTSpace (npm package "mikktspace", pinned) into PREFIX once.
# Run by the ctest fixture MikkTSpaceReference; any failure fails that test, and ctest then
# does not run (and reports as failed) the compatibility tests that need it.
#   cmake -DNPM=<npm> -DPREFIX=<dir> -DVERSION=<version> -P InstallMikkTSpaceReference.cmake
if(EXISTS "${PREFIX}/node_modules/mikktspace/package.json")
  file(READ "${PREFIX}/node_modules/mikktspace/package.json" manifest)
  if(manifest MATCHES "\"version\": \"${VERSION}\"")
    message(STATUS "mikktspace ${VERSION} already in ${PREFIX}")
    return()
  endif()
endif()
if(NOT NPM OR NOT EXISTS "${NPM}")
  message(FATAL_ERROR "npm was not found: install Debian's nodejs and npm "
    "(bash scripts/install-deps.sh) and reconfigure.")
endif()
execute_process(
  COMMAND "${NPM}" install --prefix "${PREFIX}" --no-audit --no-fund --no-save
    "mikktspace@${VERSION}"
  RESULT_VARIABLE result)
if(NOT result EQUAL 0 OR NOT EXISTS "${PREFIX}/node_modules/mikktspace/package.json")
  message(FATAL_ERROR "npm install mikktspace@${VERSION} into ${PREFIX} failed (${result}); "
    "the compatibility tests need it and the npm registry.")
endif()
