// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParametricExtrusion
 * @brief   An extrusion (the gallery's "love pillar"): a Bézier profile in x-z swept up y.
 *
 * The profile gives (x, z) at parameter u; P(u,v) = (x, Height*v, z). u runs along the
 * profile (texture s), v up (texture t), as texturing code usually has it. Du x Dv = Height*(-z', 0, x')
 * points outward for a closed profile traversed from +x towards -z (the way
 * vtkParametricCylinder turns). The default profile is the heart of
 * vtkBezierProfile::SetToHeart(), whose seam sits at the dip between the lobes.
 *
 * @sa vtkBezierProfile vtkParametricSurfaceSource vtkParametricRevolution
 */

#ifndef vtkParametricExtrusion_h
#define vtkParametricExtrusion_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkParametricProfileFunction.h"

class SURFACEDETAILSOURCES_EXPORT vtkParametricExtrusion : public vtkParametricProfileFunction
{
public:
  static vtkParametricExtrusion* New();
  vtkTypeMacro(vtkParametricExtrusion, vtkParametricProfileFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Height of the extrusion along +y, from y = 0. Default 2. */
  vtkSetMacro(Height, double);
  vtkGetMacro(Height, double);
  ///@}

  ///@{
  /**
   * The split evaluation (see vtkParametricSeparableFunction). An invalid or missing
   * profile is reported as an error and gives zeros.
   */
  int GetNumberOfUTerms() override { return 6; }
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
  vtkParametricExtrusion();
  ~vtkParametricExtrusion() override;

  double Height = 2.0;

private:
  vtkParametricExtrusion(const vtkParametricExtrusion&) = delete;
  void operator=(const vtkParametricExtrusion&) = delete;
};

#endif
