#include "vtkParametricSurfaceSource.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkParametricFunction.h"
#include "vtkParametricSeparableFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailMemory.h"
#include "vtkSurfaceDetailVectorize.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

vtkStandardNewMacro(vtkParametricSurfaceSource);

namespace
{
using vtkSurfaceDetail::Cross;
using vtkSurfaceDetail::Dot;

// Derivatives shorter than this fraction of the other one, or a cross product shorter than
// this fraction of |Du||Dv|, carry no reliable direction: such points take the limit.
constexpr double DegenerateTolerance = 1e-9;
constexpr double DegenerateTolerance2 = DegenerateTolerance * DegenerateTolerance;
// Step (in unit-square parameters) of the one-sided difference that gives the limit of a
// vanishing derivative's direction; the second-order difference leaves an O(h^2) error.
constexpr double LimitStep = 1e-4;

// Everything the per-point work needs; read-only while the threads run.
struct Grid
{
  vtkParametricFunction* Function = nullptr;
  vtkIdType U = 1;       // cells per row (vtkIdType: U + 1 and the indexes below fit)
  vtkIdType Row0 = 0;    // first point row of this piece
  vtkIdType NumRows = 0; // point rows in this piece
  double UMin = 0, UExtent = 1, VMin = 0, VExtent = 1;
  double Orientation = 1.0;   // +1: N = Du x Dv; -1: N = Dv x Du
  bool HasDerivatives = true; // false: differences of the function's points
  double InvRepeat[2] = { 1.0, 1.0 };
  double TangentSign = 1.0;             // sign of the s repeat
  double Handedness = 1.0;              // w wherever Du x Dv is regular
  std::vector<double> UUnit, VUnit;     // unit-square parameter of each column / row
  std::vector<double> UDomain, VDomain; // the function's parameter of each column / row
  std::vector<float> S, T;              // texture coordinate of each column / row
  // Separable functions: their u terms (term t of column i at t * (U + 1) + i, so that a
  // run of columns is contiguous) and the v terms of each row.
  vtkParametricSeparableFunction* Separable = nullptr;
  int NumUTerms = 0, NumVTerms = 0;
  std::vector<double> UTerms, VTerms;

  double ToDomainU(double u) const { return this->UMin + this->UExtent * u; }
  double ToDomainV(double v) const { return this->VMin + this->VExtent * v; }

