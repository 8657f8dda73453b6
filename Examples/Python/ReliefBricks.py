# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""Relief mapping (Policarpo, Oliveira & Comba 2005) on the brick wall,
beside normal mapping with the same normals. Relief mapping marches each view ray through a
box 0.1 units deep under the flat wall: the bricks hide the joints behind them and, with
self-shadowing, shade the joints away from the light at the upper right.
(Examples/Cxx/ReliefBricks.cxx draws the same.)

Usage: python3 ReliefBricks.py [<output folder>]   (writes ReliefBricks.png)
"""
import os
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkRenderer, vtkTexture

import example_scene
from surfacedetail import (vtkHeightMapToNormalMap, vtkOIIOImageReader, vtkParametricRectangle,
                           vtkParametricSurfaceSource, vtkSurfaceDetailMapper)

example_scene.answer_help(__doc__)

source = vtkParametricSurfaceSource()
source.SetParametricFunction(vtkParametricRectangle())  # x in [-2,2], y in [0,3.5]
source.SetUResolution(8)
source.SetVResolution(8)
source.GenerateTangentsOn()  # the frame the relief map's normals are stored in

depth = 0.1  # the joints lie 0.1 units behind the bricks' faces
heights = vtkOIIOImageReader()
heights.SetFileName(os.path.join(example_scene.DATA_DIR, "brick_height.png"))
relief = vtkHeightMapToNormalMap()
relief.SetInputConnection(heights.GetOutputPort())
relief.SetBumpScale(depth / 3.75)  # the texture square is 4 x 3.5 units on the wall
relief.OutputReliefOn()
relief_map = vtkTexture()
relief_map.SetInputConnection(relief.GetOutputPort())
relief_map.InterpolateOn()
relief_map.RepeatOn()
colours = example_scene.load_texture("brick_color.png")

window = example_scene.make_window(1200, 560)
techniques = (vtkSurfaceDetailMapper.NormalMapping, vtkSurfaceDetailMapper.ReliefMapping)
for k, technique in enumerate(techniques):
    mapper = vtkSurfaceDetailMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.SetTechnique(technique)
    mapper.SetNormalMap(relief_map)  # its RGB is the normal map
    mapper.SetReliefMap(relief_map)
    mapper.SetDepthScale(depth)
    mapper.SelfShadowingOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetTexture(colours)
    actor.GetProperty().SetAmbient(0.12)
    actor.GetProperty().SetDiffuse(0.9)
    actor.GetProperty().SetSpecular(0.2)
    actor.GetProperty().SetSpecularPower(25)

    renderer = vtkRenderer()
    renderer.SetViewport(0.5 * k, 0, 0.5 * (k + 1), 1)
    renderer.SetBackground(0.16, 0.18, 0.22)
    renderer.AddActor(actor)
    renderer.AutomaticLightCreationOff()
    light = vtkLight()  # upper right, in front of the wall
    light.SetLightTypeToSceneLight()
    light.PositionalOn()
    light.SetConeAngle(180)
    light.SetPosition(5.0, 5.5, 3.0)
    light.SetFocalPoint(0, 1.75, 0)
    renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.2, 1.6, 0)
    camera.SetPosition(-3.2, 2.4, 3.4)
    camera.SetViewUp(0, 1, 0)
    camera.SetViewAngle(42)
    renderer.ResetCameraClippingRange()
    example_scene.add_label(renderer, "NormalMapping" if k == 0 else "ReliefMapping, SelfShadowing")
    window.AddRenderer(renderer)

sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "ReliefBricks"))
