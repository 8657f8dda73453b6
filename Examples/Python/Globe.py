# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""The Earth: an equirectangular map on vtkParametricSphere, north pole at the top of the
image, longitude 0 (s = 0.5) on -x. The map is Debian's xplanet-images earth.jpg; where it is
missing, or with --procedural-map, a map drawn here (continents as ellipses, ice caps, a
30-degree graticule). (Examples/Cxx/Globe.cxx draws the same.)

Usage: python3 Globe.py [--procedural-map] [<output folder>]   (writes Globe.png)
"""
import math
import os
import sys

from vtkmodules.vtkIOImage import vtkJPEGReader
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkTexture

import example_scene
from surfacedetail import vtkParametricSphere, vtkParametricSurfaceSource

example_scene.answer_help(__doc__)

EARTH_MAP = "/usr/share/xplanet/images/earth.jpg"

# Longitude, latitude of the centre and the half-widths, in degrees.
CONTINENTS = ((-100, 45, 35, 20), (-60, -15, 15, 28), (15, 52, 20, 10), (20, 5, 20, 32),
              (95, 50, 45, 20), (135, -25, 17, 10))


def procedural_earth(width, height):
    pixels = bytearray(3 * width * height)
    for j in range(height):
        lat = -90.0 + 180.0 * (j + 0.5) / height  # row 0 is the south pole
        for i in range(width):
            lon = -180.0 + 360.0 * (i + 0.5) / width
            c = (0.10, 0.25, 0.55)
            for e in CONTINENTS:
                x, y = (lon - e[0]) / e[2], (lat - e[1]) / e[3]
                if x * x + y * y < 1.0:
                    c = (0.30, 0.45 if lat > 45 else 0.55, 0.22)
            if lat > 78 or lat < -70:
                c = (0.95, 0.95, 0.95)
            if abs(math.remainder(lon, 30.0)) < 0.4 or abs(math.remainder(lat, 30.0)) < 0.4:
                c = tuple(0.5 * v + 0.5 for v in c)
            k = 3 * (j * width + i)
            pixels[k:k + 3] = bytes(example_scene.to_byte(v) for v in c)
    return example_scene.image_from_bytes(width, height, 3, pixels)


texture = vtkTexture()
if "--procedural-map" not in sys.argv[1:] and os.path.exists(EARTH_MAP):
    reader = vtkJPEGReader()
    reader.SetFileName(EARTH_MAP)
    texture.SetInputConnection(reader.GetOutputPort())
else:
    if "--procedural-map" not in sys.argv[1:]:
        print(EARTH_MAP + " is missing (Debian: xplanet-images); using a procedural map")
    texture.SetInputData(procedural_earth(1024, 512))
texture.InterpolateOn()
texture.MipmapOn()
# Not Repeat: at the poles, t = 1 would blend in the south pole's row. The map's left and
# right columns are neighbours on the globe, so clamping leaves no visible seam either.
texture.SetWrap(vtkTexture.ClampToEdge)

source = vtkParametricSurfaceSource()
source.SetParametricFunction(vtkParametricSphere())
source.SetUResolution(128)
source.SetVResolution(64)

mapper = vtkPolyDataMapper()
mapper.SetInputConnection(source.GetOutputPort())
globe = vtkActor()
globe.SetMapper(mapper)
globe.SetTexture(texture)
globe.GetProperty().SetAmbient(0.25)
globe.GetProperty().SetDiffuse(0.85)

# Longitude 0 faces -x and east is +z: from there, a little north and west, Europe and Africa
# face the camera with the seam (longitude 180) behind the globe.
window = example_scene.view_actor(globe, eye=(-4.0, 1.6, -1.2), focus=(0, 0, 0))
sys.exit(example_scene.write_picture(window, example_scene.output_folder(), "Globe"))
