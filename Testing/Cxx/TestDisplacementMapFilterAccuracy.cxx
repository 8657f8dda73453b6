// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter against closed forms: a sphere, a torus and a rectangle,
// displaced by a smooth analytic height sampled into a fine image, compared with the
// analytic displaced surface and its exact normal (DisplacementTestSurfaces.h). Prints
// the error table per NormalMode and mesh resolution and asserts the convergence orders
// the theory gives:
// - vertex positions: only the image reconstruction error (Cubic, O(1/W^3)), any mesh;
// - positions between vertices (triangle centroids): the piecewise-linear chord error,
//   second order in the mesh spacing;
// - Exact normals: second order (central least-squares fits of n_s, n_t and, without
//   dPdu/dPdv, of p_s, p_t); with dNdu/dNdv, no mesh error at all, and the image's
//   reconstruction error, second order in the texel size;
// - Mesh normals: at least first order;
// - Approximate normals: no convergence on curved surfaces (the dropped d dn/du terms
//   are a fixed bias), equal to Exact on the flat rectangle; and equal to the seed's formula
//   evaluated from the closed forms (to the image's slope error with dPdu/dPdv, converging to
//   it with fitted derivatives), which shows it is that formula and not some other bias.

#include "DisplacementTestSurfaces.h"

#include "vtkDisplacementMapFilter.h"

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <vector>

using namespace DisplacementTest;

