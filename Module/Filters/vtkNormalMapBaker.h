// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNormalMapBaker
 * @brief   Bakes the normals (and heights) of a detailed mesh into a normal map of a coarse one.
 *
 * A detailed surface of millions of triangles shades almost the same as a coarse one with a
 * normal map of the detail (the classic example: a 30,000-polygon head as a 632-polygon head and a
 * map). This filter makes that map, as Blender, xNormal and Substance do, by casting rays.
 *
 * Input port 0 is the coarse mesh: polygons (or triangle strips) with point texture
 * coordinates, point normals and a tangent frame as vtkSurfaceDetailTangents stores it
 * (TANGENTS attribute, "TangentHandedness"; w = +1 without the latter, as VTK takes it).
 * Without normals or tangents they are computed with
 * vtkMikkTSpaceTangents and a warning: render that filter's output, since a map is only
 * right with the frame it was baked against. Input port 1 is the detailed mesh (polygons or
 * strips); its point normals are interpolated where it has them, else its face normals are
 * used.
 *
 * For each texel whose centre ((i+0.5)/W, (j+0.5)/H) lies in a coarse triangle in texture
 * space, the position, normal and frame are interpolated there and a ray is cast along the
 * normal N, both ways up to MaxRayDistance; the hit nearest to the coarse surface counts.
 * With CageOffset d > 0 the ray starts instead on the cage P + d*N and goes inwards, up to
 * MaxRayDistance beyond the coarse surface, and the first hit counts (as Blender's
 * extrusion). The detailed normal n at the hit is stored:
 * - Space Tangent: the coordinates (x, y, z), normalised, with which
 *   normalize(x*T + y*B + z*N) = n, where T and B are the per-vertex frames of
 *   vtkSurfaceDetailMapper (T made orthogonal to the vertex normal, B = w*cross(N, T))
 *   interpolated as the rasteriser does and N the normalised interpolated normal: the map
 *   renders with that mapper exactly as it was baked, without seams.
 * - Space Object: n itself.
 * Each is encoded as 0.5*n + 0.5 (EncodeNormal) in the RGB array "NormalMap" of
 * OutputScalarType. With BakeHeight, output port 1 holds the float array "Height": the
 * signed distance from the coarse surface to the hit along N (positive outwards).
 *
 * Texels whose ray hits nothing are counted (GetNumberOfUnhitTexels), reported with a
 * warning, and filled from their neighbours. Then Margin rings of texels around every island
 * are filled the same way, so that filtering and mipmapping do not pull the background in
 * across seams. Texels beyond that are flat (tangent space), zero (object space) and height 0.
 * Both outputs are W x H images whose points are the texel centres in texture space
 * (spacing 1/W, 1/H).
 *
 * Input that can be baked but probably not as meant gives a warning: texture coordinates
 * outside [0,1] (those parts are not baked) and texels covered by more than one triangle
 * (overlapping islands; the lower-numbered triangle is baked), naming the triangles by
 * their cell ids. Input that cannot be baked is an error, with empty outputs: no texture
 * coordinates, no polygons in either mesh, point ids out of range, a texture size below 1 or
 * a ray distance that is not positive.
 *
 * The rays run through a bounding-volume hierarchy of the detailed mesh's triangles, with
 * vtkSMPTools over texel rows; every texel depends only on the inputs, so the output does
 * not depend on the number of threads. Polygons of more than three points are split into
 * fans (triangulate non-convex ones first, e.g. with vtkTriangleFilter).
 *
 * @sa vtkMikkTSpaceTangents vtkSurfaceDetailMapper vtkHeightMapToNormalMap
 */

#ifndef vtkNormalMapBaker_h
#define vtkNormalMapBaker_h

#include "SurfaceDetailFiltersModule.h" // For export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h" // For WithTangentFrame

#include <vector> // For ReportFindings

class vtkPolyData;

