// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkDisplacementNormals.h
 * @brief  Private: the normals of vtkDisplacementMapFilter's displaced surface, in its
 *         normal modes (Approximate, Exact, Mesh), and the tangents made orthogonal to them.
 *
 * Everything is computed in double precision, reading and writing the arrays as raw values of
 * R (float or double): the formulas point by point, the normalisations over blocks of points.
 * The class description of vtkDisplacementMapFilter states the formulas; the comments here say
 * how they are evaluated.
 *
 * Part of SurfaceDetail::Filters; not installed.
 */
#ifndef vtkDisplacementNormals_h
#define vtkDisplacementNormals_h

#include "vtkDisplacementPolygons.h"
#include "vtkDisplacementSampling.h"
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
/// The input surface's point arrays as raw values of R; absent arrays are null.
template <typename R>
struct Surface
{
  vtkIdType NumPoints = 0;
  const R* Points = nullptr;
  const R* Normals = nullptr;
  const R* TCoords = nullptr;
  int TCoordsNC = 2;
  const R* DPdu = nullptr; // with DPdv, or null: P_s and P_t are then fitted
  const R* DPdv = nullptr;
  const R* DNdu = nullptr; // with DNdv, Exact only, or null: n_s and n_t are then fitted
  const R* DNdv = nullptr;
  const R* Tangents = nullptr; // re-orthogonalised to the new normals, or null
  int TangentsNC = 4;
  double DerivativeScale[2] = { 1.0, 1.0 }; // P_s = dPdu * [0], P_t = dPdv * [1]
};

/// The arrays the filter writes; Normals and Tangents are null where none are made.
template <typename R>
struct Output
{
  R* Points = nullptr;
  R* Normals = nullptr;
  R* Tangents = nullptr;
};

/// NaN becomes 0 and infinity the largest double.
inline double Finite(double x)
{
  if (std::isnan(x))
  {
    return 0.0;
  }
  return std::min(
    std::max(x, -std::numeric_limits<double>::max()), std::numeric_limits<double>::max());
}

/// Whether a length is positive and finite.
inline bool Usable(double length)
{
  return length > 0.0 && length <= std::numeric_limits<double>::max();
}

/// Loads the 3-vector @a i of @a a, times @a scale.
template <typename R>
void Load3(const R* a, vtkIdType i, double scale, double v[3])
{
  v[0] = scale * a[3 * i];
  v[1] = scale * a[3 * i + 1];
  v[2] = scale * a[3 * i + 2];
}

using Lanes = double[Block];

/// The passes work on blocks of points, each quantity of the block held as an array over it
/// ("lanes"). The square roots and divisions that make vectors unit then run over independent
/// points, which the processor overlaps (and the compiler vectorises), where one point after
/// another would wait for each result in turn.
using Lanes = double[Block];

/**
 * What the passes know about a block of points, as lanes. One object holds them all so that
 * the compiler sees that its arrays never overlap and vectorises the loops over them without
 * run-time checks; flags are doubles (1 or 0), which it can mix with the other lanes.
 */
struct PointBlock
{
  vtkIdType Ids[Block];
  int Count = 0;
  Lanes S, T;          // texture coordinates
  Lanes D, Ds, Dt;     // the height, then the displacement d, and their slopes
  Lanes Nx, Ny, Nz;    // unit input normals, zero where one has no direction
  Lanes Psx, Psy, Psz; // P_s
  Lanes Ptx, Pty, Ptz; // P_t
  Lanes Nsx, Nsy, Nsz; // n_s (Exact)
  Lanes Ntx, Nty, Ntz; // n_t (Exact)
  Lanes Mx, My, Mz;    // the output normals
  Lanes Tx, Ty, Tz;    // the output tangents
  Lanes Ok;            // a flag per point for the step at hand

  /// The points [first, first + count).
  void Span(vtkIdType first, int count)
  {
    this->Count = count;
    for (int k = 0; k < count; ++k)
    {
      this->Ids[k] = first + k;
    }
  }
};

/// Loads the 3-vectors @a a of the block's points into @a x, @a y, @a z, times @a scale.
template <typename R>
void Gather3(const R* a, const PointBlock& b, double scale, double* x, double* y, double* z)
{
  for (int k = 0; k < b.Count; ++k)
  {
    const R* p = a + 3 * b.Ids[k];
    x[k] = scale * p[0];
    y[k] = scale * p[1];
    z[k] = scale * p[2];
  }
}

