// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParametricDonut
 * @brief   A torus ("donut"), z up, on the unit square.
 *
 * P(u,v) = ((R + r cos 2 pi v) cos 2 pi u, (R + r cos 2 pi v) sin 2 pi u, r sin 2 pi v) with
 * R = RingRadius and r = CrossSectionRadius: u runs round the ring (counter-clockwise seen
 * from +z), v round the tube (outer equator first, then the top). Du x Dv points outward,
 * so a texture reads the right way round from outside. VTK's vtkParametricTorus is the same
 * surface with x and y swapped, i.e. mirrored.
 *
 * @sa vtkParametricSurfaceSource vtkParametricTorus
 */

#ifndef vtkParametricDonut_h
#define vtkParametricDonut_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkParametricSeparableFunction.h"

class SURFACEDETAILSOURCES_EXPORT vtkParametricDonut : public vtkParametricSeparableFunction
{
public:
  static vtkParametricDonut* New();
  vtkTypeMacro(vtkParametricDonut, vtkParametricSeparableFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** R: distance from the centre to the middle of the tube. Default 1. */
  vtkSetMacro(RingRadius, double);
  vtkGetMacro(RingRadius, double);
  ///@}

  ///@{
  /** r: radius of the tube. Default 0.4. */
  vtkSetMacro(CrossSectionRadius, double);
  vtkGetMacro(CrossSectionRadius, double);
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
  vtkParametricDonut();
  ~vtkParametricDonut() override = default;

  double RingRadius = 1.0;
  double CrossSectionRadius = 0.4;

private:
  vtkParametricDonut(const vtkParametricDonut&) = delete;
  void operator=(const vtkParametricDonut&) = delete;
};

#endif
