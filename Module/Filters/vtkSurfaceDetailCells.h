// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSurfaceDetailCells.h
 * @brief  Private: a check that cells name only points the dataset has.
 *
 * A polygon whose connectivity holds a point id outside [0, number of points) makes every
 * pass that follows it read (or, through vtkPolyData::BuildLinks, write) outside the point
 * arrays. VTK's own filters trust the connectivity; the filters of this module check it
 * once, before anything reads a point through a cell, and stop with an error instead.
 * One parallel pass over the connectivity array (about 1 ns per id on one core, the ids
 * compared as unsigned values so that negative ones fail too).
 *
 * Shared by the filters of this module; not installed.
 */
#ifndef vtkSurfaceDetailCells_h
#define vtkSurfaceDetailCells_h

#include "SurfaceDetailFiltersModule.h" // For export macro
#include "vtkType.h"

class vtkCellArray;

namespace vtkSurfaceDetailCells
{
/// True if every point id of @a cells lies in [0, numberOfPoints); true for a null or
/// empty cell array.
SURFACEDETAILFILTERS_EXPORT bool PointIdsInRange(vtkCellArray* cells, vtkIdType numberOfPoints);
}

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailCells.h
