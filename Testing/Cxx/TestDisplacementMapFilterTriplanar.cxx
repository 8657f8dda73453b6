// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter's triplanar sampling against closed forms: planes facing +z and -x
// (where one projection is the whole blend, and the displaced surface and its normal follow
// from the height function by hand), and a sphere (where all three blend, against the
// conventions header's formulas applied to the exact height function). Mesh normals converge
// to the closed form; Exact normals and bad input are refused with their reasons.

#include "DisplacementTestSurfaces.h"
#include "vtkDisplacementMapFilter.h"
#include "vtkSurfaceDetailConventions.h"

#include <vtkCellArray.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double Scale = 0.8;    // TriplanarScale
constexpr double S = 0.05;       // ScaleFactor
constexpr double Midlevel = 0.5; // of the height function below

// A smooth height over the texture square, periodic in both directions.
double H(double s, double t)
{
  return 0.5 + 0.2 * std::sin(2 * Pi * s) + 0.15 * std::sin(4 * Pi * t + 1.0);
}
void HGradient(double s, double t, double& hs, double& ht)
{
  hs = 0.4 * Pi * std::cos(2 * Pi * s);
  ht = 0.6 * Pi * std::cos(4 * Pi * t + 1.0);
}

using Placement = std::function<void(double u, double v, double p[3], double n[3])>;

// A grid of (cells+1)^2 points placed by @a place, with normals and no texture coordinates.
vtkSmartPointer<vtkPolyData> Grid(int cells, const Placement& place)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetName("Normals");
  for (int j = 0; j <= cells; ++j)
  {
    for (int i = 0; i <= cells; ++i)
    {
      double p[3], n[3];
      place(double(i) / cells, double(j) / cells, p, n);
      points->InsertNextPoint(p);
      normals->InsertNextTuple(n);
    }
  }
  vtkNew<vtkCellArray> polys;
  for (int j = 0; j < cells; ++j)
  {
    for (int i = 0; i < cells; ++i)
    {
      const vtkIdType a = j * (cells + 1) + i;
      const vtkIdType quad[4] = { a, a + 1, a + cells + 2, a + cells + 1 };
      polys->InsertNextCell(4, quad);
    }
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetPointData()->SetNormals(normals);
  return poly;
}

vtkSmartPointer<vtkPolyData> Displace(vtkPolyData* input, int mode, double sharpness = 4.0)
{
  vtkNew<vtkDisplacementMapFilter> filter;
  filter->SetInputData(input);
  filter->SetSourceData(DisplacementTest::MakeHeightImage(H, 512, 512));
  filter->SetWrapToRepeat();
  filter->SetInterpolationToCubic();
  filter->SetScaleFactor(S);
  filter->SetMidlevel(Midlevel);
  filter->SetNormalMode(mode);
  filter->TriplanarOn();
  filter->SetTriplanarScale(Scale);
  filter->SetTriplanarSharpness(sharpness);
  filter->Update();
  return filter->GetOutput();
}

// The largest distance between the output points and @a expected's, and the largest angle in
// degrees between the output normals and @a expected's.
struct Errors
{
  double Distance = 0.0;
  double Degrees = 0.0;
};

Errors Compare(vtkPolyData* input, vtkPolyData* output,
  const std::function<void(const double p[3], const double n[3], double q[3], double m[3])>& truth)
{
  Errors e;
  vtkDataArray* inN = input->GetPointData()->GetNormals();
  vtkDataArray* outN = output->GetPointData()->GetNormals();
  for (vtkIdType k = 0; k < input->GetNumberOfPoints(); ++k)
  {
    double p[3], n[3], q[3], m[3], got[3], gotN[3];
    input->GetPoint(k, p);
    inN->GetTuple(k, n);
    truth(p, n, q, m);
    output->GetPoint(k, got);
    outN->GetTuple(k, gotN);
    e.Distance = std::max(e.Distance,
      std::sqrt((got[0] - q[0]) * (got[0] - q[0]) + (got[1] - q[1]) * (got[1] - q[1]) +
        (got[2] - q[2]) * (got[2] - q[2])));
    e.Degrees = std::max(e.Degrees,
      DisplacementTest::AngleDeg({ gotN[0], gotN[1], gotN[2] }, { m[0], m[1], m[2] }));
  }
  return e;
}

