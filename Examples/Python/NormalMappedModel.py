# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The point of normal maps: a detailed model and a coarse one with a normal map baked
from it look alike, at a fraction of the polygons. Left: a vase with a quilt of bumps displaced
into its geometry by vtkDisplacementMapFilter, VTK's plain mapper; right: the same vase at a
hundredth of the triangles with the normal map vtkNormalMapBaker bakes from the detailed one,
vtkSurfaceDetailMapper's NormalMapping. (Examples/Cxx/NormalMappedModel.cxx draws the same.)

Usage: python3 NormalMappedModel.py [<output folder>]   (writes NormalMappedModel.png)
"""
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkTexture

import example_scene
from surfacedetail import (vtkDisplacementMapFilter, vtkNormalMapBaker, vtkParametricRevolution,
                           vtkParametricSurfaceSource, vtkSurfaceDetailMapper)

example_scene.answer_help(__doc__)


def vase(u_resolution, v_resolution):
    source = vtkParametricSurfaceSource()
    source.SetParametricFunction(vtkParametricRevolution())
    source.SetUResolution(u_resolution)
    source.SetVResolution(v_resolution)
    source.GenerateTangentsOn()  # the frame the baked normals are stored in
    source.GenerateDerivativesOn()  # exact normals for the displaced surface
    source.Update()
    return source.GetOutput()


displace = vtkDisplacementMapFilter()
displace.SetInputData(vase(384, 256))
displace.SetInputData(1, example_scene.quilt_heights(768, 512, 24, 16))
displace.SetScaleFactor(0.03)
displace.SetMidlevel(0.0)
displace.SetInterpolationToLinear()
displace.SetNormalModeToExact()
displace.Update()
detailed = displace.GetOutput()
coarse = vase(48, 24)

baker = vtkNormalMapBaker()
baker.SetInputData(0, coarse)
baker.SetInputData(1, detailed)
baker.SetTextureSize(1024, 1024)
baker.SetMaxRayDistance(0.15)
normal_map = vtkTexture()
normal_map.SetInputConnection(baker.GetOutputPort())
normal_map.InterpolateOn()

plain = vtkPolyDataMapper()
plain.SetInputData(detailed)
mapped = vtkSurfaceDetailMapper()
mapped.SetInputData(coarse)
mapped.SetNormalMap(normal_map)
mapped.SetTechniqueToNormalMapping()

window = example_scene.make_window(1000, 560)
for k, (mapper, mesh) in enumerate(((plain, detailed), (mapped, coarse))):
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.78, 0.74, 0.66)
    actor.GetProperty().SetAmbient(0.12)
    actor.GetProperty().SetDiffuse(0.88)
    actor.GetProperty().SetSpecular(0.25)
    actor.GetProperty().SetSpecularPower(30)
    renderer = vtkRenderer()
    renderer.SetViewport(0.5 * k, 0, 0.5 * (k + 1), 1)
    renderer.SetBackground(0.12, 0.13, 0.16)
    renderer.AddActor(actor)
    example_scene.add_key_light(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 1.0, 0)  # the vase stands on y = 0 and is 2 tall
    camera.SetPosition(0, 1.9, 4.6)
    camera.SetViewUp(0, 1, 0)
    camera.SetViewAngle(32)
    renderer.ResetCameraClippingRange()
    triangles = "%d triangles" % mesh.GetNumberOfCells()
    example_scene.add_label(
        renderer, ("detailed, " if k == 0 else "coarse + baked normal map, ") + triangles)
    window.AddRenderer(renderer)

sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "NormalMappedModel"))