/// Scales each vector (@a x, @a y, @a z) to unit length where its length is Usable (@a ok 1),
/// and leaves it as it is elsewhere (@a ok 0).
inline void MakeUnit(int count, double* x, double* y, double* z, double* ok)
{
  for (int k = 0; k < count; ++k)
  {
    const double length = std::sqrt(x[k] * x[k] + y[k] * y[k] + z[k] * z[k]);
    const bool usable = length > 0.0 && length <= std::numeric_limits<double>::max();
    ok[k] = usable ? 1.0 : 0.0;
    const double inv = 1.0 / (usable ? length : 1.0);
    x[k] *= inv;
    y[k] *= inv;
    z[k] *= inv;
  }
}

/// The unit input normals of the block's points, zero where one has no direction.
template <typename R>
void UnitNormals(const Surface<R>& in, PointBlock& b)
{
  Gather3(in.Normals, b, 1.0, b.Nx, b.Ny, b.Nz);
  MakeUnit(b.Count, b.Nx, b.Ny, b.Nz, b.Ok);
  for (int k = 0; k < b.Count; ++k)
  {
    b.Nx[k] = b.Ok[k] != 0.0 ? b.Nx[k] : 0.0;
    b.Ny[k] = b.Ok[k] != 0.0 ? b.Ny[k] : 0.0;
    b.Nz[k] = b.Ok[k] != 0.0 ? b.Nz[k] : 0.0;
  }
}

/// Removes from @a v its part along the unit (or zero) @a n.
inline void Across(const double n[3], double v[3])
{
  const double along = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
  v[0] -= along * n[0];
  v[1] -= along * n[1];
  v[2] -= along * n[2];
}

/// What the analytic modes know at a point: P_s, P_t and (Exact) n_s, n_t.
struct PointDerivatives
{
  double Ps[3] = {}, Pt[3] = {}, Ns[3] = {}, Nt[3] = {};
};

/// The larger magnitude of the components of @a v.
inline double Largest(const double v[3])
{
  return std::max(std::max(std::abs(v[0]), std::abs(v[1])), std::abs(v[2]));
}

/// Where the products in Direction overflow: the same direction from vectors divided by their
/// largest coefficient (only the direction matters).
inline void RescaledCross(double qs[3], double qt[3], double m[3])
{
  const double ls = Largest(qs), lt = Largest(qt);
  for (int j = 0; j < 3; ++j)
  {
    qs[j] /= ls;
    qt[j] /= lt;
  }
  vtkSurfaceDetail::Cross(qs, qt, m);
}

/**
 * The direction @a m of a point's displaced normal from its unit input normal @a n, its
 * displacement @a d and slopes @a ds, @a dt: the seed's formula (Approximate), or (Exact) the
 * cross product of the displaced surface's derivatives. P_s and P_t count only across n (n
 * defines the tangent plane), so that a map without slope gives back n itself, and the result
 * is oriented by n . (P_s x P_t), whatever the orientation of the parameterisation. Where
 * P_s x P_t vanishes (a singular point of the parameterisation) the input normal is kept.
 */
