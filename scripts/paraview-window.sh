#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Run inside the ParaView root by `scripts/paraview.sh --window <out.png>`: opens ParaView's
# window on an Xvfb screen with the plugin loaded and Examples/ParaView/DisplacedReliefTorus.py
# run, closes the welcome dialog, widens the left panels, scrolls the Properties panel to the
# Surface Detail group and writes a picture of the whole screen to the file given. The clicks
# are at fixed places of a 1500 x 950 screen: they fit ParaView 5.11's default layout.
set -euo pipefail
# --help prints the comment above and does nothing else.
if [[ "${1-}" == --help || "${1-}" == -h ]]; then
  sed -n '4,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"
  exit 0
fi
out="${1:?usage: paraview-window.sh <out.png>}"
export DISPLAY=:57 HOME=/tmp/paraview-window-home
export PV_PLUGIN_PATH=/build/lib/SurfaceDetail SURFACEDETAIL_DATA=/src/Data
mkdir -p "$HOME"
Xvfb "$DISPLAY" -screen 0 1500x950x24 -noreset >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true; wait $xvfb 2>/dev/null || true' EXIT
sleep 2
paraview --script=/src/Examples/ParaView/DisplacedReliefTorus.py >/dev/null 2>&1 &
paraview=$!
sleep 40                                    # start, load the plugin, run the script, render
xdotool mousemove 892 576 click 1            # the welcome dialog's Close
sleep 3
window=$(xdotool search --onlyvisible --name "ParaView" | head -1)
xdotool windowsize "$window" 1500 950 windowmove "$window" 0 0
sleep 5
xdotool mousemove 297 600; sleep 0.5; xdotool mousedown 1; sleep 0.5   # the panels' edge
xdotool mousemove 400 600; sleep 0.3; xdotool mousemove 540 600; sleep 0.5; xdotool mouseup 1
sleep 2
xdotool mousemove 150 750 click --repeat 5 --delay 100 5               # down to Surface Detail
sleep 3
xwd -root -display "$DISPLAY" | convert xwd:- "$out"
kill "$paraview"
wait "$paraview" 2>/dev/null || true   # gone before the root's mounts are taken down
