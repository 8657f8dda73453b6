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
  this->JoinU = 1;
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
void vtkParametricExtrusion::EvaluateUTerms(double u, double* terms)
{
  // (x, z, dx/du, dz/du)
  std::string reason = "there is no profile";
  if (!this->Profile || !this->Profile->IsValid(&reason) ||
    !this->Profile->Evaluate(u, terms, terms + 2, nullptr))
  {
    std::fill(terms, terms + 4, 0.0);
    vtkErrorMacro("Cannot evaluate the extrusion: " << reason << "; see SetProfile().");
  }
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
