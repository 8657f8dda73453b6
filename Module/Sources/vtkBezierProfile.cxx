// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBezierProfile.h"

#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkBezierProfile);

namespace
{
// Eight-point Gauss-Legendre rule on [-1, 1] (exact for polynomials of degree 15).
constexpr int GaussPoints = 4;
constexpr double GaussNode[GaussPoints] = { 0.1834346424956498, 0.5255324099163290,
  0.7966664774136267, 0.9602898564975363 };
constexpr double GaussWeight[GaussPoints] = { 0.3626837833783620, 0.3137066458778873,
  0.2223810344533745, 0.1012285362903763 };
// The speed of a cubic is the square root of a quartic: smooth enough that eight-point
// quadrature on 1/32 of a segment is exact to rounding unless the curve nearly stops.
constexpr int TableIntervalsPerSegment = 32;
} // namespace

//------------------------------------------------------------------------------
void vtkBezierProfile::AddControlPoint(double x, double y)
{
  this->ControlPoints.push_back({ x, y });
  this->Modified();
}

void vtkBezierProfile::SetControlPoint(int index, double x, double y)
{
  if (index < 0 || index >= static_cast<int>(this->ControlPoints.size()))
  {
    vtkErrorMacro("Control point " << index << " does not exist: the profile has "
                                   << this->ControlPoints.size() << " (add points first).");
    return;
  }
  this->ControlPoints[index] = { x, y };
  this->Modified();
}

void vtkBezierProfile::GetControlPoint(int index, double point[2])
{
  if (index < 0 || index >= static_cast<int>(this->ControlPoints.size()))
  {
    vtkErrorMacro("Control point " << index << " does not exist: the profile has "
                                   << this->ControlPoints.size() << ".");
    point[0] = point[1] = 0.0;
    return;
  }
  point[0] = this->ControlPoints[index][0];
  point[1] = this->ControlPoints[index][1];
}

void vtkBezierProfile::RemoveAllControlPoints()
{
  if (!this->ControlPoints.empty())
  {
    this->ControlPoints.clear();
    this->Modified();
  }
}

int vtkBezierProfile::GetNumberOfControlPoints()
{
  return static_cast<int>(this->ControlPoints.size());
}

int vtkBezierProfile::GetNumberOfSegments()
{
  return this->IsValid() ? static_cast<int>(this->ControlPoints.size() - 1) / 3 : 0;
}

//------------------------------------------------------------------------------
bool vtkBezierProfile::IsValid(std::string* reason)
{
  this->Prepare();
  if (!this->Valid && reason)
  {
    *reason = this->InvalidReason;
  }
  return this->Valid;
}

//------------------------------------------------------------------------------
void vtkBezierProfile::EvaluateBezier(
  double tau, double p[2], double d1[2], double d2[2], double d3[2]) const
{
  const int k = static_cast<int>(this->ControlPoints.size() - 1) / 3;
  const double x = std::min(std::max(tau, 0.0), 1.0) * k;
  const int seg = std::min(static_cast<int>(x), k - 1);
  const double s = x - seg;
  const double r = 1.0 - s;
  const Point* c = this->ControlPoints.data() + 3 * seg;
  for (int a = 0; a < 2; ++a)
  {
    const double p0 = c[0][a], p1 = c[1][a], p2 = c[2][a], p3 = c[3][a];
    if (p)
    {
      p[a] = r * r * r * p0 + 3.0 * r * r * s * p1 + 3.0 * r * s * s * p2 + s * s * s * p3;
    }
    // Derivatives with respect to tau = (seg + s) / k, hence the powers of k.
    if (d1)
    {
      d1[a] = 3.0 * k * (r * r * (p1 - p0) + 2.0 * r * s * (p2 - p1) + s * s * (p3 - p2));
    }
    if (d2)
    {
      d2[a] = 6.0 * k * k * (r * (p2 - 2.0 * p1 + p0) + s * (p3 - 2.0 * p2 + p1));
    }
    if (d3)
    {
      d3[a] = 6.0 * k * k * k * (p3 - 3.0 * p2 + 3.0 * p1 - p0);
    }
  }
}

double vtkBezierProfile::Speed(double tau) const
{
  double d[2];
  this->EvaluateBezier(tau, nullptr, d, nullptr, nullptr);
  return std::hypot(d[0], d[1]);
}

double vtkBezierProfile::LengthBetween(double a, double b) const
{
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double sum = 0.0;
  for (int i = 0; i < GaussPoints; ++i)
  {
    sum += GaussWeight[i] *
      (this->Speed(mid - half * GaussNode[i]) + this->Speed(mid + half * GaussNode[i]));
  }
  return sum * half;
}

