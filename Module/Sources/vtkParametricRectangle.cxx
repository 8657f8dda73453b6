// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParametricRectangle.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkParametricRectangle);

//------------------------------------------------------------------------------
vtkParametricRectangle::vtkParametricRectangle() = default;

//------------------------------------------------------------------------------
void vtkParametricRectangle::EvaluateUTerms(double u, double* terms)
{
  terms[0] = u;
}

void vtkParametricRectangle::EvaluateVTerms(double v, double* terms)
{
  terms[0] = v;
}

void vtkParametricRectangle::EvaluateTerms(
  const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9])
{
  for (int k = 0; k < 3; ++k)
  {
    const double du = this->Point1[k] - this->Origin[k];
    const double dv = this->Point2[k] - this->Origin[k];
    Pt[k] = this->Origin[k] + uTerms[0] * du + vTerms[0] * dv;
    Duvw[k] = du;
    Duvw[3 + k] = dv;
    Duvw[6 + k] = 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkParametricRectangle::EvaluateRow(int count, const double* uTerms, vtkIdType uStride,
  const double* vTerms, double* const P[3], double* const Du[3], double* const Dv[3])
{
  EvaluateRowOf(*this, count, uTerms, uStride, vTerms, P, Du, Dv);
}

bool vtkParametricRectangle::EvaluateSecondDerivatives(const double*, const double*, double D2[9])
{
  for (int k = 0; k < 9; ++k)
  {
    D2[k] = 0.0;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkParametricRectangle::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "Point1: (" << this->Point1[0] << ", " << this->Point1[1] << ", "
     << this->Point1[2] << ")\n";
  os << indent << "Point2: (" << this->Point2[0] << ", " << this->Point2[1] << ", "
     << this->Point2[2] << ")\n";
}
