// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Accuracy of vtkParametricSurfaceSource against closed-form surfaces written out here, in
// the test, from the seeds' formulas (seed 004: sphere, cylinder, rectangle; seed 000:
// donut) and from VTK's documented formulas (vtkParametricTorus, vtkParametricEllipsoid).
// Derivatives, normals and tangents are derived independently: five-point finite
// differences of the closed-form lambdas, never the classes' own derivative code.

#include "ParametricSurfaceTestHelpers.h"
#include "TangentFrameTestHelpers.h"
#include "vtkInformation.h"

#include <vtkBezierProfile.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkParametricCylinder.h>
#include <vtkParametricDonut.h>
#include <vtkParametricEllipsoid.h>
#include <vtkParametricExtrusion.h>
#include <vtkParametricKlein.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricRevolution.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSuperEllipsoid.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkParametricTorus.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

namespace
{
using Vec = std::array<double, 3>;
using SurfaceFn = std::function<Vec(double u, double v)>;
const double Pi = vtkMath::Pi();

Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Vec Scale(const Vec& a, double s)
{
  return { a[0] * s, a[1] * s, a[2] * s };
}
double DotV(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec CrossV(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double Norm(const Vec& a)
{
  return std::sqrt(DotV(a, a));
}
Vec Unit(const Vec& a)
{
  return Scale(a, 1.0 / Norm(a));
}
double Angle(const Vec& a, const Vec& b)
{
  return std::atan2(Norm(CrossV(a, b)), DotV(a, b));
}
Vec Tuple(vtkDataArray* array, vtkIdType id)
{
  return { array->GetComponent(id, 0), array->GetComponent(id, 1), array->GetComponent(id, 2) };
}

// Fourth-order differences: central where f is smooth across [x-2h, x+2h], one-sided
// (forward, else backward) where a break lies in the stencil. Breaks are the parameters
// where f is only C1 (Bézier joins) or stops (ends of a clamped profile); at a break itself
// the forward side is taken, as the classes evaluate the next segment there.
double Derivative1D(const std::function<double(double)>& f, double x,
  const std::vector<double>& breaks, double h = 1e-3)
{
  // A break at 1 means that f is not defined beyond it.
  const double hi = !breaks.empty() && breaks.back() == 1 ? 1 : HUGE_VAL;
  auto clear = [&breaks](double a, double b, bool closedLeft, bool closedRight)
  {
    for (double br : breaks)
    {
      if ((br > a || (closedLeft && br == a)) && (br < b || (closedRight && br == b)))
      {
        return false;
      }
    }
    return true;
  };
  if (clear(x - 2 * h, x + 2 * h, true, true))
  {
    return (-f(x + 2 * h) + 8 * f(x + h) - 8 * f(x - h) + f(x - 2 * h)) / (12 * h);
  }
  const double side = x + 4 * h <= hi && clear(x, x + 4 * h, false, true) ? 1.0 : -1.0;
  const double k = side * h;
  return (-25 * f(x) + 48 * f(x + k) - 36 * f(x + 2 * k) + 16 * f(x + 3 * k) - 3 * f(x + 4 * k)) /
    (12 * k);
}

Vec DerivU(const SurfaceFn& f, double u, double v, const std::vector<double>& breaks = {})
{
  Vec d;
  for (int c = 0; c < 3; ++c)
  {
    d[c] = Derivative1D([&](double x) { return f(x, v)[c]; }, u, breaks);
  }
  return d;
}
Vec DerivV(const SurfaceFn& f, double u, double v, const std::vector<double>& breaks = {})
{
  Vec d;
  for (int c = 0; c < 3; ++c)
  {
    d[c] = Derivative1D([&](double y) { return f(u, y)[c]; }, v, breaks);
  }
  return d;
}

struct Expectation
{
  SurfaceFn Surface;      // closed form on the unit square
  double Length = 1;      // size of the surface, for relative position errors
  double Orientation = 1; // +1: normal = Pu x Pv; -1: Pv x Pu
  double PositionTolerance = 1e-14;
  double Repeat[2] = { 1, 1 };
  double Offset[2] = { 0, 0 };
  std::vector<double> UBreaks, VBreaks; // where the surface is only C1 (see Derivative1D)
};

vtkSmartPointer<vtkPolyData> Generate(vtkParametricFunction* f, int U, int V, const Expectation& e,
  int precision = vtkAlgorithm::DOUBLE_PRECISION)
{
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(f);
  source->SetUResolution(U);
  source->SetVResolution(V);
  source->GenerateTangentsOn();
  source->GenerateDerivativesOn();
  source->SetTextureRepeat(e.Repeat[0], e.Repeat[1]);
  source->SetTextureOffset(e.Offset[0], e.Offset[1]);
  source->SetOutputPointsPrecision(precision);
  source->Update();
  return source->GetOutput();
}

// The closed form's unit normal, oriented as the expectation says.
Vec NormalAt(const Expectation& e, double u, double v)
{
  return Scale(Unit(CrossV(DerivU(e.Surface, u, v, e.UBreaks), DerivV(e.Surface, u, v, e.VBreaks))),
    e.Orientation);
}

// The change of that normal along u (axis 0) or v (axis 1): differences of the normal
// itself, not the Weingarten relation the source uses. A step finer than the default keeps
// the truncation error small where the curvature changes fast (the love pillar's cusp).
Vec NormalDerivative(const Expectation& e, int axis, double u, double v)
{
  Vec d;
  for (int c = 0; c < 3; ++c)
  {
    d[c] = axis == 0
      ? Derivative1D([&](double x) { return NormalAt(e, x, v)[c]; }, u, e.UBreaks, 2.5e-4)
      : Derivative1D([&](double y) { return NormalAt(e, u, y)[c]; }, v, e.VBreaks, 2.5e-4);
  }
  return d;
}

// Checks every vertex away from degenerate points; returns how many were checked.
int CheckAgainstClosedForm(vtkParametricFunction* f, int U, int V, const Expectation& e)
{
  vtkSmartPointer<vtkPolyData> out = Generate(f, U, V, e);
  EXPECT_EQ(out->GetNumberOfPoints(), (U + 1) * (V + 1));
  EXPECT_EQ(out->GetNumberOfCells(), 2 * U * V);
  vtkPointData* pd = out->GetPointData();
  vtkDataArray* normals = pd->GetNormals();
  vtkDataArray* tcoords = pd->GetTCoords();
  vtkDataArray* tangents = pd->GetTangents();
  vtkDataArray* handedness = pd->GetArray("TangentHandedness");
  vtkDataArray* dPdu = pd->GetArray("dPdu");
  vtkDataArray* dPdv = pd->GetArray("dPdv");
  vtkDataArray* dNdu = pd->GetArray("dNdu");
  vtkDataArray* dNdv = pd->GetArray("dNdv");
  EXPECT_TRUE(normals && tcoords && tangents && handedness && dPdu && dPdv && dNdu && dNdv);
  if (!(normals && tcoords && tangents && handedness && dPdu && dPdv && dNdu && dNdv))
  {
    return 0;
  }
  EXPECT_STREQ(normals->GetName(), "Normals");
  EXPECT_STREQ(tcoords->GetName(), "TCoords");
  // The frame as vtkSurfaceDetailTangents stores it: VTK's 3-component tangent attribute,
  // marked as written with the 1-component handedness beside it.
  EXPECT_STREQ(tangents->GetName(), "Tangents");
  EXPECT_EQ(tangents->GetNumberOfComponents(), 3);
  EXPECT_EQ(tangents->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(tangents->GetInformation()->Get(vtkSurfaceDetailTangents::WITH_HANDEDNESS()), 1);
  EXPECT_EQ(handedness->GetNumberOfComponents(), 1);
  EXPECT_EQ(handedness->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(vtkSurfaceDetailTangents::GetHandednessProblem(pd), "");

  double worstPos = 0, worstN = 0, worstT = 0, worstD = 0, worstDN = 0;
  int checked = 0, handednessWrong = 0, tcoordWrong = 0;
  for (int j = 0; j <= V; ++j)
  {
    for (int i = 0; i <= U; ++i)
    {
      const vtkIdType id = j * (U + 1) + i;
      const double u = static_cast<double>(i) / U, v = static_cast<double>(j) / V;
      const Vec p = e.Surface(u, v);
      worstPos = std::max(worstPos, Norm(Sub(Tuple(out->GetPoints()->GetData(), id), p)));

      const float s = static_cast<float>(e.Offset[0] + e.Repeat[0] * u);
      const float t = static_cast<float>(e.Offset[1] + e.Repeat[1] * v);
      tcoordWrong += (static_cast<float>(tcoords->GetComponent(id, 0)) != s ||
        static_cast<float>(tcoords->GetComponent(id, 1)) != t);

      const Vec pu = DerivU(e.Surface, u, v, e.UBreaks), pv = DerivV(e.Surface, u, v, e.VBreaks);
      worstD = std::max(worstD, Norm(Sub(Tuple(dPdu, id), pu)) / e.Length);
      worstD = std::max(worstD, Norm(Sub(Tuple(dPdv, id), pv)) / e.Length);
      const Vec c = CrossV(pu, pv);
      if (Norm(c) < 1e-3 * Norm(pu) * Norm(pv) || Norm(pu) < 1e-3 * e.Length ||
        Norm(pv) < 1e-3 * e.Length)
      {
        continue; // degenerate: the limit is checked by its own test
      }
      ++checked;
      const Vec n = Scale(Unit(c), e.Orientation);
      worstN = std::max(worstN, Angle(Tuple(normals, id), n));
      const Vec dPds = Scale(pu, 1.0 / e.Repeat[0]), dPdt = Scale(pv, 1.0 / e.Repeat[1]);
      const Vec tan = Unit(Sub(dPds, Scale(n, DotV(n, dPds))));
      worstT = std::max(worstT, Angle(Tuple(tangents, id), tan));
      const double w = DotV(CrossV(n, tan), dPdt) < 0 ? -1.0 : 1.0;
      handednessWrong += handedness->GetComponent(id, 0) != w;
      // dN/du has the size of |Pu| times a curvature: relative to |Pu| / Length. On a join
      // where the surface is only C1 the normal has two one-sided derivatives: not compared.
      const double dnScale = (Norm(pu) + Norm(pv)) / e.Length;
      auto onBreak = [](const std::vector<double>& breaks, double x)
      {
        return std::any_of(
          breaks.begin(), breaks.end(), [x](double b) { return std::abs(x - b) < 1e-12; });
      };
      if (!onBreak(e.UBreaks, u) && !onBreak(e.VBreaks, v))
      {
        worstDN =
          std::max(worstDN, Norm(Sub(Tuple(dNdu, id), NormalDerivative(e, 0, u, v))) / dnScale);
        worstDN =
          std::max(worstDN, Norm(Sub(Tuple(dNdv, id), NormalDerivative(e, 1, u, v))) / dnScale);
      }
    }
  }
  EXPECT_LT(worstPos, e.PositionTolerance * e.Length);
  EXPECT_LT(worstN, 1e-6);
  EXPECT_LT(worstT, 1e-6);
  EXPECT_LT(worstD, 1e-9);
  EXPECT_LT(worstDN, 1e-6);
  EXPECT_EQ(handednessWrong, 0);
  EXPECT_EQ(tcoordWrong, 0);
  return checked;
}

// Seed 004's sphere: alpha = pi (1 - v), theta = 2 pi u.
SurfaceFn SeedSphere(double r)
{
  return [r](double u, double v) -> Vec
  {
    const double a = Pi * (1 - v), t = 2 * Pi * u;
    return { r * std::sin(a) * std::cos(t), r * std::cos(a), -r * std::sin(a) * std::sin(t) };
  };
}
} // namespace

TEST(ParametricSurfaceAccuracy, SphereMatchesSeed004)
{
  vtkNew<vtkParametricSphere> sphere;
  sphere->SetRadius(2.5);
  Expectation e;
  e.Surface = SeedSphere(2.5);
  e.Length = 2.5;
  EXPECT_GT(CheckAgainstClosedForm(sphere, 48, 24, e), 40 * 20);
  // The sphere's normal is also P/R exactly: a second, derivative-free truth.
  vtkSmartPointer<vtkPolyData> out = Generate(sphere, 48, 24, e);
  // And so its change is dN = dP / R (zero along u at the poles, where dP/du vanishes).
  double worst = 0, worstDN = 0;
  vtkPointData* pd = out->GetPointData();
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    const Vec p = Tuple(out->GetPoints()->GetData(), id);
    worst = std::max(worst, Angle(Tuple(pd->GetNormals(), id), p));
    const bool pole = id <= 48 || id >= 24 * 49;
    if (!pole)
    {
      worstDN = std::max(worstDN,
        Norm(Sub(Tuple(pd->GetArray("dNdu"), id), Scale(Tuple(pd->GetArray("dPdu"), id), 0.4))));
      worstDN = std::max(worstDN,
        Norm(Sub(Tuple(pd->GetArray("dNdv"), id), Scale(Tuple(pd->GetArray("dPdv"), id), 0.4))));
    }
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(worstDN, 1e-12);
}

TEST(ParametricSurfaceAccuracy, SpherePolesTakeTheLimit)
{
  vtkNew<vtkParametricSphere> sphere;
  const int U = 16, V = 8;
  Expectation e;
  e.Surface = SeedSphere(1);
  vtkSmartPointer<vtkPolyData> out = Generate(sphere, U, V, e);
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  auto tangents = TangentFrame(out);
  for (int i = 0; i <= U; ++i)
  {
    const double theta = 2 * Pi * i / U;
    // Along each column the tangent is dP/du normalised, (-sin theta, 0, -cos theta) for
    // every 0 < v < 1; the pole's tangent must be that limit.
    const Vec columnTangent = { -std::sin(theta), 0, -std::cos(theta) };
    const vtkIdType south = i, north = V * (U + 1) + i;
    EXPECT_LT(Angle(Tuple(normals, south), { 0, -1, 0 }), 1e-4) << "column " << i;
    EXPECT_LT(Angle(Tuple(normals, north), { 0, 1, 0 }), 1e-4) << "column " << i;
    EXPECT_LT(Angle(Tuple(tangents, south), columnTangent), 1e-4) << "column " << i;
    EXPECT_LT(Angle(Tuple(tangents, north), columnTangent), 1e-4) << "column " << i;
    EXPECT_EQ(tangents->GetComponent(south, 3), 1.0);
    EXPECT_EQ(tangents->GetComponent(north, 3), 1.0);
    // ...and it matches the next point down the column.
    EXPECT_LT(Angle(Tuple(tangents, north), Tuple(tangents, north - (U + 1))), 1e-6);
  }
}

TEST(ParametricSurfaceAccuracy, CylinderMatchesSeed004)
{
  vtkNew<vtkParametricCylinder> cylinder;
  cylinder->SetRadius(1.5);
  cylinder->SetHeight(3);
  Expectation e;
  e.Surface = [](double u, double v) -> Vec
  {
    const double t = 2 * Pi * u;
    return { 1.5 * std::cos(t), 3 * v, -1.5 * std::sin(t) };
  };
  e.Length = 3;
  e.Repeat[0] = 3; // texture repeated three times round, offset upwards
  e.Offset[1] = 0.25;
  EXPECT_EQ(CheckAgainstClosedForm(cylinder, 40, 7, e), 41 * 8);
  // Outward: the normal points away from the axis.
  vtkSmartPointer<vtkPolyData> out = Generate(cylinder, 40, 7, e);
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    const Vec p = Tuple(out->GetPoints()->GetData(), id);
    EXPECT_LT(Angle(Tuple(out->GetPointData()->GetNormals(), id), { p[0], 0, p[2] }), 1e-6);
  }
}

TEST(ParametricSurfaceAccuracy, RectangleMatchesSeed004)
{
  vtkNew<vtkParametricRectangle> rect; // default: seed 004's wall, x in [-2,2], y in [0,3.5]
  Expectation e;
  e.Surface = [](double u, double v) -> Vec { return { -2 + 4 * u, 3.5 * v, 0 }; };
  e.Length = 4;
  e.Repeat[0] = 4; // seed 004's repeated bricks: s in [0,4], t in [0,1.5]
  e.Repeat[1] = 1.5;
  EXPECT_EQ(CheckAgainstClosedForm(rect, 5, 3, e), 6 * 4);
  vtkSmartPointer<vtkPolyData> out = Generate(rect, 5, 3, e);
  EXPECT_LT(Angle(Tuple(out->GetPointData()->GetNormals(), 7), { 0, 0, 1 }), 1e-7);

  // A tilted parallelogram, mirrored texture (negative repeat): handedness flips.
  rect->SetOrigin(1, 2, 3);
  rect->SetPoint1(2, 2.5, 3.5);
  rect->SetPoint2(0.5, 3, 4);
  e.Surface = [](double u, double v) -> Vec {
    return { 1 + u * 1 - v * 0.5, 2 + u * 0.5 + v * 1, 3 + u * 0.5 + v * 1 };
  };
  e.Repeat[0] = -2;
  e.Repeat[1] = 1;
  e.PositionTolerance = 1e-15;
  EXPECT_EQ(CheckAgainstClosedForm(rect, 4, 4, e), 25);
  out = Generate(rect, 4, 4, e);
  EXPECT_EQ(out->GetPointData()->GetArray("TangentHandedness")->GetComponent(0, 0), -1.0);
}

TEST(ParametricSurfaceAccuracy, DonutMatchesSeed000)
{
  vtkNew<vtkParametricDonut> donut;
  donut->SetRingRadius(2);
  donut->SetCrossSectionRadius(0.5);
  Expectation e;
  e.Surface = [](double u, double v) -> Vec
  {
    const double a = 2 * Pi * u, b = 2 * Pi * v;
    return { (2 + 0.5 * std::cos(b)) * std::cos(a), (2 + 0.5 * std::cos(b)) * std::sin(a),
      0.5 * std::sin(b) };
  };
  e.Length = 2.5;
  EXPECT_EQ(CheckAgainstClosedForm(donut, 36, 18, e), 37 * 19);
  // Outward: away from the centre of the tube's cross-section.
  vtkSmartPointer<vtkPolyData> out = Generate(donut, 36, 18, e);
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    const Vec p = Tuple(out->GetPoints()->GetData(), id);
    const double rho = std::hypot(p[0], p[1]);
    const Vec centre = { 2 * p[0] / rho, 2 * p[1] / rho, 0 };
    EXPECT_GT(DotV(Tuple(out->GetPointData()->GetNormals(), id), Sub(p, centre)), 0.49);
    // Seed 000's texture reads the right way round: w = +1 everywhere.
    EXPECT_EQ(out->GetPointData()->GetArray("TangentHandedness")->GetComponent(id, 0), 1.0);
  }
  // The unit normal is (cos b cos a, cos b sin a, sin b) with a = 2 pi u, b = 2 pi v, so
  // dN/du = 2 pi cos b (-sin a, cos a, 0) and dN/dv = 2 pi (-sin b cos a, -sin b sin a, cos b).
  double worstDN = 0;
  for (int j = 0; j <= 18; ++j)
  {
    for (int i = 0; i <= 36; ++i)
    {
      const double a = 2 * Pi * i / 36, b = 2 * Pi * j / 18;
      const Vec dndu = { -2 * Pi * std::cos(b) * std::sin(a), 2 * Pi * std::cos(b) * std::cos(a),
        0 };
      const Vec dndv = { -2 * Pi * std::sin(b) * std::cos(a), -2 * Pi * std::sin(b) * std::sin(a),
        2 * Pi * std::cos(b) };
      const vtkIdType id = j * 37 + i;
      worstDN =
        std::max(worstDN, Norm(Sub(Tuple(out->GetPointData()->GetArray("dNdu"), id), dndu)));
      worstDN =
        std::max(worstDN, Norm(Sub(Tuple(out->GetPointData()->GetArray("dNdv"), id), dndv)));
    }
  }
  EXPECT_LT(worstDN, 1e-12);
}

TEST(ParametricSurfaceAccuracy, VTKTorusIsOutwardAndMirrored)
{
  vtkNew<vtkParametricTorus> torus; // x = (R + r cos v) sin u, y = (R + r cos v) cos u
  torus->SetRingRadius(1.5);
  torus->SetCrossSectionRadius(0.5);
  Expectation e;
  e.Surface = [](double s, double t) -> Vec
  {
    const double u = 2 * Pi * s, v = 2 * Pi * t;
    return { (1.5 + 0.5 * std::cos(v)) * std::sin(u), (1.5 + 0.5 * std::cos(v)) * std::cos(u),
      0.5 * std::sin(v) };
  };
  e.Length = 2;
  e.Orientation = -1; // ClockwiseOrdering off: outward is Dv x Du
  EXPECT_EQ(CheckAgainstClosedForm(torus, 30, 20, e), 31 * 21);
  vtkSmartPointer<vtkPolyData> out = Generate(torus, 30, 20, e);
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    const Vec p = Tuple(out->GetPoints()->GetData(), id);
    const double rho = std::hypot(p[0], p[1]);
    const Vec centre = { 1.5 * p[0] / rho, 1.5 * p[1] / rho, 0 };
    EXPECT_GT(DotV(Tuple(out->GetPointData()->GetNormals(), id), Sub(p, centre)), 0.49);
    // The texture is mirrored on VTK's torus: the frame is left-handed.
    EXPECT_EQ(out->GetPointData()->GetArray("TangentHandedness")->GetComponent(id, 0), -1.0);
  }
  // Triangles wind counter-clockwise around the outward normal.
  vtkIdType npts;
  const vtkIdType* pts;
  out->GetPolys()->GetCellAtId(0, npts, pts);
  const Vec a = Tuple(out->GetPoints()->GetData(), pts[0]);
  const Vec b = Tuple(out->GetPoints()->GetData(), pts[1]);
  const Vec c = Tuple(out->GetPoints()->GetData(), pts[2]);
  EXPECT_GT(DotV(CrossV(Sub(b, a), Sub(c, a)), Tuple(out->GetPointData()->GetNormals(), 0)), 0);
}

TEST(ParametricSurfaceAccuracy, VTKEllipsoidIsOutwardWithPoleLimits)
{
  vtkNew<vtkParametricEllipsoid> ellipsoid; // a sin v cos u, b sin v sin u, c cos v
  ellipsoid->SetXRadius(1);
  ellipsoid->SetYRadius(2);
  ellipsoid->SetZRadius(3);
  Expectation e;
  e.Surface = [](double s, double t) -> Vec
  {
    const double u = 2 * Pi * s, v = Pi * t;
    return { std::sin(v) * std::cos(u), 2 * std::sin(v) * std::sin(u), 3 * std::cos(v) };
  };
  e.Length = 3;
  e.Orientation = -1;
  const int U = 24, V = 12;
  EXPECT_EQ(CheckAgainstClosedForm(ellipsoid, U, V, e), (U + 1) * (V - 1));
  vtkSmartPointer<vtkPolyData> out = Generate(ellipsoid, U, V, e);
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    const Vec p = Tuple(out->GetPoints()->GetData(), id);
    // The gradient of x^2 + y^2/4 + z^2/9 is the outward normal.
    const Vec grad = { 2 * p[0], p[1] / 2, 2 * p[2] / 9 };
    EXPECT_LT(Angle(Tuple(normals, id), grad), id <= U || id >= V * (U + 1) ? 1e-4 : 1e-6)
      << "point " << id;
  }
}