//------------------------------------------------------------------------------
void vtkBezierProfile::Prepare()
{
  if (this->PreparedTime.load() >= this->GetMTime())
  {
    return;
  }
  std::lock_guard<std::mutex> lock(this->PrepareMutex);
  const vtkMTimeType now = this->GetMTime();
  if (this->PreparedTime.load() >= now)
  {
    return;
  }
  this->LengthTable.clear();
  this->SpeedTable.clear();
  this->NewtonFactor.clear();
  const size_t n = this->ControlPoints.size();
  this->Valid = n >= 4 && (n - 1) % 3 == 0;
  this->InvalidReason.clear();
  if (!this->Valid)
  {
    this->InvalidReason = "the Bézier profile has " + std::to_string(n) +
      " control points; a composite cubic needs 3k+1 (4, 7, 10, ...)";
  }
  for (const Point& p : this->ControlPoints)
  {
    if (this->Valid && (!std::isfinite(p[0]) || !std::isfinite(p[1])))
    {
      this->Valid = false;
      this->InvalidReason = "the Bézier profile has a non-finite control point";
    }
  }
  if (this->Valid)
  {
    const int k = static_cast<int>(n - 1) / 3;
    const int intervals = k * TableIntervalsPerSegment;
    this->LengthTable.assign(intervals + 1, 0.0);
    this->SpeedTable.assign(intervals + 1, 0.0);
    this->NewtonFactor.assign(intervals, 0.0);
    // |s'| / 2s at tau, s the speed: the factor K in Newton's error e' = K e^2.
    auto newtonFactor = [this](double tau)
    {
      double d1[2], d2[2];
      this->EvaluateBezier(tau, nullptr, d1, d2, nullptr);
      const double s2 = d1[0] * d1[0] + d1[1] * d1[1];
      return s2 > 0.0 ? std::abs(d1[0] * d2[0] + d1[1] * d2[1]) / (2.0 * s2)
                      : std::numeric_limits<double>::infinity();
    };
    for (int i = 0; i <= intervals; ++i)
    {
      const double tau = static_cast<double>(i) / intervals;
      this->SpeedTable[i] = this->Speed(tau);
      if (i < intervals)
      {
        const double next = static_cast<double>(i + 1) / intervals;
        this->LengthTable[i + 1] = this->LengthTable[i] + this->LengthBetween(tau, next);
        this->NewtonFactor[i] =
          std::max({ newtonFactor(tau), newtonFactor(0.5 * (tau + next)), newtonFactor(next) });
      }
    }
  }
  this->PreparedTime.store(now);
}

double vtkBezierProfile::GetLength()
{
  return this->IsValid() ? this->LengthTable.back() : 0.0;
}

// The Bézier parameter at which the curve has run @a length from its start.
double vtkBezierProfile::InverseLength(double length) const
{
  const std::vector<double>& table = this->LengthTable;
  const int intervals = static_cast<int>(table.size()) - 1;
  if (length <= 0.0)
  {
    return 0.0;
  }
  if (length >= table.back())
  {
    return 1.0;
  }
  const int i = std::min(
    static_cast<int>(std::upper_bound(table.begin(), table.end(), length) - table.begin()) - 1,
    intervals - 1);
  const double width = 1.0 / intervals;
  double lo = static_cast<double>(i) / intervals;
  double hi = static_cast<double>(i + 1) / intervals;
  const double start = lo;
  const double rest = length - table[i];
  const double span = table[i + 1] - table[i];
  const double s0 = this->SpeedTable[i], s1 = this->SpeedTable[i + 1];
  double tau = lo;
  if (span > 0.0)
  {
    // First guess: the cubic Hermite interpolant of tau(length), whose slope is 1/speed,
    // accurate to O(width^4); linear where the curve stops at an end of the interval.
    const double x = rest / span;
    tau = lo + width * x;
    if (s0 > 0.0 && s1 > 0.0)
    {
      const double m0 = span / s0, m1 = span / s1;
      tau =
        lo + (x * (1 - x) * (1 - x)) * m0 + (x * x * (3 - 2 * x)) * width - (x * x * (1 - x)) * m1;
    }
    tau = std::min(std::max(tau, lo), hi);
  }
  // Newton on L(tau) = rest with L' = speed, falling back to bisection whenever a step
  // leaves the bracket (the speed may vanish where control points coincide). Steps stop at
  // a few ulps of tau; and once Newton's quadratic error K step^2 is below that, the step
  // just taken is the answer without evaluating the length again.
  const double factor = this->NewtonFactor[i];
  for (int iteration = 0; iteration < 100; ++iteration)
  {
    const double f = this->LengthBetween(start, tau) - rest;
    (f > 0.0 ? hi : lo) = tau;
    const double speed = this->Speed(tau);
    double next = speed > 0.0 ? tau - f / speed : lo;
    const bool newton = next > lo && next < hi;
    if (!newton)
    {
      next = 0.5 * (lo + hi);
    }
    const double step = std::abs(next - tau);
    const double tolerance = 4.0 * std::numeric_limits<double>::epsilon() * std::max(tau, width);
    if (step <= tolerance || hi - lo <= tolerance ||
      (newton && 4.0 * factor * step * step <= tolerance))
    {
      return next;
    }
    tau = next;
  }
  return tau;
}

