#include "vtkParametricSphere.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkParametricSphere);

//------------------------------------------------------------------------------
vtkParametricSphere::vtkParametricSphere()
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
void vtkParametricSphere::Evaluate(double uvw[3], double Pt[3], double Duvw[9])
{
  const double twoPi = 2.0 * vtkMath::Pi();
  const double theta = twoPi * uvw[0];
  const double alpha = vtkMath::Pi() * (1.0 - uvw[1]);
  const double ct = std::cos(theta), st = std::sin(theta);
  const double ca = std::cos(alpha), sa = std::sin(alpha);
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
double vtkParametricSphere::EvaluateScalar(double*, double*, double*)
{
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricSphere::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
}
