#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Debian 12 packages SurfaceDetail needs, and only those that are missing,
# so that a warm machine starts at once.
set -euo pipefail
# --help prints the comment above and does nothing else.
if [[ "${1-}" == --help || "${1-}" == -h ]]; then
  sed -n '4,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"
  exit 0
fi

packages=(
  build-essential cmake pkg-config git
  libvtk9-dev python3-vtk9
  libopenimageio-dev openimageio-tools
  libglm-dev
  libgtest-dev libgmock-dev googletest libbenchmark-dev
  xvfb xauth mesa-utils libgl1-mesa-dri
  libjpeg-turbo-progs
  xplanet-images
  # The MPI example and tests: VTK::ParallelMPI comes with libvtk9-dev; mpiexec and the
  # MPI headers it was built against come from Open MPI (Debian's default MPI).
  openmpi-bin libopenmpi-dev

  # CI's second stage (scripts/test-sanitizers.sh): clang with ASan and UBSan
  clang
)
# node runs the reference MikkTSpace (npm package "mikktspace") in the tests. Only
# when the commands are missing: a node from elsewhere (e.g. NodeSource, which bundles npm
# and conflicts with Debian's npm package) is fine.
if ! command -v node >/dev/null 2>&1; then packages+=(nodejs); fi
if ! command -v npm >/dev/null 2>&1; then packages+=(npm); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
