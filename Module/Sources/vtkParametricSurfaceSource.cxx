// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParametricSurfaceSource.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
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
#include "vtkSurfaceDetailProgress.h"
#include "vtkSurfaceDetailTangents.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

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

// Points are done a block of a row at a time, each quantity of the block held as an array
// ("lanes"): the square roots and divisions of the frames then run over independent points,
// which the processor overlaps (and the compiler vectorises).
constexpr int Block = 64;
using Lanes = double[Block];

// Everything the per-point work needs; read-only while the threads run.
struct Grid
{
  vtkParametricFunction* Function = nullptr;
  vtkIdType U = 1; // cells per row (vtkIdType: U + 1 and the indexes below fit)
  // The surface's row of each of this piece's point rows, in increasing order: the piece's
  // own rows, the ghost rows next to them, and (for a function joined in v) the ghost rows
  // across the v seam, which repeat the far end's points as the whole surface does.
  std::vector<vtkIdType> Rows;
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

  // The function and its unit-square derivatives at columns [col, col + count) of row @a j,
  // each component an array (p[c][k]). Separable functions do a row's points in one call.
  void EvaluateBlock(
    vtkIdType col, vtkIdType j, int count, Lanes p[3], Lanes du[3], Lanes dv[3]) const
  {
    if (this->Separable)
    {
      double* const P[3] = { p[0], p[1], p[2] };
      double* const Du[3] = { du[0], du[1], du[2] };
      double* const Dv[3] = { dv[0], dv[1], dv[2] };
      this->Separable->EvaluateRow(count, this->UTerms.data() + col, this->U + 1,
        this->VTerms.data() + j * this->NumVTerms, P, Du, Dv);
      for (int c = 0; c < 3; ++c)
      {
        for (int k = 0; k < count; ++k)
        {
          du[c][k] *= this->UExtent;
          dv[c][k] *= this->VExtent;
        }
      }
      return;
    }
    for (int k = 0; k < count; ++k)
    {
      double pk[3], duk[3], dvk[3];
      this->Evaluate(this->UDomain[col + k], this->VDomain[j], pk, duk, dvk);
      for (int c = 0; c < 3; ++c)
      {
        p[c][k] = pk[c];
        du[c][k] = duk[c];
        dv[c][k] = dvk[c];
      }
    }
  }

  // The unit-square second derivatives d2P/du2, d2P/dudv, d2P/dv2 at column @a col of row
  // @a j: in closed form where the function gives them, otherwise by differences of the
  // first derivatives.
  void SecondDerivatives(vtkIdType col, vtkIdType j, double d2[9]) const
  {
    if (this->Separable)
    {
      double uTerms[vtkParametricSeparableFunction::MaximumNumberOfTerms];
      this->ColumnTerms(col, uTerms);
      if (this->Separable->EvaluateSecondDerivatives(
            uTerms, this->VTerms.data() + j * this->NumVTerms, d2))
      {
        const double scale[3] = { this->UExtent * this->UExtent, this->UExtent * this->VExtent,
          this->VExtent * this->VExtent };
        for (int k = 0; k < 9; ++k)
        {
          d2[k] *= scale[k / 3];
        }
        return;
      }
    }
    double ignored[3];
    this->DifferenceOfDerivatives(0, this->UUnit[col], this->VUnit[j], d2, d2 + 3);
    this->DifferenceOfDerivatives(1, this->UUnit[col], this->VUnit[j], ignored, d2 + 6);
  }

  // The change of Du and Dv along @a axis at unit parameters (u, v): a second-order
  // difference of the first derivatives, central inside the domain and one-sided at its
  // edges. Truncation O(h^2) and rounding O(eps/h) both stay near 1e-8 relative.
  void DifferenceOfDerivatives(int axis, double u, double v, double dDu[3], double dDv[3]) const
  {
    constexpr double h = 1e-4;
    auto at = [&](double offset, double a[3], double b[3])
    { this->Derivatives(axis == 0 ? u + offset : u, axis == 1 ? v + offset : v, a, b); };
    const double x = axis == 0 ? u : v;
    double a1[3], b1[3], a2[3], b2[3];
    if (x - h >= 0.0 && x + h <= 1.0)
    {
      at(h, a1, b1);
      at(-h, a2, b2);
      for (int k = 0; k < 3; ++k)
      {
        dDu[k] = (a1[k] - a2[k]) / (2.0 * h);
        dDv[k] = (b1[k] - b2[k]) / (2.0 * h);
      }
      return;
    }
    const double step = x + 2.0 * h <= 1.0 ? h : -h;
    double a0[3], b0[3];
    at(0.0, a0, b0);
    at(step, a1, b1);
    at(2.0 * step, a2, b2);
    for (int k = 0; k < 3; ++k)
    {
      dDu[k] = (4.0 * a1[k] - a2[k] - 3.0 * a0[k]) / (2.0 * step);
      dDv[k] = (4.0 * b1[k] - b2[k] - 3.0 * b0[k]) / (2.0 * step);
    }
  }