namespace
{
struct Errors
{
  double Vertex = 0.0;   // max |p' - p*| at vertices
  double Centroid = 0.0; // max distance at triangle centroids
  double Angle = 0.0;    // max normal angle error, degrees
  double Interior = 0.0; // the same, more than 0.1 in v from a pole
  double Seed = 0.0;     // Approximate only: max angle to the seed's formula, degrees
};

// Seed 000's approximate normal of p*, m* = p_u x p_v + d_u (n x p_v) - d_v (n x p_u), from the
// closed forms of p_u, p_v and n and sixth-order central differences of the closed-form height,
// oriented as n.
Vec SeedNormal(const Surface& s, double u, double v)
{
  const double e = 1e-3, c[3] = { 45.0, -9.0, 1.0 };
  double hu = 0.0, hv = 0.0;
  for (int k = 1; k <= 3; ++k)
  {
    hu += c[k - 1] * (s.Height(u + k * e, v) - s.Height(u - k * e, v)) / (60.0 * e);
    hv += c[k - 1] * (s.Height(u, v + k * e) - s.Height(u, v - k * e)) / (60.0 * e);
  }
  const Vec pu = s.Pu(u, v), pv = s.Pv(u, v), n = Unit(s.N(u, v));
  Vec m = Add(Add(CrossV(pu, pv), CrossV(n, pv), s.Scale * hu), CrossV(n, pu), -s.Scale * hv);
  if (DotV(m, n) < 0.0)
  {
    m = { -m[0], -m[1], -m[2] };
  }
  return Unit(m);
}

// Which derivatives the input mesh carries.
enum Derivatives
{
  None,   // P_s, P_t (and Exact's n_s, n_t) fitted
  DP,     // dPdu/dPdv, n_s and n_t fitted
  DPAndDN // dPdu/dPdv and dNdu/dNdv
};

const char* DerivativesName(int d)
{
  return d == DPAndDN ? "dP,dN" : (d == DP ? "dP" : "no");
}

Errors Measure(const Surface& s, int U, int mode, int derivatives, vtkImageData* image)
{
  const int V = s.Name == "torus" ? U / 2 : U;
  auto mesh = MakeMesh(s, U, V, derivatives != None, false, derivatives == DPAndDN);
  vtkNew<vtkDisplacementMapFilter> filter;
  filter->SetInputData(0, mesh);
  filter->SetInputData(1, image);
  filter->SetScaleFactor(s.Scale);
  filter->SetMidlevel(s.Midlevel);
  filter->SetInterpolationToCubic();
  filter->SetWrapToRepeat();
  filter->SetNormalMode(mode);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  Errors e;
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  for (int j = 0; j <= V; ++j)
  {
    for (int i = 0; i <= U; ++i)
    {
      const vtkIdType id = static_cast<vtkIdType>(j) * (U + 1) + i;
      const double u = static_cast<double>(i) / U, v = static_cast<double>(j) / V;
      Vec p;
      out->GetPoint(id, p.data());
      const Vec truth = s.Displaced(u, v);
      e.Vertex = std::max(e.Vertex, std::sqrt(DotV(Add(p, truth, -1.0), Add(p, truth, -1.0))));
      // The normal of p* is undefined at a pole of the parameterisation (p*_u = 0); the
      // rows next to it are measured.
      if (s.Poles && (j == 0 || j == V))
      {
        continue;
      }
      Vec n;
      normals->GetTuple(id, n.data());
      const double angle = AngleDeg(n, s.DisplacedNormal(u, v));
      e.Angle = std::max(e.Angle, angle);
      if (!s.Poles || (v > 0.1 && v < 0.9))
      {
        e.Interior = std::max(e.Interior, angle);
      }
      if (mode == vtkDisplacementMapFilter::Approximate)
      {
        e.Seed = std::max(e.Seed, AngleDeg(n, SeedNormal(s, u, v)));
      }
    }
  }
  // Centroids of the triangles (a, b, d) of each quad against p* at the mean (u, v).
  for (int j = 0; j < V; ++j)
  {
    for (int i = 0; i < U; ++i)
    {
      const vtkIdType a = static_cast<vtkIdType>(j) * (U + 1) + i, b = a + 1, d = a + U + 2;
      Vec pa, pb, pd;
      out->GetPoint(a, pa.data());
      out->GetPoint(b, pb.data());
      out->GetPoint(d, pd.data());
      const Vec c = { (pa[0] + pb[0] + pd[0]) / 3, (pa[1] + pb[1] + pd[1]) / 3,
        (pa[2] + pb[2] + pd[2]) / 3 };
      const double u = (3.0 * i + 2.0) / (3.0 * U), v = (3.0 * j + 1.0) / (3.0 * V);
      const Vec truth = s.Displaced(u, v);
      e.Centroid = std::max(e.Centroid, std::sqrt(DotV(Add(c, truth, -1.0), Add(c, truth, -1.0))));
    }
  }
  return e;
}

const char* ModeName(int mode)
{
  switch (mode)
  {
    case vtkDisplacementMapFilter::Approximate:
      return "Approximate";
    case vtkDisplacementMapFilter::Exact:
      return "Exact";
    default:
      return "Mesh";
  }
}

double Order(double coarse, double fine)
{
  return std::log2(coarse / fine);
}

void RunSurface(const Surface& s)
{
  // 4096 x 2048 texels: the Cubic reconstruction error stays well under the mesh error.
  auto image = MakeHeightImage(s.Height, 4096, 2048);
  const std::vector<int> resolutions = { 32, 64, 128, 256 };
  const int modes[3] = { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
    vtkDisplacementMapFilter::Mesh };
  std::map<std::pair<int, int>, std::vector<Errors>> table;
  std::printf("%-10s %-12s %-6s %5s %12s %12s %12s %12s %12s\n", "surface", "mode", "derivs", "U",
    "vertex", "centroid", "angle(deg)", "interior", "to seed");
  for (int mode : modes)
  {
    for (int derivs : { DPAndDN, DP, None })
    {
      // Mesh normals use no derivatives, Approximate no dNdu/dNdv.
      if ((mode == vtkDisplacementMapFilter::Mesh && derivs != None) ||
        (mode == vtkDisplacementMapFilter::Approximate && derivs == DPAndDN))
      {
        continue;
      }
      for (int U : resolutions)
      {
        const Errors e = Measure(s, U, mode, derivs, image);
        table[{ mode, derivs }].push_back(e);
        std::printf("%-10s %-12s %-6s %5d %12.3e %12.3e %12.3e %12.3e %12.3e\n", s.Name.c_str(),
          ModeName(mode), DerivativesName(derivs), U, e.Vertex, e.Centroid, e.Angle, e.Interior,
          e.Seed);
      }
    }
  }
  const size_t last = resolutions.size() - 1;
  for (const auto& entry : table)
  {
    const std::vector<Errors>& e = entry.second;
    SCOPED_TRACE(std::string(s.Name) + " " + ModeName(entry.first.first) + " derivatives " +
      DerivativesName(entry.first.second));
    for (const Errors& x : e)
    {
      // Vertices sit on the displaced surface up to the image reconstruction error.
      EXPECT_LT(x.Vertex, 1e-6);
    }
    EXPECT_GT(Order(e[last - 1].Centroid, e[last].Centroid), 1.8);
    const int mode = entry.first.first;
    if (s.Name == "rectangle" && mode != vtkDisplacementMapFilter::Mesh)
    {
      // Flat: n_s = n_t = 0 and p is linear, so Exact and Approximate agree and have no
      // mesh error at all; what is left is the slope error of the Cubic reconstruction of
      // the image, O(1/W^2).
      const auto& other = table[{ vtkDisplacementMapFilter::Exact, entry.first.second }];
      for (size_t k = 0; k < e.size(); ++k)
      {
        EXPECT_NEAR(e[k].Angle, other[k].Angle, 1e-9);
        EXPECT_LT(e[k].Angle, 2e-3);
      }
    }
    else if (mode == vtkDisplacementMapFilter::Exact && entry.first.second != DPAndDN)
    {
      // Second order. Next to a pole |p_s| = O(h) while a fitted p_s is off by O(h^2),
      // so there the fitted mode drops to first order (the analytic dPdu does not).
      EXPECT_GT(Order(e[last - 1].Interior, e[last].Interior), 1.8);
      EXPECT_GT(Order(e[last - 1].Angle, e[last].Angle), entry.first.second == DP ? 1.8 : 0.9);
      EXPECT_LT(e[last].Angle, 0.01);
    }
    if (mode == vtkDisplacementMapFilter::Exact && entry.first.second == DPAndDN)
    {
      // The surface's own n_s, n_t: no mesh error is left, at any resolution and at the poles
      // too, only the slope error of the Cubic reconstruction of the image (which converges
      // at second order in the texel size: ExactFromNormalDerivativesConverges).
      const auto& fitted = table[{ vtkDisplacementMapFilter::Exact, None }];
      const auto& fittedN = table[{ vtkDisplacementMapFilter::Exact, DP }];
      for (size_t k = 0; k < e.size(); ++k)
      {
        EXPECT_LE(e[k].Angle, fitted[k].Angle * (1.0 + 1e-9)) << "U = " << resolutions[k];
        EXPECT_LE(e[k].Angle, fittedN[k].Angle * (1.0 + 1e-9)) << "U = " << resolutions[k];
        EXPECT_LT(e[k].Angle, 1e-4) << "U = " << resolutions[k];
      }
      EXPECT_LT(e[last].Angle, 1.1 * e[0].Angle);
    }
    if (mode == vtkDisplacementMapFilter::Mesh)
    {
      EXPECT_GT(Order(e[last - 1].Angle, e[last].Angle), 0.9);
    }
    if (mode == vtkDisplacementMapFilter::Approximate && entry.first.second == DP)
    {
      // The seed's formula itself, evaluated from dPdu/dPdv as given: what is left is the
      // slope error of the Cubic reconstruction of the image, at any mesh resolution.
      for (const Errors& x : e)
      {
        EXPECT_LT(x.Seed, 1e-3);
      }
    }
    else if (mode == vtkDisplacementMapFilter::Approximate)
    {
      // With P_s, P_t fitted: the formula with fitted derivatives, converging to it (first
      // order next to a pole, second elsewhere; the rectangle's fits are exact).
      EXPECT_LT(e[last].Seed, 0.01);
      if (s.Name != "rectangle")
      {
        EXPECT_GT(Order(e[last - 1].Seed, e[last].Seed), s.Poles ? 0.9 : 1.8);
      }
    }
  }
  if (s.Name != "rectangle")
  {
    // Curved and strongly displaced: Exact must beat the seed's approximation, and by far
    // at fine resolution where the approximation's bias dominates.
    for (int derivs : { DP, None })
    {
      const auto& ex = table[{ vtkDisplacementMapFilter::Exact, derivs }];
      const auto& ap = table[{ vtkDisplacementMapFilter::Approximate, derivs }];
      for (size_t k = 0; k < resolutions.size(); ++k)
      {
        EXPECT_LT(ex[k].Angle, ap[k].Angle) << "U = " << resolutions[k];
      }
      EXPECT_LT(10.0 * ex[last].Angle, ap[last].Angle);
      // Approximate is the seed's formula, whose bias from the exact normal is a hundred times
      // what separates the filter's Approximate normals (from dPdu/dPdv) from the formula.
      if (derivs == DP)
      {
        EXPECT_LT(100.0 * ap[last].Seed, ap[last].Angle);
      }
      // The approximation's bias does not go away with resolution.
      EXPECT_GT(ap[last].Angle, 0.5 * ap[0].Angle);
    }
  }
}
} // namespace

