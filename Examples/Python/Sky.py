# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The sky: a panorama on the inside of a sphere around the camera. Seen from inside,
u (from +x towards -z) runs right to left, so the texture coordinates are mirrored,
s = 1 - u, for the panorama to read as painted; the sky is not lit. The panorama is drawn
here: ground and mountains below the horizon, a gradient, clouds and a sun above it.
(Examples/Cxx/Sky.cxx draws the same.)

Usage: python3 Sky.py [<output folder>]   (writes Sky.png)
"""
import math
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkTexture

import example_scene
from surfacedetail import vtkParametricSphere, vtkParametricSurfaceSource

example_scene.answer_help(__doc__)


def smooth_step(a, b, x):
    t = min(1.0, max(0.0, (x - a) / (b - a)))
    return t * t * (3 - 2 * t)


def panorama(width, height):
    """Equirectangular: s = longitude / 360 degrees, t = 0.5 + latitude / 180 degrees."""
    sun_lon, sun_lat = 200.0, 20.0
    horizon, zenith = (0.85, 0.90, 0.97), (0.18, 0.38, 0.78)
    pixels = bytearray(3 * width * height)
    for j in range(height):
        lat = -90.0 + 180.0 * (j + 0.5) / height
        for i in range(width):
            lon = 360.0 * (i + 0.5) / width
            a = lon * math.pi / 180.0
            ridge = (4.0 + 3.0 * math.sin(3 * a) + 2.0 * math.sin(7 * a + 1.3)
                     + math.sin(17 * a + 0.4))
            if lat < 0.0:
                f = 0.7 + 0.3 * (1.0 + lat / 90.0)  # darker towards the feet
                c = (0.28 * f, 0.50 * f, 0.22 * f)
            elif lat < ridge:
                snow = 1.0 if ridge > 7.0 and lat > ridge - 1.0 else 0.0
                c = (0.34 + 0.6 * snow, 0.37 + 0.57 * snow, 0.46 + 0.5 * snow)
            else:
                f = math.sqrt(lat / 90.0)
                d_lon = math.remainder(lon - sun_lon, 360.0) * math.cos(lat * math.pi / 180.0)
                d2 = d_lon * d_lon + (lat - sun_lat) * (lat - sun_lat)
                glow = 0.35 * math.exp(-d2 / 60.0)
                puff = math.sin(5 * a + 0.15 * lat) * math.sin(0.3 * lat + 2 * math.sin(3 * a))
                cloud = (smooth_step(0.45, 0.8, puff) * smooth_step(8.0, 14.0, lat)
                         * (1.0 - smooth_step(40.0, 55.0, lat)))
                c = tuple((1 - cloud) * ((1 - f) * horizon[k] + f * zenith[k] + glow) + cloud * 0.96
                          for k in range(3))
                if d2 < 9.0:
                    c = (1.0, 0.97, 0.85)
            k = 3 * (j * width + i)
            pixels[k:k + 3] = bytes(example_scene.to_byte(min(1.0, v)) for v in c)
    return example_scene.image_from_bytes(width, height, 3, pixels)


sphere = vtkParametricSphere()
sphere.SetRadius(50)
source = vtkParametricSurfaceSource()
source.SetParametricFunction(sphere)
source.SetUResolution(128)
source.SetVResolution(64)
source.SetTextureRepeat(-1, 1)
source.SetTextureOffset(1, 0)

texture = vtkTexture()
texture.SetInputData(panorama(1024, 512))
texture.InterpolateOn()
texture.MipmapOn()
texture.SetWrap(vtkTexture.ClampToEdge)

mapper = vtkPolyDataMapper()
mapper.SetInputConnection(source.GetOutputPort())
sky = vtkActor()
sky.SetMapper(mapper)
sky.SetTexture(texture)
sky.GetProperty().LightingOff()

# From the centre towards the sun: longitude 200 is at u = 1 - 200/360, a little upwards.
theta, pitch = 2 * math.pi * (1.0 - 200.0 / 360.0), 12.0 * math.pi / 180.0
focus = (math.cos(theta) * math.cos(pitch), math.sin(pitch), -math.sin(theta) * math.cos(pitch))
window = example_scene.view_actor(sky, eye=(0, 0, 0), focus=focus, view_angle=75.0)
sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "Sky"))