  void ColumnTerms(vtkIdType col, double* uTerms) const
  {
    for (int t = 0; t < this->NumUTerms; ++t)
    {
      uTerms[t] = this->UTerms[t * (this->U + 1) + col];
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

// The change of the unit normal along u and v (Weingarten): with m = Du x Dv and
// n = orientation m / |m|, dn = orientation (dm - (n . dm) n) / |m|, where
// dm/du = Duu x Dv + Du x Duv and dm/dv = Duv x Dv + Du x Dvv.
void NormalChange(const double du[3], const double dv[3], const double d2[9], const double n[3],
  double orientation, double dndu[3], double dndv[3])
{
  double m[3];
  Cross(du, dv, m);
  const double scale = orientation / std::sqrt(Dot(m, m));
  const double* duu = d2;
  const double* duv = d2 + 3;
  const double* dvv = d2 + 6;
  double a[3], b[3], dmu[3], dmv[3];
  Cross(duu, dv, a);
  Cross(du, duv, b);
  for (int k = 0; k < 3; ++k)
  {
    dmu[k] = a[k] + b[k];
  }
  Cross(duv, dv, a);
  Cross(du, dvv, b);
  for (int k = 0; k < 3; ++k)
  {
    dmv[k] = a[k] + b[k];
  }
  const double nu = Dot(n, dmu);
  const double nv = Dot(n, dmv);
  for (int k = 0; k < 3; ++k)
  {
    dndu[k] = scale * (dmu[k] - nu * n[k]);
    dndv[k] = scale * (dmv[k] - nv * n[k]);
  }
}

template <typename Out>
void Store3(const double v[3], Out* out)
{
  out[0] = static_cast<Out>(v[0]);
  out[1] = static_cast<Out>(v[1]);
  out[2] = static_cast<Out>(v[2]);
}

// Points and point arrays of one piece, row by row in blocks of columns; each point is
// computed from its own (i, j) alone, so any split among threads gives the same bytes.
template <typename Real>
struct PointWorker
{
  const Grid& G;
  Real* Points = nullptr;
  float* Normals = nullptr;
  float* TCoords = nullptr;
  float* Tangents = nullptr;
  float* Handedness = nullptr;
  Real* DPdu = nullptr;
  Real* DPdv = nullptr;
  Real* DNdu = nullptr;
  Real* DNdv = nullptr;
  vtkSurfaceDetail::Progress* Progress = nullptr;
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

  // The piece's point rows [begin, end).
  void operator()(vtkIdType begin, vtkIdType end)
  {
    const vtkIdType rowLength = this->G.U + 1;
    for (vtkIdType r = begin; r < end && !this->Progress->Aborted(); ++r)
    {
      for (vtkIdType col = 0; col < rowLength; col += Block)
      {
        this->DoBlock(r, col, static_cast<int>(std::min<vtkIdType>(Block, rowLength - col)));
      }
      this->Progress->Advance(1);
    }
  }

  // Columns [col, col + count) of the piece's point row r.
  void DoBlock(vtkIdType r, vtkIdType col, int count)
  {
    const Grid& g = this->G;
    const vtkIdType j = g.Rows[r];
    const vtkIdType first = r * (g.U + 1) + col;
    Lanes p[3], du[3], dv[3];
    g.EvaluateBlock(col, j, count, p, du, dv);
    double sum = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      for (int k = 0; k < count; ++k)
      {
        sum += p[c][k] + du[c][k] + dv[c][k];
      }
    }
    if (!std::isfinite(sum))
    {
      this->NonFinite.Local() = 1;
      return;
    }
    Store(p, first, count, this->Points);
    if (this->DPdu)
    {
      Store(du, first, count, this->DPdu);
      Store(dv, first, count, this->DPdv);
    }
    if (this->TCoords)
    {
      for (int k = 0; k < count; ++k)
      {
        this->TCoords[2 * (first + k)] = g.S[col + k];
        this->TCoords[2 * (first + k) + 1] = g.T[j];
      }
    }
    if (this->Normals || this->Tangents || this->DNdu)
    {
      this->Frames(j, col, first, count, du, dv);
    }
  }

  // The normals and tangents of the block, and with GenerateDerivatives the change of the
  // normal.
  void Frames(
    vtkIdType j, vtkIdType col, vtkIdType first, int count, const Lanes du[3], const Lanes dv[3])
  {
    const Grid& g = this->G;
    Lanes n[3], t[3];
    Lanes regular; // 1 where the derivatives span a plane, 0 elsewhere
    // Plain pointers to each component and the settings in locals: the vectoriser follows them
    // where it loses track of rows of two-dimensional arrays and of members that stores might
    // change.
    const double *ux = du[0], *uy = du[1], *uz = du[2], *vx = dv[0], *vy = dv[1], *vz = dv[2];
    double *nx = n[0], *ny = n[1], *nz = n[2], *tx = t[0], *ty = t[1], *tz = t[2];
    const double orientation = g.Orientation, tangentSign = g.TangentSign;
    for (int k = 0; k < count; ++k)
    {
      // N = orientation (Du x Dv) / |Du x Dv|; N is orthogonal to Du already, so the shared
      // frame (MakeTangentFrame) reduces to T = Du / |Du| times the sign of the s repeat, with
      // a handedness that is constant wherever the derivatives span a plane.
      const double cx = uy[k] * vz[k] - uz[k] * vy[k];
      const double cy = uz[k] * vx[k] - ux[k] * vz[k];
      const double cz = ux[k] * vy[k] - uy[k] * vx[k];
      const double a2 = ux[k] * ux[k] + uy[k] * uy[k] + uz[k] * uz[k];
      const double b2 = vx[k] * vx[k] + vy[k] * vy[k] + vz[k] * vz[k];
      const double c2 = cx * cx + cy * cy + cz * cz;
      const bool ok = c2 > DegenerateTolerance2 * a2 * b2 && a2 > DegenerateTolerance2 * b2 &&
        b2 > DegenerateTolerance2 * a2 && c2 <= std::numeric_limits<double>::max();
      regular[k] = ok ? 1.0 : 0.0;
      const double scale = orientation / std::sqrt(ok ? c2 : 1.0);
      const double tangentScale = tangentSign / std::sqrt(ok ? a2 : 1.0);
      nx[k] = cx * scale;
      ny[k] = cy * scale;
      nz[k] = cz * scale;
      tx[k] = ux[k] * tangentScale;
      ty[k] = uy[k] * tangentScale;
      tz[k] = uz[k] * tangentScale;
    }
    Lanes w;
    vtkIdType& arbitrary = this->Arbitrary.Local();
    for (int k = 0; k < count; ++k)
    {
      w[k] = g.Handedness;
      if (regular[k] != 0.0)
      {
        continue;
      }
      double nk[3], tk[4];
      const double duk[3] = { du[0][k], du[1][k], du[2][k] };
      const double dvk[3] = { dv[0][k], dv[1][k], dv[2][k] };
      if (!DegenerateFrame(g, g.UUnit[col + k], g.VUnit[j], duk, dvk, nk, tk))
      {
        ++arbitrary;
      }
      for (int c = 0; c < 3; ++c)
      {
        n[c][k] = nk[c];
        t[c][k] = tk[c];
      }
      w[k] = tk[3];
    }
    if (this->Normals)
    {
      Store(n, first, count, this->Normals);
    }
    if (this->Tangents)
    {
      Store(t, first, count, this->Tangents);
      for (int k = 0; k < count; ++k)
      {
        this->Handedness[first + k] = static_cast<float>(w[k]);
      }
    }
    if (this->DNdu)
    {
      this->NormalDerivatives(j, col, first, count, du, dv, n, regular);
    }
  }

  // The change of the normal along u and v (GenerateDerivatives). Where the derivatives do
  // not span a plane (a pole), no derivative of the normal exists: zero.
  void NormalDerivatives(vtkIdType j, vtkIdType col, vtkIdType first, int count, const Lanes du[3],
    const Lanes dv[3], const Lanes n[3], const Lanes regular)
  {
    for (int k = 0; k < count; ++k)
    {
      double dndu[3] = { 0.0, 0.0, 0.0 }, dndv[3] = { 0.0, 0.0, 0.0 };
      if (regular[k] != 0.0)
      {
        const double duk[3] = { du[0][k], du[1][k], du[2][k] };
        const double dvk[3] = { dv[0][k], dv[1][k], dv[2][k] };
        const double nk[3] = { n[0][k], n[1][k], n[2][k] };
        double d2[9];
        this->G.SecondDerivatives(col + k, j, d2);
        NormalChange(duk, dvk, d2, nk, this->G.Orientation, dndu, dndv);
        if (!std::isfinite(Dot(dndu, dndu) + Dot(dndv, dndv)))
        {
          this->NonFinite.Local() = 1;
        }
      }
      Store3(dndu, this->DNdu + 3 * (first + k));
      Store3(dndv, this->DNdv + 3 * (first + k));
    }
  }

  template <typename Out>
  static void Store(const Lanes v[3], vtkIdType first, int count, Out* out)
  {
    for (int k = 0; k < count; ++k)
    {
      out[3 * (first + k)] = static_cast<Out>(v[0][k]);
      out[3 * (first + k) + 1] = static_cast<Out>(v[1][k]);
      out[3 * (first + k) + 2] = static_cast<Out>(v[2][k]);
    }
  }

  void Reduce() {}
};

// Two triangles per grid quad, counter-clockwise around the normal. Every row of quads has
// the connectivity of the first shifted by a multiple of the row length, so each row is one
// add of a precomputed pattern; the offsets are the ramp 0, 3, 6, ... Cell row r lies between
// point rows @a bottoms[r] and @a bottoms[r] + 1.
template <typename Id>
void BuildTriangles(
  const std::vector<vtkIdType>& bottoms, vtkIdType U, bool flip, Id* offsets, Id* connectivity)
{
  const vtkIdType numRows = static_cast<vtkIdType>(bottoms.size());
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
  vtkSMPTools::For(0, numRows,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType r = begin; r < end; ++r)
      {
        const Id shift = static_cast<Id>(bottoms[r] * (U + 1));
        Id* out = connectivity + r * rowValues;
        for (vtkIdType k = 0; k < rowValues; ++k)
        {
          out[k] = pattern[k] + shift;
        }
      }
    });
  const vtkIdType numTriangles = 2 * numRows * U;
  vtkSMPTools::For(0, numTriangles + 1,
    [offsets](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        offsets[t] = static_cast<Id>(3 * t);
      }
    });
}

