// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Under `mpirun -np N`, each rank makes its own piece (piece = rank of N) of several
// pipelines, source -> vtkDisplacementMapFilter [-> vtkMikkTSpaceTangents], and rank 0
// checks that the pieces together are the serial surface, which it computes itself with the
// same pipeline as one piece:
// - every point of every piece (its own and the border points another piece owns) is a
//   point of the serial surface (found by its texture coordinates, which the source makes
//   bit for bit the same in any piece), with the same position, normal and tangent;
// - each serial point is owned (not marked DUPLICATEPOINT) by exactly one piece, and each
//   serial triangle is in exactly one piece, with the same corners in the same order;
// - the copies of a border point in different pieces agree with one another (no crack and
//   no jump of the normal along a piece boundary).
// Positions, normals and tangents must be equal bit for bit: every value at a point is a
// function of the point's own data and of the polygons around it, all of which a piece has
// with one ghost level, in the same order as the whole surface (the source keeps the rows
// in increasing order, across the v seam too). As a control, the same pipeline fed pieces
// without ghost cells must differ at the borders in Mesh mode: the comparison can fail.
//
// With --pvtp FILE --resolution N it instead reads the pieces that the DistributedSurface
// example wrote and compares them with that example's pipeline run serially.

#include "DistributedSurfacePipeline.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkDisplacementMapFilter.h>
#include <vtkMPIController.h>
#include <vtkMikkTSpaceTangents.h>
#include <vtkNew.h>
#include <vtkParametricDonut.h>
#include <vtkParametricFunction.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPPolyDataReader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
struct Case
{
  const char* Name;
  bool Sphere;      // else the donut, joined in u and v
  int NormalMode;   // vtkDisplacementMapFilter::NormalModes
  bool Derivatives; // the source's dPdu, dPdv, dNdu, dNdv (else the filter fits them)
  bool Mikk;        // tangents recomputed by vtkMikkTSpaceTangents after displacement
  bool Ghosts;      // false: the control, pieces cut off the source without ghost cells
};

using Polys = std::vector<vtkSmartPointer<vtkPolyData>>;

vtkSmartPointer<vtkPolyData> Run(const Case& c, int piece, int numPieces)
{
  vtkSmartPointer<vtkParametricFunction> function;
  if (c.Sphere)
  {
    function = vtkSmartPointer<vtkParametricSphere>::New();
  }
  else
  {
    auto donut = vtkSmartPointer<vtkParametricDonut>::New();
    donut->SetRingRadius(1.0);
    donut->SetCrossSectionRadius(0.4);
    function = donut;
  }
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(function);
  // Rows that 2 and 3 ranks split unevenly, and columns the seams cut across.
  source->SetUResolution(40);
  source->SetVResolution(29);
  source->GenerateTangentsOn();
  source->SetGenerateDerivatives(c.Derivatives);
  vtkNew<vtkDisplacementMapFilter> displace;
  displace->SetInputConnection(0, source->GetOutputPort());
  displace->SetInputData(1, DistributedSurface::MakeHeightMap(64, 32));
  displace->SetScaleFactor(0.1);
  displace->SetMidlevel(0.5);
  displace->SetInterpolationToCubic();
  displace->SetNormalMode(c.NormalMode);
  vtkNew<vtkPolyData> cut;
  if (!c.Ghosts)
  {
    source->UpdatePiece(piece, numPieces, 0);
    cut->ShallowCopy(source->GetOutput());
    displace->SetInputData(0, cut);
  }
  vtkNew<vtkMikkTSpaceTangents> mikk;
  mikk->SetInputConnection(displace->GetOutputPort());
  vtkAlgorithm* last = c.Mikk ? static_cast<vtkAlgorithm*>(mikk) : displace;
  last->UpdatePiece(piece, numPieces, 0);
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->DeepCopy(vtkPolyData::SafeDownCast(last->GetOutputDataObject(0)));
  return result;
}

// The largest difference of the first @a nc components of a and b at rows i and j.
double Difference(vtkDataArray* a, vtkIdType i, vtkDataArray* b, vtkIdType j)
{
  if (!a || !b || a->GetNumberOfComponents() != b->GetNumberOfComponents())
  {
    return HUGE_VAL;
  }
  double d = 0.0;
  for (int k = 0; k < a->GetNumberOfComponents(); ++k)
  {
    d = std::max(d, std::abs(a->GetComponent(i, k) - b->GetComponent(j, k)));
  }
  return d;
}

vtkDataArray* Points(vtkPolyData* p)
{
  return p->GetPoints() ? p->GetPoints()->GetData() : nullptr;
}
vtkDataArray* Normals(vtkPolyData* p)
{
  return p->GetPointData()->GetNormals();
}
vtkDataArray* Tangents(vtkPolyData* p)
{
  return p->GetPointData()->GetTangents();
}

