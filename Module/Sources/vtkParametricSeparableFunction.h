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

private:
  vtkParametricSeparableFunction(const vtkParametricSeparableFunction&) = delete;
  void operator=(const vtkParametricSeparableFunction&) = delete;
};

#endif
