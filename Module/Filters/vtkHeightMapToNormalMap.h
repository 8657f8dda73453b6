// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkHeightMapToNormalMap
 * @brief   Turns a height map into a tangent-space normal map (optionally a relief map).
 *
 * The output is the normal map of the surface z = k*h(s,t) over the unit texture square,
 * k being BumpScale: n = normalize(-k*dh/ds, -k*dh/dt, 1), derivatives taken per unit of
 * texture coordinate (texel differences times the image's width or height), so the map
 * does not change with the image's resolution, only gets more accurate. Spacing and origin
 * are ignored: a height map lives in texture space. Each component is stored as 0.5*n + 0.5
 * (vtkSurfaceDetailConventions.h EncodeNormal; decode with DecodeNormal or its GLSL twin).
 *
 * Schemes (all estimate the same derivative; texel (i,j), W x H texels):
 * - Forward: dh/ds = W*(h[i+1] - h[i]), exactly the classic Cg code's
 *   `w*(tex2D(d, u + 1/w) - tex2D(d, u))`; first order (it is centred half a texel away).
 * - Central: W*(h[i+1] - h[i-1])/2; second order.
 * - Sobel: central differences smoothed across by (1,2,1)/4; second order.
 * - Scharr: the same with (3,10,3)/16, closer to rotation invariant; second order.
 *
 * Input: component HeightComponent of the point scalars (or of the point array chosen with
 * SetInputArrayToProcess) of a 2-D image of any size (1xN, Nx1 and
 * non-powers of two included). Unsigned char and unsigned short heights are fractions of
 * their range, float and double heights are used as they are; other types are an error
 * (vtkSurfaceDetail::HeightMapScale, the rule vtkDisplacementMapFilter and
 * vtkSurfaceDetailMapper apply too: convert them to float with vtkImageShiftScale). Non-finite
 * heights are filled from the finite ones outward, continuing their slope (a hole in a plane
 * is filled with the plane), within the range of the finite heights; one warning with the
 * count.
 *
 * OutputRelief adds A = depth = 1 - h (0 = top, 1 = deepest, Policarpo and Oliveira's relief map).
 * For floating-point input h is the height as given, the same value the normal map and
 * vtkDisplacementMapFilter use, so a relief rendered with DepthScale d shows the surface
 * whose normal map this is when BumpScale = d; heights outside [0,1] are clamped to it with
 * a warning (rescale first, e.g. with vtkImageShiftScale).
 *
 * The output holds one array, "NormalMap" (RGB) or "ReliefMap" (RGBA), of
 * OutputScalarType: unsigned char or unsigned short (rounded to nearest) or float.
 * Runs with vtkSMPTools; the result does not depend on the number of threads. Requests for
 * a sub-extent are honoured (the whole input is read, as borders wrap).
 *
 * @sa vtkDisplacementMapFilter vtkImageGradient
 */

#ifndef vtkHeightMapToNormalMap_h
#define vtkHeightMapToNormalMap_h

#include "SurfaceDetailFiltersModule.h" // For export macro
#include "vtkImageAlgorithm.h"
#include "vtkSurfaceDetailConventions.h" // For the wrap mode values

class SURFACEDETAILFILTERS_EXPORT vtkHeightMapToNormalMap : public vtkImageAlgorithm
{
public:
  static vtkHeightMapToNormalMap* New();
  vtkTypeMacro(vtkHeightMapToNormalMap, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum DifferenceSchemeType
  {
    Forward = 0,
    Central = 1,
    Sobel = 2,
    Scharr = 3
  };

  /// Wrap modes: vtkSurfaceDetail::WrapMode's values (vtkTexture's numbering), by name.
  enum WrapType
  {
    ClampToEdge = vtkSurfaceDetail::ClampToEdge,
    Repeat = vtkSurfaceDetail::Repeat,
    MirroredRepeat = vtkSurfaceDetail::MirroredRepeat,
    ClampToBorder = vtkSurfaceDetail::ClampToBorder
  };

  ///@{
  /**
   * The finite-difference scheme. Default Central.
   */
  vtkSetClampMacro(DifferenceScheme, int, Forward, Scharr);
  vtkGetMacro(DifferenceScheme, int);
  void SetDifferenceSchemeToForward() { this->SetDifferenceScheme(Forward); }
  void SetDifferenceSchemeToCentral() { this->SetDifferenceScheme(Central); }
  void SetDifferenceSchemeToSobel() { this->SetDifferenceScheme(Sobel); }
  void SetDifferenceSchemeToScharr() { this->SetDifferenceScheme(Scharr); }
  const char* GetDifferenceSchemeAsString();
  ///@}

  ///@{
  /**
   * BumpScale k: the map is the normal map of z = k*h(s,t) over the unit texture square.
   * Default 1. Must be finite (a non-finite value is an error at execution).
   */
  vtkSetMacro(BumpScale, double);
  vtkGetMacro(BumpScale, double);
  ///@}

  ///@{
  /**
   * The component of the height array that holds the height, as vtkDisplacementMapFilter's
   * and vtkSurfaceDetailMapper's HeightComponent. Default 0.
   */
  vtkSetClampMacro(HeightComponent, int, 0, VTK_INT_MAX);
  vtkGetMacro(HeightComponent, int);
  ///@}

  ///@{
  /**
   * Which texels the stencil reads beyond the borders, as vtkTexture::Wrap would sample
   * them. Default Repeat (tiling textures). For the one-texel stencils used here
   * MirroredRepeat reads the same texels as ClampToEdge; ClampToBorder reads BorderHeight.
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
   * On (default): +Y of the map is +t (OpenGL, Blender). Off: -Y (DirectX, Unreal);
   * only the green channel changes.
   */
  vtkSetMacro(GreenUp, bool);
  vtkGetMacro(GreenUp, bool);
  vtkBooleanMacro(GreenUp, bool);
  ///@}

  ///@{
  /**
   * VTK_UNSIGNED_CHAR (default), VTK_UNSIGNED_SHORT or VTK_FLOAT; other values are
   * rejected with an error and leave the setting unchanged.
   */
  void SetOutputScalarType(int type);
  vtkGetMacro(OutputScalarType, int);
  void SetOutputScalarTypeToUnsignedChar() { this->SetOutputScalarType(VTK_UNSIGNED_CHAR); }
  void SetOutputScalarTypeToUnsignedShort() { this->SetOutputScalarType(VTK_UNSIGNED_SHORT); }
  void SetOutputScalarTypeToFloat() { this->SetOutputScalarType(VTK_FLOAT); }
  ///@}

  ///@{
  /**
   * Off (default): RGB normal map. On: RGBA relief map, A = depth = 1 - height.
   */
  vtkSetMacro(OutputRelief, bool);
  vtkGetMacro(OutputRelief, bool);
  vtkBooleanMacro(OutputRelief, bool);
  ///@}

protected:
  vtkHeightMapToNormalMap();
  ~vtkHeightMapToNormalMap() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int DifferenceScheme = Central;
  double BumpScale = 1.0;
  int Wrap = Repeat;
  double BorderHeight = 0.0;
  bool GreenUp = true;
  int HeightComponent = 0;
  int OutputScalarType = VTK_UNSIGNED_CHAR;
  bool OutputRelief = false;

private:
  vtkHeightMapToNormalMap(const vtkHeightMapToNormalMap&) = delete;
  void operator=(const vtkHeightMapToNormalMap&) = delete;
};

#endif
