#include "vtkParametricDonut.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkSurfaceDetailVectorize.h"

#include <cmath>
#include <typeinfo>

vtkStandardNewMacro(vtkParametricDonut);

//------------------------------------------------------------------------------
vtkParametricDonut::vtkParametricDonut()
{
  this->JoinU = 1;
  this->JoinV = 1;
}

//------------------------------------------------------------------------------
void vtkParametricDonut::EvaluateUTerms(double u, double* terms)
{
  this->EvaluateTurn(u, terms);
}

void vtkParametricDonut::EvaluateVTerms(double v, double* terms)
{
  this->EvaluateTurn(v, terms);
}

void vtkParametricDonut::EvaluateTerms(
  const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9])
{
  const double twoPi = 2.0 * vtkMath::Pi();
  const double cu = uTerms[0], su = uTerms[1];
  const double cv = vTerms[0], sv = vTerms[1];
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

// AVX2 halves the vector stores of the row loop (vtkSurfaceDetailVectorize.h).

namespace
{
// One run of a row; the restrict parameters tell the compiler that the nine outputs do not
// overlap (it gives up on checking that many pointers at run time and would stay scalar).
SURFACEDETAIL_WIDE_VECTORS void DonutRun(int count, const double* __restrict cu,
  const double* __restrict su, double ring, double z, double duxScale, double duyScale,
  double dvScale, double dvz, double* __restrict px, double* __restrict py, double* __restrict pz,
  double* __restrict dux, double* __restrict duy, double* __restrict duz, double* __restrict dvx,
  double* __restrict dvy, double* __restrict dvzOut)
{
  for (int k = 0; k < count; ++k)
  {
    px[k] = ring * cu[k];
    py[k] = ring * su[k];
    pz[k] = z;
    dux[k] = duxScale * su[k];
    duy[k] = duyScale * cu[k];
    duz[k] = 0.0;
    dvx[k] = dvScale * cu[k];
    dvy[k] = dvScale * su[k];
    dvzOut[k] = dvz;
  }
}
} // namespace

void vtkParametricDonut::EvaluateTermsBlock(const double* const* uTerms, const double* vTerms,
  int count, double* const* P, double* const* Du, double* const* Dv)
{
  // The loop below repeats this class's EvaluateTerms(); a subclass that overrides
  // EvaluateTerms() alone gets its own shape from the per-point block instead.
  if (typeid(*this) != typeid(vtkParametricDonut))
  {
    this->vtkParametricSeparableFunction::EvaluateTermsBlock(uTerms, vTerms, count, P, Du, Dv);
    return;
  }
  // EvaluateTerms() with its products that depend on v only taken out of the loop, in the
  // same order of operations, so the results are the same bits.
  const double twoPi = 2.0 * vtkMath::Pi();
  const double cv = vTerms[0], sv = vTerms[1];
  const double r = this->CrossSectionRadius;
  const double ring = this->RingRadius + r * cv;
  DonutRun(count, uTerms[0], uTerms[1], ring, r * sv, -twoPi * ring, twoPi * ring, -twoPi * r * sv,
    twoPi * r * cv, P[0], P[1], P[2], Du[0], Du[1], Du[2], Dv[0], Dv[1], Dv[2]);
}

//------------------------------------------------------------------------------
void vtkParametricDonut::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RingRadius: " << this->RingRadius << "\n";
  os << indent << "CrossSectionRadius: " << this->CrossSectionRadius << "\n";
}
