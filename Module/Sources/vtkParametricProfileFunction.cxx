// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParametricProfileFunction.h"

#include "vtkBezierProfile.h"

#include <algorithm>
#include <string>

//------------------------------------------------------------------------------
vtkParametricProfileFunction::vtkParametricProfileFunction()
  : Profile(vtkSmartPointer<vtkBezierProfile>::New())
{
  this->JoinU = 1;
}

vtkParametricProfileFunction::~vtkParametricProfileFunction() = default;

//------------------------------------------------------------------------------
void vtkParametricProfileFunction::SetProfile(vtkBezierProfile* profile)
{
  if (this->Profile != profile)
  {
    this->Profile = profile;
    this->Modified();
  }
}

vtkBezierProfile* vtkParametricProfileFunction::GetProfile()
{
  return this->Profile;
}

vtkMTimeType vtkParametricProfileFunction::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->Profile)
  {
    mtime = std::max(mtime, this->Profile->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
void vtkParametricProfileFunction::EvaluateProfile(double t, double terms[6], const char* surface)
{
  if (this->Profile && this->Profile->Evaluate(t, terms, terms + 2, terms + 4))
  {
    return;
  }
  // The failure path only: the profile's validity is cached, the message is not.
  std::fill(terms, terms + 6, 0.0);
  std::string reason = "there is no profile";
  if (this->Profile && this->Profile->IsValid(&reason))
  {
    reason = "the profile parameter is not a number";
  }
  vtkErrorMacro("Cannot evaluate the " << surface << ": " << reason << "; see SetProfile().");
}

//------------------------------------------------------------------------------
void vtkParametricProfileFunction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Profile: " << this->Profile.Get() << "\n";
  if (this->Profile)
  {
    this->Profile->PrintSelf(os, indent.GetNextIndent());
  }
}
