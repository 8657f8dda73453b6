# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""Every proxy of the SurfaceDetail plugin made with its default settings and updated: each
must give a non-empty output without an error (ctest fails on any "ERROR" in the output)."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

plugin, data = sys.argv[1:3]
LoadPlugin(plugin, remote=False, ns=globals())


def check(proxy, what, port=0):
    proxy.UpdatePipeline()
    info = proxy.GetDataInformation(port)
    count = info.GetNumberOfPoints()
    if count <= 0:
        raise SystemExit("%s: empty output" % what)
    print("%s: %d points" % (what, count))


functions = ["Sphere", "Donut", "Cylinder", "Rectangle", "Revolution", "Extrusion"]
surface = ParametricSurface()
listed = surface.GetProperty("ParametricFunction").Available
if sorted(listed) != sorted(functions):
    raise SystemExit("the source lists %s, not %s" % (listed, functions))
for name in functions:
    surface = ParametricSurface(ParametricFunction=name)
    surface.GenerateTangents = 1
    check(surface, "Parametric Surface (%s)" % name)

surface = ParametricSurface()
heights = Wavelet(WholeExtent=[0, 63, 0, 63, 0, 0])
# Python sets Source after the proxy's defaults are made, so the height array is named.
check(DisplacementMap(Input=surface, Source=heights, SelectInputScalars=["POINTS", "RTData"]),
      "Displacement Map")
check(MikkTSpaceTangents(Input=surface), "MikkTSpace Tangents")
check(HeightMapToNormalMap(Input=heights), "Height Map To Normal Map")
check(HeightMapToConeMap(Input=heights), "Height Map To Cone Map")
check(HeightMapToConeMap(Input=heights, ConeType="Conservative"), "Height Map To Cone Map, conservative")
coarse = ParametricSurface(UResolution=16, VResolution=8)
baker = NormalMapBaker(Input=coarse, Source=ParametricSurface(), BakeHeight=1)
check(baker, "Normal Map Baker", 0)
check(baker, "Normal Map Baker height", 1)
reader = OpenImageIOImageReader(FileName=os.path.join(data, "test_card.png"))
check(reader, "OpenImageIO Image Reader")
print("all proxies updated")
