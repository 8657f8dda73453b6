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
  // (r, y, dr/dv, dy/dv)
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

void vtkParametricRevolution::EvaluateTermsBlock(const double* const* uTerms, const double* vTerms,
  int count, double* const* P, double* const* Du, double* const* Dv)
{
  // EvaluateTerms()' products of the row, in its order, so the results are the same bits.
  const double twoPi = 2.0 * vtkMath::Pi();
  const double r = vTerms[0], y = vTerms[1], dr = vTerms[2], dy = vTerms[3];
  const double row[7] = { r, y, -r, -twoPi * r, dr, dy, -dr };
  this->EvaluateTurnBlock(uTerms, row, count, P, Du, Dv);
}

//------------------------------------------------------------------------------
void vtkParametricRevolution::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
