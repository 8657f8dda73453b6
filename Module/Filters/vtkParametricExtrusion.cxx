#include "vtkParametricExtrusion.h"

#include "vtkBezierProfile.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <string>

vtkStandardNewMacro(vtkParametricExtrusion);

//------------------------------------------------------------------------------
vtkParametricExtrusion::vtkParametricExtrusion()
  : Profile(vtkSmartPointer<vtkBezierProfile>::New())
{
  this->Profile->SetToHeart();
  this->MinimumU = 0.0;
  this->MaximumU = 1.0;
  this->MinimumV = 0.0;
  this->MaximumV = 1.0;
  this->JoinU = 1;
  this->JoinV = 0;
  this->TwistU = 0;
  this->TwistV = 0;
  this->ClockwiseOrdering = 1; // Du x Dv is outward for the profile's orientation
  this->DerivativesAvailable = 1;
}

vtkParametricExtrusion::~vtkParametricExtrusion() = default;

//------------------------------------------------------------------------------
void vtkParametricExtrusion::SetProfile(vtkBezierProfile* profile)
{
  if (this->Profile != profile)
  {
    this->Profile = profile;
    this->Modified();
  }
}

vtkBezierProfile* vtkParametricExtrusion::GetProfile()
{
  return this->Profile;
}

vtkMTimeType vtkParametricExtrusion::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->Profile)
  {
    mtime = std::max(mtime, this->Profile->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
void vtkParametricExtrusion::Evaluate(double uvw[3], double Pt[3], double Duvw[9])
{
  std::fill(Pt, Pt + 3, 0.0);
  std::fill(Duvw, Duvw + 9, 0.0);
  double p[2], d[2];
  std::string reason = "there is no profile";
  if (!this->Profile || !this->Profile->IsValid(&reason) ||
    !this->Profile->Evaluate(uvw[0], p, d, nullptr))
  {
    vtkErrorMacro("Cannot evaluate the extrusion: " << reason << "; see SetProfile().");
    return;
  }
  Pt[0] = p[0];
  Pt[1] = this->Height * uvw[1];
  Pt[2] = p[1];
  Duvw[0] = d[0];
  Duvw[2] = d[1];
  Duvw[4] = this->Height;
}

//------------------------------------------------------------------------------
double vtkParametricExtrusion::EvaluateScalar(double*, double*, double*)
{
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricExtrusion::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "Profile: " << this->Profile.Get() << "\n";
  if (this->Profile)
  {
    this->Profile->PrintSelf(os, indent.GetNextIndent());
  }
}
