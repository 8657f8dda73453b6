// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter with float arrays: at extreme and adversarial scales they agree with
// the double computation and stay finite.

#include "DisplacementFilterTestHelpers.h"

namespace
{
// Adds @a dst to @a out in the role @a src has in @a in: normals, texture coordinates,
// tangents (with their information) or a plain array.
void AddInSameRole(vtkPointData* in, vtkDataArray* src, vtkPointData* out, vtkDataArray* dst)
{
  if (src == in->GetNormals())
  {
    out->SetNormals(dst);
  }
  else if (src == in->GetTCoords())
  {
    out->SetTCoords(dst);
  }
  else if (src == in->GetTangents())
  {
    dst->CopyInformation(src->GetInformation());
    out->SetTangents(dst);
  }
  else
  {
    out->AddArray(dst);
  }
}

// A copy of @a mesh with its points and point arrays multiplied: coordinates and dPdu/dPdv by
// @a f, texture coordinates by @a g; in float or double.
vtkSmartPointer<vtkPolyData> Rescaled(vtkPolyData* mesh, double f, double g, bool floatArrays)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->CopyStructure(mesh);
  vtkNew<vtkPoints> points;
  points->SetDataType(floatArrays ? VTK_FLOAT : VTK_DOUBLE);
  points->SetNumberOfPoints(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    points->SetPoint(i, f * p[0], f * p[1], f * p[2]);
  }
  out->SetPoints(points);
  vtkPointData* in = mesh->GetPointData();
  for (int a = 0; a < in->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* src = in->GetArray(a);
    vtkSmartPointer<vtkDataArray> dst;
    if (floatArrays)
    {
      dst = vtkSmartPointer<vtkFloatArray>::New();
    }
    else
    {
      dst = vtkSmartPointer<vtkDoubleArray>::New();
    }
    dst->SetName(src->GetName());
    dst->SetNumberOfComponents(src->GetNumberOfComponents());
    dst->SetNumberOfTuples(src->GetNumberOfTuples());
    const std::string name = src->GetName();
    const double by = (name == "dPdu" || name == "dPdv") ? f : (name == "TCoords" ? g : 1.0);
    for (vtkIdType i = 0; i < src->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < src->GetNumberOfComponents(); ++c)
      {
        dst->SetComponent(i, c, by * src->GetComponent(i, c));
      }
    }
    AddInSameRole(in, src, out->GetPointData(), dst);
  }
  return out;
}

// Finite points, unit normals and unit tangents; the largest angle between the normals of
// @a a and @a b.
double CheckAndCompare(vtkPolyData* a, vtkPolyData* b, const std::string& what)
{
  double worst = 0.0;
  for (vtkPolyData* out : { a, b })
  {
    EXPECT_TRUE(AllFinite(out)) << what;
    auto t = TangentFrame(out);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double n[3], x[4];
      out->GetPointData()->GetNormals()->GetTuple(i, n);
      t->GetTuple(i, x);
      const double nl = vtkMath::Norm(n), tl = vtkMath::Norm(x);
      if (!(std::abs(nl - 1.0) < 1e-5) || !(std::abs(tl - 1.0) < 1e-5))
      {
        ADD_FAILURE() << what << " point " << i << " |n| " << nl << " |t| " << tl;
        return 1e300;
      }
    }
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double na[3], nb[3];
    a->GetPointData()->GetNormals()->GetTuple(i, na);
    b->GetPointData()->GetNormals()->GetTuple(i, nb);
    double c[3];
    vtkMath::Cross(na, nb, c);
    worst = std::max(worst, std::atan2(vtkMath::Norm(c), vtkMath::Dot(na, nb)));
  }
  return worst;
}
} // namespace

// Float arrays, whose range and precision are short at extreme scales. Whatever the scale of
// the coordinates
// (with heights scaled alike), the normals of float arrays stay within float's error of those of
// the same mesh in double arrays, and everything stays finite and unit.
TEST(DisplacementMapFilter, FloatArraysAtExtremeScalesAgreeWithDouble)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  for (bool derivatives : { false, true })
  {
    auto mesh = MakeMesh(s, 48, 24, derivatives);
    for (double f : { 1.0, 1e-30, 1e-18, 1e-12, 1e-6, 1e6, 1e12, 1e18, 1e30, 1e36 })
    {
      auto d = Rescaled(mesh, f, 1.0, false), fl = Rescaled(mesh, f, 1.0, true);
      for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
             vtkDisplacementMapFilter::Mesh })
      {
        auto outD = Displace(d, image, mode, 0.1 * f, 0.5, vtkDisplacementMapFilter::Cubic);
        auto outF = Displace(fl, image, mode, 0.1 * f, 0.5, vtkDisplacementMapFilter::Cubic);
        std::ostringstream what;
        what << "f " << f << " mode " << mode << " derivatives " << derivatives;
        const double angle = CheckAndCompare(outD, outF, what.str());
        EXPECT_LT(angle, 2e-5) << what.str();
      }
    }
  }
}

