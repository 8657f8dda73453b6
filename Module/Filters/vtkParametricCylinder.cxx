#include "vtkParametricCylinder.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkParametricCylinder);

//------------------------------------------------------------------------------
vtkParametricCylinder::vtkParametricCylinder()
{
  this->MinimumU = 0.0;
  this->MaximumU = 1.0;
  this->MinimumV = 0.0;
  this->MaximumV = 1.0;
  this->JoinU = 1;
  this->JoinV = 0;
  this->TwistU = 0;
  this->TwistV = 0;
  this->ClockwiseOrdering = 1; // Du x Dv is outward
  this->DerivativesAvailable = 1;
}

//------------------------------------------------------------------------------
void vtkParametricCylinder::Evaluate(double uvw[3], double Pt[3], double Duvw[9])
{
  const double twoPi = 2.0 * vtkMath::Pi();
  const double theta = twoPi * uvw[0];
  const double c = std::cos(theta), s = std::sin(theta);
  const double r = this->Radius;
  Pt[0] = r * c;
  Pt[1] = this->Height * uvw[1];
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
double vtkParametricCylinder::EvaluateScalar(double*, double*, double*)
{
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricCylinder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Height: " << this->Height << "\n";
}
