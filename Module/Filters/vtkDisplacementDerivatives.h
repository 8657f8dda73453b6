// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkDisplacementDerivatives.h
 * @brief  Private: the derivatives of vtkDisplacementMapFilter's input surface in (s,t):
 *         P_s, P_t and n_s, n_t, from the surface's own arrays or fitted to neighbours.
 *
 * The analytic normal modes need the surface's derivatives with respect to the texture
 * coordinates. The input may carry them (dPdu, dPdv, dNdu, dNdv, in parameters whose map to
 * (s,t) is declared on the texture coordinates or estimated here); where it does not, they are
 * fitted by least squares over each point's polygons.
 *
 * Part of SurfaceDetail::Filters; not installed.
 */
#ifndef vtkDisplacementDerivatives_h
#define vtkDisplacementDerivatives_h

#include "vtkDataArray.h"
#include "vtkDisplacementNormals.h"
#include "vtkDisplacementPolygons.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkParametricSurfaceSource.h"
#include "vtkSurfaceDetailConventions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vtkDisplacement
{
/**
 * The least-squares fits of the derivatives in (s,t) of the points (P_s, P_t, WantP) and of
 * the normals (n_s, n_t, WantN) where the input lacks them: at point i they minimise
 * sum |f_j - f_i - f_s ds - f_t dt|^2 over the neighbours j in the point's polygons, each
 * counted once per polygon it shares with the point. On a regular grid this is a central
 * difference. The normals are fitted as they are stored and the result divided by |n_i|:
 * across n_i (where Directions uses it) that is the derivative of the unit normal. Where the
 * texture coordinates around the point do not span two directions, or (P) a neighbour sits at
 * the point with other texture coordinates (a pole: p(s,t) is singular there), the
 * derivatives are 0 and the normal falls back on the input's. The sums are made for a range of
 * points at a time (vtkDisplacementPolygons.h), Width numbers per point.
 */
template <typename R, typename Id>
struct Fits
{
  static constexpr int Width = 17; // ss, st, tt, P's 6, n's 6, nearest and farthest |dp|^2
  const Surface<R>& In;
  const Polygons<Id>& Polys;
  const CellRuns& Runs;
  bool WantP;
  bool WantN;

  bool Any() const { return this->WantP || this->WantN; }

  /// The sums of the points [a, b) into @a sums, Width numbers per point.
  void Make(vtkIdType a, vtkIdType b, std::vector<double>& sums) const
  {
    sums.assign(static_cast<size_t>(b - a) * Width, 0.0);
    for (vtkIdType i = a; i < b; ++i)
    {
      sums[(i - a) * Width + 15] = std::numeric_limits<double>::max();
    }
    this->Runs.ForRunsMeeting(a, b,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType cell = begin; cell < end; ++cell)
        {
          const Id* ids = this->Polys.Points(cell);
          const vtkIdType size = this->Polys.Size(cell);
          if (std::any_of(ids, ids + size, [&](Id id) { return Owns(a, b, id); }))
          {
            this->AddPairs(ids, size, a, b, sums.data());
          }
        }
      });
  }

  /**
   * Each pair of corners of the polygon @a ids adds its terms to the sums of the corners it owns
   * (sums indexed from @a a). The terms are products of two differences taken the other way
   * round for the other corner, so they are the same for both, bit for bit; the pairs go in
   * order, so each point gets its neighbours in the polygon's order.
   */
  void AddPairs(const Id* ids, vtkIdType size, vtkIdType a, vtkIdType b, double* sums) const
  {
    const R* tc = this->In.TCoords;
    const vtkIdType tnc = this->In.TCoordsNC;
    for (vtkIdType c1 = 0; c1 < size; ++c1)
    {
      const vtkIdType i = ids[c1];
      const bool ownI = Owns(a, b, i);
      for (vtkIdType c2 = c1 + 1; c2 < size; ++c2)
      {
        const vtkIdType j = ids[c2];
        const bool ownJ = Owns(a, b, j);
        if (i == j || !(ownI || ownJ))
        {
          continue;
        }
        double f[Width];
        const double ds = tc[tnc * j] - tc[tnc * i], dt = tc[tnc * j + 1] - tc[tnc * i + 1];
        f[0] = ds * ds;
        f[1] = ds * dt;
        f[2] = dt * dt;
        if (this->WantP)
        {
          double pi[3], d[3];
          Load3(this->In.Points, i, 1.0, pi);
          Load3(this->In.Points, j, 1.0, d);
          for (int q = 0; q < 3; ++q)
          {
            d[q] -= pi[q];
            f[3 + q] = ds * d[q];
            f[6 + q] = dt * d[q];
          }
          f[15] = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        }
        if (this->WantN)
        {
          double ni[3], d[3];
          Load3(this->In.Normals, i, 1.0, ni);
          Load3(this->In.Normals, j, 1.0, d);
          for (int q = 0; q < 3; ++q)
          {
            d[q] -= ni[q];
            f[9 + q] = ds * d[q];
            f[12 + q] = dt * d[q];
          }
        }
        if (ownI)
        {
          this->Add(f, sums + (i - a) * Width);
        }
        if (ownJ)
        {
          this->Add(f, sums + (j - a) * Width);
        }
      }
    }
  }

  // The terms @a f of one neighbour added to a point's sums @a s.
  void Add(const double* f, double* s) const
  {
    s[0] += f[0];
    s[1] += f[1];
    s[2] += f[2];
    if (this->WantP)
    {
      for (int q = 3; q < 9; ++q)
      {
        s[q] += f[q];
      }
      s[15] = std::min(s[15], f[15]);
      s[16] = std::max(s[16], f[15]);
    }
    if (this->WantN)
    {
      for (int q = 9; q < 15; ++q)
      {
        s[q] += f[q];
      }
    }
  }

  /// The fitted derivatives of point @a i from its sums @a f, into lane @a k of @a b.
  void Solve(vtkIdType i, const double* f, PointBlock& b, int k) const
  {
    const double ss = f[0], st = f[1], tt = f[2];
    const double det = ss * tt - st * st;
    const bool spans = det > 1e-12 * (ss + tt) * (ss + tt);
    auto solve =
      [&](const double* bs, const double* bt, bool ok, double scale, double* x[3], double* y[3])
    {
      for (int q = 0; q < 3; ++q)
      {
        x[q][k] = ok ? (tt * bs[q] - st * bt[q]) / (det * scale) : 0.0;
        y[q][k] = ok ? (ss * bt[q] - st * bs[q]) / (det * scale) : 0.0;
      }
    };
    if (this->WantP)
    {
      double* ps[3] = { b.Psx, b.Psy, b.Psz };
      double* pt[3] = { b.Ptx, b.Pty, b.Ptz };
      solve(f + 3, f + 6, spans && !(f[15] <= 1e-16 * f[16]), 1.0, ps, pt);
    }
    if (this->WantN)
    {
      double n[3];
      Load3(this->In.Normals, i, 1.0, n);
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      double* ns[3] = { b.Nsx, b.Nsy, b.Nsz };
      double* nt[3] = { b.Ntx, b.Nty, b.Ntz };
      solve(f + 9, f + 12, spans && Usable(length), length, ns, nt);
    }
  }
};