// Float arrays whose fitted derivatives leave float's range (huge coordinates over texture
// coordinates that barely change), or vanish (every point at one texture coordinate), or whose
// heights are NaN or infinite: everything stays finite and unit.
TEST(DisplacementMapFilter, FloatArraysAdversarialStayFinite)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  auto bad = MakeHeightImage(s.Height, 64, 32);
  auto* h = static_cast<double*>(bad->GetScalarPointer());
  for (int k = 0; k < 64 * 32; k += 7)
  {
    h[k] = k % 2 ? std::nan("") : std::numeric_limits<double>::infinity();
  }
  auto mesh = MakeMesh(s, 48, 24, false);
  struct Case
  {
    double f, g;
  };
  for (const Case& c : { Case{ 1e33, 1e-6 }, Case{ 1e36, 1e-3 }, Case{ 1e-30, 1e6 },
         Case{ 1.0, 0.0 }, Case{ 1e30, 0.0 }, Case{ 1.0, 1e-40 }, Case{ 1e-30, 1e-40 } })
  {
    auto d = Rescaled(mesh, c.f, c.g, false), fl = Rescaled(mesh, c.f, c.g, true);
    for (vtkImageData* im : { image.Get(), bad.Get() })
    {
      for (double scale : { 0.1 * c.f, 1e30, 1e38 })
      {
        for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
               vtkDisplacementMapFilter::Mesh })
        {
          std::ostringstream what;
          what << "f " << c.f << " g " << c.g << " scale " << scale << " mode " << mode
               << (im == bad ? " bad heights" : "");
          auto run = [&](vtkPolyData* mesh)
          {
            vtkNew<vtkDisplacementMapFilter> filter;
            auto obs = Watch(filter);
            filter->SetInputData(0, mesh);
            filter->SetInputData(1, im);
            filter->SetNormalMode(mode);
            filter->SetScaleFactor(scale);
            filter->SetInterpolation(vtkDisplacementMapFilter::Cubic);
            filter->Update();
            EXPECT_EQ(obs->Errors, 0) << what.str();
            auto out = vtkSmartPointer<vtkPolyData>::New();
            out->DeepCopy(filter->GetOutput());
            return out;
          };
          CheckAndCompare(run(d), run(fl), what.str());
        }
      }
    }
  }
}

// Heights whose slope dwarfs the surface (large Scale): Exact's change of the normal in float
// arrays must not carry a residue of float's epsilon times the slopes' product. The same float
// values in double arrays are the reference: normals within 2e-5 rad.
TEST(DisplacementMapFilter, FloatArraysAgreeWithDoubleAtLargeScale)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  for (bool derivatives : { false, true })
  {
    auto fl = Rescaled(MakeMesh(s, 48, 24, derivatives), 1.0, 1.0, true);
    auto d = Rescaled(fl, 1.0, 1.0, false); // the same values, exactly
    for (double scale : { 1.0, 1e2, 1e3, 1e4, 1e5, 1e7, 1e9 })
    {
      for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
             vtkDisplacementMapFilter::Mesh })
      {
        std::ostringstream what;
        what << "scale " << scale << " mode " << mode << " derivatives " << derivatives;
        auto outD = Displace(d, image, mode, scale, 0.5, vtkDisplacementMapFilter::Cubic);
        auto outF = Displace(fl, image, mode, scale, 0.5, vtkDisplacementMapFilter::Cubic);
        EXPECT_LT(CheckAndCompare(outD, outF, what.str()), 2e-5) << what.str();
      }
    }
  }
}

