// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSurfaceDetailMikkTSpace.h
 * @brief  Private: MikkTSpace tangent frames of the triangles and quads of a cell array.
 *
 * The algorithm behind vtkMikkTSpaceTangents, whose header says what it computes; the
 * filter prepares its input (normals, polygons and strips triangulated) and assembles the
 * output (split points, cells, cell data). Here: vertices welded by value, compact 32-bit
 * triangle records, vertex-to-triangle links, then each vertex's fan, groups, tangent
 * spaces and corner frames, in parallel over vertices. Every stage's result is independent
 * of the number of threads.
 *
 * Shared by the filters of this module; not installed.
 */
#ifndef vtkSurfaceDetailMikkTSpace_h
#define vtkSurfaceDetailMikkTSpace_h

#include "vtkSmartPointer.h" // For the result's arrays
#include "vtkType.h"

#include <vector>

class vtkAlgorithm;
class vtkCellArray;
class vtkDataArray;
class vtkFloatArray;

namespace vtkSurfaceDetailMikkTSpace
{
/// The frames of a surface's points.
struct Frames
{
  /// 4 components (xyz, w) per output point: the input's points, then the split points.
  vtkSmartPointer<vtkFloatArray> Tangents;
  /// The input point that each split point copies, in order.
  std::vector<vtkIdType> SplitSources;
  /// The faces' connectivity with the corners of split points renumbered; null when no
  /// point was split.
  vtkSmartPointer<vtkDataArray> Connectivity;
  /// The points with a non-finite coordinate.
  vtkIdType NonFinitePoints = 0;
  /// Whether the filter's AbortExecute stopped the computation (the rest is then empty).
  bool Aborted = false;
};

/**
 * The frames of the points of @a faces' triangles and quads (other cells add nothing) with
 * 3-component @a points and @a normals and 2 or more component @a tcoords, one tuple per
 * point. Fewer than 2^31 points and 2^31 face corners. @a progress, if given, is told of
 * the stages done.
 */
Frames Compute(vtkDataArray* points, vtkDataArray* normals, vtkDataArray* tcoords,
  vtkCellArray* faces, double angularThreshold, vtkAlgorithm* progress);
}

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailMikkTSpace.h
