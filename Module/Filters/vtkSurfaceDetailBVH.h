// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSurfaceDetailBVH.h
 * @brief  Private: a bounding-volume hierarchy over triangles for nearest ray hits.
 *
 * vtkNormalMapBaker casts one ray per texel into a detailed mesh of millions of triangles
 * and wants the hit nearest to the ray's origin on either side of it, which VTK's locators
 * (first hit along a segment) answer only with two casts. This hierarchy answers it in one
 * traversal: the search interval shrinks around t = 0 as hits are found, and children are
 * visited nearest first.
 *
 * Built once (object-median splits on the longest axis of the centroids, up to four
 * triangles per leaf; the subtrees in parallel, the result independent of the threads),
 * read-only afterwards: queries from many threads need no locking, and a
 * query's answer depends only on the ray, never on the order in which others ran. Boxes and
 * the leaf-ordered vertex copy are single precision (half the memory traffic); the
 * intersection arithmetic is double precision, on those single-precision vertices.
 *
 * Shared by the filters of this module; not installed.
 */
#ifndef vtkSurfaceDetailBVH_h
#define vtkSurfaceDetailBVH_h

#include "vtkType.h"

#include <cstdint>
#include <vector>

namespace vtkSurfaceDetail
{

/// Where a ray met a triangle: origin + T*direction = (1-U-V)*v0 + U*v1 + V*v2.
struct RayHit
{
  vtkIdType Triangle = -1; ///< index into the triangle list given to Build
  double T = 0.0;
  double U = 0.0;
  double V = 0.0;
};

class TriangleBVH
{
public:
  /**
   * Builds the hierarchy over @a numberOfTriangles triangles whose corner point ids are
   * @a corners[3k..3k+2], points given as xyz triples in @a points. Triangles with a
   * non-finite corner are left out.
   */
  void Build(const double* points, const vtkIdType* corners, vtkIdType numberOfTriangles);

  /**
   * The hit of the ray origin + t*direction with the smallest |t| for t in [tLow, tHigh]
   * (ties: the lower triangle index). Returns false when there is none.
   */
  bool Nearest(const double origin[3], const double direction[3], double tLow, double tHigh,
    RayHit& hit) const;

private:
  struct Node
  {
    float Lo[3];
    float Hi[3];
    int32_t First; // leaf: first triangle slot; inner: the right child (the left is next)
    int32_t Count; // leaf: number of triangles (> 0); inner: 0
  };

  struct Builder;
  bool IntersectLeaf(const Node& node, const double o[3], const double d[3], double tLow,
    double tHigh, double& best, RayHit& hit) const;

  std::vector<Node> Nodes;
  std::vector<float> Vertices;  // 9 floats per triangle, in leaf order
  std::vector<vtkIdType> Order; // leaf order -> input triangle index
};

} // namespace vtkSurfaceDetail

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailBVH.h
