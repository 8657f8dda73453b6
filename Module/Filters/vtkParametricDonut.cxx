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
  const double a = 2.0 * vtkMath::Pi() * u;
  terms[0] = std::cos(a);
  terms[1] = std::sin(a);
}

void vtkParametricDonut::EvaluateVTerms(double v, double* terms)
{
  const double b = 2.0 * vtkMath::Pi() * v;
  terms[0] = std::cos(b);
  terms[1] = std::sin(b);
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
void vtkParametricDonut::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RingRadius: " << this->RingRadius << "\n";
  os << indent << "CrossSectionRadius: " << this->CrossSectionRadius << "\n";
}
