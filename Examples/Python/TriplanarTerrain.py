# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""Terrain without texture coordinates: a flat grid displaced by a height map with
vtkDisplacementMapFilter's triplanar sampling, its normals from the displaced mesh, drawn with
triplanar marble colours and bump mapping, so the cliffs keep their grain.
(Examples/Cxx/TriplanarTerrain.cxx draws the same.)

Usage: python3 TriplanarTerrain.py [<output folder>]   (writes TriplanarTerrain.png)
"""
import os
import sys

from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkTexture

import example_scene
from surfacedetail import vtkDisplacementMapFilter, vtkOIIOImageReader, vtkSurfaceDetailMapper

example_scene.answer_help(__doc__)

# A 256 x 256 quad grid over [-2, 2]^2 at z = 0, facing +z.
cells = 256
points = vtkPoints()
up = vtkFloatArray()
up.SetName("Normals")
up.SetNumberOfComponents(3)
for j in range(cells + 1):
    for i in range(cells + 1):
        points.InsertNextPoint(-2.0 + 4.0 * i / cells, -2.0 + 4.0 * j / cells, 0.0)
        up.InsertNextTuple3(0, 0, 1)
quads = vtkCellArray()
for j in range(cells):
    for i in range(cells):
        a = j * (cells + 1) + i
        quads.InsertNextCell(4, (a, a + 1, a + cells + 2, a + cells + 1))
grid = vtkPolyData()
grid.SetPoints(points)
grid.SetPolys(quads)
grid.GetPointData().SetNormals(up)

heights = vtkOIIOImageReader()
heights.SetFileName(os.path.join(example_scene.DATA_DIR, "noise_height.png"))
terrain = vtkDisplacementMapFilter()
terrain.SetInputData(grid)
terrain.SetSourceConnection(heights.GetOutputPort())
terrain.SetWrapToRepeat()
terrain.SetInterpolationToCubic()
terrain.TriplanarOn()
terrain.SetTriplanarScale(0.25)  # the whole map across the grid
terrain.SetScaleFactor(0.8)
terrain.SetMidlevel(0.5)
terrain.SetNormalModeToMesh()

bumps = vtkTexture()
bumps.SetInputConnection(heights.GetOutputPort())
bumps.InterpolateOn()
bumps.RepeatOn()
mapper = vtkSurfaceDetailMapper()
mapper.SetInputConnection(terrain.GetOutputPort())
mapper.SetTechniqueToBumpMapping()
mapper.SetHeightMap(bumps)
mapper.SetBumpScale(0.15)
mapper.TriplanarOn()
mapper.SetTriplanarScale(1.5)
actor = vtkActor()
actor.SetMapper(mapper)
actor.SetTexture(example_scene.load_texture("marble.png"))
actor.GetProperty().SetAmbient(0.15)
actor.GetProperty().SetDiffuse(0.85)
actor.RotateX(-90)  # z up in the data, y up on the screen

window = example_scene.view_actor(actor, (3.9, 3.1, 4.4), (0, -0.2, 0), 40.0)
sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "TriplanarTerrain"))
