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
  this->JoinU = 1;
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
void vtkParametricRevolution::EvaluateUTerms(double u, double* terms)
{
  const double theta = 2.0 * vtkMath::Pi() * u;
  terms[0] = std::cos(theta);
  terms[1] = std::sin(theta);
}

void vtkParametricRevolution::EvaluateVTerms(double v, double* terms)
{
  // (r, y, dr/dv, dy/dv)
  std::string reason = "there is no profile";
  if (!this->Profile || !this->Profile->IsValid(&reason) ||
    !this->Profile->Evaluate(v, terms, terms + 2, nullptr))
  {
    std::fill(terms, terms + 4, 0.0);
    vtkErrorMacro("Cannot evaluate the surface of revolution: " << reason << "; see SetProfile().");
  }
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
