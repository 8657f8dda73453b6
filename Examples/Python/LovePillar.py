# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The love pillar: a heart-shaped Bezier profile in x-z extruded up +y by
vtkParametricExtrusion, u along the profile (by arc length) and v up.
(Examples/Cxx/LovePillar.cxx draws the same.)

Usage: python3 LovePillar.py [<output folder>]   (writes LovePillar.png)
"""
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

import example_scene
from surfacedetail import vtkParametricExtrusion, vtkParametricSurfaceSource

example_scene.answer_help(__doc__)

pillar = vtkParametricExtrusion()  # the default profile is the heart, height 2
pillar.GetProfile().ArcLengthParameterizationOn()
source = vtkParametricSurfaceSource()
source.SetParametricFunction(pillar)
source.SetUResolution(256)
source.SetVResolution(8)
source.SetTextureRepeat(3, 1)

mapper = vtkPolyDataMapper()
mapper.SetInputConnection(source.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
actor.SetTexture(example_scene.load_texture("test_card.png"))
actor.GetProperty().SetAmbient(0.3)
actor.GetProperty().SetDiffuse(0.8)

# From the tip of the heart (+z), a little above.
window = example_scene.view_actor(actor, eye=(2.5, 3.5, 5.5), focus=(0, 1, 0))
sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "LovePillar"))
