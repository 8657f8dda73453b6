// Accuracy of vtkParametricSurfaceSource against closed-form surfaces written out here, in
// the test, from the seeds' formulas (seed 004: sphere, cylinder, rectangle; seed 000:
// donut) and from VTK's documented formulas (vtkParametricTorus, vtkParametricEllipsoid).
// Derivatives, normals and tangents are derived independently: five-point finite
// differences of the closed-form lambdas, never the classes' own derivative code.

#include "ParametricSurfaceTestHelpers.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkParametricCylinder.h>
#include <vtkParametricDonut.h>
#include <vtkParametricEllipsoid.h>
#include <vtkParametricKlein.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkParametricTorus.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <sstream>

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

// Five-point central differences: truncation O(h^4), rounding O(eps/h).
Vec DerivU(const SurfaceFn& f, double u, double v, double h = 1e-3)
{
  Vec d;
  const Vec a = f(u + 2 * h, v), b = f(u + h, v), c = f(u - h, v), e = f(u - 2 * h, v);
  for (int k = 0; k < 3; ++k)
  {
    d[k] = (-a[k] + 8 * b[k] - 8 * c[k] + e[k]) / (12 * h);
  }
  return d;
}
Vec DerivV(const SurfaceFn& f, double u, double v, double h = 1e-3)
{
  return DerivU([&](double x, double y) { return f(y, x); }, v, u, h);
}

struct Expectation
{
  SurfaceFn Surface;      // closed form on the unit square
  double Length = 1;      // size of the surface, for relative position errors
  double Orientation = 1; // +1: normal = Pu x Pv; -1: Pv x Pu
  double PositionTolerance = 1e-14;
  double Repeat[2] = { 1, 1 };
  double Offset[2] = { 0, 0 };
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

// Checks every vertex away from degenerate points; returns how many were checked.
int CheckAgainstClosedForm(vtkParametricFunction* f, int U, int V, const Expectation& e)
{
  vtkSmartPointer<vtkPolyData> out = Generate(f, U, V, e);
  EXPECT_EQ(out->GetNumberOfPoints(), (U + 1) * (V + 1));
  EXPECT_EQ(out->GetNumberOfCells(), 2 * U * V);
  vtkPointData* pd = out->GetPointData();
  vtkDataArray* normals = pd->GetNormals();
  vtkDataArray* tcoords = pd->GetTCoords();
  vtkDataArray* tangents = pd->GetArray("Tangents");
  vtkDataArray* dPdu = pd->GetArray("dPdu");
  vtkDataArray* dPdv = pd->GetArray("dPdv");
  EXPECT_TRUE(normals && tcoords && tangents && dPdu && dPdv);
  if (!(normals && tcoords && tangents && dPdu && dPdv))
  {
    return 0;
  }
  EXPECT_STREQ(normals->GetName(), "Normals");
  EXPECT_STREQ(tcoords->GetName(), "TCoords");
  EXPECT_STREQ(tangents->GetName(), "Tangents");
  EXPECT_EQ(tangents->GetNumberOfComponents(), 4);
  EXPECT_EQ(tangents->GetDataType(), VTK_FLOAT);

  double worstPos = 0, worstN = 0, worstT = 0, worstD = 0;
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

      const Vec pu = DerivU(e.Surface, u, v), pv = DerivV(e.Surface, u, v);
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
      handednessWrong += tangents->GetComponent(id, 3) != w;
    }
  }
  EXPECT_LT(worstPos, e.PositionTolerance * e.Length);
  EXPECT_LT(worstN, 1e-6);
  EXPECT_LT(worstT, 1e-6);
  EXPECT_LT(worstD, 1e-9);
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
  double worst = 0;
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    const Vec p = Tuple(out->GetPoints()->GetData(), id);
    worst = std::max(worst, Angle(Tuple(out->GetPointData()->GetNormals(), id), p));
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(ParametricSurfaceAccuracy, SpherePolesTakeTheLimit)
{
  vtkNew<vtkParametricSphere> sphere;
  const int U = 16, V = 8;
  Expectation e;
  e.Surface = SeedSphere(1);
  vtkSmartPointer<vtkPolyData> out = Generate(sphere, U, V, e);
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  vtkDataArray* tangents = out->GetPointData()->GetArray("Tangents");
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
  EXPECT_EQ(out->GetPointData()->GetArray("Tangents")->GetComponent(0, 3), -1.0);
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
    EXPECT_EQ(out->GetPointData()->GetArray("Tangents")->GetComponent(id, 3), 1.0);
  }
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
    EXPECT_EQ(out->GetPointData()->GetArray("Tangents")->GetComponent(id, 3), -1.0);
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
  vtkDataArray* t = out->GetPointData()->GetArray("Tangents");
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
  EXPECT_EQ(source->GetOutput()->GetPointData()->GetNumberOfArrays(), 1);
  EXPECT_NE(source->GetOutput()->GetPointData()->GetArray("Tangents"), nullptr);
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
