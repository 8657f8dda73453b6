// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParametricSurfaceSource
 * @brief   Tessellates a parametric surface with analytic normals, texture coordinates and
 *          tangent frames, in pieces and threads.
 *
 * vtkParametricSurfaceSource samples any two-dimensional vtkParametricFunction (VTK's own,
 * such as vtkParametricTorus or vtkParametricEllipsoid, and SurfaceDetail's functions on the
 * unit square such as vtkParametricSphere) on a regular (UResolution+1) x (VResolution+1)
 * grid and connects it with 2*UResolution*VResolution triangles. Point i + j*(UResolution+1)
 * is the function at u = i/UResolution, v = j/VResolution of its domain (MinimumU..MaximumU,
 * MinimumV..MaximumV). Seams are not joined: the first and last columns (rows) are distinct
 * points, so texture coordinates run from 0 to 1 without wrapping back.
 *
 * Point arrays, each computed only when asked for:
 * - "Normals" (GenerateNormals): unit normals from the function's analytic derivatives,
 *   N = Du x Dv, or Dv x Du for VTK functions whose ClockwiseOrdering is off (the rule
 *   vtkParametricFunctionSource follows), so closed surfaces face outward. Triangles wind
 *   counter-clockwise around N.
 * - "TCoords" (GenerateTextureCoordinates): s = TextureOffset[0] + TextureRepeat[0]*u,
 *   t = TextureOffset[1] + TextureRepeat[1]*v with (u,v) the unit-square parameters,
 *   whatever the function's own domain.
 * - "Tangents" and "TangentHandedness" (GenerateTangents): the tangent frame as
 *   vtkSurfaceDetailTangents stores it: T = dP/ds made orthogonal to N and normalised, the
 *   point data's TANGENTS attribute (3 float components), and the handedness w = +1 or -1
 *   of the bitangent B = w*cross(N,T) in its own float array, per
 *   vtkSurfaceDetailConventions.h (MakeTangentFrame).
 * - "dPdu", "dPdv" (GenerateDerivatives): the raw derivatives with respect to the
 *   unit-square parameters (the function's own derivatives times the extent of its domain).
 * - "dNdu", "dNdv" (GenerateDerivatives): the change of the unit normal "Normals" with
 *   respect to the same parameters, from the second derivatives by Weingarten's relation
 *   (dN/du = (dm/du minus its part along N) / |m| with m = Du x Dv, oriented as N).
 *   vtkDisplacementMapFilter's Exact normals use them instead of fitting them from
 *   neighbouring points. SurfaceDetail's functions give the second derivatives in closed
 *   form (vtkParametricSeparableFunction::EvaluateSecondDerivatives); for other functions
 *   they are second-order differences of the first derivatives (about 1e-8 relative).
 *   Zero where the derivatives do not span a plane (a pole), where no such change exists.
 *
 * Functions whose DerivativesAvailable is off (vtkParametricSuperEllipsoid,
 * vtkParametricSuperToroid, vtkParametricRandomHills) get fourth-order finite differences of
 * their points instead, accurate to about 1e-9 relative; the orientation rule is the same,
 * so vtkParametricRandomHills (ClockwiseOrdering off) faces -z unless ClockwiseOrdering is
 * turned on. Functions derived from vtkParametricSeparableFunction (all of SurfaceDetail's)
 * have their per-column and per-row work done once per column and row.
 *
 * Degenerate points, where Du or Dv vanishes (a sphere's poles, the axis of a surface of
 * revolution) or where they are parallel, get the limit of the normal and tangent from the
 * surrounding surface: the vanishing derivative is replaced by its one-sided derivative
 * across the degenerate line (a second-order difference of analytic derivatives), so a
 * sphere's pole normal is the pole direction and its tangent is continuous along the column.
 * A surface with no area anywhere near a point (a zero radius) gets an arbitrary unit frame
 * there and a warning.
 *
 * Pieces: the source splits the v rows among UPDATE_NUMBER_OF_PIECES pieces like
 * vtkSphereSource; the pieces together are exactly the serial surface (boundary rows are
 * repeated as points, cells are not), and every point of a piece is bit for bit the serial
 * one. With UPDATE_NUMBER_OF_GHOST_LEVELS g > 0, each piece also has up to g rows of ghost
 * cells on each side, and for a function joined in v (GetJoinV(), e.g. vtkParametricDonut)
 * the ghost rows of the first and last pieces continue across the v seam with the far end's
 * own points (coincident with the piece's, as in the whole surface), so that filters that
 * merge seams or read neighbours see at a piece's border what they see in the whole.
 * vtkGhostType arrays mark the ghost cells (DUPLICATECELL) and the points another piece owns
 * (DUPLICATEPOINT: a piece owns the first point row of its cells, and the last piece its last
 * row too), so each point of the surface is owned by exactly one piece. Work is done by
 * vtkSMPTools and the result does not depend on the number of threads.
 *
 * Speed: a vtkParametricSeparableFunction (all of SurfaceDetail's functions) is evaluated
 * from per-row and per-column terms, so trigonometry and profile evaluation are done once per
 * row and column, not per point.
 *
 * The function is evaluated from several threads at once. VTK's functions and SurfaceDetail's
 * allow that; a function that builds state lazily is evaluated once before the threads start.
 * If the function reports an error, or returns a non-finite value, the output is empty and
 * the source reports an error.
 *
 * @sa vtkParametricFunctionSource vtkParametricSphere vtkParametricDonut
 * vtkSurfaceDetailConventions.h
 */

#ifndef vtkParametricSurfaceSource_h
#define vtkParametricSurfaceSource_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // For the function member

class vtkInformationDoubleVectorKey;
class vtkParametricFunction;

class SURFACEDETAILSOURCES_EXPORT vtkParametricSurfaceSource : public vtkPolyDataAlgorithm
{
public:
  static vtkParametricSurfaceSource* New();
  vtkTypeMacro(vtkParametricSurfaceSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The surface: a two-dimensional vtkParametricFunction. Required; no default.
   */
  void SetParametricFunction(vtkParametricFunction* function);
  vtkParametricFunction* GetParametricFunction();
  ///@}

  ///@{
  /**
   * Number of grid intervals along u and v (cells per row and rows), clamped to at least 1.
   * Default 64 x 32: the round surfaces turn once in u and go half-way round (the sphere, a
   * meridian) or once in v, so twice the intervals in u keeps their quads near square, where
   * vtkParametricFunctionSource's 50 x 50 stretches a sphere's.
   */
  vtkSetClampMacro(UResolution, int, 1, VTK_INT_MAX);
  vtkGetMacro(UResolution, int);
  vtkSetClampMacro(VResolution, int, 1, VTK_INT_MAX);
  vtkGetMacro(VResolution, int);
  ///@}

  ///@{
  /** Produce the "Normals" point array (unit, analytic). Default on. */
  vtkSetMacro(GenerateNormals, bool);
  vtkGetMacro(GenerateNormals, bool);
  vtkBooleanMacro(GenerateNormals, bool);
  ///@}

  ///@{
  /**
   * Produce the "TCoords" point array (the texture-coordinate attribute). Default on, where
   * vtkParametricFunctionSource's is off: this source exists to make surfaces to texture.
   */
  vtkSetMacro(GenerateTextureCoordinates, bool);
  vtkGetMacro(GenerateTextureCoordinates, bool);
  vtkBooleanMacro(GenerateTextureCoordinates, bool);
  ///@}

  ///@{
  /** Produce the tangent frame ("Tangents" attribute, "TangentHandedness"). Default off. */
  vtkSetMacro(GenerateTangents, bool);
  vtkGetMacro(GenerateTangents, bool);
  vtkBooleanMacro(GenerateTangents, bool);
  ///@}

  ///@{
  /**
   * Produce the "dPdu", "dPdv", "dNdu" and "dNdv" point arrays (unit-square derivatives of
   * the point and of the unit normal). Default off.
   */
  vtkSetMacro(GenerateDerivatives, bool);
  vtkGetMacro(GenerateDerivatives, bool);
  vtkBooleanMacro(GenerateDerivatives, bool);
  ///@}

  ///@{
  /**
   * Texture transform: s = TextureOffset[0] + TextureRepeat[0]*u, and the same for t with v.
   * Default repeat (1,1), offset (0,0). Non-finite values are an error when texture
   * coordinates or tangents are asked for; so is a repeat of zero, which leaves no texture
   * direction for the tangents, when tangents are asked for.
   */
  vtkSetVector2Macro(TextureRepeat, double);
  vtkGetVector2Macro(TextureRepeat, double);
  vtkSetVector2Macro(TextureOffset, double);
  vtkGetVector2Macro(TextureOffset, double);
  ///@}

  ///@{
  /**
   * vtkAlgorithm::SINGLE_PRECISION (default) or DOUBLE_PRECISION for the points and the
   * derivative arrays. Normals, texture coordinates and tangents are always float.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DOUBLE_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  /**
   * Set on the information of the "TCoords" array when the derivative arrays are made too:
   * (TextureRepeat[0], TextureOffset[0], TextureRepeat[1], TextureOffset[1]), the affine map
   * from the parameters (u,v) of dPdu/dPdv to the texture coordinates. Filters that need
   * derivatives in (s,t) (vtkDisplacementMapFilter) read it instead of estimating the map
   * from the data, so that every piece of a surface uses the same one. A filter that makes
   * new texture coordinates makes a new array, without the key.
   */
  static vtkInformationDoubleVectorKey* TEXTURE_TRANSFORM();

  /** Includes the function's modification time. */
  vtkMTimeType GetMTime() override;

protected:
  vtkParametricSurfaceSource();
  ~vtkParametricSurfaceSource() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkSmartPointer<vtkParametricFunction> ParametricFunction;
  int UResolution = 64;
  int VResolution = 32;
  bool GenerateNormals = true;
  bool GenerateTextureCoordinates = true;
  bool GenerateTangents = false;
  bool GenerateDerivatives = false;
  double TextureRepeat[2] = { 1.0, 1.0 };
  double TextureOffset[2] = { 0.0, 0.0 };
  int OutputPointsPrecision = SINGLE_PRECISION;

private:
  vtkParametricSurfaceSource(const vtkParametricSurfaceSource&) = delete;
  void operator=(const vtkParametricSurfaceSource&) = delete;
};

#endif
