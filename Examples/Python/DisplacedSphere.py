# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""Displacement mapping, p* = p + d(u,v) n, on a sphere: the points move (the
silhouette is bumpy), and vtkDisplacementMapFilter's four NormalModes shade the moved surface
side by side: Input keeps the sphere's normals, Approximate is the textbook formula, Exact adds the
change of the normal, Mesh averages the displaced triangles' normals.
(Examples/Cxx/DisplacedSphere.cxx draws the same.)

Usage: python3 DisplacedSphere.py [<output folder>]   (writes DisplacedSphere.png)
"""
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

import example_scene
from surfacedetail import vtkDisplacementMapFilter, vtkParametricSphere, vtkParametricSurfaceSource

example_scene.answer_help(__doc__)

source = vtkParametricSurfaceSource()
source.SetParametricFunction(vtkParametricSphere())
source.SetUResolution(192)
source.SetVResolution(96)
source.GenerateDerivativesOn()  # dPdu, dPdv, dNdu, dNdv for the Exact normals

heights = example_scene.quilt_heights(512, 256, 16, 8)
modes = (("Input", vtkDisplacementMapFilter.Input),
         ("Approximate", vtkDisplacementMapFilter.Approximate),
         ("Exact", vtkDisplacementMapFilter.Exact), ("Mesh", vtkDisplacementMapFilter.Mesh))

window = example_scene.make_window(1600, 460)
for k, (name, mode) in enumerate(modes):
    displace = vtkDisplacementMapFilter()
    displace.SetInputConnection(0, source.GetOutputPort())
    displace.SetInputData(1, heights)
    displace.SetScaleFactor(0.12)
    displace.SetMidlevel(0.0)
    displace.SetWrapToRepeat()
    displace.SetInterpolationToCubic()
    displace.SetNormalMode(mode)

    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(displace.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.55, 0.7, 0.85)
    actor.GetProperty().SetAmbient(0.12)
    actor.GetProperty().SetDiffuse(0.85)
    actor.GetProperty().SetSpecular(0.3)
    actor.GetProperty().SetSpecularPower(30)
    actor.GetProperty().SetInterpolationToPhong()

    renderer = vtkRenderer()
    renderer.SetViewport(0.25 * k, 0, 0.25 * (k + 1), 1)
    renderer.SetBackground(0.12, 0.13, 0.16)
    renderer.AddActor(actor)
    example_scene.add_key_light(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 1.5, 4.6)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewUp(0, 1, 0)
    camera.SetViewAngle(36)
    renderer.ResetCameraClippingRange()
    example_scene.add_label(renderer, name)
    window.AddRenderer(renderer)

sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "DisplacedSphere"))
