# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""Bump mapping (Blinn 1978) on a torus: only the normals are tilted by the
slopes of a height map. Left: the plain torus; right: vtkSurfaceDetailMapper's BumpMapping with
a quilt of round bumps, lit from the upper right; the silhouette stays round.
(Examples/Cxx/BumpyTorus.cxx draws the same.)

Usage: python3 BumpyTorus.py [<output folder>]   (writes BumpyTorus.png)
"""
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkTexture

import example_scene
from surfacedetail import vtkParametricDonut, vtkParametricSurfaceSource, vtkSurfaceDetailMapper

example_scene.answer_help(__doc__)

source = vtkParametricSurfaceSource()
source.SetParametricFunction(vtkParametricDonut())
source.SetUResolution(128)
source.SetVResolution(48)
source.GenerateTangentsOn()  # the frame the height map's slopes are taken in

heights = vtkTexture()
heights.SetInputData(example_scene.quilt_heights(1024, 512, 24, 10))
heights.InterpolateOn()
heights.SetWrap(vtkTexture.Repeat)

window = example_scene.make_window(1200, 520)
for k, technique in enumerate((vtkSurfaceDetailMapper.Plain, vtkSurfaceDetailMapper.BumpMapping)):
    mapper = vtkSurfaceDetailMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.SetHeightMap(heights)
    mapper.SetTechnique(technique)
    mapper.SetBumpScale(0.004)  # the bumps of z = 0.004 h over the unit texture square
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.85, 0.62, 0.32)
    actor.GetProperty().SetAmbient(0.15)
    actor.GetProperty().SetDiffuse(0.85)
    actor.GetProperty().SetSpecular(0.3)
    actor.GetProperty().SetSpecularPower(30)
    actor.RotateX(-90)  # the donut's z up becomes the scene's y up

    renderer = vtkRenderer()
    renderer.SetViewport(0.5 * k, 0, 0.5 * (k + 1), 1)
    renderer.SetBackground(0.12, 0.13, 0.16)
    renderer.AddActor(actor)
    example_scene.add_key_light(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.8, 2.4, 3.6)
    camera.SetFocalPoint(0, -0.1, 0)
    camera.SetViewUp(0, 1, 0)
    camera.SetViewAngle(35)
    renderer.ResetCameraClippingRange()
    example_scene.add_label(renderer, mapper.GetTechniqueAsString())
    window.AddRenderer(renderer)

sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "BumpyTorus"))
