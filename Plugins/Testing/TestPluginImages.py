# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The plugin's reader, height-map filter and baker against the C++ classes' own outputs.

    pvbatch TestPluginImages.py <plugin> <brick_height.png> <reference folder> <output folder>

Makes with the plugin's proxies the pipelines PluginReferenceImages.cxx makes with the C++
classes, writes each output as a .vti and compares it with the reference of the same name:
the same extent, spacing and origin, the same point arrays (names, types, components) and the
same values; and that a normal map of twice the bump scale does not. Prints "the C++ classes'
images match the plugin's"."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLImageDataReader

plugin, height_file, references, output = sys.argv[1:5]
LoadPlugin(plugin, remote=False, ns=globals())

reader = OpenImageIOImageReader(FileName=height_file)
normal = HeightMapToNormalMap(Input=reader, SelectInputScalars=["POINTS", "OIIOImage"])
normal.BumpScale = 0.05
relief = HeightMapToNormalMap(Input=reader, SelectInputScalars=["POINTS", "OIIOImage"])
relief.BumpScale = 0.05
relief.OutputRelief = 1
cones = HeightMapToConeMap(Input=reader, SelectInputScalars=["POINTS", "OIIOImage"])
coarse = ParametricSurface(ParametricFunction="Donut")
coarse.UResolution = 48
coarse.VResolution = 24
coarse.GenerateTangents = 1
fine = ParametricSurface(ParametricFunction="Donut")
fine.UResolution = 256
fine.VResolution = 128
displaced = DisplacementMap(Input=fine, Source=reader, SelectInputScalars=["POINTS", "OIIOImage"])
displaced.ScaleFactor = 0.02
displaced.Midlevel = 0.5
baker = NormalMapBaker(Input=coarse, Source=displaced)
baker.TextureSize = [128, 64]
baker.BakeHeight = 1

os.makedirs(output, exist_ok=True)
outputs = [("reader", reader, 0), ("normal", normal, 0), ("relief", relief, 0), ("cones", cones, 0),
           ("baked-normal", baker, 0), ("baked-height", baker, 1)]


def read(path):
    r = vtkXMLImageDataReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


failures = []
for name, proxy, port in outputs:
    path = os.path.join(output, name + ".vti")
    SaveData(path, proxy=OutputPort(proxy, port), DataMode="Ascii")
    ours, theirs = read(path), read(os.path.join(references, name + ".vti"))
    for what in ("GetExtent", "GetSpacing", "GetOrigin"):
        if getattr(ours, what)() != getattr(theirs, what)():
            failures.append("%s: %s %s, C++ %s" % (name, what[3:], getattr(ours, what)(),
                                                   getattr(theirs, what)()))
    a, b = ours.GetPointData(), theirs.GetPointData()
    names = sorted(a.GetArrayName(k) for k in range(a.GetNumberOfArrays()))
    if names != sorted(b.GetArrayName(k) for k in range(b.GetNumberOfArrays())) or not names:
        failures.append("%s: arrays %s differ from the C++ output's" % (name, names))
        continue
    worst = 0.0
    for array in names:
        x, y = a.GetArray(array), b.GetArray(array)
        if (x.GetDataType(), x.GetNumberOfComponents()) != (y.GetDataType(),
                                                             y.GetNumberOfComponents()):
            failures.append("%s: %s has another type or width" % (name, array))
            continue
        worst = max(worst, float(abs(vtk_to_numpy(x).astype(float)
                                     - vtk_to_numpy(y).astype(float)).max()))
    print("%s: %s, largest difference %g" % (name, ", ".join(names), worst))
    if worst != 0.0:
        failures.append("%s: values differ by up to %g" % (name, worst))
# The comparison can see a difference: twice the bump scale is another normal map.
steeper = HeightMapToNormalMap(Input=reader, SelectInputScalars=["POINTS", "OIIOImage"])
steeper.BumpScale = 0.1
path = os.path.join(output, "steeper.vti")
SaveData(path, proxy=steeper, DataMode="Ascii")
moved = abs(vtk_to_numpy(read(path).GetPointData().GetArray("NormalMap")).astype(float)
            - vtk_to_numpy(read(os.path.join(references, "normal.vti")).GetPointData()
                           .GetArray("NormalMap")).astype(float)).max()
print("twice the bump scale: largest difference %g" % moved)
if moved == 0:
    failures.append("the comparison did not see twice the bump scale")
for f in failures:
    print("MISMATCH: " + f)
if not failures:
    print("the C++ classes' images match the plugin's")