// Sizes @a array to @a numTuples tuples of @a components; false when the memory is not
// available.
bool Allocate(vtkDataArray* array, const char* name, int components, vtkIdType numTuples)
{
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(numTuples);
  return array->GetNumberOfTuples() == numTuples;
}

// Null when the memory is not available.
template <typename IdArray>
vtkSmartPointer<vtkCellArray> MakeTriangles(
  const std::vector<vtkIdType>& bottoms, vtkIdType U, bool flip)
{
  using Id = typename IdArray::ValueType;
  const vtkIdType numTriangles = 2 * static_cast<vtkIdType>(bottoms.size()) * U;
  vtkNew<IdArray> offsets;
  vtkNew<IdArray> connectivity;
  if (!Allocate(offsets, "offsets", 1, numTriangles + 1) ||
    !Allocate(connectivity, "connectivity", 1, 3 * numTriangles))
  {
    return nullptr;
  }
  BuildTriangles<Id>(bottoms, U, flip, offsets->GetPointer(0), connectivity->GetPointer(0));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

// The rows of one piece: its own cell rows [Row0, Row1) of the V, up to GhostLevels more on
// each side as ghost cells, and for a surface joined in v, the ghost cells that lie across the
// v seam (taken from the far end of the surface, with that end's own points, so that a piece
// holds a seam exactly as the whole surface does). Each point row belongs to one piece: the
// first point row of a piece's cells is its own, the last one is the next piece's (the last
// piece owns both of its ends).
struct PieceRows
{
  vtkIdType V, Row0, Row1;
  std::vector<vtkIdType> PointRows;   // the surface row of each point row, increasing
  std::vector<vtkIdType> CellBottoms; // the point row below each cell row
  std::vector<vtkIdType> CellRows;    // the surface row of each cell row

  PieceRows(vtkIdType v, vtkIdType row0, vtkIdType row1, int ghostLevels, bool joinV)
    : V(v)
    , Row0(row0)
    , Row1(row1)
  {
    const vtkIdType g = ghostLevels;
    const vtkIdType lo = std::max<vtkIdType>(0, row0 - g), hi = std::min(v, row1 + g);
    // Across the seam, never reaching the rows taken already: a piece at the start takes the
    // last rows, a piece at the end the first rows.
    const vtkIdType lastRows = joinV ? std::min(g - (row0 - lo), v - hi) : 0;
    const vtkIdType firstRows = joinV ? std::min(g - (hi - row1), lo) : 0;
    std::vector<char> want(v, 0);
    std::fill(want.begin() + lo, want.begin() + hi, 1);
    std::fill(want.begin(), want.begin() + firstRows, 1);
    std::fill(want.end() - lastRows, want.end(), 1);
    // Each run of consecutive cell rows [a, b) has the point rows a..b.
    for (vtkIdType a = 0; a < v;)
    {
      if (!want[a])
      {
        ++a;
        continue;
      }
      vtkIdType b = a;
      const vtkIdType first = static_cast<vtkIdType>(this->PointRows.size());
      while (b < v && want[b])
      {
        this->CellBottoms.push_back(first + (b - a));
        this->CellRows.push_back(b);
        ++b;
      }
      for (vtkIdType j = a; j <= b; ++j)
      {
        this->PointRows.push_back(j);
      }
      a = b;
    }
  }

  // vtkGhostType arrays: the ghost cells and the points another piece owns.
  void MarkGhosts(vtkIdType U, vtkPolyData* output) const
  {
    const vtkIdType rowLength = U + 1;
    vtkUnsignedCharArray* points = output->AllocatePointGhostArray();
    unsigned char* p = points->GetPointer(0);
    for (size_t k = 0; k < this->PointRows.size(); ++k)
    {
      const vtkIdType j = this->PointRows[k];
      const bool own =
        (j >= this->Row0 && j < this->Row1) || (j == this->V && this->Row1 == this->V);
      std::fill_n(p + k * rowLength, rowLength, own ? 0 : vtkDataSetAttributes::DUPLICATEPOINT);
    }
    vtkUnsignedCharArray* cells = output->AllocateCellGhostArray();
    unsigned char* c = cells->GetPointer(0);
    for (size_t r = 0; r < this->CellRows.size(); ++r)
    {
      const vtkIdType j = this->CellRows[r];
      const bool own = j >= this->Row0 && j < this->Row1;
      std::fill_n(c + r * 2 * U, 2 * U, own ? 0 : vtkDataSetAttributes::DUPLICATECELL);
    }
  }
};

enum class Outcome
{
  Done,
  NonFinite,
  OutOfMemory,
  Aborted // AbortExecute was set while the points were made
};

struct Requested
{
  bool Normals, TCoords, Tangents, Derivatives;
};

template <typename Real, typename RealArray>
Outcome GeneratePoints(const Grid& g, vtkIdType numPoints, Requested want, vtkPolyData* output,
  vtkIdType& arbitrary, vtkSurfaceDetail::Progress& progress)
{
  bool allocated = true;
  auto newArray = [numPoints, &allocated](auto* array, const char* name, int components)
  {
    allocated = allocated && Allocate(array, name, components, numPoints);
    return allocated ? array->GetPointer(0) : nullptr;
  };
  vtkNew<RealArray> points;
  PointWorker<Real> worker(g);
  worker.Points = newArray(points.Get(), "Points", 3);
  vtkNew<vtkFloatArray> normalArray, tcoordArray, tangentArray, handednessArray;
  vtkNew<RealArray> dPdu, dPdv, dNdu, dNdv;
  worker.Normals = want.Normals ? newArray(normalArray.Get(), "Normals", 3) : nullptr;
  worker.TCoords = want.TCoords ? newArray(tcoordArray.Get(), "TCoords", 2) : nullptr;
  if (want.Tangents)
  {
    worker.Tangents = newArray(tangentArray.Get(), "Tangents", 3);
    worker.Handedness = newArray(handednessArray.Get(), "TangentHandedness", 1);
  }
  if (want.Derivatives)
  {
    worker.DPdu = newArray(dPdu.Get(), "dPdu", 3);
    worker.DPdv = newArray(dPdv.Get(), "dPdv", 3);
    worker.DNdu = newArray(dNdu.Get(), "dNdu", 3);
    worker.DNdv = newArray(dNdv.Get(), "dNdv", 3);
  }
  if (!allocated)
  {
    return Outcome::OutOfMemory;
  }

  // Grain: a few thousand points amortise the scheduling; the split never changes values.
  const vtkIdType numRows = static_cast<vtkIdType>(g.Rows.size());
  worker.Progress = &progress;
  vtkSMPTools::For(0, numRows, std::max<vtkIdType>(1, 4096 / (g.U + 1)), worker);
  if (progress.Aborted())
  {
    return Outcome::Aborted;
  }

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
  if (want.Normals)
  {
    pd->SetNormals(normalArray);
  }
  if (want.TCoords)
  {
    pd->SetTCoords(tcoordArray);
  }
  if (want.Tangents)
  {
    vtkSurfaceDetailTangents::SetFrame(pd, tangentArray, handednessArray);
  }
  if (want.Derivatives)
  {
    pd->AddArray(dPdu);
    pd->AddArray(dPdv);
    pd->AddArray(dNdu);
    pd->AddArray(dNdv);
  }
  return Outcome::Done;
}
} // namespace

