// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSurfaceDetailRepresentation
 * @brief   ParaView's "Surface Detail" representation: a surface shaded by
 *          vtkCompositeSurfaceDetailMapper.
 *
 * The Surface representation of ParaView (colouring, lighting, textures, LOD, selection,
 * parallel rendering and compositing all as there), drawn with normal, bump, parallax or relief
 * mapping. Its full-resolution and level-of-detail mappers share one vtkSurfaceDetailMapper
 * for the technique and its settings; each setter here is that mapper's, with the same meaning
 * and range. The maps are textures: ParaView's texture proxies (a file) or the module's
 * pipeline-image texture.
 *
 * @sa vtkSurfaceDetailMapper vtkCompositeSurfaceDetailMapper
 */

#ifndef vtkSurfaceDetailRepresentation_h
#define vtkSurfaceDetailRepresentation_h

#include "SurfaceDetailRepresentationModule.h" // For export macro
#include "vtkGeometryRepresentationWithFaces.h"

class vtkSurfaceDetailMapper;
class vtkTexture;

class SURFACEDETAILREPRESENTATION_EXPORT vtkSurfaceDetailRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkSurfaceDetailRepresentation* New();
  vtkTypeMacro(vtkSurfaceDetailRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Forwarded to the shared vtkSurfaceDetailMapper (see there).
   */
  void SetTechnique(int technique);
  void SetNormalMap(vtkTexture* map);
  void SetHeightMap(vtkTexture* map);
  void SetReliefMap(vtkTexture* map);
  void SetConeMap(vtkTexture* map);
  void SetHeightComponent(int component);
  void SetNormalScale(double scale);
  void SetGreenUp(bool greenUp);
  void SetBumpScale(double scale);
  void SetDifferenceScheme(int scheme);
  void SetTangentFree(bool tangentFree);
  void SetTriplanar(bool triplanar);
  void SetTriplanarSpace(int space);
  void SetTriplanarScale(double scale);
  void SetTriplanarSharpness(double sharpness);
  void SetDepthScale(double depth);
  void SetLinearSearchSteps(int steps);
  void SetBinarySearchSteps(int steps);
  void SetAdaptiveSteps(bool adaptive);
  void SetSelfShadowing(bool shadowing);
  void SetDepthCorrection(bool correction);
  ///@}

  /**
   * The settings both mappers draw with.
   */
  vtkSurfaceDetailMapper* GetDetail();

protected:
  vtkSurfaceDetailRepresentation();
  ~vtkSurfaceDetailRepresentation() override = default;

private:
  vtkSurfaceDetailRepresentation(const vtkSurfaceDetailRepresentation&) = delete;
  void operator=(const vtkSurfaceDetailRepresentation&) = delete;
};

#endif