class SURFACEDETAILFILTERS_EXPORT vtkNormalMapBaker : public vtkImageAlgorithm
{
public:
  static vtkNormalMapBaker* New();
  vtkTypeMacro(vtkNormalMapBaker, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The detailed mesh: shortcuts for SetInputConnection(1, ...) and SetInputData(1, ...).
   */
  void SetSourceConnection(vtkAlgorithmOutput* algOutput)
  {
    this->SetInputConnection(1, algOutput);
  }
  void SetSourceData(vtkPolyData* detailed);
  ///@}

  enum SpaceType
  {
    Tangent = 0,
    Object = 1
  };

  ///@{
  /**
   * Width and height of the maps in texels. Default 512 x 512; both must be at least 1
   * (checked at execution).
   */
  vtkSetVector2Macro(TextureSize, int);
  vtkGetVector2Macro(TextureSize, int);
  ///@}

  ///@{
  /**
   * How far from the coarse surface a hit is looked for, in the meshes' units. Default 0.1.
   * Must be positive and finite (checked at execution).
   */
  vtkSetMacro(MaxRayDistance, double);
  vtkGetMacro(MaxRayDistance, double);
  ///@}

  ///@{
  /**
   * Distance of the cage outside the coarse surface from which rays are cast inwards.
   * Default 0: no cage, rays go both ways from the coarse surface. Range [0, inf).
   */
  vtkSetClampMacro(CageOffset, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(CageOffset, double);
  ///@}

  ///@{
  /**
   * Rings of texels filled around each island. Default 4. Range [0, 1024].
   */
  vtkSetClampMacro(Margin, int, 0, 1024);
  vtkGetMacro(Margin, int);
  ///@}

  ///@{
  /**
   * Tangent (default) or Object space normals.
   */
  vtkSetClampMacro(Space, int, Tangent, Object);
  vtkGetMacro(Space, int);
  void SetSpaceToTangent() { this->SetSpace(Tangent); }
  void SetSpaceToObject() { this->SetSpace(Object); }
  const char* GetSpaceAsString();
  ///@}

  ///@{
  /**
   * VTK_UNSIGNED_CHAR (default), VTK_UNSIGNED_SHORT (both rounded to nearest) or VTK_FLOAT;
   * other values are rejected with an error and leave the setting unchanged. The height
   * output is always float.
   */
  void SetOutputScalarType(int type);
  vtkGetMacro(OutputScalarType, int);
  void SetOutputScalarTypeToUnsignedChar() { this->SetOutputScalarType(VTK_UNSIGNED_CHAR); }
  void SetOutputScalarTypeToUnsignedShort() { this->SetOutputScalarType(VTK_UNSIGNED_SHORT); }
  void SetOutputScalarTypeToFloat() { this->SetOutputScalarType(VTK_FLOAT); }
  ///@}

  ///@{
  /**
   * On (default): +Y of a tangent-space map is +t (OpenGL, Blender), as
   * vtkHeightMapToNormalMap and vtkSurfaceDetailMapper have it. Off: -Y (DirectX, Unreal);
   * only the green channel changes. Object-space maps are not affected.
   */
  vtkSetMacro(GreenUp, bool);
  vtkGetMacro(GreenUp, bool);
  vtkBooleanMacro(GreenUp, bool);
  ///@}

  ///@{
  /**
   * Off (default): output port 1 is an empty image, and its information says so (an empty
   * whole extent). On: it holds the baked heights.
   */
  vtkSetMacro(BakeHeight, bool);
  vtkGetMacro(BakeHeight, bool);
  vtkBooleanMacro(BakeHeight, bool);
  ///@}

  ///@{
  /**
   * What the last execution found: texels covered by the coarse mesh (one ray each), those
   * of them that no ray hit, and texels covered by more than one triangle.
   */
  vtkGetMacro(NumberOfCoveredTexels, vtkIdType);
  vtkGetMacro(NumberOfUnhitTexels, vtkIdType);
  vtkGetMacro(NumberOfOverlappingTexels, vtkIdType);
  ///@}

  /// The baked height map (output port 1).
  vtkImageData* GetHeightOutput();

protected:
  vtkNormalMapBaker();
  ~vtkNormalMapBaker() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The checks of the settings and inputs that make the filter stop with an error.
  bool CheckInputs(vtkPolyData* coarse, vtkPolyData* detailed);
  /// The coarse mesh with normals and tangents: the input, or vtkMikkTSpaceTangents' output.
  vtkSmartPointer<vtkPolyData> WithTangentFrame(vtkPolyData* coarse);
  /// Keeps what the rays found and warns about overlaps and texels without a hit.
  void ReportFindings(vtkIdType covered, vtkIdType unhit, vtkIdType overlapping,
    const std::vector<vtkIdType>& overlapCells);

  int TextureSize[2] = { 512, 512 };
  double MaxRayDistance = 0.1;
  double CageOffset = 0.0;
  int Margin = 4;
  int Space = Tangent;
  int OutputScalarType = VTK_UNSIGNED_CHAR;
  bool GreenUp = true;
  bool BakeHeight = false;

  vtkIdType NumberOfCoveredTexels = 0;
  vtkIdType NumberOfUnhitTexels = 0;
  vtkIdType NumberOfOverlappingTexels = 0;

private:
  vtkNormalMapBaker(const vtkNormalMapBaker&) = delete;
  void operator=(const vtkNormalMapBaker&) = delete;
};

#endif
