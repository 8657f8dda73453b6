// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParametricSphere
 * @brief   A y-up sphere on the unit square, for equirectangular textures.
 *
 * With theta = 2*pi*u (turning from +x towards -z) and alpha = pi*(1 - v) (the angle from
 * +y), P(u,v) = Radius*(sin(alpha) cos(theta), cos(alpha), -sin(alpha) sin(theta)).
 * Texture coordinates (u,v) then put an equirectangular map (an Earth map, a sky) upright:
 * v = 0 is the south pole, v = 1 the north pole, u = 0.5 faces -x. Du x Dv points outward.
 * The derivatives are analytic; Du vanishes at the poles (vtkParametricSurfaceSource takes
 * the limit there).
 *
 * @sa vtkParametricSurfaceSource vtkParametricEllipsoid
 */

#ifndef vtkParametricSphere_h
#define vtkParametricSphere_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkParametricSeparableFunction.h"

class SURFACEDETAILSOURCES_EXPORT vtkParametricSphere : public vtkParametricSeparableFunction
{
public:
  static vtkParametricSphere* New();
  vtkTypeMacro(vtkParametricSphere, vtkParametricSeparableFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Radius of the sphere. Default 1. */
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * The split evaluation (see vtkParametricSeparableFunction).
   */
  int GetNumberOfUTerms() override { return 2; }
  int GetNumberOfVTerms() override { return 2; }
  void EvaluateUTerms(double u, double* terms) override;
  void EvaluateVTerms(double v, double* terms) override;
  void EvaluateTerms(
    const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9]) override;
  bool EvaluateSecondDerivatives(const double* uTerms, const double* vTerms, double D2[9]) override;
  void EvaluateRow(int count, const double* uTerms, vtkIdType uStride, const double* vTerms,
    double* const P[3], double* const Du[3], double* const Dv[3]) override;
  ///@}

protected:
  vtkParametricSphere();
  ~vtkParametricSphere() override = default;

  double Radius = 1.0;

private:
  vtkParametricSphere(const vtkParametricSphere&) = delete;
  void operator=(const vtkParametricSphere&) = delete;
};

#endif
