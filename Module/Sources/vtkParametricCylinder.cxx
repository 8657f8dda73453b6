// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParametricCylinder.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkParametricCylinder);

//------------------------------------------------------------------------------
vtkParametricCylinder::vtkParametricCylinder()
{
  this->JoinU = 1;
}

//------------------------------------------------------------------------------
void vtkParametricCylinder::EvaluateUTerms(double u, double* terms)
{
  this->EvaluateTurn(u, terms);
}

void vtkParametricCylinder::EvaluateVTerms(double v, double* terms)
{
  terms[0] = v;
}

void vtkParametricCylinder::EvaluateTerms(
  const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9])
{
  const double twoPi = 2.0 * vtkMath::Pi();
  const double c = uTerms[0], s = uTerms[1];
  const double r = this->Radius;
  Pt[0] = r * c;
  Pt[1] = this->Height * vTerms[0];
  Pt[2] = -r * s;
  Duvw[0] = -twoPi * r * s;
  Duvw[1] = 0.0;
  Duvw[2] = -twoPi * r * c;
  Duvw[3] = 0.0;
  Duvw[4] = this->Height;
  Duvw[5] = 0.0;
  Duvw[6] = Duvw[7] = Duvw[8] = 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricCylinder::EvaluateRow(int count, const double* uTerms, vtkIdType uStride,
  const double* vTerms, double* const P[3], double* const Du[3], double* const Dv[3])
{
  EvaluateRowOf(*this, count, uTerms, uStride, vTerms, P, Du, Dv);
}

bool vtkParametricCylinder::EvaluateSecondDerivatives(
  const double* uTerms, const double*, double D2[9])
{
  const double fourPi2 = 4.0 * vtkMath::Pi() * vtkMath::Pi();
  D2[0] = -fourPi2 * this->Radius * uTerms[0];
  D2[1] = 0.0;
  D2[2] = fourPi2 * this->Radius * uTerms[1];
  for (int k = 3; k < 9; ++k)
  {
    D2[k] = 0.0;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkParametricCylinder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Height: " << this->Height << "\n";
}
