# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""A torus displaced by a brick height map, with MikkTSpace tangents, made and drawn by ParaView.

    pvbatch DisplacedTorus.py <path to SurfaceDetail.so> <output folder>
    mpiexec -n 4 pvbatch DisplacedTorus.py <path to SurfaceDetail.so> <output folder>

Each rank makes one piece of the torus (with the ghost cells its filters ask for) and
ParaView composites the picture; writes DisplacedTorus.png and the surface as
DisplacedTorus.pvtp (one piece file per rank)."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

if len(sys.argv) != 3 or sys.argv[1] in ("-h", "--help"):
    print(__doc__)
    sys.exit(0 if len(sys.argv) == 2 else 1)
plugin, folder = sys.argv[1:3]
LoadPlugin(plugin, remote=False, ns=globals())

torus = ParametricSurface(ParametricFunction="Donut")
torus.UResolution = 256
torus.VResolution = 128
torus.GenerateTangents = 1
torus.TextureRepeat = [8.0, 2.0]  # bricks of similar size around and across the tube
# The height map: the repository's tileable brick heights (16-bit, read as fractions of
# their range), through the plugin's OpenImageIO reader.
data = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data")
heights = OpenImageIOImageReader(FileName=os.path.join(data, "brick_height.png"))
displaced = DisplacementMap(Input=torus, Source=heights,
                            SelectInputScalars=["POINTS", "OIIOImage"])
displaced.ScaleFactor = 0.04
displaced.Midlevel = 0.5
framed = MikkTSpaceTangents(Input=displaced)

view = CreateRenderView()
view.ViewSize = [800, 600]
view.Background = [0.1, 0.1, 0.15]
view.OrientationAxesVisibility = 0
display = Show(framed, view)
display.DiffuseColor = [0.85, 0.7, 0.5]
view.CameraPosition = [0.0, -4.0, 3.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
os.makedirs(folder, exist_ok=True)
SaveScreenshot(os.path.join(folder, "DisplacedTorus.png"), view)
SaveData(os.path.join(folder, "DisplacedTorus.pvtp"), proxy=framed)