template <bool Exact>
void Direction(const double n[3], PointDerivatives& b, double d, double ds, double dt, double m[3])
{
  Across(n, b.Ps);
  Across(n, b.Pt);
  double base[3];
  vtkSurfaceDetail::Cross(b.Ps, b.Pt, base);
  const double area = vtkSurfaceDetail::Dot(n, base);
  // |area| > 1e-10 |P_s| |P_t|, squared where the squares are finite (|area| <= |P_s| |P_t|).
  const double ss = vtkSurfaceDetail::Dot(b.Ps, b.Ps), tt = vtkSurfaceDetail::Dot(b.Pt, b.Pt);
  const bool regular = std::isfinite(ss * tt)
    ? area * area > 1e-20 * (ss * tt)
    : std::abs(area) > 1e-10 * std::sqrt(ss) * std::sqrt(tt);
  if (!regular || !std::isfinite(area))
  {
    m[0] = n[0];
    m[1] = n[1];
    m[2] = n[2];
    return;
  }
  const double sign = area < 0.0 ? -1.0 : 1.0;
  double qs[3], qt[3];
  if (Exact)
  {
    // (P_s + d_s n + d n_s) x (P_t + d_t n + d n_t)
    Across(n, b.Ns);
    Across(n, b.Nt);
    for (int j = 0; j < 3; ++j)
    {
      qs[j] = Finite(sign * (b.Ps[j] + ds * n[j] + d * b.Ns[j]));
      qt[j] = Finite(b.Pt[j] + dt * n[j] + d * b.Nt[j]);
    }
  }
  else
  {
    // (n . (P_s x P_t)) n + d_s (n x P_t) - d_t (n x P_s)
    double nxPs[3], nxPt[3];
    vtkSurfaceDetail::Cross(n, b.Ps, nxPs);
    vtkSurfaceDetail::Cross(n, b.Pt, nxPt);
    for (int j = 0; j < 3; ++j)
    {
      m[j] = sign * (area * n[j] + ds * nxPt[j] - dt * nxPs[j]);
    }
    if (std::isfinite(vtkSurfaceDetail::Dot(m, m)))
    {
      return;
    }
    // Huge slopes: the same sum of n, n x P_t and n x P_s with coefficients made small.
    qs[0] = sign * area;
    qs[1] = sign * ds;
    qs[2] = -sign * dt;
    const double l = Largest(qs);
    for (int j = 0; j < 3; ++j)
    {
      m[j] = (qs[0] / l) * n[j] + (qs[1] / l) * nxPt[j] + (qs[2] / l) * nxPs[j];
    }
    return;
  }
  vtkSurfaceDetail::Cross(qs, qt, m);
  if (!std::isfinite(vtkSurfaceDetail::Dot(m, m)))
  {
    RescaledCross(qs, qt, m);
  }
}

/**
 * Direction over a block of points: the directions M from the unit input normals, the
 * displacements and their slopes. One loop evaluates the formulas as they stand, which the
 * compiler vectorises; the few points where a product overflows (or an input is not finite)
 * are then evaluated again by Direction, which scales its vectors first.
 */