  // The function and its unit-square derivatives at domain parameters (u, v).
  void Evaluate(double u, double v, double p[3], double du[3], double dv[3]) const
  {
    double uvw[3] = { u, v, 0.0 };
    double d[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
    this->Function->Evaluate(uvw, p, d);
    if (!this->HasDerivatives)
    {
      this->Difference(0, (u - this->UMin) / this->UExtent, (v - this->VMin) / this->VExtent, du);
      this->Difference(1, (u - this->UMin) / this->UExtent, (v - this->VMin) / this->VExtent, dv);
      return;
    }
    for (int k = 0; k < 3; ++k)
    {
      du[k] = d[k] * this->UExtent;
      dv[k] = d[3 + k] * this->VExtent;
    }
  }

  /**
   * For functions without derivatives (DerivativesAvailable off): the unit-square derivative
   * along @a axis at unit parameters (u, v) by fourth-order differences, central inside the
   * domain and one-sided within two steps of its edge, so the function is never evaluated
   * outside its domain. Truncation O(h^4) and rounding O(eps/h) balance near h = 1e-3.
   */
  void Difference(int axis, double u, double v, double out[3]) const
  {
    constexpr double h = 1e-3;
    auto at = [&](double offset, double p[3])
    {
      double uvw[3] = { this->ToDomainU(axis == 0 ? u + offset : u),
        this->ToDomainV(axis == 1 ? v + offset : v), 0.0 };
      double d[9];
      this->Function->Evaluate(uvw, p, d);
    };
    const double x = axis == 0 ? u : v;
    double a[3], b[3], c[3], e[3];
    if (x - 2 * h >= 0.0 && x + 2 * h <= 1.0)
    {
      at(2 * h, a);
      at(h, b);
      at(-h, c);
      at(-2 * h, e);
      for (int k = 0; k < 3; ++k)
      {
        out[k] = (-a[k] + 8 * b[k] - 8 * c[k] + e[k]) / (12 * h);
      }
      return;
    }
    const double step = x + 4 * h <= 1.0 ? h : -h;
    double f0[3];
    at(0, f0);
    at(step, a);
    at(2 * step, b);
    at(3 * step, c);
    at(4 * step, e);
    for (int k = 0; k < 3; ++k)
    {
      out[k] = (-25 * f0[k] + 48 * a[k] - 36 * b[k] + 16 * c[k] - 3 * e[k]) / (12 * step);
    }
  }

  /**
   * The function at @a count consecutive columns from @a col of row @a j, in structure-of-
   * arrays form: P[c][k] is component c of the point in column col + k, Du and Dv its
   * unit-square derivatives. Separable functions work from the cached terms.
   */
  void EvaluateBlock(vtkIdType col, vtkIdType j, int count, double* const* P, double* const* Du,
    double* const* Dv) const
  {
    if (this->Separable)
    {
      const double* uTerms[vtkParametricSeparableFunction::MaximumNumberOfTerms];
      for (int t = 0; t < this->NumUTerms; ++t)
      {
        uTerms[t] = this->UTerms.data() + t * (this->U + 1) + col;
      }
      this->Separable->EvaluateTermsBlock(
        uTerms, this->VTerms.data() + j * this->NumVTerms, count, P, Du, Dv);
      // Our own functions live on the unit square, where the factors are 1 (exact anyway).
      if (this->UExtent != 1.0 || this->VExtent != 1.0)
      {
        for (int c = 0; c < 3; ++c)
        {
          for (int k = 0; k < count; ++k)
          {
            Du[c][k] *= this->UExtent;
            Dv[c][k] *= this->VExtent;
          }
        }
      }
      return;
    }
    for (int k = 0; k < count; ++k)
    {
      double p[3], du[3], dv[3];
      if (this->HasDerivatives)
      {
        double uvw[3] = { this->UDomain[col + k], this->VDomain[j], 0.0 };
        double d[9];
        this->Function->Evaluate(uvw, p, d);
        for (int c = 0; c < 3; ++c)
        {
          du[c] = d[c] * this->UExtent;
          dv[c] = d[3 + c] * this->VExtent;
        }
      }
      else
      {
        this->Evaluate(this->UDomain[col + k], this->VDomain[j], p, du, dv);
      }
      for (int c = 0; c < 3; ++c)
      {
        P[c][k] = p[c];
        Du[c][k] = du[c];
        Dv[c][k] = dv[c];
      }
    }
  }

  // Unit-square derivatives only, at unit-square parameters (clamped to the domain).
  void Derivatives(double u, double v, double du[3], double dv[3]) const
  {
    double p[3];
    this->Evaluate(this->ToDomainU(std::min(std::max(u, 0.0), 1.0)),
      this->ToDomainV(std::min(std::max(v, 0.0), 1.0)), p, du, dv);
  }
};

// True when du and dv span a plane well enough to give a normal; n is then the unit normal
// and a2 the squared length of du.
inline bool RegularNormal(
  const double du[3], const double dv[3], double orientation, double n[3], double& a2)
{
  Cross(du, dv, n);
  a2 = Dot(du, du);
  const double b2 = Dot(dv, dv);
  const double c2 = Dot(n, n);
  if (!(c2 > DegenerateTolerance2 * a2 * b2) || !(a2 > DegenerateTolerance2 * b2) ||
    !(b2 > DegenerateTolerance2 * a2) || !std::isfinite(c2))
  {
    return false;
  }
  const double scale = orientation / std::sqrt(c2);
  n[0] *= scale;
  n[1] *= scale;
  n[2] *= scale;
  return true;
}

// Direction in which the derivative along @a axis (0: Du, 1: Dv), which vanishes at unit
// parameters (u, v) with value d0, grows when one moves across the line where it vanishes
// (along the other parameter) into the domain: the one-sided derivative by the second-order
// difference (4 d(h) - d(2h) - 3 d(0)) / 2h.
void VanishingLimit(const Grid& g, int axis, double u, double v, const double d0[3], double out[3])
{
  const double x = axis == 0 ? v : u;
  const double sigma = x < 0.5 ? 1.0 : -1.0;
  double d1[2][3], d2[2][3]; // Du and Dv one and two steps away
  auto at = [&](double offset, double d[2][3])
  { g.Derivatives(axis == 0 ? u : u + offset, axis == 0 ? v + offset : v, d[0], d[1]); };
  at(sigma * LimitStep, d1);
  at(2.0 * sigma * LimitStep, d2);
  for (int k = 0; k < 3; ++k)
  {
    out[k] = (4.0 * d1[axis][k] - d2[axis][k] - 3.0 * d0[k]) / (2.0 * LimitStep);
  }
}

/**
 * The frame at a point where the plain cross product fails. Returns false when no
 * neighbourhood of the point has area either (the frame is then arbitrary but unit).
 */
bool DegenerateFrame(const Grid& g, double u, double v, const double du[3], const double dv[3],
  double n[3], double t[4])
{
  const double a2 = Dot(du, du);
  const double b2 = Dot(dv, dv);
  double a[3] = { du[0], du[1], du[2] };
  double b[3] = { dv[0], dv[1], dv[2] };
  const bool aVanishes = !(a2 > DegenerateTolerance2 * b2);
  const bool bVanishes = !(b2 > DegenerateTolerance2 * a2);
  if (aVanishes)
  {
    VanishingLimit(g, 0, u, v, du, a);
  }
  if (bVanishes)
  {
    VanishingLimit(g, 1, u, v, dv, b);
  }
  double length2;
  bool found = RegularNormal(a, b, g.Orientation, n, length2);
  // Parallel derivatives, or a limit that still vanishes: take the frame of nearby points
  // inside the domain, nearest first.
  for (double h = 1e-6; !found && h < 0.1; h *= 100.0)
  {
    const double su = u < 0.5 ? h : -h;
    const double sv = v < 0.5 ? h : -h;
    g.Derivatives(u + su, v + sv, a, b);
    found = RegularNormal(a, b, g.Orientation, n, length2);
  }
  if (!found)
  {
    // No area anywhere near: any unit normal orthogonal to what derivative there is.
    const double* d = a2 >= b2 ? du : dv;
    const double zero[3] = { 0.0, 0.0, 0.0 };
    double dn[3] = { d[0], d[1], d[2] };
    if (vtkSurfaceDetail::Normalize(dn) > 0.0 && std::isfinite(Dot(dn, dn)))
    {
      double axis[4];
      vtkSurfaceDetail::MakeTangentFrame(dn, zero, zero, axis);
      n[0] = axis[0];
      n[1] = axis[1];
      n[2] = axis[2];
    }
    else
    {
      n[0] = 0.0;
      n[1] = 0.0;
      n[2] = 1.0;
    }
    a[0] = du[0];
    a[1] = du[1];
    a[2] = du[2];
    b[0] = dv[0];
    b[1] = dv[1];
    b[2] = dv[2];
  }
  if (t)
  {
    const double dPds[3] = { a[0] * g.InvRepeat[0], a[1] * g.InvRepeat[0], a[2] * g.InvRepeat[0] };
    const double dPdt[3] = { b[0] * g.InvRepeat[1], b[1] * g.InvRepeat[1], b[2] * g.InvRepeat[1] };
    vtkSurfaceDetail::MakeTangentFrame(n, dPds, dPdt, t);
  }
  return found;
}

// Points handled together: a run of one row, in structure-of-arrays scratch on the stack.
constexpr int BlockSize = 64;

// Outputs bigger than this are written with streaming (non-temporal) stores: they do not fit
// in the caches anyway, and ordinary stores would first read every line they write.
constexpr std::size_t StreamingBytes = std::size_t(8) << 20;

#if defined(__SSE2__)
inline bool Aligned16(const void* p)
{
  return (reinterpret_cast<std::uintptr_t>(p) & 15) == 0;
}

inline void Store(float* p, __m128 v, bool stream)
{
  if (stream)
  {
    _mm_stream_ps(p, v);
  }
  else
  {
    _mm_storeu_ps(p, v);
  }
}
#endif

// out[C * k + c] = in[c][k] for a run of points: the structure-of-arrays scratch into the
// interleaved VTK array; @a stream asks for streaming stores where the output allows.
template <typename Out, int C>
void Interleave(int count, const double (*in)[BlockSize], Out* __restrict out, bool stream)
{
  const double* __restrict x = in[0];
  const double* __restrict y = in[1];
  const double* __restrict z = in[2];
  const double* __restrict w = in[C - 1];
  auto one = [&](int k)
  {
    out[C * k] = static_cast<Out>(x[k]);
    out[C * k + 1] = static_cast<Out>(y[k]);
    out[C * k + 2] = static_cast<Out>(z[k]);
    if (C == 4)
    {
      out[C * k + 3] = static_cast<Out>(w[k]);
    }
  };
  int k = 0;
#if defined(__SSE2__)
  // Float output, four points at a time: the compiler leaves this transpose scalar (eight
  // or more narrow stores per four points). The conversion is the same cvtpd2ps.
  if constexpr (std::is_same<Out, float>::value)
  {
    float* o = out;
    for (; stream && k < count && k < 4 && !Aligned16(o + C * k); ++k)
    {
      one(k);
    }
    const bool streaming = stream && Aligned16(o + C * k);
    auto four = [](const double* v)
    { return _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(v)), _mm_cvtpd_ps(_mm_loadu_pd(v + 2))); };
    for (; k + 4 <= count; k += 4)
    {
      __m128 a = four(x + k), b = four(y + k), c = four(z + k);
      if constexpr (C == 4)
      {
        __m128 d = four(w + k);
        _MM_TRANSPOSE4_PS(a, b, c, d);
        Store(o + 4 * k, a, streaming);
        Store(o + 4 * k + 4, b, streaming);
        Store(o + 4 * k + 8, c, streaming);
        Store(o + 4 * k + 12, d, streaming);
      }
      else
      {
        const __m128 ab01 = _mm_unpacklo_ps(a, b); // a0 b0 a1 b1
        const __m128 ab23 = _mm_unpackhi_ps(a, b); // a2 b2 a3 b3
        const __m128 c0a1 = _mm_shuffle_ps(c, ab01, _MM_SHUFFLE(2, 2, 0, 0));
        const __m128 b1c1 = _mm_shuffle_ps(ab01, c, _MM_SHUFFLE(1, 1, 3, 3));
        const __m128 c2a3 = _mm_shuffle_ps(c, ab23, _MM_SHUFFLE(2, 2, 2, 2));
        const __m128 b3c3 = _mm_shuffle_ps(ab23, c, _MM_SHUFFLE(3, 3, 3, 3));
        Store(o + 3 * k, _mm_shuffle_ps(ab01, c0a1, _MM_SHUFFLE(2, 0, 1, 0)), streaming);
        Store(o + 3 * k + 4, _mm_shuffle_ps(b1c1, ab23, _MM_SHUFFLE(1, 0, 2, 0)), streaming);
        Store(o + 3 * k + 8, _mm_shuffle_ps(c2a3, b3c3, _MM_SHUFFLE(2, 0, 2, 0)), streaming);
      }
    }
  }
#else
  (void)stream;
#endif
  for (; k < count; ++k)
  {
    one(k);
  }
}

