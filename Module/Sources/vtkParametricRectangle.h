// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParametricRectangle
 * @brief   A parallelogram on the unit square, as a textured brick wall is mapped.
 *
 * P(u,v) = Origin + u*(Point1 - Origin) + v*(Point2 - Origin): u runs from Origin to Point1
 * (texture s), v from Origin to Point2 (texture t), as vtkPlaneSource's corners. The normal
 * is (Point1 - Origin) x (Point2 - Origin). The default is the gallery's wall, x in [-2, 2],
 * y in [0, 3.5], facing +z.
 *
 * @sa vtkParametricSurfaceSource vtkPlaneSource
 */

#ifndef vtkParametricRectangle_h
#define vtkParametricRectangle_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkParametricSeparableFunction.h"

class SURFACEDETAILSOURCES_EXPORT vtkParametricRectangle : public vtkParametricSeparableFunction
{
public:
  static vtkParametricRectangle* New();
  vtkTypeMacro(vtkParametricRectangle, vtkParametricSeparableFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The corner at (u,v) = (0,0). Default (-2, 0, 0). */
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  ///@}

  ///@{
  /** The corner at (u,v) = (1,0). Default (2, 0, 0). */
  vtkSetVector3Macro(Point1, double);
  vtkGetVector3Macro(Point1, double);
  ///@}

  ///@{
  /** The corner at (u,v) = (0,1). Default (-2, 3.5, 0). */
  vtkSetVector3Macro(Point2, double);
  vtkGetVector3Macro(Point2, double);
  ///@}

  ///@{
  /** The split evaluation (see vtkParametricSeparableFunction). */
  int GetNumberOfUTerms() override { return 1; }
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
  vtkParametricRectangle();
  ~vtkParametricRectangle() override = default;

  double Origin[3] = { -2.0, 0.0, 0.0 };
  double Point1[3] = { 2.0, 0.0, 0.0 };
  double Point2[3] = { -2.0, 3.5, 0.0 };

private:
  vtkParametricRectangle(const vtkParametricRectangle&) = delete;
  void operator=(const vtkParametricRectangle&) = delete;
};

#endif
