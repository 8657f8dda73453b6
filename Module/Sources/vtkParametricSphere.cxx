// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParametricSphere.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkParametricSphere);

//------------------------------------------------------------------------------
vtkParametricSphere::vtkParametricSphere()
{
  this->JoinU = 1;
}

//------------------------------------------------------------------------------
void vtkParametricSphere::EvaluateUTerms(double u, double* terms)
{
  this->EvaluateTurn(u, terms);
}

void vtkParametricSphere::EvaluateVTerms(double v, double* terms)
{
  const double alpha = vtkMath::Pi() * (1.0 - v);
  terms[0] = std::cos(alpha);
  terms[1] = std::sin(alpha);
}

void vtkParametricSphere::EvaluateTerms(
  const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9])
{
  const double twoPi = 2.0 * vtkMath::Pi();
  const double ct = uTerms[0], st = uTerms[1];
  const double ca = vTerms[0], sa = vTerms[1];
  const double r = this->Radius;
  Pt[0] = r * sa * ct;
  Pt[1] = r * ca;
  Pt[2] = -r * sa * st;
  // dP/du = 2 pi dP/dtheta; dP/dv = -pi dP/dalpha.
  Duvw[0] = -twoPi * r * sa * st;
  Duvw[1] = 0.0;
  Duvw[2] = -twoPi * r * sa * ct;
  Duvw[3] = -vtkMath::Pi() * r * ca * ct;
  Duvw[4] = vtkMath::Pi() * r * sa;
  Duvw[5] = vtkMath::Pi() * r * ca * st;
  Duvw[6] = Duvw[7] = Duvw[8] = 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricSphere::EvaluateRow(int count, const double* uTerms, vtkIdType uStride,
  const double* vTerms, double* const P[3], double* const Du[3], double* const Dv[3])
{
  EvaluateRowOf(*this, count, uTerms, uStride, vTerms, P, Du, Dv);
}

bool vtkParametricSphere::EvaluateSecondDerivatives(
  const double* uTerms, const double* vTerms, double D2[9])
{
  const double pi = vtkMath::Pi();
  const double ct = uTerms[0], st = uTerms[1];
  const double ca = vTerms[0], sa = vTerms[1];
  const double r = this->Radius;
  // theta = 2 pi u and alpha = pi (1 - v): each u derivative brings 2 pi, each v one -pi.
  const double uu = -4.0 * pi * pi * r * sa;
  D2[0] = uu * ct;
  D2[1] = 0.0;
  D2[2] = -uu * st;
  const double uv = 2.0 * pi * pi * r * ca;
  D2[3] = uv * st;
  D2[4] = 0.0;
  D2[5] = uv * ct;
  const double vv = pi * pi * r;
  D2[6] = -vv * sa * ct;
  D2[7] = -vv * ca;
  D2[8] = vv * sa * st;
  return true;
}
//------------------------------------------------------------------------------
void vtkParametricSphere::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
}