// Texture coordinates (s[k], t) of a run of one row.
void InterleaveTCoords(
  int count, const float* __restrict s, float t, float* __restrict out, bool stream)
{
  int k = 0;
#if defined(__SSE2__)
  for (; stream && k < count && k < 2 && !Aligned16(out + 2 * k); ++k)
  {
    out[2 * k] = s[k];
    out[2 * k + 1] = t;
  }
  const bool streaming = stream && Aligned16(out + 2 * k);
  const __m128 tt = _mm_set1_ps(t);
  for (; k + 4 <= count; k += 4)
  {
    const __m128 ss = _mm_loadu_ps(s + k);
    Store(out + 2 * k, _mm_unpacklo_ps(ss, tt), streaming);
    Store(out + 2 * k + 4, _mm_unpackhi_ps(ss, tt), streaming);
  }
#else
  (void)stream;
#endif
  for (; k < count; ++k)
  {
    out[2 * k] = s[k];
    out[2 * k + 1] = t;
  }
}

// nonFinite[k] becomes NaN when point k's sum of coordinates or of derivatives is not finite.
void CheckFinite(int count, const double* __restrict px, const double* __restrict py,
  const double* __restrict pz, const double* __restrict dux, const double* __restrict duy,
  const double* __restrict duz, const double* __restrict dvx, const double* __restrict dvy,
  const double* __restrict dvz, double* __restrict nonFinite)
{
  for (int k = 0; k < count; ++k)
  {
    const double sp = px[k] + py[k] + pz[k];
    const double sd = dux[k] + duy[k] + duz[k] + dvx[k] + dvy[k] + dvz[k];
    nonFinite[k] += (sp - sp) + (sd - sd);
  }
}

/**
 * CheckFinite, and the unit normals (N = +-(Du x Dv)/|Du x Dv|) and tangents of a run of
 * points, in one pass over the derivatives. regular[k] is 1 where the derivatives of point
 * k span a plane (the tests and operations of RegularNormal, in its order, so the bits are
 * the same); there N is orthogonal to Du already and the shared frame
 * (vtkSurfaceDetail::MakeTangentFrame) reduces to T = Du/|Du| times the sign of the s
 * repeat, with w = cross(N,T).dP/dt of constant sign. Elsewhere regular[k] is 0 and the
 * values are meaningless: the caller replaces them. Restrict parameters rather than locals:
 * the compiler does not check that many pointers at run time and would stay scalar.
 * Always inlined, so that each target clone below vectorises it for its own instruction set.
 */
