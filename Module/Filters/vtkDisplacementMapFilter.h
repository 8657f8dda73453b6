// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkDisplacementMapFilter
 * @brief   Displaces a surface along its normals by a height map and recomputes the normals.
 *
 * Input port 0 is a vtkPolyData with point normals and texture coordinates (s,t); input
 * port 1 (`SetInputConnection(1, ...)`) is a 2-D vtkImageData, the height map h. Every point
 * moves to
 *
 *     p' = p + ScaleFactor * (h(s,t) - Midlevel) * n
 *
 * which is displacement mapping as the textbooks give it: p*(u,v) = p(u,v) + d(u,v) n(u,v) with
 * d = ScaleFactor * (h - Midlevel).
 *
 * Sampling the height map. The image is a texture: its origin and spacing are ignored,
 * row 0 is t = 0 and texel (i,j) has its centre at ((i+0.5)/W, (j+0.5)/H), as
 * vtkSurfaceDetailConventions.h defines for every SurfaceDetail filter and shader.
 * The heights are the height map's point scalars, or the point array chosen with
 * SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name), as in
 * vtkHeightMapToNormalMap; `HeightComponent` selects its channel. Unsigned char and unsigned short
 * are normalised to [0,1], float and double are used as they are; other scalar types are an error
 * (vtkSurfaceDetail::HeightMapScale, the rule every SurfaceDetail reader of height maps
 * applies: convert them to float with vtkImageShiftScale). `Wrap` has vtkTexture's values and
 * OpenGL's meaning; `Interpolation` is
 * - Nearest: the texel that contains (s,t) (GL_NEAREST). Its derivative is zero, so the
 *   analytic normal modes see flat terraces; use Mesh normals for a faceted look.
 * - Linear: GL_LINEAR, the blend of the four nearest texel centres, so that the CPU
 *   displacement matches what a vtkTexture with the same wrap mode shows on the GPU.
 * - Cubic: Catmull-Rom (Keys' cubic convolution with a = -1/2) over the 4x4 nearest texel
 *   centres, the same texel split as Linear, each index wrapped by `Wrap`. It interpolates
 *   the texels (equal to Linear at texel centres), is C1, and reproduces quadratics, so a
 *   smooth height map sampled into W texels is reconstructed with O(1/W^3) error in value
 *   and O(1/W^2) in slope.
 * A 1x1 height map is valid: it is a constant (a 1x1 texture samples to its only texel in
 * every mode), so all points move by the same distance; as that is seldom what was meant,
 * the filter says so in a warning. NaN and infinite heights are
 * treated as Midlevel; when the surface reads any, one warning gives the map's count of them.
 *
 * Normals (`NormalMode`). Let P_s = dp/ds, P_t = dp/dt, n the unit input normal and
 * d = ScaleFactor (h - Midlevel). Differentiating p* = p + d n by the product rule gives
 *     p*_s = P_s + d_s n + d n_s,   p*_t = P_t + d_t n + d n_t,   n* ~ p*_s x p*_t.
 * - Exact: exactly that, m* = (P_s + d_s n + d n_s) x (P_t + d_t n + d n_t). The
 *   derivatives of the unit normal, n_s and n_t, come from the surface itself where the point
 *   data has 3-component arrays "dNdu" and "dNdv" next to "dPdu" and "dPdv"
 *   (vtkParametricSurfaceSource's GenerateDerivatives): the derivatives of the unit normal,
 *   the "Normals" array as stored whatever its orientation, with respect to the same
 *   parameters (u,v) as dPdu/dPdv, so that n_s = dNdu / r_s and n_t = dNdv / r_t (r_s, r_t
 *   below). The normal is then exact up to the height map's reconstruction, at any mesh
 *   resolution. Without them (or without dPdu/dPdv, whose parameters they are taken in),
 *   n_s and n_t are fitted per point by least squares to the input normals of the point's
 *   neighbours (n_j - n_i ~ n_s ds + n_t dt over the polygons around it, each neighbour
 *   weighted by the polygons it shares with the point); on a regular grid this is a central
 *   difference, so the normal converges at second order in the mesh spacing
 *   (TestDisplacementMapFilterAccuracy measures both).
 * - Approximate: the textbook formula (Blinn's for bump mapping), which drops the d n_s and
 *   d n_t terms:
 *   m* = P_s x P_t + d_s (n x P_t) - d_t (n x P_s), where P_s x P_t is taken as its part
 *   along n, (n . (P_s x P_t)) n, so that a map without slope gives back n itself. d_s and
 *   d_t are the analytic derivatives of the chosen interpolant (bilinear or bicubic), not
 *   a finite difference with a fixed epsilon. Its error is a bias of order d times the
 *   curvature, which no resolution removes.
 * - Mesh: the area-weighted average of the displaced polygons' normals, each polygon
 *   oriented as the input normals of its points (vtkPolyDataNormals without splitting).
 * - Input: the input normals are kept.
 * In Approximate and Exact, P_s and P_t first lose their parts along n (the input normal
 * defines the tangent plane), and the output normal is m* / |m*| times the sign of
 * n . (P_s x P_t), so the result never depends on the orientation of the
 * parameterisation. Where P_s x P_t vanishes, at a singular point of the parameterisation
 * such as a sphere's pole (a neighbour at the same place with other texture coordinates,
 * or zero dPdu/dPdv), no (s,t) derivative describes the surface and the input normal is
 * kept. Normals are always finite: where m* has no direction, the input normal is used.
 * The fits and Mesh normals are sums over each point's polygons, taken in increasing order
 * (so they do not depend on the threads or on the pieces) and made without point links: each
 * thread owns a range of points and reads the runs of cells that use them.
 *
 * Surface derivatives. When the point data has 3-component arrays named "dPdu" and "dPdv"
 * (vtkParametricSurfaceSource's GenerateDerivatives), they give P_s and P_t. They may be
 * taken with respect to parameters (u,v) of which the texture coordinates are an
 * axis-aligned affine function (the source's TextureRepeat and TextureOffset), s = o_s +
 * r_s u, t = o_t + r_t v, and the filter uses P_s = dPdu / r_s, P_t = dPdv / r_t. r_s and r_t
 * are read from the texture coordinates' vtkParametricSurfaceSource::TEXTURE_TRANSFORM key
 * where the source set it; otherwise they are fitted by least squares over a sample of edges
 * (an estimate, which can differ slightly from piece to piece). Otherwise P_s and P_t are fitted
 * per point by least squares to the position differences over the point's polygons against
 * their texture-coordinate differences. "dPdu", "dPdv", "dNdu" and "dNdv" pass through
 * unchanged: they describe the input surface (nobody asked for them to be recomputed).
 *
 * Tangents. When the point data has a TANGENTS attribute, the output tangents are
 * re-orthogonalised to the new normals and keep the array's information (the mark of
 * vtkSurfaceDetailTangents); the handedness array "TangentHandedness" passes through, as do
 * all other point and cell arrays.
 *
 * Seams. With `MergeSeams` on (the default), points that coincide within
 * `SeamTolerance` (relative to the bounding-box diagonal), such as the duplicated points of
 * a texture seam or a pole, are moved by one shared displacement (the mean of their own),
 * so no crack can open; those that also share their input normal get one shared output
 * normal (the normalised sum of theirs). Points that coincide but have different input
 * normals (a hard edge) keep their own normals but still move together. A seam cuts the
 * mesh, so its duplicated points are boundary points: only points on an edge that is not
 * shared by two consistently oriented polygons (or in no polygon) are compared. They are
 * found by sums of hashes over the polygons' edges (no point links), and grouped with a
 * vtkStaticPointLocator over them.
 *
 * Precision: when the points and every array the filter reads are float (as VTK's sources
 * make them), the output points, normals and tangents are float; otherwise the inputs are
 * converted and the outputs are double. The computation is in double either way. With float
 * outputs, a point moved beyond float's range gets the largest float of that sign (never
 * infinity), and normals and tangents stay finite and unit.
 *
 * ScaleFactor 0 gives back the input bit for bit (points, normals, tangents; Mesh mode still
 * recomputes the normals from the faces).
 *
 * Pieces: the filter works on whatever piece it gets; the height map is always requested
 * whole. Seams, fits and Mesh normals read a point's polygons, so with several pieces the
 * filter asks its input for one ghost level more than its output was asked for, and removes
 * the ghost cells again (with the ghost points only they use) when its output was asked for
 * none. From an input that provides them (vtkParametricSurfaceSource does, across its v seam
 * too), every point a piece owns then gets what the whole surface gives it. Without ghost
 * cells, fitted and Mesh normals at a piece's border see only that piece's polygons (as
 * vtkPolyDataNormals does) and seam partners in another piece are not merged. Threads:
 * vtkSMPTools, with results independent of the number of threads. Nothing is kept between
 * executions.
 *
 * @sa vtkParametricSurfaceSource vtkHeightMapToNormalMap vtkWarpScalar vtkPolyDataNormals
 */

#ifndef vtkDisplacementMapFilter_h
#define vtkDisplacementMapFilter_h

#include "SurfaceDetailFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkAlgorithmOutput;
class vtkDataArray;
class vtkImageData;

class SURFACEDETAILFILTERS_EXPORT vtkDisplacementMapFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkDisplacementMapFilter* New();
  vtkTypeMacro(vtkDisplacementMapFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum WrapType
  {
    ClampToEdge = 0,
    Repeat = 1,
    MirroredRepeat = 2,
    ClampToBorder = 3
  };

  enum InterpolationType
  {
    Nearest = 0,
    Linear = 1,
    Cubic = 2
  };

  enum NormalModeType
  {
    Input = 0,
    Approximate = 1,
    Exact = 2,
    Mesh = 3
  };

  ///@{
  /**
   * Displacement per unit of height above Midlevel, in the input's length units.
   * Default 1.
   */
  vtkSetMacro(ScaleFactor, double);
  vtkGetMacro(ScaleFactor, double);
  ///@}

  ///@{
  /**
   * The height (after normalisation of integer maps) that does not move the surface.
   * Default 0.
   */
  vtkSetMacro(Midlevel, double);
  vtkGetMacro(Midlevel, double);
  ///@}

  ///@{
  /**
   * The component of the height array (the height map's point scalars, or the array chosen
   * with SetInputArrayToProcess) that holds the height. Default 0.
   */
  vtkSetClampMacro(HeightComponent, int, 0, VTK_INT_MAX);
  vtkGetMacro(HeightComponent, int);
  ///@}

  ///@{
  /**
   * How texture coordinates outside [0,1] read the height map, as vtkTexture::Wrap:
   * ClampToBorder reads BorderHeight outside the image. Default Repeat.
   */
  vtkSetClampMacro(Wrap, int, ClampToEdge, ClampToBorder);
  vtkGetMacro(Wrap, int);
  void SetWrapToClampToEdge() { this->SetWrap(ClampToEdge); }
  void SetWrapToRepeat() { this->SetWrap(Repeat); }
  void SetWrapToMirroredRepeat() { this->SetWrap(MirroredRepeat); }
  void SetWrapToClampToBorder() { this->SetWrap(ClampToBorder); }
  const char* GetWrapAsString();
  ///@}

  ///@{
  /**
   * With Wrap ClampToBorder, the height outside the image (after the normalisation of
   * integer heights, so in [0,1] for them), as vtkTexture's border colour gives it to
   * vtkSurfaceDetailMapper. Default 0. Must be finite.
   */
  vtkSetMacro(BorderHeight, double);
  vtkGetMacro(BorderHeight, double);
  ///@}

  ///@{
  /**
   * How the height map is reconstructed between texel centres. Default Linear.
   */
  vtkSetClampMacro(Interpolation, int, Nearest, Cubic);
  vtkGetMacro(Interpolation, int);
  void SetInterpolationToNearest() { this->SetInterpolation(Nearest); }
  void SetInterpolationToLinear() { this->SetInterpolation(Linear); }
  void SetInterpolationToCubic() { this->SetInterpolation(Cubic); }
  const char* GetInterpolationAsString();
  ///@}

  ///@{
  /**
   * How the output normals are computed (see the class description). Default Exact.
   */
  vtkSetClampMacro(NormalMode, int, Input, Mesh);
  vtkGetMacro(NormalMode, int);
  void SetNormalModeToInput() { this->SetNormalMode(Input); }
  void SetNormalModeToApproximate() { this->SetNormalMode(Approximate); }
  void SetNormalModeToExact() { this->SetNormalMode(Exact); }
  void SetNormalModeToMesh() { this->SetNormalMode(Mesh); }
  const char* GetNormalModeAsString();
  ///@}

  ///@{
  /**
   * Triplanar sampling, for surfaces without texture coordinates (isosurfaces, scans, terrain):
   * the height at a point is the blend of the height map projected along the three axes of
   * the input's coordinates, TriplanarScale texture squares per unit, weighted by the point's
   * normal with exponent TriplanarSharpness, by the rules vtkSurfaceDetailMapper's triplanar
   * mapping uses (vtkSurfaceDetail::TriplanarProject and TriplanarWeights in
   * vtkSurfaceDetailConventions.h), so that a displaced surface and a bump-mapped one of the
   * same map agree. Normal modes: Approximate gives n - grad d made unit, grad d the gradient
   * of the displacement along the surface (each projection's slope taken along its own axes,
   * the weights held constant, as bump mapping does); Mesh and Input as without it; Exact
   * needs texture coordinates and is refused. For small displacements the Approximate normal
   * is what the mapper's triplanar bump mapping shades with BumpScale = ScaleFactor *
   * TriplanarScale. Default off.
   */
  vtkSetMacro(Triplanar, bool);
  vtkGetMacro(Triplanar, bool);
  vtkBooleanMacro(Triplanar, bool);
  vtkSetMacro(TriplanarScale, double);
  vtkGetMacro(TriplanarScale, double);
  vtkSetClampMacro(TriplanarSharpness, double, 1.0, VTK_DOUBLE_MAX);
  vtkGetMacro(TriplanarSharpness, double);
  ///@}

  ///@{
  /**
   * Whether coincident points (texture seams, poles) are moved together and share normals.
   * Default on.
   */
  vtkSetMacro(MergeSeams, bool);
  vtkGetMacro(MergeSeams, bool);
  vtkBooleanMacro(MergeSeams, bool);
  ///@}

  ///@{
  /**
   * Distance under which points count as coincident, as a fraction of the input's
   * bounding-box diagonal. Default 1e-6.
   */
  vtkSetClampMacro(SeamTolerance, double, 0.0, 1.0);
  vtkGetMacro(SeamTolerance, double);
  ///@}

  ///@{
  /**
   * The precision of the output points, normals and tangents, as vtkAlgorithm's
   * DesiredOutputPrecision: DEFAULT_PRECISION (default) float when the points and every array
   * the filter reads are float, else double; SINGLE_PRECISION float; DOUBLE_PRECISION double.
   * The arrays are read in that precision (a converted copy where one differs); the computation
   * is in double either way.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /**
   * The height map: shortcuts for SetInputConnection(1, ...) and SetInputData(1, ...).
   */
  void SetSourceConnection(vtkAlgorithmOutput* algOutput)
  {
    this->SetInputConnection(1, algOutput);
  }
  void SetSourceData(vtkImageData* image);
  ///@}

protected:
  vtkDisplacementMapFilter();
  ~vtkDisplacementMapFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Each reports what is wrong with an error and returns false.
  bool CheckSurface(vtkPolyData* input);
  bool CheckHeightMap(vtkImageData* image, vtkDataArray* heights);

  // The input tangents that the output re-orthogonalises, or null (Input mode, or no tangents).
  vtkDataArray* InputTangents(vtkPolyData* input);

  // Reports cells that name points the input does not have.
  void ReportBadPointIds(vtkIdType numPts);

  double ScaleFactor = 1.0;
  double Midlevel = 0.0;
  int HeightComponent = 0;
  int Wrap = Repeat;
  double BorderHeight = 0.0;
  int Interpolation = Linear;
  int NormalMode = Exact;
  bool Triplanar = false;
  double TriplanarScale = 1.0;
  double TriplanarSharpness = 4.0;
  bool MergeSeams = true;
  double SeamTolerance = 1e-6;
  int OutputPointsPrecision = DEFAULT_PRECISION;

private:
  vtkDisplacementMapFilter(const vtkDisplacementMapFilter&) = delete;
  void operator=(const vtkDisplacementMapFilter&) = delete;
};

#endif
