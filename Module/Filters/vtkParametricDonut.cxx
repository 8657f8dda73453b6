#include "vtkParametricDonut.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkParametricDonut);

//------------------------------------------------------------------------------
vtkParametricDonut::vtkParametricDonut()
{
  this->MinimumU = 0.0;
  this->MaximumU = 1.0;
  this->MinimumV = 0.0;
  this->MaximumV = 1.0;
  this->JoinU = 1;
  this->JoinV = 1;
  this->TwistU = 0;
  this->TwistV = 0;
  this->ClockwiseOrdering = 1; // Du x Dv is outward
  this->DerivativesAvailable = 1;
}

//------------------------------------------------------------------------------
void vtkParametricDonut::Evaluate(double uvw[3], double Pt[3], double Duvw[9])
{
  const double twoPi = 2.0 * vtkMath::Pi();
  const double cu = std::cos(twoPi * uvw[0]), su = std::sin(twoPi * uvw[0]);
  const double cv = std::cos(twoPi * uvw[1]), sv = std::sin(twoPi * uvw[1]);
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
double vtkParametricDonut::EvaluateScalar(double*, double*, double*)
{
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricDonut::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RingRadius: " << this->RingRadius << "\n";
  os << indent << "CrossSectionRadius: " << this->CrossSectionRadius << "\n";
}