/**
 * P_s, P_t and (Exact) n_s, n_t of the block's points: from dPdu/dPdv (and dNdu/dNdv) scaled
 * by the map from their parameters to the texture coordinates, else fitted to the neighbours
 * (@a sums: the fits' sums of the points from @a first on).
 */
template <typename R, typename Id>
void Derivatives(const Surface<R>& in, const Fits<R, Id>& fits, const std::vector<double>& sums,
  vtkIdType first, bool exact, PointBlock& b)
{
  if (!fits.WantP)
  {
    Gather3(in.DPdu, b, in.DerivativeScale[0], b.Psx, b.Psy, b.Psz);
    Gather3(in.DPdv, b, in.DerivativeScale[1], b.Ptx, b.Pty, b.Ptz);
  }
  if (exact && !fits.WantN)
  {
    Gather3(in.DNdu, b, in.DerivativeScale[0], b.Nsx, b.Nsy, b.Nsz);
    Gather3(in.DNdv, b, in.DerivativeScale[1], b.Ntx, b.Nty, b.Ntz);
  }
  for (int k = 0; fits.Any() && k < b.Count; ++k)
  {
    fits.Solve(b.Ids[k], &sums[(b.Ids[k] - first) * fits.Width], b, k);
  }
}

/**
 * dPdu and dPdv may be derivatives with respect to parameters (u,v) of which the texture
 * coordinates are an axis-aligned affine function, s = o_s + r_s u, t = o_t + r_t v
 * (vtkParametricSurfaceSource's TextureRepeat and TextureOffset). Estimates r_s and r_t by
 * least squares over up to 4096 edges spread over the polygons: each edge's (du, dv) solves
 * dP ~ dPdu du + dPdv dv, against its (ds, dt). Sets 1/r (so dP/ds = dPdu / r_s); exactly
 * 1 when the fit is within its own error of it (0.1%, or twice the O(h^2) chord bias estimated
 * from how far the derivatives turn along the edges: float positions and that bias would
 * otherwise perturb the untransformed case) or cannot be made. Edges whose texture
 * coordinates are not finite are left out.
 */