TEST(ParametricSurfaceAccuracy, VTKFunctionWithoutDerivativesUsesDifferences)
{
  // vtkParametricSuperEllipsoid has no derivatives (DerivativesAvailable off); with both
  // exponents 1 it is the ellipsoid x = a cos v sin u, y = b cos v cos u, z = c sin v.
  vtkNew<vtkParametricSuperEllipsoid> superEllipsoid;
  ASSERT_EQ(superEllipsoid->GetDerivativesAvailable(), 0);
  superEllipsoid->SetN1(1);
  superEllipsoid->SetN2(1);
  superEllipsoid->SetXRadius(1);
  superEllipsoid->SetYRadius(2);
  superEllipsoid->SetZRadius(3);
  Expectation e;
  e.Surface = [](double s, double t) -> Vec
  {
    const double u = -Pi + 2 * Pi * s, v = -Pi / 2 + Pi * t;
    return { std::cos(v) * std::sin(u), 2 * std::cos(v) * std::cos(u), 3 * std::sin(v) };
  };
  e.Length = 3;
  e.Orientation = -1;
  e.PositionTolerance = 1e-15;
  const int U = 24, V = 12;
  EXPECT_EQ(CheckAgainstClosedForm(superEllipsoid, U, V, e), (U + 1) * (V - 1));
  vtkSmartPointer<vtkPolyData> out = Generate(superEllipsoid, U, V, e);
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    const Vec p = Tuple(out->GetPoints()->GetData(), id);
    const Vec grad = { 2 * p[0], p[1] / 2, 2 * p[2] / 9 }; // outward
    EXPECT_LT(Angle(Tuple(out->GetPointData()->GetNormals(), id), grad),
      id <= U || id >= V * (U + 1) ? 1e-4 : 1e-6)
      << "point " << id;
  }
}

