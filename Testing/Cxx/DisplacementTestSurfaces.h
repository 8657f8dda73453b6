// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Closed-form test surfaces for vtkDisplacementMapFilter's tests and benchmarks, built
// here from their formulas and nothing else: the filter's own code is never used to make
// the truth it is checked against.
//
// Each surface is p(u,v) on the unit square with its unit normal n(u,v) and the derivatives
// of both;
// the displaced truth is p*(u,v) = p + Scale (h(u,v) - Midlevel) n, and its exact normal
// n* is computed from sixth-order central differences of p* itself.

#ifndef DisplacementTestSurfaces_h
#define DisplacementTestSurfaces_h

#include "vtkSurfaceDetailTangents.h"
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>

namespace DisplacementTest
{
using Vec = std::array<double, 3>;
constexpr double Pi = 3.14159265358979323846;

inline Vec Add(const Vec& a, const Vec& b, double s = 1.0)
{
  return { a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2] };
}
inline Vec CrossV(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline double DotV(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec Unit(const Vec& a)
{
  const double l = std::sqrt(DotV(a, a));
  return { a[0] / l, a[1] / l, a[2] / l };
}
inline double AngleDeg(const Vec& a, const Vec& b)
{
  const Vec c = CrossV(Unit(a), Unit(b));
  return std::atan2(std::sqrt(DotV(c, c)), DotV(Unit(a), Unit(b))) * 180.0 / Pi;
}

struct Surface
{
  std::string Name;
  std::function<Vec(double, double)> P, N, Pu, Pv, Nu, Nv; // N unit
  std::function<double(double, double)> Height;            // h(u,v), smooth on the closed surface
  double Scale = 0.1;
  double Midlevel = 0.5;
  bool Poles = false;

  Vec Displaced(double u, double v) const
  {
    return Add(this->P(u, v), this->N(u, v), this->Scale * (this->Height(u, v) - this->Midlevel));
  }

  // Exact normal of p*: sixth-order central differences of the closed form, oriented as n.
  Vec DisplacedNormal(double u, double v) const
  {
    const double e = 1e-3;
    auto d = [&](bool alongU)
    {
      auto at = [&](double k)
      { return alongU ? this->Displaced(u + k * e, v) : this->Displaced(u, v + k * e); };
      Vec r{ 0, 0, 0 };
      const double c[3] = { 45.0, -9.0, 1.0 };
      for (int k = 1; k <= 3; ++k)
      {
        r = Add(r, Add(at(k), at(-k), -1.0), c[k - 1] / (60.0 * e));
      }
      return r;
    };
    Vec m = CrossV(d(true), d(false));
    if (DotV(m, this->N(u, v)) < 0.0)
    {
      m = { -m[0], -m[1], -m[2] };
    }
    return Unit(m);
  }
};

// vtkParametricSphere: alpha = pi (1 - v), theta = 2 pi u from +x towards -z.
// The height is smooth at the poles (sin^2(pi v) sin(4 pi u) ~ rho^2 sin(2 theta)) and
// periodic in v, so that Repeat, vtkTexture's one wrap mode for both axes, reads it right.
inline Surface Sphere(double scale = 0.15)
{
  Surface s;
  s.Name = "sphere";
  s.Poles = true;
  s.Scale = scale;
  s.P = [](double u, double v)
  {
    const double a = Pi * (1 - v), th = 2 * Pi * u;
    return Vec{ std::sin(a) * std::cos(th), std::cos(a), -std::sin(a) * std::sin(th) };
  };
  s.N = s.P;
  s.Pu = [](double u, double v)
  {
    const double a = Pi * (1 - v), th = 2 * Pi * u;
    return Vec{ -2 * Pi * std::sin(a) * std::sin(th), 0.0, -2 * Pi * std::sin(a) * std::cos(th) };
  };
  s.Pv = [](double u, double v)
  {
    const double a = Pi * (1 - v), th = 2 * Pi * u;
    return Vec{ -Pi * std::cos(a) * std::cos(th), Pi * std::sin(a),
      Pi * std::cos(a) * std::sin(th) };
  };
  s.Nu = s.Pu; // the unit sphere's normal is its point
  s.Nv = s.Pv;
  s.Height = [](double u, double v)
  {
    const double sv = std::sin(Pi * v);
    return 0.5 + 0.3 * sv * sv * std::sin(4 * Pi * u) + 0.15 * std::cos(2 * Pi * v);
  };
  return s;
}

// Seed 000's torus (z up): ring radius 1, cross-section radius 0.35.
inline Surface Torus(double scale = 0.1)
{
  Surface s;
  s.Name = "torus";
  s.Scale = scale;
  const double R = 1.0, r = 0.35;
  s.P = [=](double u, double v)
  {
    const double a = 2 * Pi * u, b = 2 * Pi * v;
    return Vec{ (R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a),
      r * std::sin(b) };
  };
  s.N = [](double u, double v)
  {
    const double a = 2 * Pi * u, b = 2 * Pi * v;
    return Vec{ std::cos(b) * std::cos(a), std::cos(b) * std::sin(a), std::sin(b) };
  };
  s.Pu = [=](double u, double v)
  {
    const double a = 2 * Pi * u, b = 2 * Pi * v;
    return Vec{ -2 * Pi * (R + r * std::cos(b)) * std::sin(a),
      2 * Pi * (R + r * std::cos(b)) * std::cos(a), 0.0 };
  };
  s.Pv = [=](double u, double v)
  {
    const double a = 2 * Pi * u, b = 2 * Pi * v;
    return Vec{ -2 * Pi * r * std::sin(b) * std::cos(a), -2 * Pi * r * std::sin(b) * std::sin(a),
      2 * Pi * r * std::cos(b) };
  };
  s.Nu = [](double u, double v)
  {
    const double a = 2 * Pi * u, b = 2 * Pi * v;
    return Vec{ -2 * Pi * std::cos(b) * std::sin(a), 2 * Pi * std::cos(b) * std::cos(a), 0.0 };
  };
  s.Nv = [](double u, double v)
  {
    const double a = 2 * Pi * u, b = 2 * Pi * v;
    return Vec{ -2 * Pi * std::sin(b) * std::cos(a), -2 * Pi * std::sin(b) * std::sin(a),
      2 * Pi * std::cos(b) };
  };
  s.Height = [](double u, double v)
  {
    return 0.5 + 0.25 * std::sin(2 * Pi * 3 * u) * std::sin(2 * Pi * 2 * v) +
      0.2 * std::cos(2 * Pi * (u + v));
  };
  return s;
}

// Seed 000's square p = (2u - 1, 2v - 1, 0).
inline Surface Rectangle(double scale = 0.1)
{
  Surface s;
  s.Name = "rectangle";
  s.Scale = scale;
  s.P = [](double u, double v) { return Vec{ 2 * u - 1, 2 * v - 1, 0.0 }; };
  s.N = [](double, double) { return Vec{ 0.0, 0.0, 1.0 }; };
  s.Pu = [](double, double) { return Vec{ 2.0, 0.0, 0.0 }; };
  s.Pv = [](double, double) { return Vec{ 0.0, 2.0, 0.0 }; };
  s.Nu = [](double, double) { return Vec{ 0.0, 0.0, 0.0 }; };
  s.Nv = s.Nu;
  s.Height = [](double u, double v)
  {
    return 0.5 + 0.25 * std::sin(2 * Pi * 2 * u) * std::cos(2 * Pi * 3 * v) +
      0.2 * std::sin(2 * Pi * (u - v));
  };
  return s;
}

// A (U+1) x (V+1) grid of points with the seam and pole points duplicated (as a
// parametric source makes them), two triangles per quad, tcoords (u,v), unit normals,
// tangent frames of Documentation/Conventions.md (vtkSurfaceDetailTangents), optionally
// dPdu/dPdv and (with them) dNdu/dNdv; all in double, or all in float.
inline vtkSmartPointer<vtkPolyData> MakeMesh(const Surface& s, int U, int V, bool derivatives,
  bool floatPoints = false, bool normalDerivatives = false)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(floatPoints ? VTK_FLOAT : VTK_DOUBLE);
  const vtkIdType n = static_cast<vtkIdType>(U + 1) * (V + 1);
  points->SetNumberOfPoints(n);
  // Float points come with float arrays, as most VTK sources make them.
  auto array = [&]() -> vtkSmartPointer<vtkDataArray>
  {
    if (floatPoints)
    {
      return vtkSmartPointer<vtkFloatArray>::New();
    }
    return vtkSmartPointer<vtkDoubleArray>::New();
  };
  auto normals = array(), tcoords = array(), du = array(), dv = array(), tangents = array();
  auto handedness = array();
  auto ndu = array(), ndv = array();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(n);
  tangents->SetNumberOfComponents(3);
  tangents->SetNumberOfTuples(n);
  handedness->SetNumberOfTuples(n);
  du->SetName("dPdu");
  du->SetNumberOfComponents(3);
  du->SetNumberOfTuples(n);
  dv->SetName("dPdv");
  dv->SetNumberOfComponents(3);
  dv->SetNumberOfTuples(n);
  ndu->SetName("dNdu");
  ndu->SetNumberOfComponents(3);
  ndu->SetNumberOfTuples(n);
  ndv->SetName("dNdv");
  ndv->SetNumberOfComponents(3);
  ndv->SetNumberOfTuples(n);
  for (int j = 0; j <= V; ++j)
  {
    for (int i = 0; i <= U; ++i)
    {
      const vtkIdType id = static_cast<vtkIdType>(j) * (U + 1) + i;
      const double u = static_cast<double>(i) / U, v = static_cast<double>(j) / V;
      const Vec p = s.P(u, v), nn = Unit(s.N(u, v)), pu = s.Pu(u, v), pv = s.Pv(u, v);
      points->SetPoint(id, p.data());
      normals->SetTuple(id, nn.data());
      tcoords->SetTuple2(id, u, v);
      du->SetTuple(id, pu.data());
      dv->SetTuple(id, pv.data());
      ndu->SetTuple(id, s.Nu(u, v).data());
      ndv->SetTuple(id, s.Nv(u, v).data());
      // At a pole dP/du vanishes; dP/dv's direction rotated about n is then the tangent.
      Vec t = Add(pu, nn, -DotV(pu, nn));
      if (DotV(t, t) < 1e-20)
      {
        t = CrossV(Add(pv, nn, -DotV(pv, nn)), nn);
      }
      t = Unit(t);
      const double w = DotV(CrossV(nn, t), pv) < 0.0 ? -1.0 : 1.0;
      tangents->SetTuple3(id, t[0], t[1], t[2]);
      handedness->SetTuple1(id, w);
    }
  }
  vtkNew<vtkCellArray> tris;
  for (int j = 0; j < V; ++j)
  {
    for (int i = 0; i < U; ++i)
    {
      const vtkIdType a = static_cast<vtkIdType>(j) * (U + 1) + i, b = a + 1, c = a + U + 1,
                      d = c + 1;
      const vtkIdType t0[3] = { a, b, d }, t1[3] = { a, d, c };
      tris->InsertNextCell(3, t0);
      tris->InsertNextCell(3, t1);
    }
  }
  poly->SetPoints(points);
  poly->SetPolys(tris);
  poly->GetPointData()->SetNormals(normals);
  poly->GetPointData()->SetTCoords(tcoords);
  vtkSurfaceDetailTangents::SetFrame(poly->GetPointData(), tangents, handedness);
  if (derivatives)
  {
    poly->GetPointData()->AddArray(du);
    poly->GetPointData()->AddArray(dv);
  }
  if (derivatives && normalDerivatives)
  {
    poly->GetPointData()->AddArray(ndu);
    poly->GetPointData()->AddArray(ndv);
  }
  return poly;
}

// The height sampled at texel centres ((i + 0.5)/W, (j + 0.5)/H) into a double image
// (float's 24 bits, differenced over 1/4096, would be slope noise of 1e-4).
inline vtkSmartPointer<vtkImageData> MakeHeightImage(
  const std::function<double(double, double)>& h, int W, int H)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  image->AllocateScalars(VTK_DOUBLE, 1);
  auto* data = static_cast<double*>(image->GetScalarPointer());
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      data[static_cast<size_t>(j) * W + i] = h((i + 0.5) / W, (j + 0.5) / H);
    }
  }
  return image;
}
} // namespace DisplacementTest

#endif