template <bool WithTangents>
VTK_ALWAYS_INLINE void CheckFiniteAndFramesRun(int count, const double* __restrict px,
  const double* __restrict py, const double* __restrict pz, const double* __restrict dux,
  const double* __restrict duy, const double* __restrict duz, const double* __restrict dvx,
  const double* __restrict dvy, const double* __restrict dvz, double orientation,
  double tangentSign, double handedness, double* __restrict nonFinite, double* __restrict regular,
  double* __restrict n0, double* __restrict n1, double* __restrict n2, double* __restrict t0,
  double* __restrict t1, double* __restrict t2, double* __restrict t3)
{
  for (int k = 0; k < count; ++k)
  {
    const double ax = dux[k], ay = duy[k], az = duz[k];
    const double bx = dvx[k], by = dvy[k], bz = dvz[k];
    const double sp = px[k] + py[k] + pz[k];
    const double sd = ax + ay + az + bx + by + bz;
    nonFinite[k] += (sp - sp) + (sd - sd);
    const double nx = ay * bz - az * by;
    const double ny = az * bx - ax * bz;
    const double nz = ax * by - ay * bx;
    const double a2 = ax * ax + ay * ay + az * az;
    const double b2 = bx * bx + by * by + bz * bz;
    const double c2 = nx * nx + ny * ny + nz * nz;
    // A double flag: a mask of another width would stop the vectorisation.
    const bool ok = (c2 > DegenerateTolerance2 * a2 * b2) & (a2 > DegenerateTolerance2 * b2) &
      (b2 > DegenerateTolerance2 * a2) & (c2 - c2 == 0.0);
    regular[k] = ok ? 1.0 : 0.0;
    const double normalScale = orientation / std::sqrt(c2);
    n0[k] = nx * normalScale;
    n1[k] = ny * normalScale;
    n2[k] = nz * normalScale;
    if (WithTangents)
    {
      const double tangentScale = tangentSign / std::sqrt(a2);
      t0[k] = ax * tangentScale;
      t1[k] = ay * tangentScale;
      t2[k] = az * tangentScale;
      t3[k] = handedness;
    }
  }
}

// The frame loop is bound by square roots and divisions, so it also has an AVX2 build
// (vtkSurfaceDetailVectorize.h: the same bits either way). Two plain functions rather than
// one template: clang rejects target_clones on templates.
SURFACEDETAIL_WIDE_VECTORS void CheckFiniteAndNormals(int count, const double* __restrict px,
  const double* __restrict py, const double* __restrict pz, const double* __restrict dux,
  const double* __restrict duy, const double* __restrict duz, const double* __restrict dvx,
  const double* __restrict dvy, const double* __restrict dvz, double orientation,
  double tangentSign, double handedness, double* __restrict nonFinite, double* __restrict regular,
  double* __restrict n0, double* __restrict n1, double* __restrict n2, double* __restrict t0,
  double* __restrict t1, double* __restrict t2, double* __restrict t3)
{
  CheckFiniteAndFramesRun<false>(count, px, py, pz, dux, duy, duz, dvx, dvy, dvz, orientation,
    tangentSign, handedness, nonFinite, regular, n0, n1, n2, t0, t1, t2, t3);
}

SURFACEDETAIL_WIDE_VECTORS void CheckFiniteAndFrames(int count, const double* __restrict px,
  const double* __restrict py, const double* __restrict pz, const double* __restrict dux,
  const double* __restrict duy, const double* __restrict duz, const double* __restrict dvx,
  const double* __restrict dvy, const double* __restrict dvz, double orientation,
  double tangentSign, double handedness, double* __restrict nonFinite, double* __restrict regular,
  double* __restrict n0, double* __restrict n1, double* __restrict n2, double* __restrict t0,
  double* __restrict t1, double* __restrict t2, double* __restrict t3)
{
  CheckFiniteAndFramesRun<true>(count, px, py, pz, dux, duy, duz, dvx, dvy, dvz, orientation,
    tangentSign, handedness, nonFinite, regular, n0, n1, n2, t0, t1, t2, t3);
}

// Points and point arrays of one piece; each point is computed from its own (i, j) alone,
// so any split among threads gives the same bytes.
template <typename Real>
struct PointWorker
{
  const Grid& G;
  Real* Points;
  float* Normals;
  float* TCoords;
  float* Tangents;
  Real* DPdu;
  Real* DPdv;
  bool Stream = false;                    // output too big for the caches: streaming stores
  vtkSMPThreadLocal<vtkIdType> Arbitrary; // points with an arbitrary frame
  vtkSMPThreadLocal<unsigned char> NonFinite;

  PointWorker(const Grid& g)
    : G(g)
  {
  }

