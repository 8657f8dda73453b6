# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""What the gallery's Python examples share: textures from Data/, the key light, panel labels,
and the picture written to <folder>/<name>.png. Examples/Cxx/ExampleScene.h is the same for
the C++ programs, and each script draws the same picture as its C++ twin (they share a
baseline in the tests). Windows have a fixed size and no multisampling, so that a picture is
the same on every run.
"""
import math
import os
import sys

# The OpenGL render window, mappers and text rendering are factory overrides: importing
# these modules registers them.
import vtkmodules.vtkRenderingFreeType  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkCommonCore import VTK_UNSIGNED_CHAR
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkImageImport, vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkLight, vtkRenderer, vtkRenderWindow, vtkTextActor,
                                         vtkTexture, vtkWindowToImageFilter)

DATA_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir, "Data")


def answer_help(usage):
    """Prints the script's usage (its docstring) and exits, writing nothing, when the arguments
    ask for help (--help or -h)."""
    if any(a in ("--help", "-h") for a in sys.argv[1:]):
        print(usage.strip())
        sys.exit(0)


def output_folder():
    """The folder to write into: the last argument that is not an option, or '.'."""
    folders = [a for a in sys.argv[1:] if not a.startswith("--")]
    return folders[-1] if folders else "."


def load_texture(name):
    """A texture from Data/ (see Data/README.md): linear, mipmapped, repeating."""
    path = os.path.join(DATA_DIR, name)
    reader = vtkPNGReader()
    if not reader.CanReadFile(path):
        sys.exit("cannot read " + path)
    reader.SetFileName(path)
    texture = vtkTexture()
    texture.SetInputConnection(reader.GetOutputPort())
    texture.InterpolateOn()
    texture.MipmapOn()
    texture.SetWrap(vtkTexture.Repeat)
    return texture


def image_from_bytes(width, height, components, pixels):
    """A vtkImageData of unsigned chars from a bytes-like object, row 0 at the bottom."""
    importer = vtkImageImport()
    importer.CopyImportVoidPointer(bytes(pixels), len(pixels))
    importer.SetDataScalarType(VTK_UNSIGNED_CHAR)
    importer.SetNumberOfScalarComponents(components)
    importer.SetWholeExtent(0, width - 1, 0, height - 1, 0, 0)
    importer.SetDataExtentToWholeExtent()
    importer.Update()
    # The importer's output points into the importer's own buffer: copy it before the
    # importer goes away.
    image = vtkImageData()
    image.DeepCopy(importer.GetOutput())
    return image


def to_byte(value):
    """value in [0, 1] to 0..255, rounded half away from zero as C++'s std::lround."""
    return int(math.floor(255.0 * value + 0.5))


def quilt_heights(width, height, across, up):
    """A height map of round bumps, `across` by `up` of them over the texture square:
    h = (sin(pi across s) sin(pi up t))^2. It tiles."""
    rows = [math.sin(math.pi * up * (j + 0.5) / height) for j in range(height)]
    cols = [math.sin(math.pi * across * (i + 0.5) / width) for i in range(width)]
    pixels = bytearray(width * height)
    for j, r in enumerate(rows):
        base = j * width
        for i, c in enumerate(cols):
            b = c * r
            pixels[base + i] = to_byte(b * b)
    return image_from_bytes(width, height, 1, pixels)


def add_key_light(renderer):
    """The key light: from the upper right and in front, wherever the camera looks from."""
    renderer.AutomaticLightCreationOff()
    key = vtkLight()
    key.SetLightTypeToCameraLight()
    key.SetPosition(1.0, 0.7, 1.0)
    key.SetFocalPoint(0, 0, 0)
    renderer.AddLight(key)


def add_label(renderer, text):
    """A caption in the lower left corner of the renderer's viewport, on a dark box."""
    label = vtkTextActor()
    label.SetInput(text)
    label.GetTextProperty().SetFontSize(20)
    label.GetTextProperty().SetColor(0.92, 0.92, 0.92)
    label.GetTextProperty().SetBackgroundColor(0.05, 0.05, 0.05)
    label.GetTextProperty().SetBackgroundOpacity(0.7)
    label.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    label.GetPositionCoordinate().SetValue(0.03, 0.03)
    renderer.AddViewProp(label)


def make_window(width, height):
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    return window


def view_actor(actor, eye, focus, view_angle=30.0):
    """An 800 x 600 window showing actor, lit by the key light, seen from eye, +y up."""
    renderer = vtkRenderer()
    renderer.AddViewProp(actor)
    renderer.SetBackground(0.12, 0.13, 0.16)
    add_key_light(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*eye)
    camera.SetFocalPoint(*focus)
    camera.SetViewUp(0, 1, 0)
    camera.SetViewAngle(view_angle)
    renderer.ResetCameraClippingRange()
    window = make_window(800, 600)
    window.AddRenderer(renderer)
    return window


def write_picture(window, folder, name):
    """Renders the window and writes <folder>/<name>.png; returns the exit status."""
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    path = os.path.join(folder, name + ".png")
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    if writer.GetErrorCode() != 0:
        print("cannot write " + path, file=sys.stderr)
        return 1
    print("wrote " + path)
    return 0