TEST(ParametricSurfaceAccuracy, SinglePrecisionPointsRoundOnce)
{
  vtkNew<vtkParametricSphere> sphere;
  Expectation e;
  e.Surface = SeedSphere(1);
  vtkSmartPointer<vtkPolyData> out = Generate(sphere, 32, 16, e, vtkAlgorithm::SINGLE_PRECISION);
  EXPECT_EQ(out->GetPoints()->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(out->GetPointData()->GetArray("dPdu")->GetDataType(), VTK_FLOAT);
  for (int j = 0; j <= 16; ++j)
  {
    for (int i = 0; i <= 32; ++i)
    {
      const Vec p = e.Surface(i / 32.0, j / 16.0);
      const vtkIdType id = j * 33 + i;
      for (int k = 0; k < 3; ++k)
      {
        // Within one float rounding of the exact value.
        EXPECT_NEAR(out->GetPoints()->GetData()->GetComponent(id, k), p[k], 1.2e-7);
      }
    }
  }
}

TEST(ParametricSurfaceAccuracy, VTKKleinBottleIsFiniteAndUnit)
{
  vtkNew<vtkParametricKlein> klein;
  Expectation e;
  vtkSmartPointer<vtkPolyData> out = Generate(klein, 40, 40, e);
  vtkDataArray* n = out->GetPointData()->GetNormals();
  auto t = TangentFrame(out);
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    EXPECT_NEAR(Norm(Tuple(n, id)), 1.0, 1e-6);
    EXPECT_NEAR(Norm(Tuple(t, id)), 1.0, 1e-6);
    EXPECT_LT(std::abs(DotV(Tuple(n, id), Tuple(t, id))), 1e-6);
  }
}

