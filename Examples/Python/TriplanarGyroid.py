# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""Triplanar mapping on an isosurface: the sheets |f| = 0.4 of the gyroid
f = sin x cos y + sin y cos z + sin z cos x, made by vtkFlyingEdges3D (normals, no texture
coordinates, no tangents), with the brick colours and a brick normal map projected along the
three axes and blended by the normal. (Examples/Cxx/TriplanarGyroid.cxx draws the same.)

Usage: python3 TriplanarGyroid.py [<output folder>]   (writes TriplanarGyroid.png)
"""
import math
import os
import sys

from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkRenderingCore import vtkActor, vtkTexture

import example_scene
from surfacedetail import vtkHeightMapToNormalMap, vtkOIIOImageReader, vtkSurfaceDetailMapper

example_scene.answer_help(__doc__)

# The field sampled on 64^3 points over [-4, 4]^3.
n = 64
half = 4.0
step = 2 * half / (n - 1)
field = vtkImageData()
field.SetDimensions(n, n, n)
field.SetOrigin(-half, -half, -half)
field.SetSpacing(step, step, step)
values = vtkFloatArray()
values.SetName("Gyroid")
values.SetNumberOfTuples(n * n * n)
coordinates = [-half + i * step for i in range(n)]
sines = [math.sin(c) for c in coordinates]
cosines = [math.cos(c) for c in coordinates]
index = 0
for k in range(n):
    for j in range(n):
        for i in range(n):
            f = sines[i] * cosines[j] + sines[j] * cosines[k] + sines[k] * cosines[i]
            values.SetValue(index, abs(f))
            index += 1
field.GetPointData().SetScalars(values)
sheets = vtkFlyingEdges3D()
sheets.SetInputData(field)
sheets.SetValue(0, 0.4)
sheets.ComputeNormalsOn()

heights = vtkOIIOImageReader()
heights.SetFileName(os.path.join(example_scene.DATA_DIR, "brick_height.png"))
normals = vtkHeightMapToNormalMap()
normals.SetInputConnection(heights.GetOutputPort())
normals.SetBumpScale(0.04)
normal_map = vtkTexture()
normal_map.SetInputConnection(normals.GetOutputPort())
normal_map.InterpolateOn()
normal_map.RepeatOn()

mapper = vtkSurfaceDetailMapper()
mapper.SetInputConnection(sheets.GetOutputPort())
mapper.ScalarVisibilityOff()
mapper.SetTechniqueToNormalMapping()
mapper.SetNormalMap(normal_map)
mapper.TriplanarOn()
mapper.SetTriplanarScale(0.5)  # a texture square (eight courses of bricks) per 2 units
mapper.SetTriplanarSharpness(6)
actor = vtkActor()
actor.SetMapper(mapper)
actor.SetTexture(example_scene.load_texture("brick_color.png"))
actor.GetProperty().SetSpecular(0.15)
actor.GetProperty().SetSpecularPower(20)

window = example_scene.view_actor(actor, (11.4, 8.4, 15.0), (0, 0, 0), 38.0)
sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "TriplanarGyroid"))