  void Initialize()
  {
    this->Arbitrary.Local() = 0;
    this->NonFinite.Local() = 0;
  }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    const Grid& g = this->G;
    const vtkIdType rowLength = g.U + 1;
    vtkIdType& arbitrary = this->Arbitrary.Local();
    const bool frame = this->Normals || this->Tangents;
    // Every loop over a run below has unit stride and no branch, so the compiler
    // vectorises it.
    double blockP[3][BlockSize], blockDu[3][BlockSize], blockDv[3][BlockSize];
    double blockN[3][BlockSize], blockT[4][BlockSize];
    double regular[BlockSize]; // 1: regular point, 0: take the limit frame
    double* P[3] = { blockP[0], blockP[1], blockP[2] };
    double* Du[3] = { blockDu[0], blockDu[1], blockDu[2] };
    double* Dv[3] = { blockDv[0], blockDv[1], blockDv[2] };
    // Lane k becomes NaN once a sum below is not finite; kept per lane, because a running
    // floating-point sum would not vectorise.
    double nonFinite[BlockSize] = {};
    for (vtkIdType id = begin; id < end;)
    {
      const vtkIdType col = id % rowLength;
      const vtkIdType j = g.Row0 + id / rowLength;
      const int count =
        static_cast<int>(std::min<vtkIdType>({ BlockSize, rowLength - col, end - id }));
      g.EvaluateBlock(col, j, count, P, Du, Dv);
      if (frame)
      {
        (this->Tangents ? CheckFiniteAndFrames : CheckFiniteAndNormals)(count, blockP[0], blockP[1],
          blockP[2], blockDu[0], blockDu[1], blockDu[2], blockDv[0], blockDv[1], blockDv[2],
          g.Orientation, g.TangentSign, g.Handedness, nonFinite, regular, blockN[0], blockN[1],
          blockN[2], blockT[0], blockT[1], blockT[2], blockT[3]);
        for (int k = 0; k < count; ++k)
        {
          if (regular[k] != 0.0)
          {
            continue;
          }
          const double du[3] = { blockDu[0][k], blockDu[1][k], blockDu[2][k] };
          const double dv[3] = { blockDv[0][k], blockDv[1][k], blockDv[2][k] };
          double n[3], t[4];
          if (!DegenerateFrame(
                g, g.UUnit[col + k], g.VUnit[j], du, dv, n, this->Tangents ? t : nullptr))
          {
            ++arbitrary;
          }
          for (int c = 0; c < 3; ++c)
          {
            blockN[c][k] = n[c];
          }
          if (this->Tangents)
          {
            for (int c = 0; c < 4; ++c)
            {
              blockT[c][k] = t[c];
            }
          }
        }
      }
      else
      {
        CheckFinite(count, blockP[0], blockP[1], blockP[2], blockDu[0], blockDu[1], blockDu[2],
          blockDv[0], blockDv[1], blockDv[2], nonFinite);
      }
      Interleave<Real, 3>(count, blockP, this->Points + 3 * id, this->Stream);
      if (this->DPdu)
      {
        Interleave<Real, 3>(count, blockDu, this->DPdu + 3 * id, this->Stream);
        Interleave<Real, 3>(count, blockDv, this->DPdv + 3 * id, this->Stream);
      }
      if (this->TCoords)
      {
        InterleaveTCoords(count, g.S.data() + col, g.T[j], this->TCoords + 2 * id, this->Stream);
      }
      if (this->Normals)
      {
        Interleave<float, 3>(count, blockN, this->Normals + 3 * id, this->Stream);
      }
      if (this->Tangents)
      {
        Interleave<float, 4>(count, blockT, this->Tangents + 4 * id, this->Stream);
      }
      id += count;
    }
#if defined(__SSE2__)
    if (this->Stream)
    {
      // Streaming stores are weakly ordered: make them visible before the threads join.
      _mm_sfence();
    }
#endif
    double anyNonFinite = 0.0;
    for (double lane : nonFinite)
    {
      anyNonFinite += lane;
    }
    if (anyNonFinite != 0.0)
    {
      this->NonFinite.Local() = 1;
    }
  }

  void Reduce() {}
};

// Makes streaming stores visible to other threads (they are weakly ordered).
inline void Fence(bool stream)
{
#if defined(__SSE2__)
  if (stream)
  {
    _mm_sfence();
  }
#else
  (void)stream;
#endif
}

// out[k] = in[k] + shift for k < n; 32-bit ids can stream.
template <typename Id>
void ShiftedCopy(const Id* __restrict in, vtkIdType n, Id shift, Id* __restrict out, bool stream)
{
  vtkIdType k = 0;
#if defined(__SSE2__)
  if constexpr (sizeof(Id) == 4)
  {
    for (; stream && k < n && !Aligned16(out + k); ++k)
    {
      out[k] = in[k] + shift;
    }
    if (stream && Aligned16(out + k))
    {
      const __m128i add = _mm_set1_epi32(shift);
      for (; k + 4 <= n; k += 4)
      {
        const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + k));
        _mm_stream_si128(reinterpret_cast<__m128i*>(out + k), _mm_add_epi32(v, add));
      }
    }
  }
#else
  (void)stream;
#endif
  for (; k < n; ++k)
  {
    out[k] = in[k] + shift;
  }
}

// offsets[t] = 3 t for begin <= t < end; 32-bit ids can stream.
template <typename Id>
void Ramp(vtkIdType begin, vtkIdType end, Id* __restrict offsets, bool stream)
{
  vtkIdType t = begin;
#if defined(__SSE2__)
  if constexpr (sizeof(Id) == 4)
  {
    for (; stream && t < end && !Aligned16(offsets + t); ++t)
    {
      offsets[t] = static_cast<Id>(3 * t);
    }
    if (stream && Aligned16(offsets + t))
    {
      const Id first = static_cast<Id>(3 * t);
      __m128i v = _mm_setr_epi32(first, first + 3, first + 6, first + 9);
      const __m128i step = _mm_set1_epi32(12);
      for (; t + 4 <= end; t += 4)
      {
        _mm_stream_si128(reinterpret_cast<__m128i*>(offsets + t), v);
        v = _mm_add_epi32(v, step);
      }
    }
  }
#else
  (void)stream;
#endif
  for (; t < end; ++t)
  {
    offsets[t] = static_cast<Id>(3 * t);
  }
}