template <typename R, typename Id>
void EstimateDerivativeScale(const Polygons<Id>& polys, Surface<R>& c)
{
  auto get = [](const R* a, vtkIdType i, double v[3])
  {
    v[0] = a[3 * i];
    v[1] = a[3 * i + 1];
    v[2] = a[3 * i + 2];
  };
  double su = 0.0, uu = 0.0, tv = 0.0, vv = 0.0, biasU = 0.0, biasV = 0.0;
  const vtkIdType stride = std::max<vtkIdType>(1, polys.Count / 4096);
  for (vtkIdType cell = 0; cell < polys.Count; cell += stride)
  {
    if (polys.Size(cell) < 2)
    {
      continue;
    }
    const vtkIdType i = polys.Points(cell)[0], j = polys.Points(cell)[1];
    // The mean of the two ends' derivatives: exact for quadratic p, so the fit has no
    // first-order bias from the surface's curvature.
    double pi[3], pj[3], a[3], b[3], aj[3], bj[3], ta[3], tb[3];
    get(c.Points, i, pi);
    get(c.Points, j, pj);
    get(c.DPdu, i, a);
    get(c.DPdv, i, b);
    get(c.DPdu, j, aj);
    get(c.DPdv, j, bj);
    for (int k = 0; k < 3; ++k)
    {
      ta[k] = aj[k] - a[k];
      tb[k] = bj[k] - b[k];
      a[k] = 0.5 * (a[k] + aj[k]);
      b[k] = 0.5 * (b[k] + bj[k]);
    }
    const double dp[3] = { pj[0] - pi[0], pj[1] - pi[1], pj[2] - pi[2] };
    const double aa = vtkSurfaceDetail::Dot(a, a), ab = vtkSurfaceDetail::Dot(a, b),
                 bb = vtkSurfaceDetail::Dot(b, b);
    const double det = aa * bb - ab * ab;
    if (!(det > 1e-12 * (aa + bb) * (aa + bb)))
    {
      continue;
    }
    double du = (bb * vtkSurfaceDetail::Dot(a, dp) - ab * vtkSurfaceDetail::Dot(b, dp)) / det;
    double dv = (aa * vtkSurfaceDetail::Dot(b, dp) - ab * vtkSurfaceDetail::Dot(a, dp)) / det;
    // The chord of an arc that turns its tangent by phi is tan(phi/2) / (phi/2) = 1 + phi^2/12
    // times the mean tangent's step, so (du, dv) comes out that much long: a bias of order h^2,
    // which the correction leaves at order h^4 (exact to that order for constant-speed curves
    // such as the parametric circles of a sphere or torus).
    double turn[3], step[3];
    for (int k = 0; k < 3; ++k)
    {
      turn[k] = ta[k] * du + tb[k] * dv;
      step[k] = a[k] * du + b[k] * dv;
    }
    const double step2 = vtkSurfaceDetail::Dot(step, step);
    double bias = 0.0;
    if (step2 > 0.0)
    {
      bias = vtkSurfaceDetail::Dot(turn, turn) / (12.0 * step2);
      du /= 1.0 + bias;
      dv /= 1.0 + bias;
    }
    const double ds = c.TCoords[c.TCoordsNC * j] - c.TCoords[c.TCoordsNC * i];
    const double dt = c.TCoords[c.TCoordsNC * j + 1] - c.TCoords[c.TCoordsNC * i + 1];
    if (!std::isfinite(ds * du + dt * dv + du * du + dv * dv))
    {
      continue;
    }
    su += ds * du;
    uu += du * du;
    tv += dt * dv;
    vv += dv * dv;
    biasU += bias * du * du;
    biasV += bias * dv * dv;
  }
  const double r[2] = { uu > 0.0 ? su / uu : 1.0, vv > 0.0 ? tv / vv : 1.0 };
  // Within the estimate's own error of 1, r is 1: the common case of texture coordinates that
  // are the parameters, whose derivatives are then used as given.
  const double tolerance[2] = { std::max(1e-3, uu > 0.0 ? 2.0 * biasU / uu : 0.0),
    std::max(1e-3, vv > 0.0 ? 2.0 * biasV / vv : 0.0) };
  for (int k = 0; k < 2; ++k)
  {
    const bool useful =
      r[k] != 0.0 && std::isfinite(1.0 / r[k]) && std::abs(r[k] - 1.0) > tolerance[k];
    c.DerivativeScale[k] = useful ? 1.0 / r[k] : 1.0;
  }
}

/// The map from dPdu/dPdv's parameters to the texture coordinates as vtkParametricSurfaceSource
/// declares it on them: exact, and the same in every piece, where an estimate depends on the
/// polygons at hand. False where it is not declared or not usable.
template <typename R>
bool DeclaredDerivativeScale(vtkDataArray* tcoords, Surface<R>& c)
{
  vtkInformationDoubleVectorKey* key = vtkParametricSurfaceSource::TEXTURE_TRANSFORM();
  vtkInformation* info = tcoords->HasInformation() ? tcoords->GetInformation() : nullptr;
  if (!info || !info->Has(key) || info->Length(key) != 4)
  {
    return false;
  }
  const double* transform = info->Get(key);
  const double repeat[2] = { transform[0], transform[2] };
  for (int k = 0; k < 2; ++k)
  {
    if (!std::isfinite(1.0 / repeat[k]) || repeat[k] == 0.0)
    {
      return false;
    }
  }
  c.DerivativeScale[0] = 1.0 / repeat[0];
  c.DerivativeScale[1] = 1.0 / repeat[1];
  return true;
}

} // namespace vtkDisplacement

#endif
// VTK-HeaderTest-Exclude: vtkDisplacementDerivatives.h
