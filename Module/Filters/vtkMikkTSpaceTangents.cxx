// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMikkTSpaceTangents.h"

#include "vtkSurfaceDetailCells.h"
#include "vtkSurfaceDetailGhosts.h"
#include "vtkSurfaceDetailMikkTSpace.h"
#include "vtkSurfaceDetailTangents.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolygon.h"

#include <algorithm>
#include <numeric>
#include <vector>

vtkStandardNewMacro(vtkMikkTSpaceTangents);

namespace
{
/// The output's polygons ("faces") and, when they are not the input's own, the input cell
/// each one came from.
struct Faces
{
  vtkSmartPointer<vtkCellArray> Cells;
  std::vector<vtkIdType> Source;
};

// Triangles and quads as they are (MikkTSpace takes both), larger polygons triangulated
// (ear cutting, a fan where that fails), polygons of fewer than 3 points kept, strips
// split into triangles (every other one turned round, those with a repeated point left
// out). Every triangle made here keeps the cell data of the cell it came from. An input
// with only polygons of up to 4 points keeps its own cell array.
Faces MakeFaces(vtkPolyData* input)
{
  vtkCellArray* inPolys = input->GetPolys();
  Faces faces;
  faces.Cells = inPolys;
  if (input->GetNumberOfStrips() == 0 && inPolys->GetMaxCellSize() <= 4)
  {
    return faces;
  }
  faces.Cells = vtkSmartPointer<vtkCellArray>::New();
  if (!inPolys->IsStorage64Bit())
  {
    faces.Cells->Use32BitStorage();
  }
  faces.Source.reserve(input->GetNumberOfPolys());
  vtkIdType cell = input->GetNumberOfVerts() + input->GetNumberOfLines();
  auto addFace = [&](vtkIdType npts, const vtkIdType* ids)
  {
    faces.Cells->InsertNextCell(npts, ids);
    faces.Source.push_back(cell);
  };
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> triIds;
  auto polys = vtk::TakeSmartPointer(inPolys->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cell)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    polys->GetCurrentCell(npts, pts);
    if (npts <= 4)
    {
      addFace(npts, pts);
      continue;
    }
    polygon->Initialize(static_cast<int>(npts), pts, input->GetPoints());
    triIds->Reset();
    const bool ok = polygon->Triangulate(triIds) != 0 && triIds->GetNumberOfIds() == 3 * (npts - 2);
    for (vtkIdType t = 0; t < npts - 2; ++t)
    {
      vtkIdType tri[3];
      for (int k = 0; k < 3; ++k)
      {
        tri[k] = ok ? pts[triIds->GetId(3 * t + k)] : pts[k == 0 ? 0 : t + k];
      }
      addFace(3, tri);
    }
  }
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cell)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    strips->GetCurrentCell(npts, pts);
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      const vtkIdType tri[3] = { pts[k + (k & 1)], pts[k + 1 - (k & 1)], pts[k + 2] };
      if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2])
      {
        addFace(3, tri);
      }
    }
  }
  return faces;
}

// 0, 1, ..., n - 1.
vtkSmartPointer<vtkIdList> Identity(vtkIdType n)
{
  auto ids = vtkSmartPointer<vtkIdList>::New();
  ids->SetNumberOfIds(n);
  std::iota(ids->begin(), ids->end(), 0);
  return ids;
}

// The output: the input's points and point data (copied to the split points), the
// tangent frame, vertices and lines as they are, the faces with their cell data.
void Assemble(vtkPolyData* input, vtkPointData* inPD, const Faces& faces,
  const vtkSurfaceDetailMikkTSpace::Frames& frames, vtkPolyData* output)
{
  const vtkIdType nPts = input->GetNumberOfPoints();
  const vtkIdType nOut = frames.Tangents->GetNumberOfTuples();
  if (nOut == nPts)
  {
    output->SetPoints(input->GetPoints());
    output->GetPointData()->PassData(inPD);
  }
  else
  {
    auto src = Identity(nOut);
    std::copy(frames.SplitSources.begin(), frames.SplitSources.end(), src->begin() + nPts);
    vtkNew<vtkPoints> points;
    points->SetDataType(input->GetPoints()->GetDataType());
    points->SetNumberOfPoints(nOut);
    input->GetPoints()->GetData()->GetTuples(src, points->GetData());
    output->SetPoints(points);
    output->GetPointData()->CopyAllocate(inPD, nOut);
    output->GetPointData()->CopyData(inPD, src, Identity(nOut));
  }
  // The frame is computed four floats per point; VTK's tangent attribute takes three.
  vtkSurfaceDetailTangents::SetFrameFromXYZW(output->GetPointData(), frames.Tangents);

  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());
  if (!frames.Connectivity)
  {
    output->SetPolys(faces.Cells);
  }
  else
  {
    vtkNew<vtkCellArray> polys;
    polys->SetData(faces.Cells->GetOffsetsArray(), frames.Connectivity);
    output->SetPolys(polys);
  }
  if (faces.Cells == input->GetPolys())
  {
    output->GetCellData()->PassData(input->GetCellData());
  }
  else
  {
    const vtkIdType nLead = input->GetNumberOfVerts() + input->GetNumberOfLines();
    const vtkIdType nCells = nLead + static_cast<vtkIdType>(faces.Source.size());
    auto src = Identity(nCells);
    std::copy(faces.Source.begin(), faces.Source.end(), src->begin() + nLead);
    output->GetCellData()->CopyAllocate(input->GetCellData(), nCells);
    output->GetCellData()->CopyData(input->GetCellData(), src, Identity(nCells));
  }
  output->GetFieldData()->PassData(input->GetFieldData());
}
} // anonymous namespace

