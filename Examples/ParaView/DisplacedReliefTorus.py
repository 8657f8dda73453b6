# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""A torus displaced by rolling heights and relief-mapped with bricks, in ParaView.

    pvpython DisplacedReliefTorus.py <path to SurfaceDetail.so> <output folder>
    paraview --script=DisplacedReliefTorus.py     (with PV_PLUGIN_PATH naming the plugin's
                                                 folder: builds the pipeline in the window)

The large shape is geometry ("Displacement Map" with Data/noise_height.png, then MikkTSpace
tangents of the displaced surface); the bricks are shading only (the "Surface Detail"
representation, relief mapping with self-shadowing and the brick colours). From pvpython,
writes DisplacedReliefTorus.png."""
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

in_gui = len(sys.argv) < 2 or not sys.argv[1]  # paraview --script passes no arguments
if not in_gui and (len(sys.argv) != 3 or sys.argv[1] in ("-h", "--help")):
    print(__doc__)
    sys.exit(0 if len(sys.argv) == 2 else 1)
if not in_gui:
    LoadPlugin(sys.argv[1], remote=False, ns=globals())
here = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else os.getcwd()
data = os.environ.get("SURFACEDETAIL_DATA", os.path.join(here, "..", "..", "Data"))

torus = ParametricSurface(ParametricFunction="Donut")
torus.UResolution = 256
torus.VResolution = 128
torus.TextureRepeat = [8.0, 2.0]  # bricks of similar size around and across the tube
waves = OpenImageIOImageReader(FileName=os.path.join(data, "noise_height.png"))
displaced = DisplacementMap(Input=torus, Source=waves, SelectInputScalars=["POINTS", "OIIOImage"])
displaced.ScaleFactor = 0.05
displaced.Midlevel = 0.5
framed = MikkTSpaceTangents(Input=displaced)
bricks = OpenImageIOImageReader(FileName=os.path.join(data, "brick_height.png"))
relief = HeightMapToNormalMap(Input=bricks, SelectInputScalars=["POINTS", "OIIOImage"])
relief.BumpScale = 0.05
relief.OutputRelief = 1
# ParaView's "Texture" proxy turns an image of the pipeline into a texture; registered, it is
# listed in the window's texture menus.
relief_map = servermanager._getPyProxy(
    servermanager.ProxyManager().NewProxy("textures", "Texture"))
relief_map.Input = relief
servermanager.ProxyManager().RegisterProxy("textures", "Brick relief map", relief_map)

view = GetActiveViewOrCreate("RenderView")
if not in_gui:
    view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
display = Show(framed, view)
display.SetRepresentationType("Surface Detail")
display.SurfaceDetailTechnique = "Relief Mapping"
display.SurfaceDetailReliefMap = relief_map
display.SurfaceDetailDepthScale = 0.03
display.SurfaceDetailSelfShadowing = 1
display.Texture = CreateTexture(os.path.join(data, "brick_color.png"))
view.CameraPosition = [0.0, -3.2, 2.4]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
GetActiveCamera().Dolly(1.4)
SetActiveSource(framed)
if in_gui:
    Render(view)
else:
    os.makedirs(sys.argv[2], exist_ok=True)
    SaveScreenshot(os.path.join(sys.argv[2], "DisplacedReliefTorus.png"), view)
