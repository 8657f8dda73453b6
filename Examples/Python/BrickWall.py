# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The brick wall: the rectangle x in [-2,2], y in [0,3.5] as one quad whose corners carry
texture coordinates (top-left, bottom-left, bottom-right, top-right, as classic OpenGL code
glTexCoord2f() calls), five ways: the picture whole; repeated (0..4 x 0..1.5); mirrored
repeat; a photo of the wall taken askew (the bricks turned by 12 degrees); and that photo
straightened by mapping only its slanted part that holds straight bricks. Unlit, as classic OpenGL code
GL_REPLACE. (Examples/Cxx/BrickWall.cxx draws the same.)

Usage: python3 BrickWall.py [<output folder>]   (writes BrickWall.png)
"""
import math
import sys

from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkImagingCore import vtkImageReslice
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkTexture

import example_scene

example_scene.answer_help(__doc__)

TILT_DEGREES = 12.0


def wall(st):
    corners = ((-2, 3.5, 0), (-2, 0, 0), (2, 0, 0), (2, 3.5, 0))
    points = vtkPoints()
    tcoords = vtkFloatArray()
    tcoords.SetName("TextureCoordinates")
    tcoords.SetNumberOfComponents(2)
    for corner, coordinates in zip(corners, st):
        points.InsertNextPoint(corner)
        tcoords.InsertNextTuple(coordinates)
    quads = vtkCellArray()
    quads.InsertNextCell(4, (0, 1, 2, 3))
    polydata = vtkPolyData()
    polydata.SetPoints(points)
    polydata.SetPolys(quads)
    polydata.GetPointData().SetTCoords(tcoords)
    return polydata


bricks = example_scene.load_texture("brick_color.png")
picture = bricks.GetInputConnection(0, 0)
mirrored = vtkTexture()
mirrored.SetInputConnection(picture)
mirrored.InterpolateOn()
mirrored.MipmapOn()
mirrored.SetWrap(vtkTexture.MirroredRepeat)

# The askew photo: each output texel x shows the wall at c + R(-tilt) (x - c), c the centre, so
# the bricks appear turned by +tilt; the wall continues past the picture's edges.
c = 255.5  # Data/brick_color.png is 512 x 512
turn = vtkTransform()
turn.Translate(c, c, 0)
turn.RotateZ(-TILT_DEGREES)
turn.Translate(-c, -c, 0)
askew = vtkImageReslice()
askew.SetInputConnection(picture)
askew.SetResliceTransform(turn)
askew.SetInterpolationModeToCubic()
askew.WrapOn()
photo = vtkTexture()
photo.SetInputConnection(askew.GetOutputPort())
photo.InterpolateOn()
photo.MipmapOn()

# The straight part [0.125, 0.875]^2 of the wall appears in the photo at 0.5 + R(tilt) (q - 0.5):
# those are the corners' texture coordinates.
a = math.radians(TILT_DEGREES)
part = ((0.125, 0.875), (0.125, 0.125), (0.875, 0.125), (0.875, 0.875))
straightened = [(0.5 + math.cos(a) * (x - 0.5) - math.sin(a) * (y - 0.5),
                 0.5 + math.sin(a) * (x - 0.5) + math.cos(a) * (y - 0.5)) for x, y in part]

whole = ((0, 1), (0, 0), (1, 0), (1, 1))
repeated = ((0, 1.5), (0, 0), (4, 0), (4, 1.5))
panels = (("Whole", whole, bricks), ("Repeated", repeated, bricks),
          ("Mirrored repeat", repeated, mirrored), ("Tilted photo", whole, photo),
          ("Straightened", straightened, photo))

window = example_scene.make_window(1500, 400)
for k, (label, st, texture) in enumerate(panels):
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(wall(st))
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetTexture(texture)
    actor.GetProperty().LightingOff()

    renderer = vtkRenderer()
    renderer.SetViewport(0.2 * k, 0, 0.2 * (k + 1), 1)
    renderer.SetBackground(0.18, 0.2, 0.24)
    renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetParallelScale(2.9)  # 4.35 units across: the wall and a margin
    camera.SetFocalPoint(0, 1.35, 0)
    camera.SetPosition(0, 1.35, 10)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCameraClippingRange()
    example_scene.add_label(renderer, label)
    window.AddRenderer(renderer)

sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "BrickWall"))