// Float arrays whose values float holds but whose results it does not: points near float's
// largest value moved beyond it, and fitted derivatives beyond float's range (points near its
// largest value, or texture coordinates near its smallest, with no dPdu/dPdv to use). Reference:
// the same values in double arrays. An output coordinate that float cannot hold is the largest
// float of its sign (never infinity); every other coordinate is the double computation's
// rounded to float. The analytic modes' normals do not depend on the moved points and agree with
// double's, as do Mesh's where no point is clamped (Mesh's normals from clamped points must only
// stay finite and unit). A re-execution (a new Scale) gives a fresh filter's bits.
TEST(DisplacementMapFilter, FloatArraysBeyondFloatRangeAgreeWithDouble)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  constexpr double big = std::numeric_limits<float>::max();
  struct Case
  {
    double f, g;
    std::vector<double> scales;
    bool overflows;
  };
  // 2e38 x (ring radius 1 + tube 0.35): coordinates up to 2.7e38 of float's 3.4e38, and dP/ds
  // about 2 pi x 2.7e38. Texture coordinates of 1e-40: n_s about 1e40.
  for (const Case& c : { Case{ 2e38, 1.0, { 4e38, -4e38, 1e39, 1e300 }, true },
         Case{ 2e38, 1.0, { 1e37, -1e37 }, false }, Case{ 1.0, 1e-40, { 0.1, -0.1 }, false } })
  {
    for (bool derivatives : { false, true })
    {
      auto fl = Rescaled(MakeMesh(s, 48, 24, derivatives), c.f, c.g, true);
      auto d = Rescaled(fl, 1.0, 1.0, false); // the same values, exactly
      for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
             vtkDisplacementMapFilter::Mesh })
      {
        vtkNew<vtkDisplacementMapFilter> again;
        again->SetInputData(0, fl);
        again->SetInputData(1, image);
        again->SetNormalMode(mode);
        again->SetInterpolation(vtkDisplacementMapFilter::Cubic);
        again->SetMidlevel(0.5);
        for (double scale : c.scales)
        {
          std::ostringstream what;
          what << "f " << c.f << " g " << c.g << " scale " << scale << " mode " << mode
               << " derivatives " << derivatives;
          auto outD = Displace(d, image, mode, scale, 0.5, vtkDisplacementMapFilter::Cubic);
          auto outF = Displace(fl, image, mode, scale, 0.5, vtkDisplacementMapFilter::Cubic);
          const double angle = CheckAndCompare(outD, outF, what.str());
          if (mode != vtkDisplacementMapFilter::Mesh || !c.overflows)
          {
            EXPECT_LT(angle, 2e-5) << what.str();
          }
          again->SetScaleFactor(scale);
          again->Update();
          EXPECT_TRUE(SameOutput(again->GetOutput(), outF)) << what.str() << " re-execution";
          vtkIdType clamped = 0;
          for (vtkIdType i = 0; i < outF->GetNumberOfPoints(); ++i)
          {
            double pd[3], pf[3];
            outD->GetPoint(i, pd);
            outF->GetPoint(i, pf);
            for (int k = 0; k < 3; ++k)
            {
              const double expected = std::min(std::max(pd[k], -big), big);
              clamped += std::abs(pd[k]) > big;
              if (!(std::abs(pf[k] - expected) <= 1e-6 * std::abs(expected) + 1e-6 * c.f))
              {
                ADD_FAILURE() << what.str() << " point " << i << " component " << k << ": float "
                              << pf[k] << ", double " << pd[k];
                return;
              }
            }
          }
          // The first case is only tested if some coordinates did overflow.
          EXPECT_EQ(clamped > 0, c.overflows) << what.str();
        }
      }
    }
  }
}

// Fitted derivatives too small for float: P_s and P_t of a 1e-30 torus whose texture coordinates
// span 1e15 (about 6e-45: subnormal in float) or 1e16, 1e17 (below float's smallest subnormal:
// zero in float). Either way float cannot hold them, and the normals of the float arrays must
// agree with those of the same values in double arrays (not fall back on the input normals, 90
// degrees off where the heights' slope dwarfs the surface's), in first executions and
// re-executions alike. The heights slope at (0,0), where such texture coordinates sample them.
TEST(DisplacementMapFilter, FloatArraysWithVanishingFitsAgreeWithDouble)
{
  const Surface s = Torus();
  auto image = MakeHeightImage([](double u, double v)
    { return 0.5 + 0.3 * std::sin(2 * Pi * u + 1.0) + 0.2 * std::cos(2 * Pi * v + 0.5); },
    64, 32);
  for (double g : { 1e15, 1e16, 1e17 })
  {
    for (bool derivatives : { false, true })
    {
      auto fl = Rescaled(MakeMesh(s, 48, 24, derivatives), 1e-30, g, true);
      auto d = Rescaled(fl, 1.0, 1.0, false); // the same values, exactly
      for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact })
      {
        vtkNew<vtkDisplacementMapFilter> again;
        again->SetInputData(0, fl);
        again->SetInputData(1, image);
        again->SetNormalMode(mode);
        again->SetInterpolation(vtkDisplacementMapFilter::Cubic);
        again->SetMidlevel(0.5);
        for (double scale : { 0.1, -1.0 })
        {
          std::ostringstream what;
          what << "g " << g << " scale " << scale << " mode " << mode << " derivatives "
               << derivatives;
          auto outD = Displace(d, image, mode, scale, 0.5, vtkDisplacementMapFilter::Cubic);
          auto outF = Displace(fl, image, mode, scale, 0.5, vtkDisplacementMapFilter::Cubic);
          EXPECT_LT(CheckAndCompare(outD, outF, what.str()), 2e-5) << what.str();
          again->SetScaleFactor(scale);
          again->Update();
          EXPECT_TRUE(SameOutput(again->GetOutput(), outF)) << what.str() << " re-execution";
        }
      }
    }
  }
}
