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

void vtkParametricSphere::EvaluateTermsBlock(const double* const* uTerms, const double* vTerms,
  int count, double* const* P, double* const* Du, double* const* Dv)
{
  // EvaluateTerms() with its products that depend on v only taken out of the loop, in the
  // same order of operations, so the results are the same bits.
  const double twoPi = 2.0 * vtkMath::Pi();
  const double ca = vTerms[0], sa = vTerms[1];
  const double r = this->Radius;
  const double row[7] = { r * sa, r * ca, -r * sa, -twoPi * r * sa, -vtkMath::Pi() * r * ca,
    vtkMath::Pi() * r * sa, vtkMath::Pi() * r * ca };
  this->EvaluateTurnBlock(uTerms, row, count, P, Du, Dv);
}

//------------------------------------------------------------------------------
void vtkParametricSphere::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
}
