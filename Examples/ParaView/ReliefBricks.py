# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The relief-mapped brick wall of the gallery (ReliefBricks), in ParaView.

    pvpython ReliefBricks.py <path to SurfaceDetail.so> <output folder>

A flat rectangle of 8 x 8 quads, drawn with the "Surface Detail" representation: relief
mapping with self-shadowing, the relief map made in the pipeline from Data/brick_height.png
by "Height Map To Normal Map", the colours from Data/brick_color.png. Writes ReliefBricks.png."""
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

if len(sys.argv) != 3 or sys.argv[1] in ("-h", "--help"):
    print(__doc__)
    sys.exit(0 if len(sys.argv) == 2 else 1)
plugin, folder = sys.argv[1:3]
LoadPlugin(plugin, remote=False, ns=globals())
data = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data")

wall = ParametricSurface(ParametricFunction="Rectangle")  # x in [-2,2], y in [0,3.5]
wall.UResolution = 8
wall.VResolution = 8
wall.GenerateTangents = 1  # the frame the relief map's normals are stored in
depth = 0.1  # the joints lie 0.1 units behind the bricks' faces
heights = OpenImageIOImageReader(FileName=os.path.join(data, "brick_height.png"))
relief = HeightMapToNormalMap(Input=heights, SelectInputScalars=["POINTS", "OIIOImage"])
relief.BumpScale = depth / 3.75  # the texture square is 4 x 3.5 units on the wall
relief.OutputRelief = 1
# ParaView's "Texture" proxy turns an image of the pipeline into a texture; registered, it is
# listed in the window's texture menus.
relief_map = servermanager._getPyProxy(
    servermanager.ProxyManager().NewProxy("textures", "Texture"))
relief_map.Input = relief
servermanager.ProxyManager().RegisterProxy("textures", "Brick relief map", relief_map)

view = CreateRenderView()
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.16, 0.18, 0.22]
display = Show(wall, view)
display.SetRepresentationType("Surface Detail")
display.SurfaceDetailTechnique = "Relief Mapping"
display.SurfaceDetailReliefMap = relief_map
display.SurfaceDetailDepthScale = depth
display.SurfaceDetailSelfShadowing = 1
display.Texture = CreateTexture(os.path.join(data, "brick_color.png"))
display.Specular = 0.2
view.CameraPosition = [3.2, 0.6, 3.4]
view.CameraFocalPoint = [0.0, 1.75, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera()
GetActiveCamera().Dolly(1.3)
os.makedirs(folder, exist_ok=True)
SaveScreenshot(os.path.join(folder, "ReliefBricks.png"), view)
