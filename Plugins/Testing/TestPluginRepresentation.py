# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""Each technique of the "Surface Detail" representation, drawn by pvbatch and compared with
its baseline by the project's strict comparison.

    [mpiexec -n N] pvbatch TestPluginRepresentation.py <plugin> <Data> <baselines> <output> [off]

A torus with the repository's brick maps: normal mapping with a normal map made in the pipeline
(a "Height Map To Normal Map" filter behind a texture), bump mapping with a height map read from
a file, parallax mapping with both and the brick colours, relief mapping with the filter's
relief map and self-shadowing; and triplanar normal mapping with the brick colours on an
isosurface of the Wavelet source, which has no texture coordinates. Prints "every picture
matches its baseline"; with "off" the same scenes are drawn with the technique (or triplanar
mapping) switched off, and each must then fail its baseline:
prints "every technique switched off was caught"."""
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkParallelCore import vtkMultiProcessController

plugin, data, baselines, output = sys.argv[1:5]
switched_off = sys.argv[5:] == ["off"]
LoadPlugin(plugin, remote=False, ns=globals())
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()

# The project's strict comparison (Testing/Cxx/SurfaceDetailImageComparison.h): per pixel the
# largest difference over R, G and B; a picture fails when more than 0.2 % of its pixels differ
# by more than 8 levels.
TOLERANCE = 8
MAX_FRACTION_OVER = 0.002


def pixels(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    values = vtk_to_numpy(image.GetPointData().GetScalars())
    return values.reshape(height, width, -1)[:, :, :3].astype(int)


def fraction_over(candidate, baseline):
    a, b = pixels(candidate), pixels(baseline)
    if a.shape != b.shape:
        return 1.0
    return float(((abs(a - b).max(axis=2)) > TOLERANCE).mean())


def pipeline_texture(image):
    """A texture of an image made in the pipeline (ParaView's own "Texture" proxy)."""
    texture = servermanager._getPyProxy(
        servermanager.ProxyManager().NewProxy("textures", "Texture"))
    texture.Input = image
    return texture


torus = ParametricSurface(ParametricFunction="Donut")
torus.UResolution = 128
torus.VResolution = 64
torus.GenerateTangents = 1
torus.TextureRepeat = [8.0, 2.0]  # bricks of similar size around and across the tube
brick_height = os.path.join(data, "brick_height.png")
heights = OpenImageIOImageReader(FileName=brick_height)
normal_map = HeightMapToNormalMap(Input=heights, SelectInputScalars=["POINTS", "OIIOImage"])
normal_map.BumpScale = 0.05
relief_map = HeightMapToNormalMap(Input=heights, SelectInputScalars=["POINTS", "OIIOImage"])
relief_map.BumpScale = 0.05
relief_map.OutputRelief = 1
cone_map = HeightMapToConeMap(Input=heights, SelectInputScalars=["POINTS", "OIIOImage"])

view = CreateRenderView()
view.ViewSize = [400, 300]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.1, 0.1, 0.15]
display = Show(torus, view)
display.SetRepresentationType("Surface Detail")
display.DiffuseColor = [0.85, 0.7, 0.5]
view.CameraPosition = [0.0, -3.2, 2.4]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
GetActiveCamera().Dolly(1.6)

scenes = {
    "normal": dict(SurfaceDetailTechnique="Normal Mapping",
                   SurfaceDetailNormalMap=pipeline_texture(normal_map)),
    "bump": dict(SurfaceDetailTechnique="Bump Mapping",
                 SurfaceDetailHeightMap=CreateTexture(brick_height),
                 SurfaceDetailBumpScale=0.05),
    "parallax": dict(SurfaceDetailTechnique="Parallax Mapping",
                     SurfaceDetailDepthScale=0.03,
                     Texture=CreateTexture(os.path.join(data, "brick_color.png"))),
    "relief": dict(SurfaceDetailTechnique="Relief Mapping",
                   SurfaceDetailReliefMap=pipeline_texture(relief_map),
                   SurfaceDetailSelfShadowing=1),
    # Relief mapping by cone stepping: the same relief, with the heights' cone map.
    "relief-cones": dict(SurfaceDetailConeMap=pipeline_texture(cone_map)),
}
os.makedirs(output, exist_ok=True)
results = {}
for name, settings in scenes.items():
    # The scenes build on each other (parallax keeps the bump's height map and the normal map).
    for key, value in settings.items():
        setattr(display, key, value)
    if switched_off:
        display.SurfaceDetailTechnique = "Plain"
    candidate = os.path.join(output, "Representation_%s.png" % name)
    SaveScreenshot(candidate, view)
    if rank != 0:
        continue
    baseline = os.path.join(baselines, "Representation_%s.png" % name)
    if not os.path.exists(baseline):
        print("ImageNotFound: %s (the candidate is %s)" % (baseline, candidate))
        results[name] = 1.0
        continue
    results[name] = fraction_over(candidate, baseline)
    print("%s: %.4f of the pixels differ by more than %d levels" %
          (name, results[name], TOLERANCE))

# Triplanar mapping on an isosurface without texture coordinates or tangents: the brick
# colours and the pipeline normal map projected along the axes.
Hide(torus, view)
iso = Contour(Input=Wavelet(), ContourBy=["POINTS", "RTData"], Isosurfaces=[157.0],
              ComputeNormals=1)
iso_display = Show(iso, view)
ColorBy(iso_display, None)
iso_display.SetRepresentationType("Surface Detail")
iso_display.DiffuseColor = [1.0, 1.0, 1.0]
iso_display.SurfaceDetailTechnique = "Normal Mapping"
iso_display.SurfaceDetailNormalMap = pipeline_texture(normal_map)
iso_display.Texture = scenes["parallax"]["Texture"]
iso_display.SurfaceDetailTriplanar = 0 if switched_off else 1
iso_display.SurfaceDetailTriplanarScale = 0.1
view.CameraPosition = [30.0, 24.0, 40.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera()
GetActiveCamera().Dolly(1.5)
scenes["triplanar"] = {}
candidate = os.path.join(output, "Representation_triplanar.png")
SaveScreenshot(candidate, view)
if rank == 0:
    baseline = os.path.join(baselines, "Representation_triplanar.png")
    if not os.path.exists(baseline):
        print("ImageNotFound: %s (the candidate is %s)" % (baseline, candidate))
        results["triplanar"] = 1.0
    else:
        results["triplanar"] = fraction_over(candidate, baseline)
        print("triplanar: %.4f of the pixels differ by more than %d levels" %
              (results["triplanar"], TOLERANCE))

if rank == 0:
    failed = [name for name, over in results.items() if over > MAX_FRACTION_OVER]
    if switched_off:
        if failed == list(scenes):
            print("every technique switched off was caught")
        else:
            print("MISMATCH: switched off but passing: %s" %
                  sorted(set(scenes) - set(failed)))
    elif failed:
        print("MISMATCH: %s" % failed)
    else:
        print("every picture matches its baseline")