template <bool Exact>
void Directions(PointBlock& b)
{
  constexpr double most = std::numeric_limits<double>::max();
  for (int k = 0; k < b.Count; ++k)
  {
    const double ax = b.Nx[k], ay = b.Ny[k], az = b.Nz[k];
    // P_s and P_t across n.
    const double ps = ax * b.Psx[k] + ay * b.Psy[k] + az * b.Psz[k];
    const double sx = b.Psx[k] - ps * ax, sy = b.Psy[k] - ps * ay, sz = b.Psz[k] - ps * az;
    const double pt = ax * b.Ptx[k] + ay * b.Pty[k] + az * b.Ptz[k];
    const double tx = b.Ptx[k] - pt * ax, ty = b.Pty[k] - pt * ay, tz = b.Ptz[k] - pt * az;
    const double cx = sy * tz - sz * ty, cy = sz * tx - sx * tz, cz = sx * ty - sy * tx;
    const double area = ax * cx + ay * cy + az * cz;
    const double size2 = (sx * sx + sy * sy + sz * sz) * (tx * tx + ty * ty + tz * tz);
    const bool regular = area * area > 1e-20 * size2;
    const double sign = area < 0.0 ? -1.0 : 1.0;
    double x, y, z;
    if (Exact)
    {
      // (P_s + d_s n + d n_s) x (P_t + d_t n + d n_t), with n_s and n_t across n.
      const double d = b.D[k];
      const double ns = ax * b.Nsx[k] + ay * b.Nsy[k] + az * b.Nsz[k];
      const double nt = ax * b.Ntx[k] + ay * b.Nty[k] + az * b.Ntz[k];
      const double qsx = sign * (sx + b.Ds[k] * ax + d * (b.Nsx[k] - ns * ax));
      const double qsy = sign * (sy + b.Ds[k] * ay + d * (b.Nsy[k] - ns * ay));
      const double qsz = sign * (sz + b.Ds[k] * az + d * (b.Nsz[k] - ns * az));
      const double qtx = tx + b.Dt[k] * ax + d * (b.Ntx[k] - nt * ax);
      const double qty = ty + b.Dt[k] * ay + d * (b.Nty[k] - nt * ay);
      const double qtz = tz + b.Dt[k] * az + d * (b.Ntz[k] - nt * az);
      x = qsy * qtz - qsz * qty;
      y = qsz * qtx - qsx * qtz;
      z = qsx * qty - qsy * qtx;
    }
    else
    {
      // (n . (P_s x P_t)) n + d_s (n x P_t) - d_t (n x P_s)
      const double a = sign * area, s = sign * b.Ds[k], t = sign * b.Dt[k];
      x = a * ax + s * (ay * tz - az * ty) - t * (ay * sz - az * sy);
      y = a * ay + s * (az * tx - ax * tz) - t * (az * sx - ax * sz);
      z = a * az + s * (ax * ty - ay * tx) - t * (ax * sy - ay * sx);
    }
    const double m2 = x * x + y * y + z * z;
    b.Ok[k] = (size2 <= most ? 1.0 : 0.0) * (m2 <= most ? 1.0 : 0.0);
    b.Mx[k] = regular ? x : ax;
    b.My[k] = regular ? y : ay;
    b.Mz[k] = regular ? z : az;
  }
  for (int k = 0; k < b.Count; ++k)
  {
    if (b.Ok[k] == 0.0)
    {
      PointDerivatives p;
      const double n[3] = { b.Nx[k], b.Ny[k], b.Nz[k] };
      const double ps[3] = { b.Psx[k], b.Psy[k], b.Psz[k] };
      const double pt[3] = { b.Ptx[k], b.Pty[k], b.Ptz[k] };
      std::copy_n(ps, 3, p.Ps);
      std::copy_n(pt, 3, p.Pt);
      if (Exact)
      {
        const double ns[3] = { b.Nsx[k], b.Nsy[k], b.Nsz[k] };
        const double nt[3] = { b.Ntx[k], b.Nty[k], b.Ntz[k] };
        std::copy_n(ns, 3, p.Ns);
        std::copy_n(nt, 3, p.Nt);
      }
      double m[3];
      Direction<Exact>(n, p, b.D[k], b.Ds[k], b.Dt[k], m);
      b.Mx[k] = m[0];
      b.My[k] = m[1];
      b.Mz[k] = m[2];
    }
  }
}

/**
 * Normalises the directions M of the block's points and writes them as their normals (the
 * unit input normal where a direction is degenerate, +z where that is zero too), then their
 * tangents re-orthogonalised to them with the handedness kept.
 */
template <typename R>
void WriteNormalsAndTangents(const Surface<R>& in, const Output<R>& out, PointBlock& b)
{
  const int count = b.Count;
  MakeUnit(count, b.Mx, b.My, b.Mz, b.Ok);
  for (int k = 0; k < count; ++k)
  {
    const bool none = b.Nx[k] == 0.0 && b.Ny[k] == 0.0 && b.Nz[k] == 0.0;
    b.Mx[k] = b.Ok[k] != 0.0 ? b.Mx[k] : b.Nx[k];
    b.My[k] = b.Ok[k] != 0.0 ? b.My[k] : b.Ny[k];
    b.Mz[k] = b.Ok[k] != 0.0 ? b.Mz[k] : (none ? 1.0 : b.Nz[k]);
  }
  R* normals = out.Normals;
  for (int k = 0; k < count; ++k)
  {
    R* normal = normals + 3 * b.Ids[k];
    normal[0] = static_cast<R>(b.Mx[k]);
    normal[1] = static_cast<R>(b.My[k]);
    normal[2] = static_cast<R>(b.Mz[k]);
  }
  if (!out.Tangents)
  {
    return;
  }
  const int nc = in.TangentsNC;
  const R* tangents = in.Tangents;
  for (int k = 0; k < count; ++k)
  {
    const R* ti = tangents + nc * b.Ids[k];
    b.Tx[k] = ti[0];
    b.Ty[k] = ti[1];
    b.Tz[k] = ti[2];
  }
  for (int k = 0; k < count; ++k)
  {
    const double along = b.Mx[k] * b.Tx[k] + b.My[k] * b.Ty[k] + b.Mz[k] * b.Tz[k];
    b.Tx[k] -= along * b.Mx[k];
    b.Ty[k] -= along * b.My[k];
    b.Tz[k] -= along * b.Mz[k];
  }
  MakeUnit(count, b.Tx, b.Ty, b.Tz, b.Ok);
  R* outTangents = out.Tangents;
  for (int k = 0; k < count; ++k)
  {
    if (b.Ok[k] == 0.0)
    {
      // No direction left across the normal: any unit vector orthogonal to it.
      const double m[3] = { b.Mx[k], b.My[k], b.Mz[k] }, zero[3] = { 0.0, 0.0, 0.0 };
      double frame[4];
      vtkSurfaceDetail::MakeTangentFrame(m, zero, zero, frame);
      b.Tx[k] = frame[0];
      b.Ty[k] = frame[1];
      b.Tz[k] = frame[2];
    }
    R* tangent = outTangents + nc * b.Ids[k];
    tangent[0] = static_cast<R>(b.Tx[k]);
    tangent[1] = static_cast<R>(b.Ty[k]);
    tangent[2] = static_cast<R>(b.Tz[k]);
    if (nc == 4)
    {
      tangent[3] = tangents[4 * b.Ids[k] + 3];
    }
  }
}

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

