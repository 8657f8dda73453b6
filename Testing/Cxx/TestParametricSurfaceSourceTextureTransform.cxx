// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkParametricSurfaceSource's texture transform (TextureRepeat, TextureOffset) on seed 004's
// sphere, for repeats of either sign and of different sizes along s and t:
// - texture coordinates are offset + repeat * (i/U, j/V), and the source declares that map on
//   them (TEXTURE_TRANSFORM) when it makes derivatives;
// - the tangent is dP/ds = dP/du / repeat_s made unit (so it turns round with a negative s
//   repeat, and does not care about t's), and w is the sign of (N x T) . dP/dt, which a
//   negative repeat along either axis flips. Two truths: the sphere's closed form, and the
//   output mesh itself (each triangle's dP/ds and dP/dt from its positions and texture
//   coordinates), which knows nothing of the source's parameters.

#include "TangentFrameTestHelpers.h"
#include "vtkParametricSphere.h"
#include "vtkParametricSurfaceSource.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
using Vec = std::array<double, 3>;
constexpr double Pi = 3.14159265358979323846;
constexpr double Radius = 1.5;
constexpr int U = 48, V = 24;

struct Transform
{
  double Repeat[2], Offset[2];
};

// Different sizes along s and t (a swap shows), each sign on each axis, and fractions.
const Transform Transforms[] = { { { 1.0, 1.0 }, { 0.0, 0.0 } }, { { 3.0, 2.0 }, { 0.25, 0.5 } },
  { { -3.0, 2.0 }, { 0.1, 0.0 } }, { { 3.0, -2.0 }, { 0.0, 0.3 } },
  { { -2.0, -0.5 }, { 1.0, 1.0 } }, { { 0.25, 5.0 }, { -0.75, 2.0 } } };

Vec Unit(const Vec& a)
{
  const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return { a[0] / l, a[1] / l, a[2] / l };
}

Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double AngleDeg(const Vec& a, const Vec& b)
{
  return std::atan2(std::sqrt(Dot(Cross(a, b), Cross(a, b))), Dot(a, b)) * 180.0 / Pi;
}

Vec Tuple(vtkDataArray* array, vtkIdType id)
{
  return { array->GetComponent(id, 0), array->GetComponent(id, 1), array->GetComponent(id, 2) };
}

// vtkParametricSphere: alpha = pi (1 - v), theta = 2 pi u from +x towards -z; its
// derivatives in u and v, and its outward normal P / R.
Vec SphereDu(double u, double v)
{
  const double a = Pi * (1 - v), th = 2 * Pi * u;
  return { -2 * Pi * Radius * std::sin(a) * std::sin(th), 0.0,
    -2 * Pi * Radius * std::sin(a) * std::cos(th) };
}

Vec SphereDv(double u, double v)
{
  const double a = Pi * (1 - v), th = 2 * Pi * u;
  return { -Pi * Radius * std::cos(a) * std::cos(th), Pi * Radius * std::sin(a),
    Pi * Radius * std::cos(a) * std::sin(th) };
}

Vec SphereNormal(double u, double v)
{
  const double a = Pi * (1 - v), th = 2 * Pi * u;
  return { std::sin(a) * std::cos(th), std::cos(a), -std::sin(a) * std::sin(th) };
}

vtkSmartPointer<vtkPolyData> Sphere(const Transform& transform, bool derivatives)
{
  vtkNew<vtkParametricSphere> sphere;
  sphere->SetRadius(Radius);
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->SetUResolution(U);
  source->SetVResolution(V);
  source->SetTextureRepeat(transform.Repeat[0], transform.Repeat[1]);
  source->SetTextureOffset(transform.Offset[0], transform.Offset[1]);
  source->GenerateTangentsOn();
  source->SetGenerateDerivatives(derivatives);
  source->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(source->GetOutput());
  return out;
}

