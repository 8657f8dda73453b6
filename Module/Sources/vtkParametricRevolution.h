// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParametricRevolution
 * @brief   A surface of revolution (the gallery's "marble vase"): a Bézier profile turned about y.
 *
 * The profile gives (r, y) at parameter v; with theta = 2*pi*u (turning from +x towards -z),
 * P(u,v) = (r cos(theta), y, -r sin(theta)). u runs round (texture s), v along the profile
 * (texture t). Du x Dv points outward where the profile rises (dy/dv > 0) at positive r.
 * Where the profile touches the axis (r = 0) Du vanishes; vtkParametricSurfaceSource takes
 * the limit there. The default profile is the vase of vtkBezierProfile::SetToVase(); turn
 * on the profile's ArcLengthParameterization to spread the texture evenly along it.
 *
 * @sa vtkBezierProfile vtkParametricSurfaceSource vtkParametricExtrusion
 */

#ifndef vtkParametricRevolution_h
#define vtkParametricRevolution_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkParametricProfileFunction.h"

class SURFACEDETAILSOURCES_EXPORT vtkParametricRevolution : public vtkParametricProfileFunction
{
public:
  static vtkParametricRevolution* New();
  vtkTypeMacro(vtkParametricRevolution, vtkParametricProfileFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The split evaluation (see vtkParametricSeparableFunction). An invalid or missing
   * profile is reported as an error and gives zeros.
   */
  int GetNumberOfUTerms() override { return 2; }
  int GetNumberOfVTerms() override { return 6; }
  void EvaluateUTerms(double u, double* terms) override;
  void EvaluateVTerms(double v, double* terms) override;
  void EvaluateTerms(
    const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9]) override;
  bool EvaluateSecondDerivatives(const double* uTerms, const double* vTerms, double D2[9]) override;
  void EvaluateRow(int count, const double* uTerms, vtkIdType uStride, const double* vTerms,
    double* const P[3], double* const Du[3], double* const Dv[3]) override;
  ///@}

protected:
  vtkParametricRevolution();
  ~vtkParametricRevolution() override;

private:
  vtkParametricRevolution(const vtkParametricRevolution&) = delete;
  void operator=(const vtkParametricRevolution&) = delete;
};

#endif
