# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The marble vase: a Bezier profile (radius, height) turned about +y by
vtkParametricRevolution, in Data/marble.png (procedural marble), spread by arc length along the
profile. (Examples/Cxx/MarbleVase.cxx draws the same.)

Usage: python3 MarbleVase.py [<output folder>]   (writes MarbleVase.png)
"""
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

import example_scene
from surfacedetail import vtkParametricRevolution, vtkParametricSurfaceSource

example_scene.answer_help(__doc__)

vase = vtkParametricRevolution()  # the default profile is the vase
vase.GetProfile().ArcLengthParameterizationOn()
source = vtkParametricSurfaceSource()
source.SetParametricFunction(vase)
source.SetUResolution(128)
source.SetVResolution(96)
source.SetTextureRepeat(3, 1)

mapper = vtkPolyDataMapper()
mapper.SetInputConnection(source.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
actor.SetTexture(example_scene.load_texture("marble.png"))
actor.GetProperty().SetAmbient(0.3)
actor.GetProperty().SetDiffuse(0.8)
actor.GetProperty().SetSpecular(0.2)

window = example_scene.view_actor(actor, eye=(4.5, 3.0, 4.5), focus=(0, 0.95, 0))
sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "MarbleVase"))
