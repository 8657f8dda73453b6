// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSurfaceDetailGhosts.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <vector>

using SDDP = vtkStreamingDemandDrivenPipeline;

//------------------------------------------------------------------------------
void vtkSurfaceDetailGhosts::RequestOneMoreLevel(vtkInformation* inInfo, vtkInformation* outInfo)
{
  const int numPieces = outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES());
  const int ghostLevels = outInfo->Get(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS());
  inInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), outInfo->Get(SDDP::UPDATE_PIECE_NUMBER()));
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), numPieces);
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), ghostLevels + (numPieces > 1 ? 1 : 0));
}

namespace
{
constexpr unsigned char Ghost = vtkDataSetAttributes::DUPLICATECELL;

// Marks the points of the kept cells of one cell array (@a ghost: its cells' marks) and
// counts the kept cells and their connectivity.
struct MarkKept
{
  template <typename State>
  void operator()(State& state, const unsigned char* ghost, std::vector<vtkIdType>& pointMap,
    vtkIdType& keptCells, vtkIdType& keptIds) const
  {
    const auto* offsets = state.GetOffsets()->GetPointer(0);
    const auto* conn = state.GetConnectivity()->GetPointer(0);
    for (vtkIdType c = 0; c < state.GetNumberOfCells(); ++c)
    {
      if (!(ghost[c] & Ghost))
      {
        for (auto k = offsets[c]; k < offsets[c + 1]; ++k)
        {
          pointMap[conn[k]] = 0;
        }
        ++keptCells;
        keptIds += offsets[c + 1] - offsets[c];
      }
    }
  }
};

// Writes the kept cells of one cell array, renumbered by @a pointMap.
struct CopyKept
{
  template <typename State>
  void operator()(State& state, const unsigned char* ghost, const std::vector<vtkIdType>& pointMap,
    vtkIdType* offsetsOut, vtkIdType* connOut) const
  {
    const auto* offsets = state.GetOffsets()->GetPointer(0);
    const auto* conn = state.GetConnectivity()->GetPointer(0);
    vtkIdType at = 0;
    *offsetsOut++ = 0;
    for (vtkIdType c = 0; c < state.GetNumberOfCells(); ++c)
    {
      if (!(ghost[c] & Ghost))
      {
        for (auto k = offsets[c]; k < offsets[c + 1]; ++k)
        {
          connOut[at++] = pointMap[conn[k]];
        }
        *offsetsOut++ = at;
      }
    }
  }
};

// Calls @a body(start, count) for each run of consecutive items of [0, n) that @a keep keeps:
// the kept points and cells are mostly long runs, copied as ranges.
template <typename Keep, typename Body>
void ForEachRun(vtkIdType n, Keep&& keep, Body&& body)
{
  for (vtkIdType a = 0; a < n;)
  {
    if (!keep(a))
    {
      ++a;
      continue;
    }
    vtkIdType b = a + 1;
    while (b < n && keep(b))
    {
      ++b;
    }
    body(a, b - a);
    a = b;
  }
}
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailGhosts::RemoveUnrequested(vtkInformation* outInfo, vtkPolyData* output)
{
  vtkUnsignedCharArray* ghosts = output->GetCellGhostArray();
  if (!ghosts || outInfo->Get(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS()) > 0)
  {
    return;
  }
  const unsigned char* ghost = ghosts->GetPointer(0);
  const vtkIdType numCells = output->GetNumberOfCells();
  if (std::none_of(ghost, ghost + numCells, [](unsigned char g) { return (g & Ghost) != 0; }))
  {
    return;
  }
  const vtkIdType numPts = output->GetNumberOfPoints();

  // vtkPolyData numbers its cells verts, lines, polys, strips: each array's marks follow the
  // previous arrays'.
  vtkCellArray* in[4] = { output->GetVerts(), output->GetLines(), output->GetPolys(),
    output->GetStrips() };
  vtkIdType first[4], keptCells[4] = { 0, 0, 0, 0 }, keptIds[4] = { 0, 0, 0, 0 };
  std::vector<vtkIdType> pointMap(numPts, -1);
  for (int a = 0; a < 4; ++a)
  {
    first[a] = a == 0 ? 0 : first[a - 1] + in[a - 1]->GetNumberOfCells();
    in[a]->Visit(MarkKept{}, ghost + first[a], pointMap, keptCells[a], keptIds[a]);
  }
  vtkIdType numKept = 0;
  for (vtkIdType& id : pointMap)
  {
    id = id == 0 ? numKept++ : -1;
  }

  vtkNew<vtkPolyData> piece;
  vtkNew<vtkPoints> points;
  points->SetDataType(output->GetPoints()->GetDataType());
  points->SetNumberOfPoints(numKept);
  vtkPointData* inPD = output->GetPointData();
  piece->GetPointData()->CopyAllocate(inPD, numKept);
  vtkIdType at = 0;
  ForEachRun(
    numPts, [&](vtkIdType i) { return pointMap[i] >= 0; },
    [&](vtkIdType start, vtkIdType count)
    {
      points->GetData()->InsertTuples(at, count, start, output->GetPoints()->GetData());
      piece->GetPointData()->CopyData(inPD, at, count, start);
      at += count;
    });
  piece->SetPoints(points);

  vtkSmartPointer<vtkCellArray> out[4];
  for (int a = 0; a < 4; ++a)
  {
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfValues(keptCells[a] + 1);
    connectivity->SetNumberOfValues(keptIds[a]);
    in[a]->Visit(
      CopyKept{}, ghost + first[a], pointMap, offsets->GetPointer(0), connectivity->GetPointer(0));
    out[a] = vtkSmartPointer<vtkCellArray>::New();
    out[a]->SetData(offsets, connectivity);
  }
  piece->SetVerts(out[0]);
  piece->SetLines(out[1]);
  piece->SetPolys(out[2]);
  piece->SetStrips(out[3]);

  vtkCellData* inCD = output->GetCellData();
  piece->GetCellData()->CopyAllocate(inCD, numCells);
  bool otherMarks = false; // e.g. hidden cells, which keep the ghost array
  at = 0;
  ForEachRun(
    numCells, [&](vtkIdType c) { return !(ghost[c] & Ghost); },
    [&](vtkIdType start, vtkIdType count)
    {
      piece->GetCellData()->CopyData(inCD, at, count, start);
      otherMarks = otherMarks ||
        std::any_of(ghost + start, ghost + start + count, [](unsigned char g) { return g != 0; });
      at += count;
    });
  // Every cell left is the piece's own: no cell ghost array is needed any more.
  if (!otherMarks)
  {
    piece->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  }
  piece->GetFieldData()->PassData(output->GetFieldData());
  output->ShallowCopy(piece);
}