TEST(ParametricSurfaceAccuracy, OnlyRequestedArrays)
{
  vtkNew<vtkParametricSphere> sphere;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->GenerateNormalsOff();
  source->GenerateTextureCoordinatesOff();
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetPointData()->GetNumberOfArrays(), 0);
  source->GenerateTangentsOn();
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetPointData()->GetNumberOfArrays(), 2); // tangents and handedness
  EXPECT_NE(source->GetOutput()->GetPointData()->GetTangents(), nullptr);
  // Changing the function re-executes the source.
  const double before = source->GetOutput()->GetPoints()->GetData()->GetComponent(0, 1);
  sphere->SetRadius(3);
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetPoints()->GetData()->GetComponent(0, 1), 3 * before);

  std::ostringstream printed;
  source->Print(printed);
  sphere->Print(printed);
  EXPECT_NE(printed.str().find("GenerateTangents: 1"), std::string::npos);
  EXPECT_NE(printed.str().find("Radius: 3"), std::string::npos);
}

// ---- Bézier profiles and the surfaces made from them --------------------------------------
namespace
{
using Point2 = std::array<double, 2>;

// de Casteljau's construction: an evaluation independent of the Bernstein form in the class.
Point2 DeCasteljau(const std::vector<Point2>& cps, double t)
{
  const int k = static_cast<int>(cps.size() - 1) / 3;
  const int seg = std::min(static_cast<int>(t * k), k - 1);
  const double s = t * k - seg;
  std::array<Point2, 4> q = { cps[3 * seg], cps[3 * seg + 1], cps[3 * seg + 2], cps[3 * seg + 3] };
  for (int level = 3; level > 0; --level)
  {
    for (int i = 0; i < level; ++i)
    {
      q[i] = { (1 - s) * q[i][0] + s * q[i + 1][0], (1 - s) * q[i][1] + s * q[i + 1][1] };
    }
  }
  return q[0];
}

std::vector<Point2> ControlPoints(vtkBezierProfile* profile)
{
  std::vector<Point2> cps(profile->GetNumberOfControlPoints());
  for (size_t i = 0; i < cps.size(); ++i)
  {
    profile->GetControlPoint(static_cast<int>(i), cps[i].data());
  }
  return cps;
}

// Length of the polyline through n + 1 samples of t in [a, b]: converges as 1/n^2.
double PolylineLength(const std::vector<Point2>& cps, double a, double b, int n)
{
  double length = 0;
  Point2 prev = DeCasteljau(cps, a);
  for (int i = 1; i <= n; ++i)
  {
    const Point2 next = DeCasteljau(cps, a + (b - a) * i / n);
    length += std::hypot(next[0] - prev[0], next[1] - prev[1]);
    prev = next;
  }
  return length;
}
} // namespace

