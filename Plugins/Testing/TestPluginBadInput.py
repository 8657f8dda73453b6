# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""Each filter of the SurfaceDetail plugin given input it cannot use: the filter's own error
message names the problem, the output is empty, and pvpython goes on (no crash). The
representation given a surface it cannot shade says why once and draws it plain.

    pvpython TestPluginBadInput.py <plugin> <a normal map image>"""
import sys

from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkCommonCore import vtkCommand, vtkOutputWindow

LoadPlugin(sys.argv[1], remote=False, ns=globals())


class Messages:
    """Collects what VTK's output window is given (ParaView routes errors through it)."""

    def __init__(self):
        self.text = []
        window = vtkOutputWindow.GetInstance()
        for event in (vtkCommand.ErrorEvent, vtkCommand.WarningEvent):
            window.AddObserver(event, self.add)

    def add(self, caller, event, calldata=None):
        self.text.append(str(calldata))

    add.CallDataType = "string0"


messages = Messages()
sphere = Sphere()  # normals, no texture coordinates
volume = Wavelet()  # a 3-D image
cases = [
    ("Displacement Map", lambda: DisplacementMap(Input=ParametricSurface(), Source=volume,
                                            SelectInputScalars=["POINTS", "RTData"]),
     "2-D image"),
    ("MikkTSpace Tangents", lambda: MikkTSpaceTangents(Input=sphere), "texture coordinates"),
    ("Height Map To Normal Map", lambda: HeightMapToNormalMap(Input=volume), "3-D"),
    ("Height Map To Cone Map", lambda: HeightMapToConeMap(Input=volume), "2-D"),
    ("Normal Map Baker", lambda: NormalMapBaker(Input=sphere, Source=sphere),
     "texture coordinates"),
]
failed = False
for name, make, expected in cases:
    before = len(messages.text)
    proxy = make()
    proxy.UpdatePipeline()
    said = " ".join(messages.text[before:])
    points = proxy.GetDataInformation(0).GetNumberOfPoints()
    print("%s: %d points; said: %s" % (name, points, said.strip()[:200]))
    if expected not in said or points != 0:
        print("FAILED: %s did not refuse its bad input clearly" % name)
        failed = True

# The representation given a surface without tangents: normal mapping names what is missing
# once, and the surface is drawn plain.
view = CreateRenderView()
view.ViewSize = [200, 150]
display = Show(ParametricSurface(), view)  # texture coordinates, no tangents
display.SetRepresentationType("Surface Detail")
display.SurfaceDetailTechnique = "Normal Mapping"
display.SurfaceDetailNormalMap = CreateTexture(sys.argv[2])
before = len(messages.text)
Render(view)
Render(view)
said = [text for text in messages.text[before:] if "tangents" in text]
print("Surface Detail representation said: %s" % " ".join(said).strip()[:200])
if len(said) != 1:
    print("FAILED: the representation did not report the missing tangents once")
    failed = True
if not failed:
    print("every bad input refused")
