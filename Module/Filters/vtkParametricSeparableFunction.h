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
 * - EvaluateTerms(uTerms, vTerms, P, D): the point and its derivatives from both, cheaply.
 * Evaluate() is exactly these three calls, so the split and the plain evaluation give
 * identical results. EvaluateTermsBlock() is EvaluateTerms() for a run of points of one
 * row, which subclasses may override with a loop the compiler vectorises.
 * vtkParametricSurfaceSource uses the split for any such function.
 *
 * @sa vtkParametricSurfaceSource vtkParametricSphere vtkParametricRevolution
 */

#ifndef vtkParametricSeparableFunction_h
#define vtkParametricSeparableFunction_h

#include "SurfaceDetailFiltersModule.h" // For export macro
#include "vtkParametricFunction.h"

class SURFACEDETAILFILTERS_EXPORT vtkParametricSeparableFunction : public vtkParametricFunction
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

  /** A surface: 2. */
  int GetDimension() override { return 2; }

  /**
   * EvaluateTerms() for @a count points that share the v terms @a vTerms (a run of one row
   * of a grid), in structure-of-arrays form: uTerms[t][k] is u term t of point k, and
   * component c of point k's position, dP/du and dP/dv goes to P[c][k], Du[c][k] and
   * Dv[c][k]. The results are EvaluateTerms()' bit for bit. The default calls
   * EvaluateTerms() per point. Thread-safe.
   */
  virtual void EvaluateTermsBlock(const double* const* uTerms, const double* vTerms, int count,
    double* const* P, double* const* Du, double* const* Dv);

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
   * EvaluateTermsBlock() of a surface turned about the y axis, from the turn's terms
   * (c, s) = (uTerms[0][k], uTerms[1][k]) and seven numbers of the row:
   * P = (row[0] c, row[1], row[2] s), dP/du = (row[3] s, 0, row[3] c),
   * dP/dv = (row[4] c, row[5], row[6] s). A subclass gets EvaluateTerms()' bits when it
   * computes the row numbers as the products EvaluateTerms() forms before multiplying by
   * c or s.
   */
  static void EvaluateTurnBlock(const double* const* uTerms, const double row[7], int count,
    double* const* P, double* const* Du, double* const* Dv);

private:
  vtkParametricSeparableFunction(const vtkParametricSeparableFunction&) = delete;
  void operator=(const vtkParametricSeparableFunction&) = delete;
};

#endif