TEST(ParametricSurfaceAccuracy, BezierProfileMatchesDeCasteljau)
{
  vtkNew<vtkBezierProfile> profile;
  profile->SetToVase();
  const std::vector<Point2> cps = ControlPoints(profile);
  ASSERT_EQ(cps.size(), 10u);
  EXPECT_EQ(profile->GetNumberOfSegments(), 3);
  for (int i = 0; i <= 300; ++i)
  {
    const double t = i / 300.0;
    double p[2], d1[2], d2[2];
    ASSERT_TRUE(profile->Evaluate(t, p, d1, d2));
    const Point2 q = DeCasteljau(cps, t);
    EXPECT_NEAR(p[0], q[0], 1e-15);
    EXPECT_NEAR(p[1], q[1], 1e-15);
    // Derivatives by differences inside one segment (never across a join).
    const double seg = std::min(std::floor(t * 3), 2.0);
    const double h = 1e-4;
    const double tc = std::min(std::max(t, seg / 3 + 2 * h), (seg + 1) / 3 - 2 * h);
    profile->Evaluate(tc, p, d1, d2);
    const Point2 a = DeCasteljau(cps, tc + h), b = DeCasteljau(cps, tc - h),
                 c = DeCasteljau(cps, tc);
    for (int k = 0; k < 2; ++k)
    {
      EXPECT_NEAR(d1[k], (a[k] - b[k]) / (2 * h), 1e-6);
      EXPECT_NEAR(d2[k], (a[k] - 2 * c[k] + b[k]) / (h * h), 1e-4 * 3 * 3 * 6);
    }
  }
  // The joins are smooth: the first derivative is continuous across them.
  double left[2], right[2], p[2];
  profile->Evaluate(1.0 / 3 - 1e-9, p, left, nullptr);
  profile->Evaluate(1.0 / 3, p, right, nullptr);
  EXPECT_LT(std::hypot(left[0] - right[0], left[1] - right[1]), 1e-6);
}

