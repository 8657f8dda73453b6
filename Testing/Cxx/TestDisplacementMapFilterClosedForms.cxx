// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter against truths computed here from the inputs alone:
// - a pole where 201 points coincide, each with its own texture coordinate: the pole
//   moves by the mean of every member's own displacement, sampled by an independent
//   transcription of OpenGL's bilinear rule;
// - Mesh normals orient each displaced polygon as the input normals of its points, whatever
//   its winding: a plane displaced by an affine height (a plane again, whose normal is closed
//   form) with every winding and both normal directions, and a sphere whose normals point in;
// - dPdu/dPdv taken with respect to parameters that the texture coordinates repeat (the
//   source's TextureRepeat and TextureOffset, negative too): the filter must divide by the
//   repeat, declared by the source or fitted, and the normals are closed form on a plane.

#include "DisplacementTestSurfaces.h"

#include "vtkDisplacementMapFilter.h"
#include "vtkParametricRectangle.h"
#include "vtkParametricSurfaceSource.h"

#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkMinimalStandardRandomSequence.h>
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

using namespace DisplacementTest;

namespace
{
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  int Count = 0;
};

struct Settings
{
  int Mode = vtkDisplacementMapFilter::Exact;
  double Scale = 0.1;
  double Midlevel = 0.5;
  int Interpolation = vtkDisplacementMapFilter::Linear;
  int Wrap = vtkDisplacementMapFilter::Repeat;
};

vtkSmartPointer<vtkPolyData> Displace(vtkPolyData* mesh, vtkImageData* image, const Settings& s)
{
  vtkNew<vtkDisplacementMapFilter> filter;
  filter->SetInputData(0, mesh);
  filter->SetInputData(1, image);
  filter->SetNormalMode(s.Mode);
  filter->SetScaleFactor(s.Scale);
  filter->SetMidlevel(s.Midlevel);
  filter->SetInterpolation(s.Interpolation);
  filter->SetWrap(s.Wrap);
  vtkNew<ErrorCounter> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->Update();
  EXPECT_EQ(errors->Count, 0);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(filter->GetOutput());
  return out;
}

Vec PointOf(vtkPolyData* mesh, vtkIdType id)
{
  Vec p;
  mesh->GetPoint(id, p.data());
  return p;
}

Vec NormalOf(vtkPolyData* mesh, vtkIdType id)
{
  Vec n;
  mesh->GetPointData()->GetNormals()->GetTuple(id, n.data());
  return n;
}

const char* ModeName(int mode)
{
  static const char* names[] = { "Input", "Approximate", "Exact", "Mesh" };
  return names[mode];
}

// OpenGL's GL_LINEAR with GL_REPEAT (4.5 spec, 8.14.2), written out for a double image.
double RepeatBilinear(vtkImageData* image, double s, double t)
{
  int dims[3];
  image->GetDimensions(dims);
  const int W = dims[0], H = dims[1];
  const auto* texels = static_cast<const double*>(image->GetScalarPointer());
  const double u = s * W - 0.5, v = t * H - 0.5;
  const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
  const double a = u - i0, b = v - j0;
  auto texel = [&](int i, int j)
  { return texels[static_cast<size_t>(((j % H) + H) % H) * W + ((i % W) + W) % W]; };
  return (1 - a) * (1 - b) * texel(i0, j0) + a * (1 - b) * texel(i0 + 1, j0) +
    (1 - a) * b * texel(i0, j0 + 1) + a * b * texel(i0 + 1, j0 + 1);
}

vtkSmartPointer<vtkImageData> RandomHeights(int W, int H, int seed)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(seed);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  image->AllocateScalars(VTK_DOUBLE, 1);
  auto* texels = static_cast<double*>(image->GetScalarPointer());
  for (int k = 0; k < W * H; ++k)
  {
    texels[k] = random->GetNextValue();
  }
  return image;
}