// Exact with dNdu/dNdv has no mesh error left (RunSurface): its error is the slope error of the
// Cubic reconstruction of the height map, which falls at second order in the texel size. A
// coarse mesh (U = 64) and ever finer images show it.
TEST(DisplacementMapFilterAccuracy, ExactFromNormalDerivativesConverges)
{
  for (const Surface& s : { Sphere(), Torus() })
  {
    const int U = 64, V = s.Name == "torus" ? U / 2 : U;
    auto mesh = MakeMesh(s, U, V, true, false, true);
    std::vector<double> angles;
    const std::vector<int> widths = { 128, 256, 512, 1024 };
    for (int W : widths)
    {
      vtkNew<vtkDisplacementMapFilter> filter;
      filter->SetInputData(0, mesh);
      filter->SetInputData(1, MakeHeightImage(s.Height, W, W / 2));
      filter->SetScaleFactor(s.Scale);
      filter->SetMidlevel(s.Midlevel);
      filter->SetInterpolationToCubic();
      filter->Update();
      double worst = 0.0;
      vtkDataArray* normals = filter->GetOutput()->GetPointData()->GetNormals();
      for (int j = 0; j <= V; ++j)
      {
        for (int i = 0; i <= U; ++i)
        {
          if (s.Poles && (j == 0 || j == V))
          {
            continue;
          }
          Vec n;
          normals->GetTuple(static_cast<vtkIdType>(j) * (U + 1) + i, n.data());
          const double u = static_cast<double>(i) / U, v = static_cast<double>(j) / V;
          worst = std::max(worst, AngleDeg(n, s.DisplacedNormal(u, v)));
        }
      }
      angles.push_back(worst);
      std::printf("%-10s Exact dP,dN  U %3d  image %4d x %4d  angle(deg) %10.3e\n", s.Name.c_str(),
        U, W, W / 2, worst);
    }
    for (size_t k = 1; k < angles.size(); ++k)
    {
      EXPECT_GT(Order(angles[k - 1], angles[k]), 1.8) << s.Name << " image width " << widths[k];
    }
  }
}

