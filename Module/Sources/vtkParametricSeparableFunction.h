// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParametricSeparableFunction
 * @brief   A parametric surface whose evaluation splits into work on u alone and on v alone.
 *
 * Most surfaces built for texturing are products of a curve in u and a curve in v: a
 * sphere's cos/sin of longitude and latitude, a profile and its turn about the axis. On a
 * grid the expensive part (trigonometry, a Bézier profile, an arc-length inversion) then
 * needs to be done once per column and once per row instead of once per point.
 * Subclasses split Evaluate() into:
 * - EvaluateUTerms(u, terms): the GetNumberOfUTerms() numbers that depend on u only;
 * - EvaluateVTerms(v, terms): the same for v;
 * - EvaluateTerms(uTerms, vTerms, P, D): the point and its derivatives from both, cheaply;
 * - EvaluateSecondDerivatives(uTerms, vTerms, D2): optionally, the second derivatives in
 *   closed form, from which vtkParametricSurfaceSource gives the change of the unit normal
 *   ("dNdu", "dNdv"); without them the source differences the first derivatives.
 * Evaluate() is exactly the first three calls, so the split and the plain evaluation give
 * identical results. vtkParametricSurfaceSource uses the split for any such function.
 *
 * @sa vtkParametricSurfaceSource vtkParametricSphere vtkParametricRevolution
 */

#ifndef vtkParametricSeparableFunction_h
#define vtkParametricSeparableFunction_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkParametricFunction.h"

#include <typeinfo> // For EvaluateRowOf

class SURFACEDETAILSOURCES_EXPORT vtkParametricSeparableFunction : public vtkParametricFunction
{
public:
  vtkTypeMacro(vtkParametricSeparableFunction, vtkParametricFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The most terms a subclass may use in either direction. */
  static constexpr int MaximumNumberOfTerms = 8;

  ///@{
  /** How many numbers EvaluateUTerms() and EvaluateVTerms() write (<= MaximumNumberOfTerms). */
  virtual int GetNumberOfUTerms() = 0;
  virtual int GetNumberOfVTerms() = 0;
  ///@}

  ///@{
  /** The parts of the evaluation that depend on u (v) only. Thread-safe. */
  virtual void EvaluateUTerms(double u, double* terms) = 0;
  virtual void EvaluateVTerms(double v, double* terms) = 0;
  ///@}

  /**
   * The point and its derivatives (Duvw[0..2] = dP/du, Duvw[3..5] = dP/dv, Duvw[6..8] = 0)
   * from the terms of its u and its v. Thread-safe.
   */
  virtual void EvaluateTerms(
    const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9]) = 0;

  /**
   * The points and first derivatives of @a count grid points of one row: column k's u terms
   * are uTerms[t * uStride + k] (t < GetNumberOfUTerms()), the row's v terms are vTerms, and
   * component c of the point, dP/du and dP/dv goes to P[c][k], Du[c][k] and Dv[c][k]. The same
   * values as EvaluateTerms() at each column, without a virtual call per point: SurfaceDetail's
   * functions define it with EvaluateRowOf(), in which their EvaluateTerms() is inlined. The
   * default calls EvaluateTerms() at each column. Thread-safe.
   */
  virtual void EvaluateRow(int count, const double* uTerms, vtkIdType uStride, const double* vTerms,
    double* const P[3], double* const Du[3], double* const Dv[3]);

  /**
   * The second derivatives d2P/du2 (D2[0..2]), d2P/dudv (D2[3..5]) and d2P/dv2 (D2[6..8])
   * from the same terms, if the subclass knows them in closed form: returns true then. The
   * default returns false, and vtkParametricSurfaceSource differences the first derivatives
   * instead. A subclass that changes the shape through EvaluateTerms() must override this too
   * (returning false is enough), or "dNdu"/"dNdv" describe its parent's shape. Thread-safe.
   */
  virtual bool EvaluateSecondDerivatives(const double* uTerms, const double* vTerms, double D2[9]);

  /** A surface: 2. */
  int GetDimension() override { return 2; }

  /** EvaluateUTerms, EvaluateVTerms, then EvaluateTerms. */
  void Evaluate(double uvw[3], double Pt[3], double Duvw[9]) final;

  /** No scalar: 0. */
  double EvaluateScalar(double uvw[3], double Pt[3], double Duvw[9]) override;

protected:
  vtkParametricSeparableFunction();
  ~vtkParametricSeparableFunction() override = default;

  /** terms[0] = cos(2 pi x), terms[1] = sin(2 pi x): the turn of the round surfaces. */
  static void EvaluateTurn(double x, double* terms);

  /**
   * EvaluateRow() for a subclass @a Function whose EvaluateTerms() is visible where this is
   * instantiated (its own source file), so that the call is inlined. An object of a class
   * derived from @a Function may have changed EvaluateTerms(): it gets the default, one virtual
   * call per point.
   */
  template <typename Function>
  static void EvaluateRowOf(Function& f, int count, const double* uTerms, vtkIdType uStride,
    const double* vTerms, double* const P[3], double* const Du[3], double* const Dv[3])
  {
    if (typeid(f) != typeid(Function))
    {
      f.vtkParametricSeparableFunction::EvaluateRow(count, uTerms, uStride, vTerms, P, Du, Dv);
      return;
    }
    const int numTerms = f.Function::GetNumberOfUTerms();
    for (int k = 0; k < count; ++k)
    {
      double u[MaximumNumberOfTerms], p[3], d[9];
      for (int t = 0; t < numTerms; ++t)
      {
        u[t] = uTerms[t * uStride + k];
      }
      f.Function::EvaluateTerms(u, vTerms, p, d);
      for (int c = 0; c < 3; ++c)
      {
        P[c][k] = p[c];
        Du[c][k] = d[c];
        Dv[c][k] = d[3 + c];
      }
    }
  }

private:
  vtkParametricSeparableFunction(const vtkParametricSeparableFunction&) = delete;
  void operator=(const vtkParametricSeparableFunction&) = delete;
};

#endif