// A flat n x n grid over [0,1]^2 in z = 0 with texture coordinates 0.1 + 0.8 (x, y), inside
// the texel centres of a 16 x 16 map. Each triangle is wound counter-clockwise about +z, or
// clockwise, or at random (@a winding +1, -1, 0); every normal is @a normalSign z.
vtkSmartPointer<vtkPolyData> FlatGrid(int n, int winding, double normalSign)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(17);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals, tcoords;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
      points->InsertNextPoint(x, y, 0.0);
      normals->InsertNextTuple3(0.0, 0.0, normalSign);
      tcoords->InsertNextTuple2(0.1 + 0.8 * x, 0.1 + 0.8 * y);
    }
  }
  vtkNew<vtkCellArray> tris;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      for (std::array<vtkIdType, 3> t :
        { std::array<vtkIdType, 3>{ a, b, d }, std::array<vtkIdType, 3>{ a, d, c } })
      {
        const bool clockwise = winding < 0 || (winding == 0 && random->GetNextValue() < 0.5);
        if (clockwise)
        {
          std::swap(t[1], t[2]);
        }
        tris->InsertNextCell(3, t.data());
      }
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(tris);
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->SetTCoords(tcoords);
  return mesh;
}
} // namespace

// The south pole of a 200 x 16 sphere is 201 coincident points with texture coordinates
// (i/200, 0): each reads its own height. All of them must end at the pole moved by the mean of
// the 201 displacements; the seam's pairs likewise by the mean of their two.
TEST(DisplacementMapFilterClosedForms, PoleMovesByTheMeanOfEveryMembersDisplacement)
{
  const int U = 200, V = 16;
  vtkSmartPointer<vtkPolyData> mesh = MakeMesh(Sphere(), U, V, false);
  vtkSmartPointer<vtkImageData> image = RandomHeights(64, 32, 3);
  vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
  for (int mode : { vtkDisplacementMapFilter::Input, vtkDisplacementMapFilter::Approximate,
         vtkDisplacementMapFilter::Exact, vtkDisplacementMapFilter::Mesh })
  {
    SCOPED_TRACE(ModeName(mode));
    Settings settings;
    settings.Mode = mode;
    settings.Scale = 0.3;
    vtkSmartPointer<vtkPolyData> out = Displace(mesh, image, settings);
    // Each point's own displacement d n, from the independent sampler.
    auto own = [&](vtkIdType id)
    {
      const double h = RepeatBilinear(image, tc->GetComponent(id, 0), tc->GetComponent(id, 1));
      const Vec n = Unit(NormalOf(mesh, id));
      const double d = settings.Scale * (h - settings.Midlevel);
      return Vec{ d * n[0], d * n[1], d * n[2] };
    };
    auto expectMovedByMean = [&](const std::vector<vtkIdType>& group, const char* what)
    {
      Vec mean{ 0.0, 0.0, 0.0 };
      for (vtkIdType id : group)
      {
        mean = Add(mean, own(id), 1.0 / static_cast<double>(group.size()));
      }
      double worst = 0.0;
      for (vtkIdType id : group)
      {
        const Vec gap = Add(PointOf(out, id), Add(PointOf(mesh, id), mean), -1.0);
        worst = std::max(worst, std::sqrt(DotV(gap, gap)));
      }
      EXPECT_LT(worst, 1e-13) << what << " (" << group.size() << " points)";
    };
    std::vector<vtkIdType> south, north;
    for (int i = 0; i <= U; ++i)
    {
      south.push_back(i);
      north.push_back(static_cast<vtkIdType>(V) * (U + 1) + i);
    }
    // The pole's members read very different heights: the mean is not any one of them.
    double spread = 0.0;
    for (vtkIdType id : south)
    {
      spread = std::max(spread, std::abs(DotV(Add(own(id), own(south[0]), -1.0), { 0, 1, 0 })));
    }
    ASSERT_GT(spread, 0.1);
    expectMovedByMean(south, "south pole");
    expectMovedByMean(north, "north pole");
    for (int j = 1; j < V; ++j)
    {
      const vtkIdType first = static_cast<vtkIdType>(j) * (U + 1);
      expectMovedByMean({ first, first + U }, "seam");
    }
  }
}