std::string Describe(const Transform& t)
{
  char text[96];
  std::snprintf(text, sizeof(text), "repeat (%g, %g), offset (%g, %g)", t.Repeat[0], t.Repeat[1],
    t.Offset[0], t.Offset[1]);
  return text;
}
} // namespace

TEST(ParametricSurfaceSourceTextureTransform, TextureCoordinatesAreOffsetPlusRepeatTimesParameter)
{
  for (const Transform& tt : Transforms)
  {
    SCOPED_TRACE(Describe(tt));
    for (bool derivatives : { false, true })
    {
      vtkSmartPointer<vtkPolyData> out = Sphere(tt, derivatives);
      vtkDataArray* tc = out->GetPointData()->GetTCoords();
      ASSERT_NE(tc, nullptr);
      ASSERT_EQ(tc->GetNumberOfTuples(), (U + 1) * (V + 1));
      double worst = 0.0;
      for (int j = 0; j <= V; ++j)
      {
        for (int i = 0; i <= U; ++i)
        {
          const vtkIdType id = static_cast<vtkIdType>(j) * (U + 1) + i;
          const double s = tt.Offset[0] + tt.Repeat[0] * i / U;
          const double t = tt.Offset[1] + tt.Repeat[1] * j / V;
          // Stored as float: within float's rounding of the value.
          worst = std::max(worst,
            std::max(std::abs(tc->GetComponent(id, 0) - s) / std::max(1.0, std::abs(s)),
              std::abs(tc->GetComponent(id, 1) - t) / std::max(1.0, std::abs(t))));
        }
      }
      EXPECT_LT(worst, 1e-7);
      // The declaration that lets filters divide dPdu/dPdv by the repeat.
      vtkInformationDoubleVectorKey* key = vtkParametricSurfaceSource::TEXTURE_TRANSFORM();
      if (derivatives)
      {
        ASSERT_TRUE(tc->HasInformation() && tc->GetInformation()->Has(key));
        ASSERT_EQ(tc->GetInformation()->Length(key), 4);
        const double* declared = tc->GetInformation()->Get(key);
        EXPECT_EQ(declared[0], tt.Repeat[0]);
        EXPECT_EQ(declared[1], tt.Offset[0]);
        EXPECT_EQ(declared[2], tt.Repeat[1]);
        EXPECT_EQ(declared[3], tt.Offset[1]);
      }
    }
  }
}

// The closed form: T = sign(repeat_s) Du / |Du| (Du is tangent to the sphere), w = sign of
// (N x T) . Dv / repeat_t. The poles, where Du vanishes, take a limit tested elsewhere.
TEST(ParametricSurfaceSourceTextureTransform, TangentIsDPdsOfTheClosedForm)
{
  for (const Transform& tt : Transforms)
  {
    SCOPED_TRACE(Describe(tt));
    vtkSmartPointer<vtkPolyData> out = Sphere(tt, false);
    auto tangents = TangentFrame(out);
    vtkDataArray* normals = out->GetPointData()->GetNormals();
    ASSERT_NE(tangents, nullptr);
    ASSERT_EQ(tangents->GetNumberOfComponents(), 4);
    double worstT = 0.0, worstN = 0.0;
    int wrongW = 0;
    for (int j = 1; j < V; ++j)
    {
      for (int i = 0; i <= U; ++i)
      {
        const vtkIdType id = static_cast<vtkIdType>(j) * (U + 1) + i;
        const double u = static_cast<double>(i) / U, v = static_cast<double>(j) / V;
        const Vec n = SphereNormal(u, v);
        const Vec du = SphereDu(u, v), dv = SphereDv(u, v);
        const Vec dPds{ du[0] / tt.Repeat[0], du[1] / tt.Repeat[0], du[2] / tt.Repeat[0] };
        const Vec dPdt{ dv[0] / tt.Repeat[1], dv[1] / tt.Repeat[1], dv[2] / tt.Repeat[1] };
        const Vec t = Unit(dPds);
        const double w = Dot(Cross(n, t), dPdt) < 0.0 ? -1.0 : 1.0;
        worstN = std::max(worstN, AngleDeg(Tuple(normals, id), n));
        worstT = std::max(worstT, AngleDeg(Tuple(tangents, id), t));
        wrongW += tangents->GetComponent(id, 3) == w ? 0 : 1;
      }
    }
    std::printf("%s: worst tangent angle %.3e deg, %d wrong handedness\n", Describe(tt).c_str(),
      worstT, wrongW);
    EXPECT_LT(worstN, 1e-4);
    EXPECT_LT(worstT, 1e-4); // float tangents
    EXPECT_EQ(wrongW, 0);
  }
}