// A cell as its corners, rotated to start at the smallest: same cell, same orientation.
std::vector<vtkIdType> Canonical(std::vector<vtkIdType> ids)
{
  std::rotate(ids.begin(), std::min_element(ids.begin(), ids.end()), ids.end());
  return ids;
}

struct Report
{
  double Position = 0.0, Normal = 0.0, Tangent = 0.0; // largest differences from serial
  double Crack = 0.0; // largest difference between the copies of a point in two pieces
  std::vector<std::string> Errors;
};

Report Compare(vtkPolyData* serial, const Polys& pieces)
{
  Report r;
  vtkDataArray* tc = serial->GetPointData()->GetTCoords();
  std::map<std::pair<float, float>, vtkIdType> byTCoords;
  for (vtkIdType i = 0; i < serial->GetNumberOfPoints(); ++i)
  {
    const auto key = std::make_pair(
      static_cast<float>(tc->GetComponent(i, 0)), static_cast<float>(tc->GetComponent(i, 1)));
    if (!byTCoords.emplace(key, i).second)
    {
      r.Errors.push_back("the serial surface repeats texture coordinates: no unique key");
      return r;
    }
  }
  std::vector<int> owners(serial->GetNumberOfPoints(), 0);
  std::vector<std::pair<int, vtkIdType>> firstCopy(serial->GetNumberOfPoints(), { -1, -1 });
  std::map<std::vector<vtkIdType>, int> cells;
  auto addCells = [&cells](vtkPolyData* p, const std::vector<vtkIdType>& toSerial, int count)
  {
    auto it = vtk::TakeSmartPointer(p->GetPolys()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      std::vector<vtkIdType> mapped(n);
      for (vtkIdType k = 0; k < n; ++k)
      {
        mapped[k] = toSerial.empty() ? ids[k] : toSerial[ids[k]];
      }
      cells[Canonical(mapped)] += count;
    }
  };
  addCells(serial, {}, 1);
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    vtkPolyData* piece = pieces[p];
    const vtkIdType n = piece->GetNumberOfPoints();
    if (n == 0)
    {
      continue;
    }
    vtkDataArray* ptc = piece->GetPointData()->GetTCoords();
    vtkUnsignedCharArray* ghosts = piece->GetPointGhostArray();
    if (piece->GetCellGhostArray())
    {
      r.Errors.push_back("piece " + std::to_string(p) + " still has ghost cells");
    }
    std::vector<vtkIdType> toSerial(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const auto found = byTCoords.find(std::make_pair(
        static_cast<float>(ptc->GetComponent(i, 0)), static_cast<float>(ptc->GetComponent(i, 1))));
      if (found == byTCoords.end())
      {
        r.Errors.push_back("piece " + std::to_string(p) + " has a point the serial surface lacks");
        return r;
      }
      const vtkIdType s = found->second;
      toSerial[i] = s;
      if (!ghosts || !(ghosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT))
      {
        ++owners[s];
      }
      r.Position = std::max(r.Position, Difference(Points(piece), i, Points(serial), s));
      r.Normal = std::max(r.Normal, Difference(Normals(piece), i, Normals(serial), s));
      r.Tangent = std::max(r.Tangent, Difference(Tangents(piece), i, Tangents(serial), s));
      if (firstCopy[s].first < 0)
      {
        firstCopy[s] = { static_cast<int>(p), i };
      }
      else if (firstCopy[s].first != static_cast<int>(p))
      {
        vtkPolyData* other = pieces[firstCopy[s].first];
        const vtkIdType j = firstCopy[s].second;
        r.Crack = std::max({ r.Crack, Difference(Points(piece), i, Points(other), j),
          Difference(Normals(piece), i, Normals(other), j),
          Difference(Tangents(piece), i, Tangents(other), j) });
      }
    }
    addCells(piece, toSerial, -1);
  }
  const auto owned = std::count(owners.begin(), owners.end(), 1);
  if (owned != static_cast<long>(owners.size()))
  {
    r.Errors.push_back(std::to_string(owners.size() - owned) + " of " +
      std::to_string(owners.size()) + " serial points are not owned by exactly one piece");
  }
  const auto wrongCells = std::count_if(cells.begin(), cells.end(),
    [](const std::pair<const std::vector<vtkIdType>, int>& c) { return c.second != 0; });
  if (wrongCells > 0)
  {
    r.Errors.push_back(std::to_string(wrongCells) +
      " serial triangles are missing from the pieces, repeated, or turned");
  }
  return r;
}

// Sends every rank's piece to rank 0. VTK 9.1 sends data objects in its legacy format, whose
// writer drops the TANGENTS attribute; the tangents travel as a plain array and are made the
// attribute again on arrival.
Polys Gather(vtkMultiProcessController* controller, vtkPolyData* mine, int tag)
{
  Polys all;
  if (controller->GetLocalProcessId() != 0)
  {
    vtkNew<vtkPolyData> sent;
    sent->ShallowCopy(mine);
    sent->GetPointData()->SetActiveAttribute(-1, vtkDataSetAttributes::TANGENTS);
    controller->Send(sent, 0, tag);
    return all;
  }
  all.push_back(mine);
  for (int r = 1; r < controller->GetNumberOfProcesses(); ++r)
  {
    auto piece = vtkSmartPointer<vtkPolyData>::New();
    controller->Receive(piece, r, tag);
    piece->GetPointData()->SetActiveAttribute("Tangents", vtkDataSetAttributes::TANGENTS);
    all.push_back(piece);
  }
  return all;
}