// Two triangles per grid quad, counter-clockwise around the normal. Every row of quads has
// the connectivity of the first shifted by a multiple of the row length, so each row is one
// vectorisable add of a precomputed pattern; the offsets are the ramp 0, 3, 6, ...
template <typename Id>
void BuildTriangles(vtkIdType numRows, vtkIdType U, bool flip, Id* offsets, Id* connectivity)
{
  const vtkIdType rowValues = 6 * U;
  std::vector<Id> pattern(rowValues);
  for (vtkIdType i = 0; i < U; ++i)
  {
    const Id p00 = static_cast<Id>(i);
    const Id p10 = p00 + 1;
    const Id p01 = static_cast<Id>(p00 + U + 1);
    const Id p11 = p01 + 1;
    Id* c = pattern.data() + 6 * i;
    c[0] = p00;
    c[1] = flip ? p11 : p10;
    c[2] = flip ? p10 : p11;
    c[3] = p00;
    c[4] = flip ? p01 : p11;
    c[5] = flip ? p11 : p01;
  }
  const vtkIdType numTriangles = 2 * numRows * U;
  const bool stream = static_cast<std::size_t>(numTriangles) * 4 * sizeof(Id) > StreamingBytes;
  vtkSMPTools::For(0, numRows,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType r = begin; r < end; ++r)
      {
        ShiftedCopy(pattern.data(), rowValues, static_cast<Id>(r * (U + 1)),
          connectivity + r * rowValues, stream);
      }
      Fence(stream);
    });
  vtkSMPTools::For(0, numTriangles + 1,
    [offsets, stream](vtkIdType begin, vtkIdType end)
    {
      Ramp(begin, end, offsets, stream);
      Fence(stream);
    });
}

// Null when the memory is not available.
template <typename IdArray>
vtkSmartPointer<vtkCellArray> MakeTriangles(vtkIdType numRows, vtkIdType U, bool flip)
{
  using Id = typename IdArray::ValueType;
  const vtkIdType numTriangles = 2 * numRows * U;
  vtkNew<IdArray> offsets;
  vtkNew<IdArray> connectivity;
  if (!vtkSurfaceDetailMemory::AllocateTuples(offsets.Get(), numTriangles + 1) ||
    !vtkSurfaceDetailMemory::AllocateTuples(connectivity.Get(), 3 * numTriangles))
  {
    return nullptr;
  }
  BuildTriangles<Id>(numRows, U, flip, offsets->GetPointer(0), connectivity->GetPointer(0));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

enum class Outcome
{
  Done,
  NonFinite,
  OutOfMemory
};

template <typename Real, typename RealArray>
Outcome GeneratePoints(const Grid& g, vtkIdType numPoints, bool normals, bool tcoords,
  bool tangents, bool derivatives, vtkPolyData* output, vtkIdType& arbitrary)
{
  // Every value is written below, so the arrays are not initialised; their memory comes in
  // huge pages, warm from the cache when an earlier output was released.
  bool allocated = true;
  auto newArray = [numPoints, &allocated](auto array, const char* name, int components)
  {
    array->SetName(name);
    array->SetNumberOfComponents(components);
    allocated = allocated && vtkSurfaceDetailMemory::AllocateTuples(array, numPoints);
    return allocated ? array->GetPointer(0) : nullptr;
  };
  vtkNew<RealArray> points;
  PointWorker<Real> worker(g);
  worker.Points = newArray(points.Get(), "Points", 3);
  vtkNew<vtkFloatArray> normalArray, tcoordArray, tangentArray;
  vtkNew<RealArray> dPdu, dPdv;
  worker.Normals = normals ? newArray(normalArray.Get(), "Normals", 3) : nullptr;
  worker.TCoords = tcoords ? newArray(tcoordArray.Get(), "TCoords", 2) : nullptr;
  worker.Tangents = tangents ? newArray(tangentArray.Get(), "Tangents", 4) : nullptr;
  worker.DPdu = derivatives ? newArray(dPdu.Get(), "dPdu", 3) : nullptr;
  worker.DPdv = derivatives ? newArray(dPdv.Get(), "dPdv", 3) : nullptr;
  if (!allocated)
  {
    return Outcome::OutOfMemory;
  }
  // The bytes the workers write per point: the arrays asked for.
  const std::size_t bytesPerPoint = 3 * sizeof(Real) + (normals ? 3 * sizeof(float) : 0) +
    (tcoords ? 2 * sizeof(float) : 0) + (tangents ? 4 * sizeof(float) : 0) +
    (derivatives ? 6 * sizeof(Real) : 0);
  worker.Stream = static_cast<std::size_t>(numPoints) * bytesPerPoint > StreamingBytes;

  // Grain: a few thousand points amortise the scheduling; the split never changes values.
  vtkSMPTools::For(0, numPoints, 4096, worker);

  for (unsigned char bad : worker.NonFinite)
  {
    if (bad)
    {
      return Outcome::NonFinite;
    }
  }
  arbitrary = 0;
  for (vtkIdType count : worker.Arbitrary)
  {
    arbitrary += count;
  }

  vtkNew<vtkPoints> pts;
  pts->SetData(points);
  output->SetPoints(pts);
  vtkPointData* pd = output->GetPointData();
  if (normals)
  {
    pd->SetNormals(normalArray);
  }
  if (tcoords)
  {
    pd->SetTCoords(tcoordArray);
  }
  if (tangents)
  {
    // VTK 9.1 accepts only 3-component tangent attributes (vtkDataSetAttributes), so the
    // 4-component frame is an ordinary array found by its name.
    pd->AddArray(tangentArray);
  }
  if (derivatives)
  {
    pd->AddArray(dPdu);
    pd->AddArray(dPdv);
  }
  return Outcome::Done;
}
} // namespace

//------------------------------------------------------------------------------
vtkParametricSurfaceSource::vtkParametricSurfaceSource()
{
  this->SetNumberOfInputPorts(0);
}

vtkParametricSurfaceSource::~vtkParametricSurfaceSource() = default;

//------------------------------------------------------------------------------
void vtkParametricSurfaceSource::SetParametricFunction(vtkParametricFunction* function)
{
  if (this->ParametricFunction != function)
  {
    this->ParametricFunction = function;
    this->Modified();
  }
}

