// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParametricCylinder
 * @brief   A y-up cylinder (a label wrapped round a can) on the unit square.
 *
 * With theta = 2*pi*u (turning from +x towards -z),
 * P(u,v) = (Radius cos(theta), Height*v, -Radius sin(theta)): u runs round the side and v
 * up it, so a texture wraps once round like paper with its top edge at y = Height.
 * Du x Dv points outward. Open at both ends.
 *
 * @sa vtkParametricSurfaceSource vtkParametricRevolution
 */

#ifndef vtkParametricCylinder_h
#define vtkParametricCylinder_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkParametricSeparableFunction.h"

class SURFACEDETAILSOURCES_EXPORT vtkParametricCylinder : public vtkParametricSeparableFunction
{
public:
  static vtkParametricCylinder* New();
  vtkTypeMacro(vtkParametricCylinder, vtkParametricSeparableFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Radius of the cylinder. Default 1. */
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /** Height along +y, from y = 0. Default 2. */
  vtkSetMacro(Height, double);
  vtkGetMacro(Height, double);
  ///@}

  ///@{
  /** The split evaluation (see vtkParametricSeparableFunction). */
  int GetNumberOfUTerms() override { return 2; }
  int GetNumberOfVTerms() override { return 1; }
  void EvaluateUTerms(double u, double* terms) override;
  void EvaluateVTerms(double v, double* terms) override;
  void EvaluateTerms(
    const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9]) override;
  bool EvaluateSecondDerivatives(const double* uTerms, const double* vTerms, double D2[9]) override;
  void EvaluateRow(int count, const double* uTerms, vtkIdType uStride, const double* vTerms,
    double* const P[3], double* const Du[3], double* const Dv[3]) override;
  ///@}

protected:
  vtkParametricCylinder();
  ~vtkParametricCylinder() override = default;

  double Radius = 1.0;
  double Height = 2.0;

private:
  vtkParametricCylinder(const vtkParametricCylinder&) = delete;
  void operator=(const vtkParametricCylinder&) = delete;
};

#endif
