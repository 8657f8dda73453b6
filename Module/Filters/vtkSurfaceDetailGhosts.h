// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSurfaceDetailGhosts.h
 * @brief  Private: the ghost-level protocol of the filters that read a point's neighbours.
 *
 * A filter whose value at a point depends on the polygons around it (Mesh normals, fitted
 * derivatives, merged seams, MikkTSpace groups) is exact at a piece's border only if the
 * polygons of the neighbouring pieces are there too. Such a filter asks its input for one
 * ghost level more than its own output was asked for; the points of the outermost ghost
 * layer then lack neighbours of their own and their values are only approximate, which is
 * acceptable for ghosts. When the output was asked for no ghost levels (a writer, a mapper),
 * the ghost cells, and the ghost points that only they use, are removed again, so that the
 * output is the piece itself, with DUPLICATEPOINT marks left on the border points that
 * another piece owns.
 *
 * Shared by the filters of this module; not installed.
 */
#ifndef vtkSurfaceDetailGhosts_h
#define vtkSurfaceDetailGhosts_h

#include "SurfaceDetailFiltersModule.h" // For export macro

class vtkInformation;
class vtkPolyData;

namespace vtkSurfaceDetailGhosts
{
/// Forwards the piece requested of @a outInfo to @a inInfo, with one ghost level more when
/// there are several pieces.
SURFACEDETAILFILTERS_EXPORT void RequestOneMoreLevel(
  vtkInformation* inInfo, vtkInformation* outInfo);

/// When @a outInfo asked for no ghost levels, removes the ghost cells of @a output and the
/// points that no remaining cell uses, keeping the order of what remains.
SURFACEDETAILFILTERS_EXPORT void RemoveUnrequested(vtkInformation* outInfo, vtkPolyData* output);
}

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailGhosts.h