vtkParametricFunction* vtkParametricSurfaceSource::GetParametricFunction()
{
  return this->ParametricFunction;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkParametricSurfaceSource::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->ParametricFunction)
  {
    mtime = std::max(mtime, this->ParametricFunction->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
int vtkParametricSurfaceSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkParametricSurfaceSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  output->Initialize();

  vtkParametricFunction* function = this->ParametricFunction;
  if (!function)
  {
    vtkErrorMacro("No parametric function: call SetParametricFunction() with a "
                  "vtkParametricFunction (e.g. vtkParametricSphere) first.");
    return 0;
  }
  if (function->GetDimension() != 2)
  {
    vtkErrorMacro("The parametric function " << function->GetClassName() << " has dimension "
                                             << function->GetDimension()
                                             << "; only surfaces (dimension 2) can be "
                                                "tessellated.");
    return 0;
  }
  if (this->UResolution < 1 || this->VResolution < 1)
  {
    vtkErrorMacro("Resolution " << this->UResolution << " x " << this->VResolution
                                << " is invalid: UResolution and VResolution must be at "
                                   "least 1.");
    return 0;
  }
  const double umin = function->GetMinimumU(), umax = function->GetMaximumU();
  const double vmin = function->GetMinimumV(), vmax = function->GetMaximumV();
  if (!std::isfinite(umax - umin) || !std::isfinite(vmax - vmin) || umin == umax || vmin == vmax)
  {
    vtkErrorMacro("The parametric function's domain [" << umin << ", " << umax << "] x [" << vmin
                                                       << ", " << vmax
                                                       << "] is empty or not finite: set "
                                                          "its Minimum/Maximum U and V.");
    return 0;
  }
  // The transform feeds the texture coordinates and the tangents (through 1/repeat); a
  // non-finite value would put NaN into them.
  const bool textured = this->GenerateTextureCoordinates || this->GenerateTangents;
  if (textured &&
    (!std::isfinite(this->TextureOffset[0]) || !std::isfinite(this->TextureOffset[1]) ||
      !std::isfinite(this->TextureRepeat[0]) || !std::isfinite(this->TextureRepeat[1])))
  {
    vtkErrorMacro("TextureOffset (" << this->TextureOffset[0] << ", " << this->TextureOffset[1]
                                    << ") and TextureRepeat (" << this->TextureRepeat[0] << ", "
                                    << this->TextureRepeat[1]
                                    << ") must be finite: set finite values.");
    return 0;
  }
  constexpr double floatMax = std::numeric_limits<float>::max();
  if (this->GenerateTextureCoordinates &&
    (std::abs(this->TextureOffset[0]) + std::abs(this->TextureRepeat[0]) > floatMax ||
      std::abs(this->TextureOffset[1]) + std::abs(this->TextureRepeat[1]) > floatMax))
  {
    vtkErrorMacro("TextureOffset and TextureRepeat give texture coordinates beyond the float "
                  "range of the TCoords array: use smaller values.");
    return 0;
  }
  if (this->GenerateTangents &&
    (!(this->TextureRepeat[0] != 0.0) || !(this->TextureRepeat[1] != 0.0) ||
      !std::isfinite(1.0 / this->TextureRepeat[0]) || !std::isfinite(1.0 / this->TextureRepeat[1])))
  {
    vtkErrorMacro("TextureRepeat (" << this->TextureRepeat[0] << ", " << this->TextureRepeat[1]
                                    << ") leaves no texture direction for the tangents: "
                                       "use a non-zero repeat.");
    return 0;
  }
  const vtkIdType U = this->UResolution;
  const vtkIdType V = this->VResolution;
  const vtkIdType rowLength = U + 1;
  // Each factor is below 2^31, so the products are exact in vtkIdType. The biggest array
  // per point has 32 bytes (double points or derivatives: 24, float tangents: 16), the
  // connectivity 48 bytes per quad (6 ids of 8 bytes): both must be indexable in bytes.
  constexpr vtkIdType mostIndex = std::numeric_limits<vtkIdType>::max();
  if (rowLength * (V + 1) > mostIndex / 32 || U * V > mostIndex / 48)
  {
    vtkErrorMacro("Resolution " << U << " x " << V << " is too large: (UResolution+1) x "
                                << "(VResolution+1) = " << rowLength * (V + 1)
                                << " points (at most " << mostIndex / 32 << ") and 2 x "
                                << "UResolution x VResolution = " << 2 * U * V
                                << " triangles (at most " << 2 * (mostIndex / 48)
                                << ") must fit the output's arrays: use smaller resolutions.");
    return 0;
  }

  // Pieces split the rows of cells, as vtkSphereSource splits its theta range.
  int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  int numPieces = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  if (numPieces < 1)
  {
    numPieces = 1;
    piece = 0;
  }
  if (numPieces > V)
  {
    numPieces = static_cast<int>(V);
  }
  if (piece < 0 || piece >= numPieces)
  {
    return 1; // a surplus piece is empty
  }
  const vtkIdType cellRow0 = piece * V / numPieces;
  const vtkIdType cellRow1 = (piece + 1) * V / numPieces;

  Grid g;
  g.Function = function;
  g.U = this->UResolution;
  g.Row0 = cellRow0;
  g.NumRows = cellRow1 - cellRow0 + 1;
  g.UMin = umin;
  g.UExtent = umax - umin;
  g.VMin = vmin;
  g.VExtent = vmax - vmin;
  g.Orientation = function->GetClockwiseOrdering() ? 1.0 : -1.0;
  g.HasDerivatives = function->GetDerivativesAvailable() != 0;
  g.InvRepeat[0] = 1.0 / this->TextureRepeat[0];
  g.InvRepeat[1] = 1.0 / this->TextureRepeat[1];
  g.TangentSign = this->TextureRepeat[0] < 0.0 ? -1.0 : 1.0;
  g.Handedness = g.Orientation * g.TangentSign * (this->TextureRepeat[1] < 0.0 ? -1.0 : 1.0);
  // Unit-square parameter, the function's own parameter (its maximum exactly at the end)
  // and texture coordinate of each of the n + 1 columns (rows).
  auto sample = [](vtkIdType n, double lo, double hi, double offset, double repeat,
                  std::vector<double>& unit, std::vector<double>& domain, std::vector<float>& tex)
  {
    unit.resize(n + 1);
    domain.resize(n + 1);
    tex.resize(n + 1);
    for (vtkIdType i = 0; i <= n; ++i)
    {
      const double x = static_cast<double>(i) / static_cast<double>(n);
      unit[i] = x;
      domain[i] = i == n ? hi : lo + (hi - lo) * x;
      tex[i] = static_cast<float>(offset + repeat * x);
    }
  };
  sample(U, umin, umax, this->TextureOffset[0], this->TextureRepeat[0], g.UUnit, g.UDomain, g.S);
  sample(V, vmin, vmax, this->TextureOffset[1], this->TextureRepeat[1], g.VUnit, g.VDomain, g.T);

  // One evaluation before the threads start: functions that build state lazily (profiles,
  // splines) do it here, and errors they report stop the source before any output exists.
  {
    std::string message;
    vtkNew<vtkCallbackCommand> onError;
    onError->SetClientData(&message);
    onError->SetCallback(
      [](vtkObject*, unsigned long, void* clientData, void* callData)
      {
        auto* text = static_cast<std::string*>(clientData);
        if (callData && text->empty())
        {
          *text = static_cast<const char*>(callData);
        }
      });
    const unsigned long tag = function->AddObserver(vtkCommand::ErrorEvent, onError);
    double p[3], du[3], dv[3];
    g.Evaluate(g.UDomain[0], g.VDomain[cellRow0], p, du, dv);
    function->RemoveObserver(tag);
    if (!message.empty())
    {
      vtkErrorMacro("The parametric function " << function->GetClassName()
                                               << " reported an error: " << message);
      return 0;
    }
  }

  // Separable functions do their per-column and per-row work once, not at every point.
  g.Separable = vtkParametricSeparableFunction::SafeDownCast(function);
  if (g.Separable)
  {
    g.NumUTerms = g.Separable->GetNumberOfUTerms();
    g.NumVTerms = g.Separable->GetNumberOfVTerms();
    g.UTerms.resize(rowLength * g.NumUTerms);
    g.VTerms.resize((V + 1) * g.NumVTerms);
    vtkSMPTools::For(0, rowLength,
      [&g, rowLength](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          double terms[vtkParametricSeparableFunction::MaximumNumberOfTerms];
          g.Separable->EvaluateUTerms(g.UDomain[i], terms);
          for (int t = 0; t < g.NumUTerms; ++t)
          {
            g.UTerms[t * rowLength + i] = terms[t];
          }
        }
      });
    vtkSMPTools::For(cellRow0, cellRow1 + 1,
      [&g](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType j = begin; j < end; ++j)
        {
          g.Separable->EvaluateVTerms(g.VDomain[j], g.VTerms.data() + j * g.NumVTerms);
        }
      });
  }

  const vtkIdType numPoints = g.NumRows * rowLength;
  vtkIdType arbitrary = 0;
  const Outcome outcome = this->OutputPointsPrecision == DOUBLE_PRECISION
    ? GeneratePoints<double, vtkDoubleArray>(g, numPoints, this->GenerateNormals,
        this->GenerateTextureCoordinates, this->GenerateTangents, this->GenerateDerivatives, output,
        arbitrary)
    : GeneratePoints<float, vtkFloatArray>(g, numPoints, this->GenerateNormals,
        this->GenerateTextureCoordinates, this->GenerateTangents, this->GenerateDerivatives, output,
        arbitrary);
  if (outcome == Outcome::OutOfMemory)
  {
    output->Initialize();
    vtkErrorMacro("Not enough memory for " << numPoints << " points: use a lower resolution.");
    return 0;
  }
  if (outcome == Outcome::NonFinite)
  {
    output->Initialize();
    vtkErrorMacro("The parametric function " << function->GetClassName()
                                             << " returned non-finite points or derivatives: "
                                                "check its parameters (scale, radii).");
    return 0;
  }
  if (arbitrary > 0)
  {
    vtkWarningMacro(<< arbitrary
                    << " points lie where the surface has no area (e.g. a zero "
                       "radius): their normals and tangents are arbitrary.");
  }

  const vtkIdType numTriangles = 2 * (g.NumRows - 1) * U;
  const bool flip = g.Orientation < 0.0;
  const bool fits32 = 3 * numTriangles < std::numeric_limits<vtkTypeInt32>::max() &&
    numPoints < std::numeric_limits<vtkTypeInt32>::max();
  vtkSmartPointer<vtkCellArray> triangles = fits32
    ? MakeTriangles<vtkTypeInt32Array>(g.NumRows - 1, g.U, flip)
    : MakeTriangles<vtkTypeInt64Array>(g.NumRows - 1, g.U, flip);
  if (!triangles)
  {
    output->Initialize();
    vtkErrorMacro("Not enough memory for " << numTriangles
                                           << " triangles: use a lower "
                                              "resolution.");
    return 0;
  }
  output->SetPolys(triangles);
  return 1;
}

//------------------------------------------------------------------------------
void vtkParametricSurfaceSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ParametricFunction: ";
  if (this->ParametricFunction)
  {
    os << this->ParametricFunction->GetClassName() << " (" << this->ParametricFunction.Get()
       << ")\n";
  }
  else
  {
    os << "(none)\n";
  }
  os << indent << "UResolution: " << this->UResolution << "\n";
  os << indent << "VResolution: " << this->VResolution << "\n";
  os << indent << "GenerateNormals: " << this->GenerateNormals << "\n";
  os << indent << "GenerateTextureCoordinates: " << this->GenerateTextureCoordinates << "\n";
  os << indent << "GenerateTangents: " << this->GenerateTangents << "\n";
  os << indent << "GenerateDerivatives: " << this->GenerateDerivatives << "\n";
  os << indent << "TextureRepeat: (" << this->TextureRepeat[0] << ", " << this->TextureRepeat[1]
     << ")\n";
  os << indent << "TextureOffset: (" << this->TextureOffset[0] << ", " << this->TextureOffset[1]
     << ")\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