// On a plane facing +z only the z projection counts: s = c x, t = c y, and the displaced
// plane z = S (H(c x, c y) - mid) has the normal (-S c H_s, -S c H_t, 1).
void PlaneFacingZ(const double p[3], const double[3], double q[3], double m[3])
{
  double hs, ht;
  HGradient(Scale * p[0], Scale * p[1], hs, ht);
  q[0] = p[0];
  q[1] = p[1];
  q[2] = p[2] + S * (H(Scale * p[0], Scale * p[1]) - Midlevel);
  m[0] = -S * Scale * hs;
  m[1] = -S * Scale * ht;
  m[2] = 1.0;
}

// On a plane facing -x the x projection seen from -x: s = -c y, t = c z. The surface
// x = x0 - d(y, z) has the outward normal (-1, -d_y, -d_z), d_y = -S c H_s, d_z = S c H_t.
void PlaneFacingMinusX(const double p[3], const double[3], double q[3], double m[3])
{
  double hs, ht;
  HGradient(-Scale * p[1], Scale * p[2], hs, ht);
  q[0] = p[0] - S * (H(-Scale * p[1], Scale * p[2]) - Midlevel);
  q[1] = p[1];
  q[2] = p[2];
  m[0] = -1.0;
  m[1] = S * Scale * hs;
  m[2] = -S * Scale * ht;
}

vtkSmartPointer<vtkPolyData> PlaneZ(int cells)
{
  return Grid(cells,
    [](double u, double v, double p[3], double n[3])
    {
      p[0] = -1.3 + 2.6 * u, p[1] = -0.9 + 2.2 * v, p[2] = 0.2;
      n[0] = 0, n[1] = 0, n[2] = 1;
    });
}

vtkSmartPointer<vtkPolyData> PlaneMinusX(int cells)
{
  return Grid(cells,
    [](double u, double v, double p[3], double n[3])
    {
      p[0] = 0.4, p[1] = -1.1 + 2.4 * u, p[2] = -0.7 + 2.0 * v;
      n[0] = -1, n[1] = 0, n[2] = 0;
    });
}

constexpr double SphereRadius = 1.0;

vtkSmartPointer<vtkPolyData> Sphere(int cells)
{
  return Grid(cells,
    [](double u, double v, double p[3], double n[3])
    {
      const double theta = 2 * Pi * u, phi = 0.05 + (Pi - 0.1) * v;
      n[0] = std::sin(phi) * std::cos(theta);
      n[1] = std::sin(phi) * std::sin(theta);
      n[2] = std::cos(phi);
      for (int i = 0; i < 3; ++i)
      {
        p[i] = SphereRadius * n[i];
      }
    });
}

// The sphere in closed form: the conventions' projections and weights of the exact H, each
// projection's slope along its axes, the weights held constant (the filter's definition).
std::function<void(const double*, const double*, double*, double*)> SphereTruth(double sharpness)
{
  return [sharpness](const double p[3], const double n[3], double q[3], double m[3])
  {
    double w[3], h = 0.0, g[3] = { 0, 0, 0 };
    vtkSurfaceDetail::TriplanarWeights(n, sharpness, w);
    for (int axis = 0; axis < 3; ++axis)
    {
      double st[2], T[3], B[3], hs, ht;
      vtkSurfaceDetail::TriplanarProject(axis, p, n, Scale, st, T, B);
      HGradient(st[0], st[1], hs, ht);
      h += w[axis] * H(st[0], st[1]);
      for (int i = 0; i < 3; ++i)
      {
        g[i] += w[axis] * S * Scale * (hs * T[i] + ht * B[i]);
      }
    }
    const double d = S * (h - Midlevel);
    const double along = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
    for (int i = 0; i < 3; ++i)
    {
      q[i] = p[i] + d * n[i];
      m[i] = n[i] - (g[i] - along * n[i]);
    }
  };
}
} // namespace