TEST(ParametricSurfaceAccuracy, BezierProfileLength)
{
  vtkNew<vtkBezierProfile> line; // a straight segment of length 5 with bunched controls
  line->AddControlPoint(0, 0);
  line->AddControlPoint(0.03, 0.04);
  line->AddControlPoint(0.06, 0.08);
  line->AddControlPoint(3, 4);
  EXPECT_NEAR(line->GetLength(), 5.0, 1e-13);

  vtkNew<vtkBezierProfile> vase;
  vase->SetToVase();
  const double reference = PolylineLength(ControlPoints(vase), 0, 1, 200000);
  EXPECT_NEAR(vase->GetLength(), reference, 1e-9);
}

TEST(ParametricSurfaceAccuracy, BezierProfileArcLength)
{
  vtkNew<vtkBezierProfile> line; // bunched controls: Bézier speed varies a hundredfold
  line->AddControlPoint(0, 0);
  line->AddControlPoint(0.03, 0.04);
  line->AddControlPoint(0.06, 0.08);
  line->AddControlPoint(3, 4);
  line->ArcLengthParameterizationOn();
  for (int i = 0; i <= 20; ++i)
  {
    const double t = i / 20.0;
    double p[2], d1[2], d2[2];
    line->Evaluate(t, p, d1, d2);
    EXPECT_NEAR(p[0], 3 * t, 1e-12);
    EXPECT_NEAR(p[1], 4 * t, 1e-12);
    EXPECT_NEAR(d1[0], 3, 1e-9);
    EXPECT_NEAR(d1[1], 4, 1e-9);
    EXPECT_NEAR(d2[0], 0, 1e-7);
    EXPECT_NEAR(d2[1], 0, 1e-7);
  }

  // The parabola y = x^2 on [0,1] (a quadratic raised to a cubic), whose length from 0 to x
  // is x sqrt(1 + 4x^2) / 2 + asinh(2x) / 4: the inversion must be exact to rounding.
  vtkNew<vtkBezierProfile> parabola;
  parabola->AddControlPoint(0, 0);
  parabola->AddControlPoint(1.0 / 3, 0);
  parabola->AddControlPoint(2.0 / 3, 1.0 / 3);
  parabola->AddControlPoint(1, 1);
  parabola->ArcLengthParameterizationOn();
  auto parabolaLength = [](double x)
  { return 0.5 * x * std::sqrt(1 + 4 * x * x) + 0.25 * std::asinh(2 * x); };
  EXPECT_NEAR(parabola->GetLength(), parabolaLength(1), 1e-14);
  for (int i = 0; i <= 1000; ++i)
  {
    const double t = i / 1000.0;
    double p[2];
    parabola->Evaluate(t, p, nullptr, nullptr);
    EXPECT_NEAR(p[1], p[0] * p[0], 1e-15);
    EXPECT_NEAR(parabolaLength(p[0]), t * parabolaLength(1), 2e-15) << "t = " << t;
  }

  vtkNew<vtkBezierProfile> vase;
  vase->SetToVase();
  vase->ArcLengthParameterizationOn();
  const std::vector<Point2> cps = ControlPoints(vase);
  const double length = vase->GetLength();
  for (int i = 1; i < 10; ++i)
  {
    const double t = i / 10.0;
    double p[2], d1[2], d2[2];
    vase->Evaluate(t, p, d1, d2);
    EXPECT_NEAR(std::hypot(d1[0], d1[1]), length, 1e-9 * length);
    // Acceleration of a unit-speed curve is normal to it.
    EXPECT_NEAR(d1[0] * d2[0] + d1[1] * d2[1], 0, 1e-8 * length * length * length);
    // Independent check: find the Bézier parameter of p by bisection on the polyline, and
    // the polyline length up to it must be t * length.
    double lo = 0, hi = 1;
    for (int it = 0; it < 60; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      (PolylineLength(cps, 0, mid, 4000) < t * length ? lo : hi) = mid;
    }
    const Point2 q = DeCasteljau(cps, 0.5 * (lo + hi));
    EXPECT_NEAR(p[0], q[0], 1e-6);
    EXPECT_NEAR(p[1], q[1], 1e-6);
    // Second derivative by differences of the arc-length curve itself.
    const double h = 1e-4;
    double a[2], b[2], c[2];
    vase->Evaluate(t + h, a, nullptr, nullptr);
    vase->Evaluate(t - h, b, nullptr, nullptr);
    vase->Evaluate(t, c, nullptr, nullptr);
    for (int k = 0; k < 2; ++k)
    {
      EXPECT_NEAR(d1[k], (a[k] - b[k]) / (2 * h), 1e-6 * length);
      EXPECT_NEAR(d2[k], (a[k] - 2 * c[k] + b[k]) / (h * h), 1e-3 * length * length);
    }
  }
}

