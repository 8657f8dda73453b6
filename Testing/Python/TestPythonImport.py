# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""`import surfacedetail` from the Python that VTK's own modules are built for, and every
class working with VTK's Python objects.

Usage: python3 TestPythonImport.py <source-dir> [<expected-package-folder>]
The optional folder is where the package must have been found (the build tree's or an
install prefix's site-packages), so that a test of the install tree cannot pass on the
build tree's copy.
"""
import os
import re
import sys
import tempfile

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAILED: " + what)


source_dir = sys.argv[1]
import surfacedetail  # noqa: E402

if len(sys.argv) > 2:
    expected = os.path.realpath(sys.argv[2])
    found = os.path.realpath(os.path.dirname(surfacedetail.__file__))
    check(found.startswith(expected + os.sep),
          "surfacedetail came from %s, not from under %s" % (found, expected))

from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus  # noqa: E402
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkObjectBase  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkTriangleFilter  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkTexturedSphereSource  # noqa: E402
from vtkmodules.vtkIOImage import vtkImageReader2Factory, vtkPNGReader  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkTexture  # noqa: E402
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLPolyDataMapper  # noqa: E402

# Every exported class of every module, found in the headers rather than listed here, so
# that a class added to a module and left out of the wrapping fails this test.
declared = set()
for root, _, files in os.walk(os.path.join(source_dir, "Module")):
    for name in files:
        if name.endswith(".h"):
            with open(os.path.join(root, name), encoding="utf-8") as header:
                declared.update(re.findall(r"^class\s+\w+_EXPORT\s+(vtk\w+)", header.read(),
                                           re.MULTILINE))
check(len(declared) >= 16, "only %d exported classes found in Module/" % len(declared))
abstract = []
for name in sorted(declared):
    cls = getattr(surfacedetail, name, None)
    check(cls is not None, "surfacedetail has no " + name)
    if cls is None:
        continue
    check(issubclass(cls, vtkObjectBase), name + " is not a vtkObjectBase")
    try:
        obj = cls()
    except TypeError:
        abstract.append(cls)  # abstract in C++: checked through a subclass below
        continue
    check(obj.GetClassName() == name and obj.IsA(name), name + "() is not a " + name)
for cls in abstract:
    concrete = [getattr(surfacedetail, n) for n in declared
                if hasattr(surfacedetail, n) and getattr(surfacedetail, n) is not cls
                and issubclass(getattr(surfacedetail, n), cls)]
    check(len(concrete) > 0, "abstract " + cls.__name__ + " has no wrapped subclass")

# VTK's own parametric function through our source, into VTK's filters.
source = surfacedetail.vtkParametricSurfaceSource()
source.SetParametricFunction(vtkParametricTorus())
source.SetUResolution(16)
source.SetVResolution(8)
source.GenerateTangentsOn()
triangles = vtkTriangleFilter()
triangles.SetInputConnection(source.GetOutputPort())
triangles.Update()
torus = source.GetOutput()
check(isinstance(torus, vtkPolyData), "the source's output is not a vtkPolyData")
check(torus.GetNumberOfPoints() == 17 * 9, "the torus has %d points, not 17 x 9"
      % torus.GetNumberOfPoints())
tangents = torus.GetPointData().GetTangents()
check(tangents is not None and tangents.GetNumberOfComponents() == 3,
      "the torus has no 3-component TANGENTS attribute")
handedness = surfacedetail.vtkSurfaceDetailTangents.GetHandedness(torus.GetPointData())
check(handedness is not None and handedness.GetName() == "TangentHandedness",
      "the torus has no TangentHandedness array")
check(tangents.GetInformation().Get(surfacedetail.vtkSurfaceDetailTangents.WITH_HANDEDNESS())
      == 1, "the torus's tangents are not marked WITH_HANDEDNESS")
check(triangles.GetOutput().GetNumberOfCells() == torus.GetNumberOfCells(),
      "VTK's vtkTriangleFilter did not take the source's triangles")

# Displacement by a height map made with VTK's vtkImageData: a constant height of 1 moves
# the unit sphere out to radius 1 + Scale.
sphere = surfacedetail.vtkParametricSurfaceSource()
sphere.SetParametricFunction(surfacedetail.vtkParametricSphere())
heights = vtkImageData()
heights.SetDimensions(8, 4, 1)
ones = vtkFloatArray()
ones.SetNumberOfTuples(32)
ones.Fill(1.0)
heights.GetPointData().SetScalars(ones)
displace = surfacedetail.vtkDisplacementMapFilter()
displace.SetInputConnection(0, sphere.GetOutputPort())
displace.SetInputData(1, heights)
displace.SetScaleFactor(0.25)
displace.SetMidlevel(0.0)
displace.SetNormalModeToExact()
check(displace.GetNormalMode() == surfacedetail.vtkDisplacementMapFilter.Exact,
      "SetNormalModeToExact() did not set Exact")
displace.Update()
moved = displace.GetOutput().GetPoints()
radii = [sum(c * c for c in moved.GetPoint(i)) ** 0.5 for i in range(moved.GetNumberOfPoints())]
check(len(radii) > 0 and max(abs(r - 1.25) for r in radii) < 1e-5,
      "a constant height 1 with Scale 0.25 did not give radius 1.25")

# A flat height map gives the flat normal (0, 0, 1): encoded (128, 128, 255).
to_normals = surfacedetail.vtkHeightMapToNormalMap()
to_normals.SetInputData(heights)
to_normals.SetOutputScalarTypeToUnsignedChar()
to_normals.Update()
rgb = to_normals.GetOutput().GetPointData().GetScalars()
check(rgb.GetNumberOfComponents() == 3, "the normal map is not RGB")
check(all(abs(rgb.GetComponent(i, 0) - 127.5) <= 0.5 and abs(rgb.GetComponent(i, 1) - 127.5) <= 0.5
          and rgb.GetComponent(i, 2) == 255 for i in range(rgb.GetNumberOfTuples())),
      "a flat height map did not give the flat normal")

# A flat height map at the top: every apex at depth 0, and the widest cone (MaxConeRatio) where
# nothing rises above it; the mapper takes the map as its cone map.
to_cones = surfacedetail.vtkHeightMapToConeMap()
to_cones.SetInputData(heights)
to_cones.SetMaxConeRatio(0.5)
to_cones.Update()
cones = to_cones.GetOutput().GetPointData().GetArray("ConeMap")
check(cones is not None and cones.GetNumberOfComponents() == 2, "no 2-component ConeMap array")
check(all(cones.GetComponent(i, 0) == 0.0 and cones.GetComponent(i, 1) == 0.5
          for i in range(cones.GetNumberOfTuples())),
      "a flat height map at the top did not give apex 0 and the widest cone")
check(to_cones.GetConeTypeAsString() == "Relaxed", "the cones are not relaxed by default")
to_cones.SetConeTypeToConservative()
to_cones.Update()
cones = to_cones.GetOutput().GetPointData().GetArray("ConeMap")
check(all(cones.GetComponent(i, 1) == 0.5 for i in range(cones.GetNumberOfTuples())),
      "conservative cones over a flat map at the top are not the widest")
cone_texture = vtkTexture()
cone_texture.SetInputConnection(to_cones.GetOutputPort())
relief_mapper = surfacedetail.vtkSurfaceDetailMapper()
relief_mapper.SetConeMap(cone_texture)
check(relief_mapper.GetConeMap() is cone_texture, "SetConeMap did not keep the texture")

# The Bezier profile's output arguments are filled in Python lists.
profile = surfacedetail.vtkBezierProfile()
profile.RemoveAllControlPoints()
for x, y in ((0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0)):
    profile.AddControlPoint(x, y)
point, d1, d2 = [9.0, 9.0], [9.0, 9.0], [9.0, 9.0]
profile.Evaluate(0.5, point, d1, d2)
check(abs(point[0] - 1.5) < 1e-12 and abs(point[1]) < 1e-12,
      "vtkBezierProfile.Evaluate(0.5) gave %s, not (1.5, 0)" % point)
check(abs(profile.GetLength() - 3.0) < 1e-9, "the straight profile is not 3 long")

# MikkTSpace tangents on VTK's own textured sphere.
textured = vtkTexturedSphereSource()
mikk = surfacedetail.vtkMikkTSpaceTangents()
mikk.SetInputConnection(textured.GetOutputPort())
mikk.Update()
frames = mikk.GetOutput().GetPointData()
check(frames.GetTangents() is not None and frames.GetArray("TangentHandedness") is not None,
      "vtkMikkTSpaceTangents gave no tangent frame on vtkTexturedSphereSource")

# The OpenImageIO reader and writer beside VTK's PNG reader.
reader = surfacedetail.vtkOIIOImageReader()
reader.SetFileName(os.path.join(source_dir, "Data", "test_card.png"))
reader.Update()
check(reader.GetOutput().GetDimensions() == (512, 512, 1), "the test card is not 512 x 512")
with tempfile.TemporaryDirectory() as scratch:
    path = os.path.join(scratch, "card.png")
    writer = surfacedetail.vtkOIIOImageWriter()
    writer.SetInputConnection(reader.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    check(png.GetOutput().GetDimensions() == (512, 512, 1)
          and png.GetOutput().GetPointData().GetScalars().GetComponent(0, 0)
          == reader.GetOutput().GetPointData().GetScalars().GetComponent(0, 0),
          "VTK's PNG reader did not read back what vtkOIIOImageWriter wrote")
    # Importing the package registers the reader with VTK's factory, which has no OpenEXR
    # reader of its own.
    exr = os.path.join(scratch, "card.exr")
    writer.SetFileName(exr)
    writer.Write()
    found = vtkImageReader2Factory.CreateImageReader2(exr)
    check(found is not None and found.IsA("vtkOIIOImageReader"),
          "vtkImageReader2Factory did not hand out vtkOIIOImageReader for an .exr")

# The mapper is one of VTK's OpenGL mappers and takes VTK's textures and actors.
mapper = surfacedetail.vtkSurfaceDetailMapper()
check(isinstance(mapper, vtkOpenGLPolyDataMapper), "the mapper is not a vtkOpenGLPolyDataMapper")
mapper.SetInputConnection(source.GetOutputPort())
normal_map = vtkTexture()
mapper.SetNormalMap(normal_map)
mapper.SetTechniqueToBumpMapping()
check(mapper.GetTechnique() == surfacedetail.vtkSurfaceDetailMapper.BumpMapping,
      "SetTechniqueToBumpMapping() did not set BumpMapping")
actor = vtkActor()
actor.SetMapper(mapper)
check(actor.GetMapper() is mapper, "vtkActor did not keep the mapper")

# The composite mapper takes its technique from a vtkSurfaceDetailMapper it holds or shares.
composite = surfacedetail.vtkCompositeSurfaceDetailMapper()
check(composite.IsA("vtkCompositePolyDataMapper2"),
      "the composite mapper is not a vtkCompositePolyDataMapper2")
composite.SetDetail(mapper)
check(composite.GetDetail() is mapper, "SetDetail did not share the settings")
check(composite.GetDetail().GetTechnique() == surfacedetail.vtkSurfaceDetailMapper.BumpMapping,
      "the shared settings lost the technique")

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("surfacedetail: %d classes, all checks passed" % len(declared))
