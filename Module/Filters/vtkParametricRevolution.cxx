#include "vtkParametricRevolution.h"

#include "vtkBezierProfile.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkParametricRevolution);

//------------------------------------------------------------------------------
vtkParametricRevolution::vtkParametricRevolution()
  : Profile(vtkSmartPointer<vtkBezierProfile>::New())
{
  this->Profile->SetToVase();
  this->MinimumU = 0.0;
  this->MaximumU = 1.0;
  this->MinimumV = 0.0;
  this->MaximumV = 1.0;
  this->JoinU = 1;
  this->JoinV = 0;
  this->TwistU = 0;
  this->TwistV = 0;
  this->ClockwiseOrdering = 1; // Du x Dv is outward for a rising profile
  this->DerivativesAvailable = 1;
}

vtkParametricRevolution::~vtkParametricRevolution() = default;

//------------------------------------------------------------------------------
void vtkParametricRevolution::SetProfile(vtkBezierProfile* profile)
{
  if (this->Profile != profile)
  {
    this->Profile = profile;
    this->Modified();
  }
}

vtkBezierProfile* vtkParametricRevolution::GetProfile()
{
  return this->Profile;
}

vtkMTimeType vtkParametricRevolution::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->Profile)
  {
    mtime = std::max(mtime, this->Profile->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
void vtkParametricRevolution::Evaluate(double uvw[3], double Pt[3], double Duvw[9])
{
  std::fill(Pt, Pt + 3, 0.0);
  std::fill(Duvw, Duvw + 9, 0.0);
  double p[2], d[2];
  std::string reason = "there is no profile";
  if (!this->Profile || !this->Profile->IsValid(&reason) ||
    !this->Profile->Evaluate(uvw[1], p, d, nullptr))
  {
    vtkErrorMacro("Cannot evaluate the surface of revolution: " << reason << "; see SetProfile().");
    return;
  }
  const double twoPi = 2.0 * vtkMath::Pi();
  const double c = std::cos(twoPi * uvw[0]), s = std::sin(twoPi * uvw[0]);
  Pt[0] = p[0] * c;
  Pt[1] = p[1];
  Pt[2] = -p[0] * s;
  Duvw[0] = -twoPi * p[0] * s;
  Duvw[2] = -twoPi * p[0] * c;
  Duvw[3] = d[0] * c;
  Duvw[4] = d[1];
  Duvw[5] = -d[0] * s;
}

//------------------------------------------------------------------------------
double vtkParametricRevolution::EvaluateScalar(double*, double*, double*)
{
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricRevolution::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Profile: " << this->Profile.Get() << "\n";
  if (this->Profile)
  {
    this->Profile->PrintSelf(os, indent.GetNextIndent());
  }
}
