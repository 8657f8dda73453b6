#include "vtkParametricSeparableFunction.h"

#include "vtkMath.h"

#include <cmath>

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
double vtkParametricSeparableFunction::EvaluateScalar(double*, double*, double*)
{
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricSeparableFunction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