// A plane displaced by an affine height is a plane: every displaced triangle has its normal,
// whatever the triangles' areas, so Mesh normals are exactly closed form, on the side of the
// input normals. Triangles wound either way, or each at random, must give the same normals; so
// must Approximate and Exact, which do not look at the winding.
TEST(DisplacementMapFilterClosedForms, MeshNormalsFollowTheInputNormalsNotTheWinding)
{
  const double H0 = 0.3, Hs = 0.5, Ht = -0.2;
  vtkSmartPointer<vtkImageData> image =
    MakeHeightImage([&](double s, double t) { return H0 + Hs * s + Ht * t; }, 16, 16);
  Settings settings;
  settings.Scale = 0.4;
  settings.Midlevel = 0.2;
  settings.Wrap = vtkDisplacementMapFilter::ClampToEdge;
  for (double normalSign : { 1.0, -1.0 })
  {
    // z = sign Scale (h(s(x), t(y)) - Midlevel) with ds/dx = dt/dy = 0.8; the normal of that
    // plane, on the input normals' side.
    const double zx = normalSign * settings.Scale * Hs * 0.8;
    const double zy = normalSign * settings.Scale * Ht * 0.8;
    const Vec up = Unit({ -zx, -zy, 1.0 });
    const Vec truth{ normalSign * up[0], normalSign * up[1], normalSign * up[2] };
    for (int winding : { 1, -1, 0 })
    {
      vtkSmartPointer<vtkPolyData> mesh = FlatGrid(12, winding, normalSign);
      for (int mode : { vtkDisplacementMapFilter::Mesh, vtkDisplacementMapFilter::Approximate,
             vtkDisplacementMapFilter::Exact })
      {
        settings.Mode = mode;
        vtkSmartPointer<vtkPolyData> out = Displace(mesh, image, settings);
        double worst = 0.0;
        for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
        {
          worst = std::max(worst, AngleDeg(NormalOf(out, i), truth));
        }
        EXPECT_LT(worst, 1e-9) << ModeName(mode) << ", normals " << normalSign << "z, winding "
                               << (winding > 0      ? "counter-clockwise"
                                      : winding < 0 ? "clockwise"
                                                    : "random");
      }
    }
  }
}

// A sphere whose normals point in, its triangles wound about the outward direction (clockwise
// about its normals), displaced inward by Scale: the same surface as the outward sphere
// displaced by -Scale. Mesh normals must be that surface's, turned to the input normals' side,
// exactly the outward ones negated, and point into the sphere everywhere.
TEST(DisplacementMapFilterClosedForms, MeshNormalsOfAnInwardSphereAreTheOutwardOnesNegated)
{
  const Surface s = Sphere();
  vtkSmartPointer<vtkPolyData> outward = MakeMesh(s, 48, 24, false);
  auto inward = vtkSmartPointer<vtkPolyData>::New();
  inward->DeepCopy(outward);
  vtkDataArray* normals = inward->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    normals->SetTuple3(
      i, -normals->GetComponent(i, 0), -normals->GetComponent(i, 1), -normals->GetComponent(i, 2));
  }
  vtkSmartPointer<vtkImageData> image = MakeHeightImage(s.Height, 128, 64);
  Settings settings;
  settings.Mode = vtkDisplacementMapFilter::Mesh;
  settings.Scale = s.Scale;
  vtkSmartPointer<vtkPolyData> in = Displace(inward, image, settings);
  settings.Scale = -s.Scale;
  vtkSmartPointer<vtkPolyData> out = Displace(outward, image, settings);
  double worstPosition = 0.0, worstNegation = 0.0, leastInward = 1.0;
  for (vtkIdType i = 0; i < in->GetNumberOfPoints(); ++i)
  {
    const Vec gap = Add(PointOf(in, i), PointOf(out, i), -1.0);
    worstPosition = std::max(worstPosition, std::sqrt(DotV(gap, gap)));
    const Vec n = NormalOf(in, i), m = NormalOf(out, i);
    worstNegation = std::max(worstNegation, AngleDeg(n, { -m[0], -m[1], -m[2] }));
    leastInward = std::min(leastInward, -DotV(n, Unit(PointOf(in, i))));
  }
  EXPECT_LT(worstPosition, 1e-15); // the same surface
  EXPECT_LT(worstNegation, 1e-9);
  // Heights tilt the normals by less than 45 degrees from the radius here.
  EXPECT_GT(leastInward, std::cos(Pi / 4));
}

