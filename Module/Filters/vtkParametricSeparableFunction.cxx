#include "vtkParametricSeparableFunction.h"

#include "vtkMath.h"
#include "vtkSurfaceDetailVectorize.h"

#include <cmath>

// AVX2 halves the vector stores of the row loops (vtkSurfaceDetailVectorize.h).

namespace
{
// One run of a row; restrict parameters, because the compiler gives up on checking nine
// output pointers for overlap at run time and would stay scalar.
SURFACEDETAIL_WIDE_VECTORS void TurnRun(int count, const double* __restrict c,
  const double* __restrict s, const double* row, double* __restrict px, double* __restrict py,
  double* __restrict pz, double* __restrict dux, double* __restrict duy, double* __restrict duz,
  double* __restrict dvx, double* __restrict dvy, double* __restrict dvz)
{
  const double x = row[0], y = row[1], z = row[2], du = row[3], dvX = row[4], dvY = row[5],
               dvZ = row[6];
  for (int k = 0; k < count; ++k)
  {
    px[k] = x * c[k];
    py[k] = y;
    pz[k] = z * s[k];
    dux[k] = du * s[k];
    duy[k] = 0.0;
    duz[k] = du * c[k];
    dvx[k] = dvX * c[k];
    dvy[k] = dvY;
    dvz[k] = dvZ * s[k];
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkParametricSeparableFunction::vtkParametricSeparableFunction()
{
  // SurfaceDetail's functions live on the unit square with Du x Dv facing out.
  this->MinimumU = 0.0;
  this->MaximumU = 1.0;
  this->MinimumV = 0.0;
  this->MaximumV = 1.0;
  this->JoinU = 0;
  this->JoinV = 0;
  this->TwistU = 0;
  this->TwistV = 0;
  this->ClockwiseOrdering = 1;
  this->DerivativesAvailable = 1;
}

//------------------------------------------------------------------------------
void vtkParametricSeparableFunction::Evaluate(double uvw[3], double Pt[3], double Duvw[9])
{
  double uTerms[MaximumNumberOfTerms];
  double vTerms[MaximumNumberOfTerms];
  this->EvaluateUTerms(uvw[0], uTerms);
  this->EvaluateVTerms(uvw[1], vTerms);
  this->EvaluateTerms(uTerms, vTerms, Pt, Duvw);
}

//------------------------------------------------------------------------------
void vtkParametricSeparableFunction::EvaluateTermsBlock(const double* const* uTerms,
  const double* vTerms, int count, double* const* P, double* const* Du, double* const* Dv)
{
  const int numUTerms = this->GetNumberOfUTerms();
  for (int k = 0; k < count; ++k)
  {
    double u[MaximumNumberOfTerms];
    for (int t = 0; t < numUTerms; ++t)
    {
      u[t] = uTerms[t][k];
    }
    double point[3];
    double d[9];
    this->EvaluateTerms(u, vTerms, point, d);
    for (int c = 0; c < 3; ++c)
    {
      P[c][k] = point[c];
      Du[c][k] = d[c];
      Dv[c][k] = d[3 + c];
    }
  }
}

//------------------------------------------------------------------------------
void vtkParametricSeparableFunction::EvaluateTurn(double x, double* terms)
{
  const double angle = 2.0 * vtkMath::Pi() * x;
  terms[0] = std::cos(angle);
  terms[1] = std::sin(angle);
}

//------------------------------------------------------------------------------
void vtkParametricSeparableFunction::EvaluateTurnBlock(const double* const* uTerms,
  const double row[7], int count, double* const* P, double* const* Du, double* const* Dv)
{
  TurnRun(
    count, uTerms[0], uTerms[1], row, P[0], P[1], P[2], Du[0], Du[1], Du[2], Dv[0], Dv[1], Dv[2]);
}

//------------------------------------------------------------------------------
double vtkParametricSeparableFunction::EvaluateScalar(double*, double*, double*)
{
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricSeparableFunction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