TEST(ParametricSurfaceAccuracy, VaseMatchesSeed004Revolution)
{
  vtkNew<vtkParametricRevolution> vase;
  const std::vector<Point2> cps = ControlPoints(vase->GetProfile());
  Expectation e;
  e.Surface = [&cps](double u, double v) -> Vec
  {
    const Point2 q = DeCasteljau(cps, std::min(std::max(v, 0.0), 1.0));
    const double t = 2 * Pi * u;
    return { q[0] * std::cos(t), q[1], -q[0] * std::sin(t) };
  };
  e.Length = 2;
  e.VBreaks = { 0, 1.0 / 3, 2.0 / 3, 1 };
  const int U = 32, V = 3 * 20;
  EXPECT_EQ(CheckAgainstClosedForm(vase, U, V, e), (U + 1) * V); // all but the base
  vtkSmartPointer<vtkPolyData> out = Generate(vase, U, V, e);
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  auto tangents = TangentFrame(out);
  for (int i = 0; i <= U; ++i)
  {
    // The base touches the axis at v = 0: the normal there is straight down, and the tangent
    // is the limit along its column, (-sin theta, 0, -cos theta).
    const double theta = 2 * Pi * i / U;
    EXPECT_LT(Angle(Tuple(normals, i), { 0, -1, 0 }), 1e-4);
    EXPECT_LT(Angle(Tuple(tangents, i), { -std::sin(theta), 0, -std::cos(theta) }), 1e-4);
    // Outward on the belly: away from the axis.
    const vtkIdType belly = (V / 2) * (U + 1) + i;
    const Vec p = Tuple(out->GetPoints()->GetData(), belly);
    EXPECT_GT(DotV(Tuple(normals, belly), { p[0], 0, p[2] }), 0);
  }
}

TEST(ParametricSurfaceAccuracy, LovePillarMatchesSeed004Extrusion)
{
  vtkNew<vtkParametricExtrusion> pillar;
  pillar->SetHeight(3);
  const std::vector<Point2> cps = ControlPoints(pillar->GetProfile());
  ASSERT_EQ(cps.size(), 13u);
  Expectation e;
  e.Surface = [&cps](double u, double v) -> Vec
  {
    const Point2 q = DeCasteljau(cps, std::min(std::max(u, 0.0), 1.0));
    return { q[0], 3 * v, q[1] };
  };
  e.Length = 3;
  e.UBreaks = { 0, 0.25, 0.5, 0.75, 1 };
  const int U = 4 * 16, V = 5;
  EXPECT_EQ(CheckAgainstClosedForm(pillar, U, V, e), (U + 1) * (V + 1));
  // Outward, shown without derivatives: a step along the normal leaves the heart, a step
  // against it enters (even-odd test against a fine polygon of the profile).
  std::vector<Point2> polygon;
  for (int i = 0; i < 4000; ++i)
  {
    polygon.push_back(DeCasteljau(cps, i / 4000.0));
  }
  auto inside = [&polygon](double x, double z)
  {
    bool in = false;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    {
      const Point2 &a = polygon[i], &b = polygon[j];
      if ((a[1] > z) != (b[1] > z) && x < (b[0] - a[0]) * (z - a[1]) / (b[1] - a[1]) + a[0])
      {
        in = !in;
      }
    }
    return in;
  };
  vtkSmartPointer<vtkPolyData> out = Generate(pillar, U, V, e);
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  for (int i = 1; i < U; ++i)
  {
    const Vec p = Tuple(out->GetPoints()->GetData(), i);
    const Vec n = Tuple(normals, i);
    EXPECT_NEAR(n[1], 0, 1e-7);
    EXPECT_FALSE(inside(p[0] + 0.01 * n[0], p[2] + 0.01 * n[2])) << "column " << i;
    EXPECT_TRUE(inside(p[0] - 0.01 * n[0], p[2] - 0.01 * n[2])) << "column " << i;
  }
}