// dNdu/dNdv are the derivatives of the normals as stored, whatever their orientation: a sphere
// whose normals point inwards (and their derivatives with them) moves inwards by the heights,
// and Exact's normals are that surface's, oriented as its normals, with no mesh error left.
TEST(DisplacementMapFilterAccuracy, ExactFromNormalDerivativesOfInwardNormals)
{
  Surface s = Sphere();
  const Surface out = Sphere();
  auto negated = [](const std::function<Vec(double, double)>& f)
  {
    return [f](double u, double v)
    {
      const Vec x = f(u, v);
      return Vec{ -x[0], -x[1], -x[2] };
    };
  };
  s.N = negated(out.N);
  s.Nu = negated(out.Nu);
  s.Nv = negated(out.Nv);
  auto image = MakeHeightImage(s.Height, 1024, 512);
  for (int U : { 32, 64 })
  {
    const Errors e = Measure(s, U, vtkDisplacementMapFilter::Exact, DPAndDN, image);
    std::printf(
      "inward sphere, Exact dP,dN, U %d: vertex %.3e, angle(deg) %.3e\n", U, e.Vertex, e.Angle);
    EXPECT_LT(e.Vertex, 1e-6);
    EXPECT_LT(e.Angle, 1e-3);
  }
}

TEST(DisplacementMapFilterAccuracy, Sphere)
{
  RunSurface(Sphere());
}

TEST(DisplacementMapFilterAccuracy, Torus)
{
  RunSurface(Torus());
}

TEST(DisplacementMapFilterAccuracy, Rectangle)
{
  RunSurface(Rectangle());
}
