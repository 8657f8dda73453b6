#include "vtkParametricSphere.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkParametricSphere);

// As in vtkParametricSurfaceSource.cxx: AVX2 halves the vector stores of the row loop; no
// FMA in either build, so the bits are the same.
#if defined(__x86_64__) && defined(__linux__) && (defined(__GNUC__) || defined(__clang__))
#define SURFACEDETAIL_WIDE_VECTORS __attribute__((target_clones("avx2", "default")))
#else
#define SURFACEDETAIL_WIDE_VECTORS
#endif

namespace
{
// One run of a row; restrict parameters, because the compiler gives up on checking nine
// output pointers for overlap at run time and would stay scalar.
SURFACEDETAIL_WIDE_VECTORS void SphereRun(int count, const double* __restrict ct,
  const double* __restrict st, const double* row, double* __restrict px, double* __restrict py,
  double* __restrict pz, double* __restrict dux, double* __restrict duy, double* __restrict duz,
  double* __restrict dvx, double* __restrict dvy, double* __restrict dvz)
{
  const double x = row[0], y = row[1], z = row[2], du = row[3], dvX = row[4], dvY = row[5],
               dvZ = row[6];
  for (int k = 0; k < count; ++k)
  {
    px[k] = x * ct[k];
    py[k] = y;
    pz[k] = z * st[k];
    dux[k] = du * st[k];
    duy[k] = 0.0;
    duz[k] = du * ct[k];
    dvx[k] = dvX * ct[k];
    dvy[k] = dvY;
    dvz[k] = dvZ * st[k];
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkParametricSphere::vtkParametricSphere()
{
  this->JoinU = 1;
}

//------------------------------------------------------------------------------
void vtkParametricSphere::EvaluateUTerms(double u, double* terms)
{
  this->EvaluateTurn(u, terms);
}

void vtkParametricSphere::EvaluateVTerms(double v, double* terms)
{
  const double alpha = vtkMath::Pi() * (1.0 - v);
  terms[0] = std::cos(alpha);
  terms[1] = std::sin(alpha);
}

void vtkParametricSphere::EvaluateTerms(
  const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9])
{
  const double twoPi = 2.0 * vtkMath::Pi();
  const double ct = uTerms[0], st = uTerms[1];
  const double ca = vTerms[0], sa = vTerms[1];
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

void vtkParametricSphere::EvaluateTermsBlock(const double* const* uTerms, const double* vTerms,
  int count, double* const* P, double* const* Du, double* const* Dv)
{
  // EvaluateTerms() with its products that depend on v only taken out of the loop, in the
  // same order of operations, so the results are the same bits.
  const double twoPi = 2.0 * vtkMath::Pi();
  const double ca = vTerms[0], sa = vTerms[1];
  const double r = this->Radius;
  const double row[7] = { r * sa, r * ca, -r * sa, -twoPi * r * sa, -vtkMath::Pi() * r * ca,
    vtkMath::Pi() * r * sa, vtkMath::Pi() * r * ca };
  SphereRun(
    count, uTerms[0], uTerms[1], row, P[0], P[1], P[2], Du[0], Du[1], Du[2], Dv[0], Dv[1], Dv[2]);
}

//------------------------------------------------------------------------------
void vtkParametricSphere::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
}