TEST(ParametricSurfaceAccuracy, BezierProfileBadInput)
{
  vtkNew<vtkBezierProfile> profile;
  vtkNew<ParametricErrorObserver> observer;
  observer->Observe(profile);
  double p[2] = { 7, 7 }, d1[2] = { 7, 7 }, d2[2] = { 7, 7 };
  // Empty, then 5 points (not 3k+1): not evaluable, zeros, no length.
  for (int n : { 0, 5 })
  {
    profile->RemoveAllControlPoints();
    for (int i = 0; i < n; ++i)
    {
      profile->AddControlPoint(i, i);
    }
    std::string reason;
    EXPECT_FALSE(profile->IsValid(&reason));
    EXPECT_NE(reason.find("3k+1"), std::string::npos);
    EXPECT_EQ(profile->GetNumberOfSegments(), 0);
    EXPECT_FALSE(profile->Evaluate(0.5, p, d1, d2));
    EXPECT_EQ(p[0], 0.0);
    EXPECT_EQ(d1[1], 0.0);
    EXPECT_EQ(d2[0], 0.0);
    EXPECT_EQ(profile->GetLength(), 0.0);
  }
  // Out-of-range control point indices are errors that change nothing.
  profile->RemoveAllControlPoints();
  profile->SetToVase();
  const vtkMTimeType before = profile->GetMTime();
  profile->SetControlPoint(10, 1, 1);
  profile->GetControlPoint(-1, p);
  EXPECT_EQ(observer->ErrorCount, 2);
  EXPECT_NE(observer->Errors.find("does not exist"), std::string::npos);
  EXPECT_EQ(profile->GetMTime(), before);
  EXPECT_EQ(profile->GetNumberOfControlPoints(), 10);
  // Parameters outside [0,1] are clamped to the ends; NaN is refused.
  profile->Evaluate(-3, p, nullptr, nullptr);
  EXPECT_EQ(p[0], 0.0);
  EXPECT_EQ(p[1], 0.0);
  profile->Evaluate(3, p, nullptr, nullptr);
  EXPECT_EQ(p[0], 0.5);
  EXPECT_EQ(p[1], 2.0);
  EXPECT_FALSE(profile->Evaluate(vtkMath::Nan(), p, nullptr, nullptr));
  std::ostringstream printed;
  profile->Print(printed);
  EXPECT_NE(printed.str().find("NumberOfControlPoints: 10"), std::string::npos);

  // The surfaces made from profiles print theirs (the heart has 13 control points).
  vtkNew<vtkParametricExtrusion> pillar;
  vtkNew<vtkParametricRevolution> vase;
  std::ostringstream surfaces;
  pillar->Print(surfaces);
  vase->Print(surfaces);
  EXPECT_NE(surfaces.str().find("Height: 2"), std::string::npos);
  EXPECT_NE(surfaces.str().find("NumberOfControlPoints: 13"), std::string::npos);
  EXPECT_NE(surfaces.str().find("NumberOfControlPoints: 10"), std::string::npos);
}

TEST(ParametricSurfaceAccuracy, ConeApexTakesEachColumnsLimit)
{
  // A cone rising from (r, y) = (1, 0) to its apex (0, 1). Along column theta the surface
  // normal is (cos theta, 1, -sin theta)/sqrt(2) everywhere, so at the apex, where Du
  // vanishes, the limit differs per column; the tangent there is (-sin theta, 0, -cos theta).
  vtkNew<vtkParametricRevolution> cone;
  vtkBezierProfile* profile = cone->GetProfile();
  profile->RemoveAllControlPoints();
  profile->AddControlPoint(1, 0);
  profile->AddControlPoint(2.0 / 3, 1.0 / 3);
  profile->AddControlPoint(1.0 / 3, 2.0 / 3);
  profile->AddControlPoint(0, 1);
  Expectation e;
  const int U = 12, V = 4;
  vtkSmartPointer<vtkPolyData> out = Generate(cone, U, V, e);
  for (int j = 0; j <= V; ++j)
  {
    for (int i = 0; i <= U; ++i)
    {
      const double theta = 2 * Pi * i / U;
      const vtkIdType id = j * (U + 1) + i;
      const Vec n = { std::cos(theta) / std::sqrt(2.0), 1 / std::sqrt(2.0),
        -std::sin(theta) / std::sqrt(2.0) };
      const Vec t = { -std::sin(theta), 0, -std::cos(theta) };
      const double tolerance = j == V ? 1e-4 : 1e-6;
      EXPECT_LT(Angle(Tuple(out->GetPointData()->GetNormals(), id), n), tolerance) << id;
      EXPECT_LT(Angle(Tuple(out->GetPointData()->GetTangents(), id), t), tolerance) << id;
    }
  }
}
