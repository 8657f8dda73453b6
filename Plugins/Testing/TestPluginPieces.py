# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
"""A displaced torus with MikkTSpace tangents, made by the plugin under pvbatch.

`pvbatch TestPluginPieces.py <plugin> write <file.pvtp>` (one rank) writes the whole surface;
`mpiexec -n N pvbatch TestPluginPieces.py <plugin> compare <file.pvtp>` makes it one piece per
rank, writes the pieces beside it and compares them on rank 0 with that file: the same number
of cells and the same bounds, and at every point (matched by its texture coordinates, which are
unique on the surface) the same position, normal, tangent and handedness. A point that two
pieces share must agree in both (no crack). `pvbatch TestPluginPieces.py <plugin> reference
<file.pvtp> <cxx.vtp>` compares the same way the C++ filters' surface with the plugin's."""
import sys

from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkIOXML import vtkXMLPPolyDataReader
from vtkmodules.vtkParallelCore import vtkMultiProcessController

plugin, mode, path = sys.argv[1:4]
if mode == "reference":
    # The plugin's serial surface against the C++ filters' own (PluginReferenceSurface).
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    reference = vtkXMLPolyDataReader()
    reference.SetFileName(sys.argv[4])
    reference.Update()
LoadPlugin(plugin, remote=False, ns=globals())

surface = ParametricSurface(ParametricFunction="Donut")
surface.UResolution = 60
surface.VResolution = 31
surface.GenerateTangents = 1
heights = Wavelet(WholeExtent=[0, 63, 0, 31, 0, 0])
displaced = DisplacementMap(Input=surface, Source=heights, SelectInputScalars=["POINTS", "RTData"])
displaced.ScaleFactor = 0.002
displaced.Midlevel = 100.0
tangents = MikkTSpaceTangents(Input=displaced)
# Each rank writes its piece (the parallel XML writer keeps the TANGENTS attribute; moving
# data objects between processes, as Fetch does, goes through VTK's legacy format, which drops
# it). ASCII: this VTK 9.2 could not read back its own appended binary file of this surface.
controller = vtkMultiProcessController.GetGlobalController()
pieces = path.replace(".pvtp", "-%d-ranks.pvtp" % controller.GetNumberOfProcesses())
if mode != "reference":
    SaveData(path if mode == "write" else pieces, proxy=tangents, DataMode="Ascii")
if controller.GetLocalProcessId() != 0:
    sys.exit(0)
if mode == "write":
    print("serial surface written")
    sys.exit(0)


def read(name):
    reader = vtkXMLPPolyDataReader()
    reader.SetFileName(name)
    reader.Update()
    return reader.GetOutput()


serial = read(path)
gathered = reference.GetOutput() if mode == "reference" else read(pieces)


def values(poly, i):
    pd = poly.GetPointData()
    return (list(poly.GetPoint(i)) + list(pd.GetNormals().GetTuple3(i))
            + list(pd.GetTangents().GetTuple3(i))
            + [pd.GetArray("TangentHandedness").GetValue(i)])


def key(poly, i):
    tc = poly.GetPointData().GetTCoords()
    return (round(tc.GetComponent(i, 0), 5), round(tc.GetComponent(i, 1), 5))


def own_cells(poly):
    """The cells that are not ghosts (ParaView may ask the pipeline for ghost levels), and the
    points they use."""
    ghosts = poly.GetCellData().GetArray("vtkGhostType")
    cells = [c for c in range(poly.GetNumberOfCells())
             if ghosts is None or not (int(ghosts.GetValue(c)) & 1)]  # DUPLICATECELL
    points = set()
    for c in cells:
        ids = poly.GetCell(c).GetPointIds()
        points.update(ids.GetId(k) for k in range(ids.GetNumberOfIds()))
    return cells, sorted(points)


failures = []
index = {key(serial, i): i for i in range(serial.GetNumberOfPoints())}
if len(index) != serial.GetNumberOfPoints():
    failures.append("the serial surface repeats texture coordinates")
cells, points = own_cells(gathered)
if len(cells) != serial.GetNumberOfCells():
    failures.append("%d cells, serial %d" % (len(cells), serial.GetNumberOfCells()))
worst = 0.0
seen = set()
for i in points:
    j = index.get(key(gathered, i))
    if j is None:
        failures.append("point %d is not on the serial surface" % i)
        break
    seen.add(j)
    worst = max([worst] + [abs(a - b) for a, b in zip(values(gathered, i), values(serial, j))])
if len(seen) != serial.GetNumberOfPoints():
    failures.append("%d of %d serial points in the pieces" % (len(seen),
                                                              serial.GetNumberOfPoints()))
names = [set(p.GetPointData().GetArrayName(a) for a in range(p.GetPointData().GetNumberOfArrays()))
         - {"vtkGhostType"} for p in (gathered, serial)]
if names[0] != names[1]:
    failures.append("point arrays %s, serial %s" % (sorted(names[0]), sorted(names[1])))
bounds = [abs(a - b) for a, b in zip(gathered.GetBounds(), serial.GetBounds())]
if max(bounds) > 1e-6:
    failures.append("bounds differ by %g" % max(bounds))
if worst > 1e-5:
    failures.append("largest difference from serial %g" % worst)
print("%d points gathered (%d serial), largest difference %g"
      % (gathered.GetNumberOfPoints(), serial.GetNumberOfPoints(), worst))
for f in failures:
    print("MISMATCH: " + f)
if not failures:
    print("the C++ filters' surface matches the plugin's" if mode == "reference"
          else "pieces match the serial surface")