vtkInformationKeyRestrictedMacro(vtkParametricSurfaceSource, TEXTURE_TRANSFORM, DoubleVector, 4);

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
  // per point has at most 32 bytes (double points or derivatives: 24), the
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
  const int ghostLevels = numPieces > 1
    ? std::max(0, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()))
    : 0;
  const PieceRows rows(
    V, piece * V / numPieces, (piece + 1) * V / numPieces, ghostLevels, function->GetJoinV() != 0);

  Grid g;
  g.Function = function;
  g.U = this->UResolution;
  g.Rows = rows.PointRows;
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
    g.Evaluate(g.UDomain[0], g.VDomain[g.Rows[0]], p, du, dv);
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
    vtkSMPTools::For(0, static_cast<vtkIdType>(g.Rows.size()),
      [&g](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          const vtkIdType j = g.Rows[k];
          g.Separable->EvaluateVTerms(g.VDomain[j], g.VTerms.data() + j * g.NumVTerms);
        }
      });
  }

  const vtkIdType numPoints = static_cast<vtkIdType>(g.Rows.size()) * rowLength;
  vtkIdType arbitrary = 0;
  const Requested want{ this->GenerateNormals, this->GenerateTextureCoordinates,
    this->GenerateTangents, this->GenerateDerivatives };
  vtkSurfaceDetail::Progress progress(this, 0.0, 0.9, static_cast<vtkIdType>(g.Rows.size()));
  const Outcome outcome = this->OutputPointsPrecision == DOUBLE_PRECISION
    ? GeneratePoints<double, vtkDoubleArray>(g, numPoints, want, output, arbitrary, progress)
    : GeneratePoints<float, vtkFloatArray>(g, numPoints, want, output, arbitrary, progress);
  if (outcome == Outcome::Aborted)
  {
    // Stopped by the user (AbortExecute): no error, and no half-made output.
    output->Initialize();
    return 1;
  }
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

  const vtkIdType numTriangles = 2 * static_cast<vtkIdType>(rows.CellBottoms.size()) * U;
  const bool flip = g.Orientation < 0.0;
  const bool fits32 = 3 * numTriangles < std::numeric_limits<vtkTypeInt32>::max() &&
    numPoints < std::numeric_limits<vtkTypeInt32>::max();
  vtkSmartPointer<vtkCellArray> triangles = fits32
    ? MakeTriangles<vtkTypeInt32Array>(rows.CellBottoms, g.U, flip)
    : MakeTriangles<vtkTypeInt64Array>(rows.CellBottoms, g.U, flip);
  if (!triangles)
  {
    output->Initialize();
    vtkErrorMacro("Not enough memory for " << numTriangles
                                           << " triangles: use a lower "
                                              "resolution.");
    return 0;
  }
  output->SetPolys(triangles);
  if (this->GenerateTextureCoordinates && this->GenerateDerivatives)
  {
    const double transform[4] = { this->TextureRepeat[0], this->TextureOffset[0],
      this->TextureRepeat[1], this->TextureOffset[1] };
    output->GetPointData()->GetTCoords()->GetInformation()->Set(TEXTURE_TRANSFORM(), transform, 4);
  }
  if (ghostLevels > 0)
  {
    rows.MarkGhosts(U, output);
  }
  this->UpdateProgress(1.0);
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