//------------------------------------------------------------------------------
bool vtkBezierProfile::Evaluate(double t, double point[2], double d1[2], double d2[2])
{
  double p[2], b1[2], b2[2], b3[2];
  if (!this->IsValid() || std::isnan(t))
  {
    for (double* out : { point, d1, d2 })
    {
      if (out)
      {
        out[0] = out[1] = 0.0;
      }
    }
    return false;
  }
  t = std::min(std::max(t, 0.0), 1.0);
  if (!this->ArcLengthParameterization)
  {
    this->EvaluateBezier(t, p, b1, b2, nullptr);
  }
  else
  {
    const double length = this->LengthTable.back();
    const double tau = this->InverseLength(t * length);
    this->EvaluateBezier(tau, p, b1, b2, b3);
    // Chain rule with dtau/dt = L/|B'|: dP/dt = B' L/|B'| and
    // d2P/dt2 = (L/|B'|)^2 (B'' minus its part along B').
    const double speed = std::hypot(b1[0], b1[1]);
    const double scale = std::max(std::hypot(p[0], p[1]), length);
    if (speed > 1e-12 * scale)
    {
      const double f = length / speed;
      const double along = (b1[0] * b2[0] + b1[1] * b2[1]) / (speed * speed);
      for (int a = 0; a < 2; ++a)
      {
        b2[a] = f * f * (b2[a] - along * b1[a]);
        b1[a] *= f;
      }
    }
    else
    {
      // The curve stops here (coincident control points): the unit tangent is the limit
      // direction of motion, that of the first derivative of B that does not vanish; just
      // before the very end B' = -(1 - tau) B'' points against B''.
      const bool second = std::hypot(b2[0], b2[1]) > 1e-12 * scale;
      const double* dir = second ? b2 : b3;
      const double n = std::hypot(dir[0], dir[1]);
      const double f = (n > 0.0 ? length / n : 0.0) * (second && tau >= 1.0 ? -1.0 : 1.0);
      b1[0] = f * dir[0];
      b1[1] = f * dir[1];
      b2[0] = b2[1] = 0.0;
    }
  }
  for (int a = 0; a < 2; ++a)
  {
    if (point)
    {
      point[a] = p[a];
    }
    if (d1)
    {
      d1[a] = b1[a];
    }
    if (d2)
    {
      d2[a] = b2[a];
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBezierProfile::SetToVase()
{
  // (radius, height): a closed base from the axis, a belly, a narrow neck and a flared lip;
  // joins are smooth (each join lies on the line through its neighbours).
  this->ControlPoints = { { 0.0, 0.0 }, { 0.5, 0.0 }, { 0.7, 0.05 }, { 0.75, 0.2 }, { 0.8, 0.35 },
    { 1.05, 1.0 }, { 0.4, 1.45 }, { 0.27, 1.54 }, { 0.3, 1.85 }, { 0.5, 2.0 } };
  this->Modified();
}

void vtkBezierProfile::SetToHeart()
{
  // (x, z) of a heart seen from +y, traversed from +x towards -z (as the cylinder's theta)
  // so that extrusions face outward. It starts and ends at the dip between the lobes,
  // where the curve has a corner: the extrusion's seam then falls on the corner.
  this->ControlPoints = { { 0.0, -0.7 }, { -0.35, -1.3 }, { -0.95, -1.3 }, { -1.0, -0.55 },
    { -1.05, 0.2 }, { -0.25, 1.0 }, { 0.0, 1.0 }, { 0.25, 1.0 }, { 1.05, 0.2 }, { 1.0, -0.55 },
    { 0.95, -1.3 }, { 0.35, -1.3 }, { 0.0, -0.7 } };
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkBezierProfile::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ArcLengthParameterization: " << this->ArcLengthParameterization << "\n";
  os << indent << "NumberOfControlPoints: " << this->ControlPoints.size() << "\n";
  for (const Point& p : this->ControlPoints)
  {
    os << indent.GetNextIndent() << "(" << p[0] << ", " << p[1] << ")\n";
  }
}
