#include "vtkSurfaceDetailGhosts.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
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
  if (std::none_of(ghost, ghost + numCells,
        [](unsigned char g) { return (g & vtkDataSetAttributes::DUPLICATECELL) != 0; }))
  {
    return;
  }
  const vtkIdType numPts = output->GetNumberOfPoints();

  // The cells kept, in their order (verts, lines, polys, strips, as vtkPolyData numbers
  // them), and the points they use.
  vtkCellArray* in[4] = { output->GetVerts(), output->GetLines(), output->GetPolys(),
    output->GetStrips() };
  std::vector<vtkIdType> pointMap(numPts, -1);
  vtkNew<vtkIdList> keptCells;
  bool otherBits = false; // e.g. hidden cells, which keep the array
  vtkIdType cellId = 0;
  for (vtkCellArray* cells : in)
  {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cellId)
    {
      if (ghost[cellId] & vtkDataSetAttributes::DUPLICATECELL)
      {
        continue;
      }
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k < n; ++k)
      {
        pointMap[ids[k]] = 0;
      }
      keptCells->InsertNextId(cellId);
      otherBits = otherBits || ghost[cellId] != 0;
    }
  }
  vtkNew<vtkIdList> keptPoints;
  for (vtkIdType i = 0; i < numPts; ++i)
  {
    if (pointMap[i] == 0)
    {
      pointMap[i] = keptPoints->GetNumberOfIds();
      keptPoints->InsertNextId(i);
    }
  }

  vtkNew<vtkPolyData> piece;
  vtkNew<vtkPoints> points;
  points->SetDataType(output->GetPoints()->GetDataType());
  points->SetNumberOfPoints(keptPoints->GetNumberOfIds());
  output->GetPoints()->GetData()->GetTuples(keptPoints, points->GetData());
  piece->SetPoints(points);
  vtkNew<vtkIdList> identity;
  identity->SetNumberOfIds(keptPoints->GetNumberOfIds());
  for (vtkIdType i = 0; i < identity->GetNumberOfIds(); ++i)
  {
    identity->SetId(i, i);
  }
  piece->GetPointData()->CopyAllocate(output->GetPointData(), keptPoints->GetNumberOfIds());
  piece->GetPointData()->CopyData(output->GetPointData(), keptPoints, identity);

  vtkSmartPointer<vtkCellArray> out[4];
  cellId = 0;
  std::vector<vtkIdType> renumbered;
  for (int a = 0; a < 4; ++a)
  {
    out[a] = vtkSmartPointer<vtkCellArray>::New();
    auto it = vtk::TakeSmartPointer(in[a]->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cellId)
    {
      if (ghost[cellId] & vtkDataSetAttributes::DUPLICATECELL)
      {
        continue;
      }
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      renumbered.resize(n);
      std::transform(ids, ids + n, renumbered.begin(), [&](vtkIdType i) { return pointMap[i]; });
      out[a]->InsertNextCell(n, renumbered.data());
    }
  }
  piece->SetVerts(out[0]);
  piece->SetLines(out[1]);
  piece->SetPolys(out[2]);
  piece->SetStrips(out[3]);
  identity->SetNumberOfIds(keptCells->GetNumberOfIds());
  for (vtkIdType i = 0; i < identity->GetNumberOfIds(); ++i)
  {
    identity->SetId(i, i);
  }
  piece->GetCellData()->CopyAllocate(output->GetCellData(), keptCells->GetNumberOfIds());
  piece->GetCellData()->CopyData(output->GetCellData(), keptCells, identity);
  // Every cell left is the piece's own: no cell ghost array is needed any more.
  if (!otherBits)
  {
    piece->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  }
  piece->GetFieldData()->PassData(output->GetFieldData());
  output->ShallowCopy(piece);
}
