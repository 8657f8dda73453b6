# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The donut, z up: P = ((R + r cos 2 pi v) cos 2 pi u, (R + r cos 2 pi v) sin 2 pi u,
r sin 2 pi v) with a checkerboard, dark square at (0,0); the checks stay square and meet across
both seams. (Examples/Cxx/Donut.cxx draws the same.)

Usage: python3 Donut.py [<output folder>]   (writes Donut.png)
"""
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

import example_scene
from surfacedetail import vtkParametricDonut, vtkParametricSurfaceSource

example_scene.answer_help(__doc__)

source = vtkParametricSurfaceSource()
source.SetParametricFunction(vtkParametricDonut())
source.SetUResolution(128)
source.SetVResolution(48)
source.SetTextureRepeat(5, 2)  # square checks: the ring is 2.5 times the tube

mapper = vtkPolyDataMapper()
mapper.SetInputConnection(source.GetOutputPort())
donut = vtkActor()
donut.SetMapper(mapper)
donut.SetTexture(example_scene.load_texture("checkerboard.png"))
donut.GetProperty().SetAmbient(0.3)
donut.GetProperty().SetDiffuse(0.8)
donut.RotateX(-90)  # the donut's z up becomes the scene's y up

window = example_scene.view_actor(donut, eye=(1.0, 2.2, 4.0), focus=(0, 0, 0))
sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "Donut"))
