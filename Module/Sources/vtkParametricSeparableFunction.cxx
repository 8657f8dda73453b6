// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
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
void vtkParametricSeparableFunction::EvaluateRow(int count, const double* uTerms, vtkIdType uStride,
  const double* vTerms, double* const P[3], double* const Du[3], double* const Dv[3])
{
  const int numTerms = this->GetNumberOfUTerms();
  for (int k = 0; k < count; ++k)
  {
    double u[MaximumNumberOfTerms], p[3], d[9];
    for (int t = 0; t < numTerms; ++t)
    {
      u[t] = uTerms[t * uStride + k];
    }
    this->EvaluateTerms(u, vTerms, p, d);
    for (int c = 0; c < 3; ++c)
    {
      P[c][k] = p[c];
      Du[c][k] = d[c];
      Dv[c][k] = d[3 + c];
    }
  }
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
