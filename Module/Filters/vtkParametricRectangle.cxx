#include "vtkParametricRectangle.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkParametricRectangle);

//------------------------------------------------------------------------------
vtkParametricRectangle::vtkParametricRectangle()
{
  this->MinimumU = 0.0;
  this->MaximumU = 1.0;
  this->MinimumV = 0.0;
  this->MaximumV = 1.0;
  this->JoinU = 0;
  this->JoinV = 0;
  this->TwistU = 0;
  this->TwistV = 0;
  this->ClockwiseOrdering = 1; // the normal is Du x Dv
  this->DerivativesAvailable = 1;
}

//------------------------------------------------------------------------------
void vtkParametricRectangle::Evaluate(double uvw[3], double Pt[3], double Duvw[9])
{
  for (int k = 0; k < 3; ++k)
  {
    const double du = this->Point1[k] - this->Origin[k];
    const double dv = this->Point2[k] - this->Origin[k];
    Pt[k] = this->Origin[k] + uvw[0] * du + uvw[1] * dv;
    Duvw[k] = du;
    Duvw[3 + k] = dv;
    Duvw[6 + k] = 0.0;
  }
}

//------------------------------------------------------------------------------
double vtkParametricRectangle::EvaluateScalar(double*, double*, double*)
{
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkParametricRectangle::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "Point1: (" << this->Point1[0] << ", " << this->Point1[1] << ", "
     << this->Point1[2] << ")\n";
  os << indent << "Point2: (" << this->Point2[0] << ", " << this->Point2[1] << ", "
     << this->Point2[2] << ")\n";
}
