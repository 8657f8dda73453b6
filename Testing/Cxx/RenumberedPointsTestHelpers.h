// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Copies of a test mesh with its points given other ids, for tests that show that a filter's
// result at a point depends on the point's data and neighbours, not on its id (nor on where
// its id falls in the filter's blocks and tasks).
#ifndef RenumberedPointsTestHelpers_h
#define RenumberedPointsTestHelpers_h

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace RenumberedPoints
{
/// A random permutation of 0 .. @a count - 1 (Fisher-Yates, fixed @a seed, so that a failure
/// can be rerun).
inline std::vector<vtkIdType> RandomIds(vtkIdType count, int seed)
{
  std::vector<vtkIdType> ids(static_cast<size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    ids[i] = i;
  }
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(seed);
  for (vtkIdType i = count - 1; i > 0; --i)
  {
    random->Next();
    const vtkIdType j = std::min(i, static_cast<vtkIdType>(random->GetValue() * (i + 1)));
    std::swap(ids[i], ids[j]);
  }
  return ids;
}

/// @a mesh with point i moved to id @a newId[i] among @a total points (at least as many as the
/// mesh has, the new ids distinct), its point data (every array, in its type and attribute
/// role) with it, and its polygons in the same order with their ids rewritten. An id that no
/// point moves to gets the coordinates @a unused (the origin if null) and point 0's data: a
/// point no polygon uses.
inline vtkSmartPointer<vtkPolyData> Moved(vtkPolyData* mesh, const std::vector<vtkIdType>& newId,
  vtkIdType total, const double unused[3] = nullptr)
{
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const vtkIdType count = mesh->GetNumberOfPoints();
  std::vector<vtkIdType> source(static_cast<size_t>(total), -1);
  for (vtkIdType i = 0; i < count; ++i)
  {
    source[newId[i]] = i;
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  points->SetNumberOfPoints(total);
  vtkPointData* in = mesh->GetPointData();
  vtkPointData* pd = out->GetPointData();
  pd->CopyAllocate(in, total);
  for (vtkIdType i = 0; i < total; ++i)
  {
    const vtkIdType from = source[i];
    if (from >= 0)
    {
      points->SetPoint(i, mesh->GetPoint(from));
    }
    else
    {
      points->SetPoint(i, unused ? unused : origin);
    }
    pd->CopyData(in, from >= 0 ? from : 0, i);
  }
  out->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetPolys()->GetNumberOfCells(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      ids->SetId(k, newId[ids->GetId(k)]);
    }
    polys->InsertNextCell(ids);
  }
  out->SetPolys(polys);
  return out;
}
} // namespace RenumberedPoints

#endif