/**
 * Mesh normals: each point's normal is the sum of the normals of its displaced polygons,
 * area-weighted (a fan of cross products from corner 0) and each oriented as its input
 * normals (the input polygon's normal against the sum of its points' input normals). Made
 * for a range of points at a time (vtkDisplacementPolygons.h), each point's polygons in
 * increasing order: the bits depend neither on the threads nor on the pieces.
 */
template <typename R, typename Id>
struct MeshNormals
{
  const Surface<R>& In;
  const Polygons<Id>& Polys;
  const CellRuns& Runs;
  const R* Moved;

  static void FanSum(const R* pts, const Id* ids, vtkIdType n, double sum[3])
  {
    double p0[3];
    Load3(pts, ids[0], 1.0, p0);
    for (vtkIdType k = 1; k + 1 < n; ++k)
    {
      double a[3], c[3], x[3];
      Load3(pts, ids[k], 1.0, a);
      Load3(pts, ids[k + 1], 1.0, c);
      for (int q = 0; q < 3; ++q)
      {
        a[q] -= p0[q];
        c[q] -= p0[q];
      }
      vtkSurfaceDetail::Cross(a, c, x);
      sum[0] += x[0];
      sum[1] += x[1];
      sum[2] += x[2];
    }
  }

  /// The unnormalised normals of the points [a, b) into @a sums, 3 numbers per point.
  void Make(vtkIdType a, vtkIdType b, std::vector<double>& sums) const
  {
    sums.assign(static_cast<size_t>(b - a) * 3, 0.0);
    this->Runs.ForRunsMeeting(a, b,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType cell = begin; cell < end; ++cell)
        {
          const Id* ids = this->Polys.Points(cell);
          const vtkIdType n = this->Polys.Size(cell);
          // No area, and an empty polygon's ids are not there to read.
          if (n < 3 || std::none_of(ids, ids + n, [&](Id id) { return Owns(a, b, id); }))
          {
            continue;
          }
          double before[3] = { 0.0, 0.0, 0.0 }, after[3] = { 0.0, 0.0, 0.0 };
          double normals[3] = { 0.0, 0.0, 0.0 };
          FanSum(this->In.Points, ids, n, before);
          FanSum(this->Moved, ids, n, after);
          for (vtkIdType k = 0; k < n; ++k)
          {
            const R* nk = this->In.Normals + 3 * ids[k];
            normals[0] += nk[0];
            normals[1] += nk[1];
            normals[2] += nk[2];
          }
          const double sign = vtkSurfaceDetail::Dot(before, normals) < 0.0 ? -1.0 : 1.0;
          for (vtkIdType k = 0; k < n; ++k)
          {
            if (Owns(a, b, ids[k]))
            {
              double* m = &sums[3 * (ids[k] - a)];
              m[0] += sign * after[0];
              m[1] += sign * after[1];
              m[2] += sign * after[2];
            }
          }
        }
      });
  }
};
} // namespace vtkDisplacement

#endif
// VTK-HeaderTest-Exclude: vtkDisplacementNormals.h
