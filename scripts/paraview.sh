#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Builds the SurfaceDetail ParaView plugin (Plugins/) against Debian 12's ParaView 5.11 and
# runs its tests (pvpython, and pvbatch under MPI). Debian's ParaView cannot be installed
# beside libvtk9-dev (python3-paraview conflicts with python3-vtk9), so everything runs in a
# Debian root made with debootstrap: made once (about 4 GB, a few minutes) and reused, at
# $PARAVIEW_ROOT (default /var/cache/surfacedetail/paraview-root). Needs root.
#
#   bash scripts/paraview.sh                      build the plugin and run its tests
#   bash scripts/paraview.sh --window <out.png>   build it, then open ParaView's window on
#       Examples/ParaView/DisplacedReliefTorus.py under Xvfb and take a picture of the whole
#       window (scripts/paraview-window.sh, run in the root; the README's picture)
set -euo pipefail
# --help prints the comment above and does nothing else.
if [[ "${1-}" == --help || "${1-}" == -h ]]; then
  sed -n '4,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"
  exit 0
fi
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="${PARAVIEW_ROOT:-/var/cache/surfacedetail/paraview-root}"

# What ParaView's CMake package looks for (find_package of each), the compiler, an X server
# for rendering, MPI, and OpenImageIO for the reader.
packages=(paraview paraview-dev python3-paraview cmake g++ make pkg-config xvfb xauth
  libgl1-mesa-dri openmpi-bin libopenmpi-dev python3-mpi4py libopenimageio-dev
  qtbase5-dev libutfcpp-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools
  libqt5x11extras5-dev libboost-dev libexpat1-dev libeigen3-dev libavcodec-dev
  libavformat-dev libavutil-dev libswscale-dev libfreetype-dev libgdal-dev libgl2ps-dev
  libglew-dev libhdf5-openmpi-dev libjpeg-dev liblz4-dev liblzma-dev libxml2-dev
  libnetcdf-dev libgl-dev libpng-dev python3-dev libtheora-dev libtiff-dev libx11-dev
  zlib1g-dev libdouble-conversion-dev libxt-dev)

if [[ ! -x "$root/usr/bin/pvbatch" ]]; then
  if ! command -v debootstrap >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null
  fi
  mirror=$(awk '/^URIs:/{print $2; exit}' /etc/apt/sources.list.d/debian.sources)
  mkdir -p "$(dirname "$root")"
  [[ -x "$root/bin/bash" ]] || debootstrap --variant=minbase bookworm "$root" "$mirror"
  cp /etc/apt/sources.list.d/debian.sources "$root/etc/apt/sources.list.d/"
  rm -f "$root/etc/apt/sources.list"
fi

# /proc, /sys, /dev and /dev/shm for MPI; the sources read-only at /src; the build at /build.
mounted=()
mount_bind() {
  mkdir -p "$2"
  if ! mountpoint -q "$2"; then
    mount --bind "$1" "$2"
    mounted=("$2" "${mounted[@]}")
  fi
}
cleanup() { for m in "${mounted[@]}"; do umount "$m" || true; done; }
trap cleanup EXIT
mount_bind /proc "$root/proc"
mount_bind /sys "$root/sys"
mount_bind /dev "$root/dev"
mount_bind /dev/shm "$root/dev/shm"
mount_bind "$src" "$root/src"
mount -o remount,bind,ro "$root/src"

# Packages are (re)installed when the list above differs from the one last installed.
stamp="$root/var/lib/surfacedetail-packages"
if [[ "$(cat "$stamp" 2>/dev/null)" != "${packages[*]}" ]]; then
  chroot "$root" bash -c "export DEBIAN_FRONTEND=noninteractive; apt-get update -qq &&
    apt-get install -y -qq --no-install-recommends ${packages[*]} >/dev/null"
  echo "${packages[*]}" > "$stamp"
fi

chroot "$root" bash -c "set -e
  cmake -S /src/Plugins -B /build -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build /build -j $(nproc)"
if [[ "${1-}" == --window ]]; then
  # Only the picture needs these: an X screen grabber, a converter and a way to click.
  chroot "$root" bash -c "export DEBIAN_FRONTEND=noninteractive
    apt-get install -y -qq --no-install-recommends x11-apps imagemagick xdotool >/dev/null"
  chroot "$root" bash /src/scripts/paraview-window.sh /tmp/paraview-window.png
  cp "$root/tmp/paraview-window.png" "$2"
  exit 0
fi
chroot "$root" bash -c "cd /build && xvfb-run -a -s '-screen 0 1280x1024x24 -noreset' \
    ctest --output-on-failure --timeout 600 -j $(nproc)"
