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
bool vtkParametricSeparableFunction::EvaluateSecondDerivatives(
  const double*, const double*, double*)
{
  return false;
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
