# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The cylinder, a paper lantern: the picture wrapped round vtkParametricCylinder as
paper is, u round (from +x towards -z) and v up; it reads left to right and upright from
outside, with no seam where u = 0 meets u = 1. (Examples/Cxx/Lantern.cxx draws the same.)

Usage: python3 Lantern.py [<output folder>]   (writes Lantern.png)
"""
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

import example_scene
from surfacedetail import vtkParametricCylinder, vtkParametricSurfaceSource

example_scene.answer_help(__doc__)

source = vtkParametricSurfaceSource()
source.SetParametricFunction(vtkParametricCylinder())  # radius 1, height 2
source.SetUResolution(96)
source.SetVResolution(4)
source.SetTextureRepeat(2, 1)  # the card twice round

mapper = vtkPolyDataMapper()
mapper.SetInputConnection(source.GetOutputPort())
lantern = vtkActor()
lantern.SetMapper(mapper)
lantern.SetTexture(example_scene.load_texture("test_card.png"))
lantern.GetProperty().SetAmbient(0.3)
lantern.GetProperty().SetDiffuse(0.8)

window = example_scene.view_actor(lantern, eye=(5.0, 2.5, 3.0), focus=(0, 1, 0))
sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "Lantern"))