TEST(vtkDisplacementMapFilterTriplanar, PlanesMatchTheirClosedForms)
{
  for (const auto& plane : { std::make_pair(PlaneZ(64), PlaneFacingZ),
         std::make_pair(PlaneMinusX(64), PlaneFacingMinusX) })
  {
    const auto output = Displace(plane.first, vtkDisplacementMapFilter::Approximate);
    const Errors e = Compare(plane.first, output, plane.second);
    std::cout << "plane: " << e.Distance << " units, " << e.Degrees << " degrees\n";
    EXPECT_LT(e.Distance, 1e-6);
    EXPECT_LT(e.Degrees, 1e-3);
  }
}

// A mirrored or swapped rule would move the -x plane elsewhere: its closed form sees that.
TEST(vtkDisplacementMapFilterTriplanar, ClosedFormSeesAMirroredRule)
{
  const auto plane = PlaneMinusX(64);
  const auto output = Displace(plane, vtkDisplacementMapFilter::Approximate);
  auto mirrored = [](const double p[3], const double n[3], double q[3], double m[3])
  {
    const double flipped[3] = { p[0], -p[1], p[2] };
    PlaneFacingMinusX(flipped, n, q, m);
    q[1] = p[1];
  };
  EXPECT_GT(Compare(plane, output, mirrored).Distance, 1e-3);
}

TEST(vtkDisplacementMapFilterTriplanar, SphereMatchesTheFormulas)
{
  for (const double sharpness : { 1.0, 4.0 })
  {
    const auto sphere = Sphere(96);
    const auto output = Displace(sphere, vtkDisplacementMapFilter::Approximate, sharpness);
    const Errors e = Compare(sphere, output, SphereTruth(sharpness));
    std::cout << "sphere, sharpness " << sharpness << ": " << e.Distance << " units, "
              << e.Degrees << " degrees\n";
    // The filter samples H from a 512^2 image (Catmull-Rom): errors of that order only.
    EXPECT_LT(e.Distance, 1e-6);
    EXPECT_LT(e.Degrees, 1e-3);
  }
}

// Mesh normals, from the displaced polygons, converge to the closed form with the mesh.
TEST(vtkDisplacementMapFilterTriplanar, MeshNormalsConverge)
{
  double previous = 180.0;
  for (const int cells : { 32, 64, 128 })
  {
    const auto plane = PlaneZ(cells);
    const auto output = Displace(plane, vtkDisplacementMapFilter::Mesh);
    const Errors e = Compare(plane, output, PlaneFacingZ);
    std::cout << cells << " cells: Mesh normals within " << e.Degrees << " degrees\n";
    EXPECT_LT(e.Distance, 1e-6);
    EXPECT_LT(e.Degrees, previous / 1.8); // at least first order
    previous = e.Degrees;
  }
  EXPECT_LT(previous, 1.0);
}

TEST(vtkDisplacementMapFilterTriplanar, ExactIsRefused)
{
  vtkNew<vtkDisplacementMapFilter> filter;
  filter->SetInputData(PlaneZ(4));
  filter->SetSourceData(DisplacementTest::MakeHeightImage(H, 8, 8));
  filter->TriplanarOn();
  filter->SetNormalModeToExact();
  std::string said;
  vtkNew<vtkCallbackCommand> listen;
  listen->SetClientData(&said);
  listen->SetCallback([](vtkObject*, unsigned long, void* client, void* data)
    { *static_cast<std::string*>(client) = static_cast<const char*>(data); });
  filter->AddObserver(vtkCommand::ErrorEvent, listen);
  filter->Update();
  EXPECT_NE(said.find("Approximate or Mesh"), std::string::npos) << said;
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  // Without Triplanar, a surface without texture coordinates is refused as before.
  said.clear();
  filter->TriplanarOff();
  filter->SetNormalModeToApproximate();
  filter->Update();
  EXPECT_NE(said.find("texture coordinates"), std::string::npos) << said;
}