// The mesh's own truth: each triangle's affine dP/ds and dP/dt, solved from its corners'
// positions and texture coordinates. At every corner of every triangle away from the poles
// the tangent must point along that triangle's dP/ds, within the angle the surface turns over
// one triangle, and w must be the sign of (N x T) . dP/dt.
TEST(ParametricSurfaceSourceTextureTransform, TangentFollowsTheMeshesOwnDPds)
{
  for (const Transform& tt : Transforms)
  {
    SCOPED_TRACE(Describe(tt));
    vtkSmartPointer<vtkPolyData> out = Sphere(tt, false);
    auto tangents = TangentFrame(out);
    vtkDataArray* normals = out->GetPointData()->GetNormals();
    vtkDataArray* tc = out->GetPointData()->GetTCoords();
    vtkNew<vtkIdList> ids;
    double worst = 0.0;
    int wrongW = 0, corners = 0;
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      out->GetCellPoints(c, ids);
      ASSERT_EQ(ids->GetNumberOfIds(), 3);
      Vec p[3];
      double st[3][2];
      bool pole = false;
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType id = ids->GetId(k);
        out->GetPoint(id, p[k].data());
        st[k][0] = tc->GetComponent(id, 0);
        st[k][1] = tc->GetComponent(id, 1);
        pole = pole || id <= U || id >= static_cast<vtkIdType>(V) * (U + 1);
      }
      if (pole)
      {
        continue;
      }
      const Vec e1{ p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
      const Vec e2{ p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
      const double s1 = st[1][0] - st[0][0], t1 = st[1][1] - st[0][1];
      const double s2 = st[2][0] - st[0][0], t2 = st[2][1] - st[0][1];
      const double det = s1 * t2 - s2 * t1;
      Vec dPds, dPdt;
      for (int q = 0; q < 3; ++q)
      {
        dPds[q] = (e1[q] * t2 - e2[q] * t1) / det;
        dPdt[q] = (e2[q] * s1 - e1[q] * s2) / det;
      }
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType id = ids->GetId(k);
        const Vec n = Unit(Tuple(normals, id)), t = Tuple(tangents, id);
        const Vec inPlane = Unit({ dPds[0] - Dot(dPds, n) * n[0], dPds[1] - Dot(dPds, n) * n[1],
          dPds[2] - Dot(dPds, n) * n[2] });
        worst = std::max(worst, AngleDeg(t, inPlane));
        const double w = Dot(Cross(n, t), dPdt) < 0.0 ? -1.0 : 1.0;
        wrongW += tangents->GetComponent(id, 3) == w ? 0 : 1;
        ++corners;
      }
    }
    std::printf("%s: %d corners, worst angle to the triangle's dP/ds %.3f deg\n",
      Describe(tt).c_str(), corners, worst);
    EXPECT_EQ(corners, 3 * 2 * U * (V - 2)); // every triangle off the poles' rows
    // A triangle's dP/ds is the chord of a parallel over 2 pi / U of longitude: at either end
    // it makes pi / U with the parallel's tangent, less once projected on the tangent plane.
    EXPECT_LT(worst, 180.0 / U);
    EXPECT_EQ(wrongW, 0);
  }
}
