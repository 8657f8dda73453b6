#include "vtkParametricExtrusion.h"

#include "vtkBezierProfile.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkParametricExtrusion);

//------------------------------------------------------------------------------
vtkParametricExtrusion::vtkParametricExtrusion()
{
  this->Profile->SetToHeart();
}

vtkParametricExtrusion::~vtkParametricExtrusion() = default;

//------------------------------------------------------------------------------
void vtkParametricExtrusion::EvaluateUTerms(double u, double* terms)
{
  // (x, z, dx/du, dz/du)
  this->EvaluateProfile(u, terms, "extrusion");
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
}