int CheckCases(vtkMultiProcessController* controller)
{
  using F = vtkDisplacementMapFilter;
  const Case cases[] = {
    { "donut Exact, analytic derivatives", false, F::Exact, true, false, true },
    { "donut Exact, fitted derivatives", false, F::Exact, false, false, true },
    { "donut Approximate, fitted derivatives", false, F::Approximate, false, false, true },
    { "donut Mesh, MikkTSpace tangents", false, F::Mesh, false, true, true },
    { "sphere Exact, analytic derivatives", true, F::Exact, true, false, true },
    { "sphere Mesh, MikkTSpace tangents", true, F::Mesh, false, true, true },
  };
  const Case control = { "control: donut Mesh, pieces without ghosts", false, F::Mesh, false, false,
    false };
  const int rank = controller->GetLocalProcessId(), ranks = controller->GetNumberOfProcesses();
  int failures = 0, tag = 1000;
  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkPolyData> mine = Run(c, rank, ranks);
    const Polys pieces = Gather(controller, mine, ++tag);
    if (rank != 0)
    {
      continue;
    }
    const Report r = Compare(Run(c, 0, 1), pieces);
    const bool exact = r.Position == 0.0 && r.Normal == 0.0 && r.Tangent == 0.0 && r.Crack == 0.0;
    const bool ok = exact && r.Errors.empty();
    std::printf("%s: %s (largest differences from serial: position %g, normal %g, tangent %g; "
                "between pieces %g)\n",
      c.Name, ok ? "pieces == serial" : "FAILED", r.Position, r.Normal, r.Tangent, r.Crack);
    for (const std::string& e : r.Errors)
    {
      std::printf("  %s\n", e.c_str());
    }
    failures += ok ? 0 : 1;
  }
  vtkSmartPointer<vtkPolyData> mine = Run(control, rank, ranks);
  const Polys pieces = Gather(controller, mine, ++tag);
  if (rank == 0 && ranks > 1)
  {
    // A piece's border normals see only half their polygons: off by tens of degrees.
    const Report r = Compare(Run(control, 0, 1), pieces);
    const bool caught = r.Normal > 0.1;
    std::printf("%s: %s (largest normal difference %g)\n", control.Name,
      caught ? "differs from serial at the borders, as it must" : "FAILED: the check is blind",
      r.Normal);
    failures += caught ? 0 : 1;
  }
  return failures;
}

int CheckWrittenPieces(const char* fileName, int resolution)
{
  vtkNew<vtkXMLPPolyDataReader> reader;
  reader->SetFileName(fileName);
  reader->Update();
  const int numPieces = reader->GetNumberOfPieces();
  Polys pieces;
  for (int p = 0; p < numPieces; ++p)
  {
    reader->UpdatePiece(p, numPieces, 0);
    auto piece = vtkSmartPointer<vtkPolyData>::New();
    piece->DeepCopy(reader->GetOutput());
    pieces.push_back(piece);
  }
  DistributedSurface::Pipeline serial(resolution);
  serial.Displace->Update();
  const Report r = Compare(serial.Displace->GetOutput(), pieces);
  const bool exact = r.Position == 0.0 && r.Normal == 0.0 && r.Tangent == 0.0 && r.Crack == 0.0;
  const bool ok = numPieces > 1 && exact && r.Errors.empty();
  std::printf("%s, %d pieces: %s (largest differences from serial: position %g, normal %g, "
              "tangent %g; between pieces %g)\n",
    fileName, numPieces, ok ? "pieces == serial" : "FAILED", r.Position, r.Normal, r.Tangent,
    r.Crack);
  for (const std::string& e : r.Errors)
  {
    std::printf("  %s\n", e.c_str());
  }
  return ok ? 0 : 1;
}
}

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  const char* pvtp = nullptr;
  int resolution = 0;
  for (int a = 1; a + 1 < argc; a += 2)
  {
    if (!std::strcmp(argv[a], "--pvtp"))
    {
      pvtp = argv[a + 1];
    }
    else if (!std::strcmp(argv[a], "--resolution"))
    {
      resolution = std::atoi(argv[a + 1]);
    }
  }
  int failures = 0;
  if (pvtp)
  {
    failures = controller->GetLocalProcessId() == 0 ? CheckWrittenPieces(pvtp, resolution) : 0;
  }
  else
  {
    failures = CheckCases(controller);
  }
  controller->Broadcast(&failures, 1, 0);
  controller->Finalize();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