// dPdu/dPdv of a rectangle from vtkParametricSurfaceSource with a texture transform: dP/ds is
// dPdu / repeat. The height is affine in (s,t) and the texture coordinates stay inside the
// texel centres, so the displaced surface is a plane with a closed-form normal. Repeats of
// either sign and size, declared by the source on its texture coordinates or (with the same
// coordinates in a new array) fitted by the filter.
TEST(DisplacementMapFilterClosedForms, DerivativesAreDividedByTheTextureRepeat)
{
  const double H0 = 0.2, Hs = 0.9, Ht = 0.6;
  vtkSmartPointer<vtkImageData> image =
    MakeHeightImage([&](double s, double t) { return H0 + Hs * s + Ht * t; }, 32, 32);
  // P = (-1, -0.5, 0) + u (2, 0, 0) + v (0, 1, 0): x = 2u - 1, y = v - 0.5.
  const double width = 2.0, height = 1.0;
  struct Transform
  {
    double Repeat[2], Offset[2];
  };
  // s and t stay in [0.1, 0.9], inside the map's texel centres.
  const Transform transforms[] = { { { 0.5, 0.6 }, { 0.25, 0.2 } },
    { { -0.5, 0.6 }, { 0.75, 0.2 } }, { { 0.5, -0.6 }, { 0.25, 0.8 } },
    { { -0.8, -0.3 }, { 0.9, 0.6 } }, { { 0.3, 0.8 }, { 0.1, 0.1 } } };
  for (const Transform& tt : transforms)
  {
    vtkNew<vtkParametricRectangle> rectangle;
    rectangle->SetOrigin(-1.0, -0.5, 0.0);
    rectangle->SetPoint1(1.0, -0.5, 0.0);
    rectangle->SetPoint2(-1.0, 0.5, 0.0);
    vtkNew<vtkParametricSurfaceSource> source;
    source->SetParametricFunction(rectangle);
    source->SetUResolution(20);
    source->SetVResolution(10);
    source->SetTextureRepeat(tt.Repeat[0], tt.Repeat[1]);
    source->SetTextureOffset(tt.Offset[0], tt.Offset[1]);
    source->GenerateDerivativesOn();
    source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    source->Update();
    vtkPolyData* declared = source->GetOutput();
    ASSERT_NE(declared->GetPointData()->GetArray("dPdu"), nullptr);
    // The same coordinates in an array without the source's declaration.
    auto fitted = vtkSmartPointer<vtkPolyData>::New();
    fitted->DeepCopy(declared);
    vtkDataArray* tc = declared->GetPointData()->GetTCoords();
    vtkNew<vtkFloatArray> copy;
    copy->SetName("TCoords");
    copy->SetNumberOfComponents(2);
    copy->SetNumberOfTuples(tc->GetNumberOfTuples());
    for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
    {
      copy->SetTuple(i, tc->GetTuple(i));
    }
    fitted->GetPointData()->SetTCoords(copy);
    ASSERT_FALSE(fitted->GetPointData()->GetTCoords()->HasInformation() &&
      fitted->GetPointData()->GetTCoords()->GetInformation()->Has(
        vtkParametricSurfaceSource::TEXTURE_TRANSFORM()));
    // z = Scale (h - Midlevel), dz/dx = Scale Hs repeat_s / width, dz/dy likewise in t; the
    // normal on the side of the source's (+z) normals.
    const double scale = 0.15;
    const Vec truth =
      Unit({ -scale * Hs * tt.Repeat[0] / width, -scale * Ht * tt.Repeat[1] / height, 1.0 });
    for (vtkPolyData* mesh : { declared, fitted.GetPointer() })
    {
      for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact })
      {
        Settings settings;
        settings.Mode = mode;
        settings.Scale = scale;
        settings.Wrap = vtkDisplacementMapFilter::ClampToEdge;
        vtkSmartPointer<vtkPolyData> out = Displace(mesh, image, settings);
        double worst = 0.0;
        for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
        {
          worst = std::max(worst, AngleDeg(NormalOf(out, i), truth));
        }
        std::printf("repeat (%g, %g), %s, %s: worst normal angle %.3e deg\n", tt.Repeat[0],
          tt.Repeat[1], mesh == declared ? "declared" : "fitted", ModeName(mode), worst);
        // Single-precision texture coordinates limit the fitted repeat.
        EXPECT_LT(worst, mesh == declared ? 1e-9 : 1e-5)
          << ModeName(mode) << (mesh == declared ? ", declared" : ", fitted") << " repeat ("
          << tt.Repeat[0] << ", " << tt.Repeat[1] << ")";
      }
    }
  }
}
