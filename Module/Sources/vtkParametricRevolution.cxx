// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParametricRevolution.h"

#include "vtkBezierProfile.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkParametricRevolution);

//------------------------------------------------------------------------------
vtkParametricRevolution::vtkParametricRevolution()
{
  this->Profile->SetToVase();
}

vtkParametricRevolution::~vtkParametricRevolution() = default;

//------------------------------------------------------------------------------
void vtkParametricRevolution::EvaluateUTerms(double u, double* terms)
{
  this->EvaluateTurn(u, terms);
}

void vtkParametricRevolution::EvaluateVTerms(double v, double* terms)
{
  // (r, y, dr/dv, dy/dv, d2r/dv2, d2y/dv2)
  this->EvaluateProfile(v, terms, "surface of revolution");
}

void vtkParametricRevolution::EvaluateTerms(
  const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9])
{
  const double twoPi = 2.0 * vtkMath::Pi();
  const double c = uTerms[0], s = uTerms[1];
  const double r = vTerms[0], y = vTerms[1], dr = vTerms[2], dy = vTerms[3];
  Pt[0] = r * c;
  Pt[1] = y;
  Pt[2] = -r * s;
  Duvw[0] = -twoPi * r * s;
  Duvw[1] = 0.0;
  Duvw[2] = -twoPi * r * c;
  Duvw[3] = dr * c;
  Duvw[4] = dy;
  Duvw[5] = -dr * s;
  Duvw[6] = Duvw[7] = Duvw[8] = 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricRevolution::EvaluateRow(int count, const double* uTerms, vtkIdType uStride,
  const double* vTerms, double* const P[3], double* const Du[3], double* const Dv[3])
{
  EvaluateRowOf(*this, count, uTerms, uStride, vTerms, P, Du, Dv);
}

bool vtkParametricRevolution::EvaluateSecondDerivatives(
  const double* uTerms, const double* vTerms, double D2[9])
{
  const double twoPi = 2.0 * vtkMath::Pi();
  const double c = uTerms[0], s = uTerms[1];
  const double r = vTerms[0], dr = vTerms[2], ddr = vTerms[4], ddy = vTerms[5];
  D2[0] = -twoPi * twoPi * r * c;
  D2[1] = 0.0;
  D2[2] = twoPi * twoPi * r * s;
  D2[3] = -twoPi * dr * s;
  D2[4] = 0.0;
  D2[5] = -twoPi * dr * c;
  D2[6] = ddr * c;
  D2[7] = ddy;
  D2[8] = -ddr * s;
  return true;
}
//------------------------------------------------------------------------------
void vtkParametricRevolution::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
