// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParametricExtrusion.h"

#include "vtkBezierProfile.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkParametricExtrusion);

//------------------------------------------------------------------------------
vtkParametricExtrusion::vtkParametricExtrusion()
{
  this->Profile->SetToHeart();
}

vtkParametricExtrusion::~vtkParametricExtrusion() = default;

//------------------------------------------------------------------------------
void vtkParametricExtrusion::EvaluateUTerms(double u, double* terms)
{
  // (x, z, dx/du, dz/du, d2x/du2, d2z/du2)
  this->EvaluateProfile(u, terms, "extrusion");
}

void vtkParametricExtrusion::EvaluateVTerms(double v, double* terms)
{
  terms[0] = v;
}

void vtkParametricExtrusion::EvaluateTerms(
  const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9])
{
  Pt[0] = uTerms[0];
  Pt[1] = this->Height * vTerms[0];
  Pt[2] = uTerms[1];
  Duvw[0] = uTerms[2];
  Duvw[1] = 0.0;
  Duvw[2] = uTerms[3];
  Duvw[3] = 0.0;
  Duvw[4] = this->Height;
  Duvw[5] = 0.0;
  Duvw[6] = Duvw[7] = Duvw[8] = 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricExtrusion::EvaluateRow(int count, const double* uTerms, vtkIdType uStride,
  const double* vTerms, double* const P[3], double* const Du[3], double* const Dv[3])
{
  EvaluateRowOf(*this, count, uTerms, uStride, vTerms, P, Du, Dv);
}

bool vtkParametricExtrusion::EvaluateSecondDerivatives(
  const double* uTerms, const double*, double D2[9])
{
  D2[0] = uTerms[4];
  D2[1] = 0.0;
  D2[2] = uTerms[5];
  for (int k = 3; k < 9; ++k)
  {
    D2[k] = 0.0;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkParametricExtrusion::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Height: " << this->Height << "\n";
}