//------------------------------------------------------------------------------
void vtkMikkTSpaceTangents::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AngularThreshold: " << this->AngularThreshold << "\n";
}

//------------------------------------------------------------------------------
int vtkMikkTSpaceTangents::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkSurfaceDetailGhosts::RequestOneMoreLevel(
    inputVector[0]->GetInformationObject(0), outputVector->GetInformationObject(0));
  return 1;
}

//------------------------------------------------------------------------------
int vtkMikkTSpaceTangents::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  vtkNew<vtkPointData> inPD; // the input's point data, with normals if we make them
  if (!this->CheckInput(input, output) || !this->PrepareNormals(input, inPD))
  {
    return 0;
  }
  const Faces faces = MakeFaces(input);
  const auto frames = vtkSurfaceDetailMikkTSpace::Compute(input->GetPoints()->GetData(),
    inPD->GetNormals(), inPD->GetTCoords(), faces.Cells, this->AngularThreshold, this);
  if (frames.Aborted)
  {
    // Stopped by the user (AbortExecute): no error, and no half-made output.
    output->Initialize();
    return 1;
  }
  Assemble(input, inPD, faces, frames, output);
  this->UpdateProgress(1.0);
  vtkSurfaceDetailGhosts::RemoveUnrequested(outputVector->GetInformationObject(0), output);
  if (frames.NonFinitePoints > 0)
  {
    vtkWarningMacro(<< frames.NonFinitePoints
                    << " points have non-finite coordinates; the tangents around "
                       "them are arbitrary unit vectors orthogonal to the normal.");
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkMikkTSpaceTangents::CheckInput(vtkPolyData* input, vtkPolyData* output)
{
  if (!input || !output)
  {
    vtkErrorMacro("The input must be a vtkPolyData.");
    return false;
  }
  const vtkIdType nPts = input->GetNumberOfPoints();
  if (nPts == 0 || !input->GetPoints())
  {
    vtkErrorMacro("The input has no points; give it a surface with points, normals and "
                  "texture coordinates.");
    return false;
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("The input has no polygons or triangle strips; tangents need a surface.");
    return false;
  }
  // Triangulated, polygons and strips have at most three corners per point id they list.
  const vtkIdType ids = input->GetPolys()->GetNumberOfConnectivityIds() +
    input->GetStrips()->GetNumberOfConnectivityIds();
  if (nPts >= VTK_TYPE_INT32_MAX || ids >= VTK_TYPE_INT32_MAX / 3)
  {
    vtkErrorMacro("The input has " << nPts << " points and " << ids
                                   << " polygon and strip point ids; the filter takes fewer "
                                      "than 2^31 points and 2^31 / 3 ids: process it in "
                                      "pieces.");
    return false;
  }
  if (!vtkSurfaceDetailCells::PointIdsInRange(input->GetPolys(), nPts) ||
    !vtkSurfaceDetailCells::PointIdsInRange(input->GetStrips(), nPts))
  {
    vtkErrorMacro("A polygon or triangle strip of the input names a point id outside [0, "
      << nPts << "); fix the connectivity (e.g. with vtkCleanPolyData) first.");
    return false;
  }
  vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
  if (!tcoords || tcoords->GetNumberOfComponents() < 2 || tcoords->GetNumberOfTuples() != nPts)
  {
    vtkErrorMacro("The input has no 2-component point texture coordinates; set them as the "
                  "point data's TCoords (e.g. with vtkTextureMapToPlane or a parametric "
                  "source) before computing tangents.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkMikkTSpaceTangents::PrepareNormals(vtkPolyData* input, vtkPointData* inPD)
{
  inPD->ShallowCopy(input->GetPointData());
  vtkDataArray* normals = inPD->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() == input->GetNumberOfPoints())
  {
    return true;
  }
  vtkWarningMacro("The input has no 3-component point normals; computing them with "
                  "vtkPolyDataNormals (no splitting, no reordering).");
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(input->GetPolys());
  surface->SetStrips(input->GetStrips());
  vtkNew<vtkPolyDataNormals> pdn;
  pdn->SetInputData(surface);
  pdn->SplittingOff();
  pdn->ConsistencyOff();
  pdn->AutoOrientNormalsOff();
  pdn->ComputeCellNormalsOff();
  pdn->ComputePointNormalsOn();
  pdn->Update();
  vtkDataArray* computed = pdn->GetOutput()->GetPointData()->GetNormals();
  if (!computed || computed->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkErrorMacro("The input has no point normals and vtkPolyDataNormals could not make "
                  "them; set the point data's Normals.");
    return false;
  }
  inPD->SetNormals(computed);
  return true;
}
