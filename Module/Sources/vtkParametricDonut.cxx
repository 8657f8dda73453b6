// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParametricDonut.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkParametricDonut);

//------------------------------------------------------------------------------
vtkParametricDonut::vtkParametricDonut()
{
  this->JoinU = 1;
  this->JoinV = 1;
}

//------------------------------------------------------------------------------
void vtkParametricDonut::EvaluateUTerms(double u, double* terms)
{
  this->EvaluateTurn(u, terms);
}

void vtkParametricDonut::EvaluateVTerms(double v, double* terms)
{
  this->EvaluateTurn(v, terms);
}

void vtkParametricDonut::EvaluateTerms(
  const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9])
{
  const double twoPi = 2.0 * vtkMath::Pi();
  const double cu = uTerms[0], su = uTerms[1];
  const double cv = vTerms[0], sv = vTerms[1];
  const double r = this->CrossSectionRadius;
  const double ring = this->RingRadius + r * cv;
  Pt[0] = ring * cu;
  Pt[1] = ring * su;
  Pt[2] = r * sv;
  Duvw[0] = -twoPi * ring * su;
  Duvw[1] = twoPi * ring * cu;
  Duvw[2] = 0.0;
  Duvw[3] = -twoPi * r * sv * cu;
  Duvw[4] = -twoPi * r * sv * su;
  Duvw[5] = twoPi * r * cv;
  Duvw[6] = Duvw[7] = Duvw[8] = 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricDonut::EvaluateRow(int count, const double* uTerms, vtkIdType uStride,
  const double* vTerms, double* const P[3], double* const Du[3], double* const Dv[3])
{
  EvaluateRowOf(*this, count, uTerms, uStride, vTerms, P, Du, Dv);
}

//------------------------------------------------------------------------------
bool vtkParametricDonut::EvaluateSecondDerivatives(
  const double* uTerms, const double* vTerms, double D2[9])
{
  const double fourPi2 = 4.0 * vtkMath::Pi() * vtkMath::Pi();
  const double cu = uTerms[0], su = uTerms[1];
  const double cv = vTerms[0], sv = vTerms[1];
  const double r = this->CrossSectionRadius;
  const double ring = this->RingRadius + r * cv;
  D2[0] = -fourPi2 * ring * cu;
  D2[1] = -fourPi2 * ring * su;
  D2[2] = 0.0;
  D2[3] = fourPi2 * r * sv * su;
  D2[4] = -fourPi2 * r * sv * cu;
  D2[5] = 0.0;
  D2[6] = -fourPi2 * r * cv * cu;
  D2[7] = -fourPi2 * r * cv * su;
  D2[8] = -fourPi2 * r * sv;
  return true;
}
//------------------------------------------------------------------------------
void vtkParametricDonut::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RingRadius: " << this->RingRadius << "\n";
  os << indent << "CrossSectionRadius: " << this->CrossSectionRadius << "\n";
}
