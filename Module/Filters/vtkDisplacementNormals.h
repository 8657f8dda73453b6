// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkDisplacementNormals.h
 * @brief  Private: the normals of vtkDisplacementMapFilter's displaced surface, in its
 *         normal modes (Approximate, Exact, Mesh), and the tangents made orthogonal to them.
 *
 * The derivatives these formulas take are in vtkDisplacementDerivatives.h. Everything is
 * computed in double precision, reading and writing the arrays as raw values of
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
  const R* Tangents = nullptr; // 3 components, re-orthogonalised to the new normals, or null
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
  Lanes Gx, Gy, Gz;    // triplanar: the height's, then the displacement's gradient
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
 * displacement @a d and slopes @a ds, @a dt: the textbook formula (Approximate), or (Exact) the
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
 * tangents re-orthogonalised to them (the handedness array passes through unchanged).
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
  const R* tangents = in.Tangents;
  for (int k = 0; k < count; ++k)
  {
    const R* ti = tangents + 3 * b.Ids[k];
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
    R* tangent = outTangents + 3 * b.Ids[k];
    tangent[0] = static_cast<R>(b.Tx[k]);
    tangent[1] = static_cast<R>(b.Ty[k]);
    tangent[2] = static_cast<R>(b.Tz[k]);
  }
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
