# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The minification: a checkerboard floor running to the horizon, four ways side by side:
Nearest and Linear shimmer into moire far away, Mipmapped turns the distance grey too soon, and
Anisotropic keeps the checks sharp further out. (Examples/Cxx/Mipmapping.cxx draws the same.)

Usage: python3 Mipmapping.py [<output folder>]   (writes Mipmapping.png)
"""
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

import example_scene
from surfacedetail import vtkParametricRectangle, vtkParametricSurfaceSource

example_scene.answer_help(__doc__)

# The floor: 100 units wide, 400 deep, in y = 0; a 2-unit tile of 8 x 8 checks.
floor = vtkParametricRectangle()
floor.SetOrigin(-50, 0, 5)
floor.SetPoint1(50, 0, 5)
floor.SetPoint2(-50, 0, -395)
source = vtkParametricSurfaceSource()
source.SetParametricFunction(floor)
source.SetUResolution(8)
source.SetVResolution(32)
source.SetTextureRepeat(50, 200)

# Label, Interpolate, Mipmap, anisotropy (VTK's default is 4: the first three turn it off).
panels = (("Nearest", False, False, 1.0), ("Linear", True, False, 1.0),
          ("Mipmapped (trilinear)", True, True, 1.0), ("Anisotropic (16x)", True, True, 16.0))

window = example_scene.make_window(1000, 640)
for k, (label, interpolate, mipmap, anisotropy) in enumerate(panels):
    checks = example_scene.load_texture("checkerboard.png")
    checks.SetInterpolate(interpolate)
    checks.SetMipmap(mipmap)
    checks.SetMaximumAnisotropicFiltering(anisotropy)

    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetTexture(checks)
    actor.GetProperty().LightingOff()  # the texture as it is: only filtering differs

    renderer = vtkRenderer()
    x, y = (k % 2) * 0.5, 0.5 if k < 2 else 0.0
    renderer.SetViewport(x, y, x + 0.5, y + 0.5)
    renderer.SetBackground(0.55, 0.7, 0.9)
    renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 1.2, 4)
    camera.SetFocalPoint(0, -0.5, -6)
    camera.SetViewUp(0, 1, 0)
    camera.SetViewAngle(50)
    camera.SetClippingRange(0.1, 500)
    example_scene.add_label(renderer, label)
    window.AddRenderer(renderer)

sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "Mipmapping"))
