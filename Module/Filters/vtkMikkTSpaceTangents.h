// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMikkTSpaceTangents
 * @brief   tangent frames for any polygonal surface, compatible with MikkTSpace
 *
 * Normal maps are only right when the renderer rebuilds the tangent frame the baker used,
 * and the content tools (Blender, Substance, xNormal, Unity, glTF) bake against MikkTSpace
 * (M. S. Mikkelsen, "Simulation of wrinkled surfaces revisited", 2008, and the reference
 * implementation's description in mikktspace.h). This filter computes that frame:
 *
 * - per triangle, the directions of dP/ds and dP/dt from positions and texture
 *   coordinates, and the triangle's orientation in texture space (the sign of its signed
 *   texture area);
 * - at each vertex (vertices with identical position, normal and texture coordinates are
 *   one vertex, whether or not they share a point id), the triangles around it that are
 *   connected across edges and have the same orientation form a group; their directions,
 *   projected onto the vertex normal's tangent plane, are averaged with the corner angle
 *   as weight (over the sub-group of those within AngularThreshold of each other);
 * - the tangent is that average, w = +1 for orientation-preserving groups and -1 for
 *   mirrored ones (so B = w cross(N, T) as in vtkSurfaceDetailConventions.h).
 *
 * Quads are split along the shorter texture-space diagonal (the shorter position-space
 * one on a tie) and their two triangles are forced to one orientation, as MikkTSpace does;
 * the output keeps them as quads. Larger polygons and triangle strips are triangulated;
 * their triangles carry the cell data of the cell they came from. Vertices, lines and
 * polygons with fewer than three points pass through.
 *
 * The output is the input surface with the tangent frame stored as vtkSurfaceDetailTangents
 * says, as vtkParametricSurfaceSource's: T in the TANGENTS attribute "Tangents" (3 float
 * components) and w in the float array "TangentHandedness".
 * A point whose corners get different frames (a mirrored texture shell, or faces around
 * it that MikkTSpace does not join) is split: the first frame keeps the point, every
 * other frame gets a new point appended after the input's points, with all point data
 * copied, and the polygons are renumbered. Points whose texture coordinates differ across
 * a seam are separate points in the input already and stay so.
 *
 * One implementation, in stages, parallel (vtkSMPTools) where their parts are independent
 * and all deterministic, so that the result does not depend on the number of threads. The
 * input's values are read in place, float or double (a float widens to double exactly;
 * arrays of other types are converted to double once).
 * Vertices are welded by value: each point's values are hashed, the hashes radix sorted,
 * and points of equal hash compared exactly. Each face gets compact 32-bit triangle
 * records, and vtkStaticCellLinksTemplate the vertex-to-triangle links. Then, per vertex,
 * the triangles around it are matched across their edges and grouped, and their corners'
 * spaces and frames computed, the corner arithmetic several corners at a time. The few
 * points whose corners get several frames are split last, in point order. Ids are 32-bit:
 * an input of 2^31 points or more, or with 2^31 / 3 polygon and strip point ids or more, is
 * refused with an error (process it in pieces).
 *
 * The reference's handling of awkward input is kept: triangles with two corners at one
 * position are degenerate and take the frame of the first good triangle at each corner's
 * vertex (a quad with one degenerate triangle gives its lone corner the frame of the
 * corner at the same position); triangles with no usable texture derivatives join the
 * first group that reaches them and add nothing to it; triangles sharing an edge with
 * more than one other are paired greedily in triangle order. Its decisions that hinge on
 * rounding (the quad diagonal, the sign of a triangle's texture area, whether its
 * derivatives are usable) are made with the reference's own single-precision expressions
 * on the values as floats, so that near zero they come out as in every tool that bakes
 * with MikkTSpace; directions, angles and averages are computed in double precision.
 *
 * Where the filter differs from the reference, and why:
 * - A corner's weight is its angle computed as atan2 in double. The reference takes the
 *   acos of a single-precision cosine, which is exactly 0 for a sliver (edges within
 *   about 3e-4 radians of each other once projected, as on the seams of
 *   vtkParametricFunctionSource's surfaces); at a vertex whose group has only such
 *   corners the reference returns a zero vector, the filter the group's direction.
 * - Normals are normalised before use (the reference assumes unit normals). Corners for
 *   which the reference returns its (1, 0, 0) placeholder (no group reaches them) get it
 *   made orthogonal to the normal, and any corner whose direction leaves nothing across
 *   the normal gets some unit vector orthogonal to it: the output is always finite and
 *   unit length.
 * - Groups of more than 1024 triangles at one vertex are not split into sub-groups by
 *   the angular threshold (the pairwise test is quadratic).
 * Missing normals are computed with vtkPolyDataNormals (no splitting, no reordering),
 * with a warning.
 *
 * Pieces: a vertex's frame depends on the triangles around it, so with several pieces the
 * filter asks its input for one ghost level more than its output was asked for, and removes
 * the ghost cells again (with the ghost points only they use) when the output was asked for
 * none; the points a piece owns then get the frames of the whole surface.
 *
 * @sa vtkPolyDataTangents vtkPolyDataNormals
 */

#ifndef vtkMikkTSpaceTangents_h
#define vtkMikkTSpaceTangents_h

#include "SurfaceDetailFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkPointData;

class SURFACEDETAILFILTERS_EXPORT vtkMikkTSpaceTangents : public vtkPolyDataAlgorithm
{
public:
  static vtkMikkTSpaceTangents* New();
  vtkTypeMacro(vtkMikkTSpaceTangents, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * MikkTSpace's angular threshold in degrees (genTangSpace's fAngularThreshold): within
   * a group, triangles whose projected tangent or bitangent directions differ by this
   * angle or more are given separate frames. The default, 180, is what every tool uses
   * (genTangSpaceDefault) and never separates a group. Range [0, 180].
   */
  vtkSetClampMacro(AngularThreshold, double, 0.0, 180.0);
  vtkGetMacro(AngularThreshold, double);
  ///@}

protected:
  vtkMikkTSpaceTangents() = default;
  ~vtkMikkTSpaceTangents() override = default;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// The checks of the input that make the filter stop with an error.
  bool CheckInput(vtkPolyData* input, vtkPolyData* output);
  /// The input's point data in @a inPD, with normals from vtkPolyDataNormals if it has none.
  bool PrepareNormals(vtkPolyData* input, vtkPointData* inPD);

  double AngularThreshold = 180.0;

private:
  vtkMikkTSpaceTangents(const vtkMikkTSpaceTangents&) = delete;
  void operator=(const vtkMikkTSpaceTangents&) = delete;
};

#endif
