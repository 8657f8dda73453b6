// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNormalMapBaker against truth. The detailed meshes are displaced tori and spheres
// (DisplacementTestSurfaces.h, displaced by vtkDisplacementMapFilter with Exact normals); the
// coarse meshes are the same undisplaced surfaces at low resolution. Every covered texel is
// decoded here with the coarse mesh's frame, rebuilt from the coarse mesh's arrays as
// vtkSurfaceDetailMapper rebuilds it, and compared with the closed-form normal of the displaced
// surface where the baked ray meets it; that point is found by Newton's method on the closed
// form, so the truth owes nothing to the baker. Also: a plane baked onto a tilted plane (exact
// answers), the same output for any number of threads, and every kind of bad input.

#include "DisplacementTestSurfaces.h"
#include "NormalMapBakerTestFrames.h"
#include "TangentFrameTestHelpers.h"

#include "vtkDisplacementMapFilter.h"
#include "vtkNormalMapBaker.h"

#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkImageShiftScale.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkSurfaceDetailConventions.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace DisplacementTest;

class Observer : public vtkCommand
{
public:
  static Observer* New() { return new Observer; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)++;
    this->Messages += data ? static_cast<const char*>(data) : "";
  }
  int Errors = 0;
  int Warnings = 0;
  std::string Messages;
};

vtkSmartPointer<Observer> Watch(vtkAlgorithm* algorithm)
{
  auto obs = vtkSmartPointer<Observer>::New();
  algorithm->AddObserver(vtkCommand::ErrorEvent, obs);
  algorithm->AddObserver(vtkCommand::WarningEvent, obs);
  algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, obs);
  return obs;
}

// Where the ray o + d n meets the displaced closed form: Newton's method on
// p*(u,v) - o - d n = 0 from (u0, v0, d0). Returns false if it does not converge.
bool MeetSurface(const Surface& s, const Vec& o, const Vec& n, double& u, double& v, double& d)
{
  for (int it = 0; it < 30; ++it)
  {
    const Vec f = Add(Add(s.Displaced(u, v), o, -1.0), n, -d);
    if (std::sqrt(DotV(f, f)) < 1e-12)
    {
      return true;
    }
    const double e = 1e-6;
    const Vec pu = Add(s.Displaced(u + e, v), s.Displaced(u - e, v), -1.0);
    const Vec pv = Add(s.Displaced(u, v + e), s.Displaced(u, v - e), -1.0);
    const Vec cu = { pu[0] / (2 * e), pu[1] / (2 * e), pu[2] / (2 * e) };
    const Vec cv = { pv[0] / (2 * e), pv[1] / (2 * e), pv[2] / (2 * e) };
    const Vec cd = { -n[0], -n[1], -n[2] };
    // Cramer's rule for [cu cv cd] x = -f.
    const double det = DotV(cu, CrossV(cv, cd));
    if (std::abs(det) < 1e-300)
    {
      return false;
    }
    const Vec r = { -f[0], -f[1], -f[2] };
    u += DotV(r, CrossV(cv, cd)) / det;
    v += DotV(cu, CrossV(r, cd)) / det;
    d += DotV(cu, CrossV(cv, r)) / det;
  }
  const Vec f = Add(Add(s.Displaced(u, v), o, -1.0), n, -d);
  return std::sqrt(DotV(f, f)) < 1e-9;
}

Vec Decode(vtkDataArray* map, vtkIdType texel)
{
  double rgb[3], n[3];
  const double top = map->GetDataType() == VTK_UNSIGNED_CHAR ? 255.0
    : map->GetDataType() == VTK_UNSIGNED_SHORT               ? 65535.0
                                                             : 1.0;
  map->GetTuple(texel, rgb);
  for (double& c : rgb)
  {
    c /= top;
  }
  vtkSurfaceDetail::DecodeNormal(rgb, true, n);
  return { n[0], n[1], n[2] };
}

struct Accuracy
{
  int Texels = 0;
  double MeanAngle = 0, MaxAngle = 0;
  double MeanHeightError = 0, MaxHeightError = 0;
  double MeanDisplacementGap = 0;
};

// Bakes @a s into a W x W map and compares every texel of the texture square (the poles'
// rows of the sphere excepted: the closed form's (u,v) is singular there, so Newton's method
// on it is not a truth) with the displaced closed form.
Accuracy Measure(const Surface& s, int space, int type)
{
  const int U = 24, V = 12, W = 256;
  vtkSmartPointer<vtkPolyData> coarse = MakeMesh(s, U, V, false);
  vtkSmartPointer<vtkPolyData> detailed = Detailed(s, 768, 384);
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, coarse);
  baker->SetInputData(1, detailed);
  baker->SetTextureSize(W, W);
  baker->SetMaxRayDistance(0.2);
  baker->SetSpace(space);
  baker->SetOutputScalarType(type);
  baker->BakeHeightOn();
  auto obs = Watch(baker);
  baker->Update();
  EXPECT_EQ(obs->Errors, 0);
  EXPECT_EQ(obs->Warnings, 0) << obs->Messages;
  EXPECT_EQ(baker->GetNumberOfCoveredTexels(), W * W); // the grid covers the unit square
  EXPECT_EQ(baker->GetNumberOfUnhitTexels(), 0);
  EXPECT_EQ(baker->GetNumberOfOverlappingTexels(), 0);
  vtkDataArray* map = baker->GetOutput()->GetPointData()->GetScalars();
  vtkDataArray* heights = baker->GetHeightOutput()->GetPointData()->GetScalars();

  Accuracy a;
  for (int j = 0; j < W; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const double st[2] = { (i + 0.5) / W, (j + 0.5) / W };
      if (s.Poles && std::sin(Pi * st[1]) < 0.1)
      {
        continue;
      }
      const vtkIdType texel = static_cast<vtkIdType>(j) * W + i;
      const Frame f = CoarseFrame(coarse, U, V, st[0], st[1]);
      const double baked = heights->GetComponent(texel, 0);
      // Newton starts on the coarse surface (d = 0), not at the baked height: the hit it finds
      // is the closed form's own.
      double u = st[0], v = st[1], d = 0.0;
      if (!MeetSurface(s, f.P, f.N, u, v, d))
      {
        ADD_FAILURE() << s.Name << ": no closed-form hit at texel " << i << "," << j;
        continue;
      }
      const Vec n = Decode(map, texel);
      const Vec decoded = space == vtkNormalMapBaker::Object
        ? n
        : Unit(Add(Add({ n[0] * f.T[0], n[0] * f.T[1], n[0] * f.T[2] }, f.B, n[1]), f.N, n[2]));
      const double angle = AngleDeg(decoded, s.DisplacedNormal(u, v));
      const double heightError = std::abs(baked - d);
      a.MeanAngle += angle;
      a.MaxAngle = std::max(a.MaxAngle, angle);
      a.MeanHeightError += heightError;
      a.MaxHeightError = std::max(a.MaxHeightError, heightError);
      a.MeanDisplacementGap += std::abs(baked - s.Scale * (s.Height(st[0], st[1]) - s.Midlevel));
      ++a.Texels;
    }
  }
  a.MeanAngle /= a.Texels;
  a.MeanHeightError /= a.Texels;
  a.MeanDisplacementGap /= a.Texels;
  std::cout << s.Name << ", " << (space == vtkNormalMapBaker::Object ? "object" : "tangent")
            << " space, " << (type == VTK_FLOAT ? "float" : "uchar") << ": " << a.Texels
            << " texels; normal angle to the closed form mean " << a.MeanAngle << " deg, max "
            << a.MaxAngle << " deg; height error mean " << a.MeanHeightError << ", max "
            << a.MaxHeightError << " (Scale " << s.Scale
            << "); mean |height - Scale (h(s,t) - Midlevel)| " << a.MeanDisplacementGap << "\n";
  return a;
}

void ExpectAccurate(const Accuracy& a, double scale)
{
  EXPECT_GT(a.Texels, 40000);
  EXPECT_LT(a.MeanAngle, 1.0);
  // Everywhere, seams included: 8-bit rounding alone is up to half a degree.
  EXPECT_LT(a.MaxAngle, 1.0);
  // The detailed mesh is a tessellation: its facets stand off the closed form by their chord
  // error, a small fraction of the displacement.
  EXPECT_LT(a.MeanHeightError, 0.01 * scale);
  EXPECT_LT(a.MaxHeightError, 0.05 * scale);
}

TEST(NormalMapBaker, TorusAgainstClosedForm)
{
  const Surface s = Torus();
  for (int space : { vtkNormalMapBaker::Tangent, vtkNormalMapBaker::Object })
  {
    for (int type : { VTK_UNSIGNED_CHAR, VTK_FLOAT })
    {
      ExpectAccurate(Measure(s, space, type), s.Scale);
    }
  }
}

TEST(NormalMapBaker, SphereAgainstClosedForm)
{
  const Surface s = Sphere();
  for (int space : { vtkNormalMapBaker::Tangent, vtkNormalMapBaker::Object })
  {
    ExpectAccurate(Measure(s, space, VTK_UNSIGNED_CHAR), s.Scale);
  }
}

// A square at z = 0 baked against the plane z = 0.02 + 0.1 x - 0.05 y: the normal is one
// constant vector and the height a linear function, known exactly.
vtkSmartPointer<vtkPolyData> Square(int n, double a, double b, double c, bool frame)
{
  const Surface s = Rectangle();
  vtkSmartPointer<vtkPolyData> mesh = MakeMesh(s, n, n, false);
  vtkPoints* points = mesh->GetPoints();
  for (vtkIdType k = 0; k < points->GetNumberOfPoints(); ++k)
  {
    double p[3];
    points->GetPoint(k, p);
    p[2] = c + a * p[0] + b * p[1];
    points->SetPoint(k, p);
  }
  const Vec normal = Unit({ -a, -b, 1.0 });
  for (vtkIdType k = 0; k < points->GetNumberOfPoints(); ++k)
  {
    mesh->GetPointData()->GetNormals()->SetTuple(k, normal.data());
  }
  if (!frame)
  {
    mesh->GetPointData()->RemoveArray("Tangents");
    mesh->GetPointData()->SetNormals(nullptr);
  }
  return mesh;
}

vtkSmartPointer<vtkImageData> Bake(vtkNormalMapBaker* baker)
{
  baker->Update();
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->DeepCopy(baker->GetOutput());
  return copy;
}

TEST(NormalMapBaker, TiltedPlaneExactly)
{
  const double a = 0.1, b = -0.05, c = 0.02;
  vtkSmartPointer<vtkPolyData> coarse = Square(3, 0, 0, 0, true);
  vtkSmartPointer<vtkPolyData> detailed = Square(17, a, b, c, true);
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, coarse);
  baker->SetInputData(1, detailed);
  baker->SetTextureSize(40, 30);
  baker->SetMaxRayDistance(0.2); // the plane is up to 0.17 away
  baker->SetOutputScalarTypeToFloat();
  baker->BakeHeightOn();
  baker->Update();
  vtkImageData* map = baker->GetOutput();
  int dims[3];
  map->GetDimensions(dims);
  ASSERT_EQ(dims[0], 40);
  ASSERT_EQ(dims[1], 30);
  EXPECT_NEAR(map->GetOrigin()[0], 0.5 / 40, 1e-15);
  EXPECT_NEAR(map->GetSpacing()[1], 1.0 / 30, 1e-15);
  vtkDataArray* normals = map->GetPointData()->GetScalars();
  vtkDataArray* heights = baker->GetHeightOutput()->GetPointData()->GetScalars();
  ASSERT_STREQ(normals->GetName(), "NormalMap");
  ASSERT_STREQ(heights->GetName(), "Height");
  const Vec truth = Unit({ -a, -b, 1.0 });
  for (int j = 0; j < 30; ++j)
  {
    for (int i = 0; i < 40; ++i)
    {
      // The square's tangent frame is x, y, z: tangent space is object space here.
      const vtkIdType texel = j * 40 + i;
      EXPECT_LT(AngleDeg(Decode(normals, texel), truth), 1e-4);
      const double x = 2 * (i + 0.5) / 40 - 1, y = 2 * (j + 0.5) / 30 - 1;
      EXPECT_NEAR(heights->GetComponent(texel, 0), c + a * x + b * y, 1e-6);
    }
  }

  // A cage above both planes: the first hit from outside. Two layers, the upper 0.05 above.
  vtkSmartPointer<vtkPolyData> upper = Square(5, 0, 0, 0.05, true);
  vtkSmartPointer<vtkPolyData> lower = Square(5, 0, 0, -0.01, true);
  vtkNew<vtkPolyData> layers;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  for (vtkPolyData* layer : { upper.GetPointer(), lower.GetPointer() })
  {
    const vtkIdType base = points->GetNumberOfPoints();
    for (vtkIdType k = 0; k < layer->GetNumberOfPoints(); ++k)
    {
      points->InsertNextPoint(layer->GetPoint(k));
    }
    for (vtkIdType k = 0; k < layer->GetNumberOfCells(); ++k)
    {
      vtkIdType ids[3];
      for (int m = 0; m < 3; ++m)
      {
        ids[m] = base + layer->GetCell(k)->GetPointId(m);
      }
      polys->InsertNextCell(3, ids);
    }
  }
  layers->SetPoints(points);
  layers->SetPolys(polys);
  baker->SetInputData(1, layers);
  baker->Update();
  EXPECT_NEAR(baker->GetHeightOutput()->GetPointData()->GetScalars()->GetComponent(0, 0), -0.01,
    1e-7); // the nearer layer, below
  baker->SetCageOffset(0.1);
  baker->Update();
  EXPECT_NEAR(baker->GetHeightOutput()->GetPointData()->GetScalars()->GetComponent(0, 0), 0.05,
    1e-7); // the first layer seen from the cage
  // Face normals when the detailed mesh has no point normals: the layers' are +z.
  EXPECT_LT(
    AngleDeg(Decode(baker->GetOutput()->GetPointData()->GetScalars(), 0), { 0, 0, 1 }), 1e-4);
}

// The height map is an optional output: with BakeHeight off, port 1's information must say
// that it is empty, or a downstream image filter sized from the information reads a W x H image
// that is not there (vtkImageShiftScale crashed on it).
TEST(NormalMapBaker, HeightOutputIsEmptyWhenNotBaked)
{
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, Square(3, 0, 0, 0, true));
  baker->SetInputData(1, Square(5, 0, 0, 0.02, true));
  baker->SetTextureSize(16, 8);
  baker->SetMaxRayDistance(0.1);
  vtkNew<vtkImageShiftScale> shift;
  shift->SetInputConnection(baker->GetOutputPort(1));
  shift->SetScale(2.0);
  for (const bool height : { false, true, false })
  {
    SCOPED_TRACE(height ? "BakeHeight on" : "BakeHeight off");
    baker->SetBakeHeight(height);
    shift->Update();
    int extent[6];
    baker->GetOutputInformation(1)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
    EXPECT_EQ(extent[1] - extent[0] + 1, height ? 16 : 0);
    EXPECT_EQ(extent[3] - extent[2] + 1, height ? 8 : 0);
    EXPECT_EQ(shift->GetOutput()->GetNumberOfPoints(), height ? 16 * 8 : 0);
    EXPECT_EQ(baker->GetOutput()->GetNumberOfPoints(), 16 * 8);
    if (height)
    {
      EXPECT_NEAR(shift->GetOutput()->GetPointData()->GetScalars()->GetComponent(0, 0), 0.04, 1e-6);
    }
  }
}

TEST(NormalMapBaker, SameOutputForAnyNumberOfThreads)
{
  const Surface s = Torus();
  vtkSmartPointer<vtkPolyData> coarse = MakeMesh(s, 16, 8, false);
  vtkSmartPointer<vtkPolyData> detailed = Detailed(s, 256, 128);
  std::vector<vtkSmartPointer<vtkImageData>> maps, heights;
  // Two threads (TBB; this machine's cores) against the sequential backend.
  const std::string backend = vtkSMPTools::GetBackend();
  for (int threads : { 2, 1 })
  {
    if (threads == 1)
    {
      vtkSMPTools::SetBackend("Sequential");
    }
    vtkSMPTools::Initialize(threads);
    vtkNew<vtkNormalMapBaker> baker;
    baker->SetInputData(0, coarse);
    baker->SetInputData(1, detailed);
    baker->SetTextureSize(200, 120);
    baker->SetMaxRayDistance(0.2);
    baker->SetOutputScalarTypeToFloat();
    baker->BakeHeightOn();
    maps.push_back(Bake(baker));
    auto h = vtkSmartPointer<vtkImageData>::New();
    h->DeepCopy(baker->GetHeightOutput());
    heights.push_back(h);
  }
  vtkSMPTools::SetBackend(backend.c_str());
  vtkSMPTools::Initialize(0);
  auto bytes = [](vtkImageData* image)
  {
    vtkDataArray* a = image->GetPointData()->GetScalars();
    return std::string(static_cast<const char*>(a->GetVoidPointer(0)),
      a->GetNumberOfValues() * a->GetDataTypeSize());
  };
  for (size_t k = 1; k < maps.size(); ++k)
  {
    EXPECT_EQ(bytes(maps[0]), bytes(maps[k])) << "normal map, run " << k;
    EXPECT_EQ(bytes(heights[0]), bytes(heights[k])) << "height map, run " << k;
  }
}

TEST(NormalMapBaker, ScalarTypesEncodeTheSameNormals)
{
  const Surface s = Torus();
  vtkSmartPointer<vtkPolyData> coarse = MakeMesh(s, 16, 8, false);
  vtkSmartPointer<vtkPolyData> detailed = Detailed(s, 128, 64);
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, coarse);
  baker->SetInputData(1, detailed);
  baker->SetTextureSize(64, 64);
  baker->SetMaxRayDistance(0.2);
  baker->SetOutputScalarTypeToFloat();
  vtkSmartPointer<vtkImageData> f = Bake(baker);
  baker->SetOutputScalarTypeToUnsignedShort();
  vtkSmartPointer<vtkImageData> us = Bake(baker);
  baker->SetOutputScalarTypeToUnsignedChar();
  vtkSmartPointer<vtkImageData> uc = Bake(baker);
  vtkDataArray* fa = f->GetPointData()->GetScalars();
  ASSERT_EQ(fa->GetDataType(), VTK_FLOAT);
  ASSERT_EQ(us->GetPointData()->GetScalars()->GetDataType(), VTK_UNSIGNED_SHORT);
  ASSERT_EQ(uc->GetPointData()->GetScalars()->GetDataType(), VTK_UNSIGNED_CHAR);
  for (vtkIdType k = 0; k < fa->GetNumberOfTuples(); ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = fa->GetComponent(k, c);
      // The float map holds the colour rounded to 24 bits: within one 16-bit level.
      ASSERT_NEAR(us->GetPointData()->GetScalars()->GetComponent(k, c), v * 65535, 1.0);
      ASSERT_EQ(uc->GetPointData()->GetScalars()->GetComponent(k, c), std::lround(v * 255));
    }
  }
  baker->SetOutputScalarType(VTK_INT); // refused, setting kept
  EXPECT_EQ(baker->GetOutputScalarType(), VTK_UNSIGNED_CHAR);
}

// GreenUp off (DirectX) stores -Y: the green channel becomes 1 - green, red and blue stay;
// an object-space map is the same either way.
TEST(NormalMapBaker, GreenDownFlipsOnlyTheGreenOfTangentSpaceMaps)
{
  const Surface s = Torus();
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, MakeMesh(s, 16, 8, false));
  baker->SetInputData(1, Detailed(s, 128, 64));
  baker->SetTextureSize(64, 64);
  baker->SetMaxRayDistance(0.2);
  baker->SetOutputScalarTypeToFloat();
  EXPECT_TRUE(baker->GetGreenUp());
  for (bool tangentSpace : { true, false })
  {
    baker->SetSpace(tangentSpace ? vtkNormalMapBaker::Tangent : vtkNormalMapBaker::Object);
    baker->GreenUpOn();
    vtkSmartPointer<vtkImageData> up = Bake(baker);
    baker->GreenUpOff();
    vtkSmartPointer<vtkImageData> down = Bake(baker);
    vtkDataArray* u = up->GetPointData()->GetScalars();
    vtkDataArray* d = down->GetPointData()->GetScalars();
    ASSERT_EQ(u->GetNumberOfTuples(), d->GetNumberOfTuples());
    int flipped = 0;
    for (vtkIdType k = 0; k < u->GetNumberOfTuples(); ++k)
    {
      ASSERT_EQ(d->GetComponent(k, 0), u->GetComponent(k, 0));
      ASSERT_EQ(d->GetComponent(k, 2), u->GetComponent(k, 2));
      const double green = tangentSpace ? 1.0 - u->GetComponent(k, 1) : u->GetComponent(k, 1);
      ASSERT_NEAR(d->GetComponent(k, 1), green, 1e-6);
      flipped += std::abs(u->GetComponent(k, 1) - 0.5) > 0.01;
    }
    EXPECT_GT(flipped, 100) << "the maps must have green that flipping changes";
  }
}

// Half of the unit square (the triangle below the diagonal), baked with a margin: texels
// within Margin rings of it are filled, those beyond keep the flat background.
TEST(NormalMapBaker, MarginAndUnhitTexels)
{
  vtkNew<vtkPolyData> coarse;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(1, 1, 0);
  coarse->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType tri[3] = { 0, 1, 2 };
  polys->InsertNextCell(3, tri);
  coarse->SetPolys(polys);
  vtkNew<vtkFloatArray> tc, normals, tangents;
  tc->SetNumberOfComponents(2);
  normals->SetNumberOfComponents(3);
  tangents->SetNumberOfComponents(4);
  tangents->SetName("Tangents");
  for (int k = 0; k < 3; ++k)
  {
    tc->InsertNextTuple2(points->GetPoint(k)[0], points->GetPoint(k)[1]);
    normals->InsertNextTuple3(0, 0, 1);
    tangents->InsertNextTuple4(1, 0, 0, 1);
  }
  coarse->GetPointData()->SetTCoords(tc);
  coarse->GetPointData()->SetNormals(normals);
  SetTangentFrame(coarse, tangents);
  // A detailed square tilted about y, with a hole (no triangles) over x in [0.6, 0.8].
  vtkNew<vtkPolyData> detailed;
  vtkNew<vtkPoints> dp;
  vtkNew<vtkCellArray> dpolys;
  const double xs[4] = { -0.1, 0.6, 0.8, 1.1 };
  for (double x : xs)
  {
    dp->InsertNextPoint(x, -0.1, 0.1 * x);
    dp->InsertNextPoint(x, 1.1, 0.1 * x);
  }
  for (int strip : { 0, 2 })
  {
    const vtkIdType q[4] = { 2 * strip, 2 * strip + 2, 2 * strip + 3, 2 * strip + 1 };
    dpolys->InsertNextCell(4, q);
  }
  detailed->SetPoints(dp);
  detailed->SetPolys(dpolys);

  const int W = 50;
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, coarse);
  baker->SetInputData(1, detailed);
  baker->SetTextureSize(W, W);
  baker->SetMargin(3);
  auto obs = Watch(baker);
  vtkSmartPointer<vtkImageData> map = Bake(baker);
  EXPECT_EQ(obs->Errors, 0);
  EXPECT_EQ(obs->Warnings, 1);
  EXPECT_NE(obs->Messages.find("no detailed surface within MaxRayDistance"), std::string::npos)
    << obs->Messages;
  // Texel centres (i + 0.5)/W in [0.6, 0.8] (i = 30..39) below the diagonal have no hit.
  vtkIdType expected = 0;
  for (int j = 0; j < W; ++j)
  {
    for (int i = 30; i < 40; ++i)
    {
      expected += j <= i;
    }
  }
  EXPECT_EQ(baker->GetNumberOfUnhitTexels(), expected);
  EXPECT_EQ(baker->GetNumberOfCoveredTexels(), W * (W + 1) / 2);
  const Vec tilted = Unit({ -0.1, 0.0, 1.0 });
  vtkDataArray* rgb = map->GetPointData()->GetScalars();
  for (int j = 0; j < W; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const Vec n = Decode(rgb, j * W + i);
      // Covered (j <= i), or within 3 rings of 8-neighbours: Chebyshev distance
      // ceil((j - i)/2) <= 3 from the covered half.
      if (j - i <= 6)
      {
        // Hit, filled or margin: all from the same tilted normal (within 8-bit rounding).
        EXPECT_LT(AngleDeg(n, tilted), 0.5) << i << "," << j;
      }
      else
      {
        EXPECT_LT(AngleDeg(n, { 0, 0, 1 }), 0.5) << i << "," << j; // flat background
      }
    }
  }
}

TEST(NormalMapBaker, MissingTangentsAreComputedWithAWarning)
{
  const Surface s = Torus();
  vtkSmartPointer<vtkPolyData> coarse = MakeMesh(s, 16, 8, false);
  vtkSmartPointer<vtkPolyData> detailed = Detailed(s, 128, 64);
  vtkNew<vtkPolyData> bare;
  bare->ShallowCopy(coarse);
  bare->GetPointData()->RemoveArray("Tangents");
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, bare);
  baker->SetInputData(1, detailed);
  baker->SetTextureSize(32, 32);
  baker->SetMaxRayDistance(0.2);
  auto obs = Watch(baker);
  baker->Update();
  EXPECT_EQ(obs->Errors, 0);
  EXPECT_GE(obs->Warnings, 1);
  EXPECT_NE(obs->Messages.find("vtkMikkTSpaceTangents"), std::string::npos);
  EXPECT_EQ(bare->GetPointData()->GetTangents(), nullptr); // input untouched
  EXPECT_EQ(baker->GetNumberOfCoveredTexels(), 32 * 32);
}

TEST(NormalMapBaker, TextureCoordinatesOutsideTheSquareAndOverlaps)
{
  const Surface s = Rectangle();
  vtkSmartPointer<vtkPolyData> coarse = MakeMesh(s, 4, 4, false);
  vtkSmartPointer<vtkPolyData> detailed = MakeMesh(s, 8, 8, false);
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(1, detailed);
  baker->SetTextureSize(32, 32);

  // Point 0's texture coordinates moved out of the square: cells 0 and 1 use it.
  vtkNew<vtkPolyData> outside;
  outside->DeepCopy(coarse);
  outside->GetPointData()->GetTCoords()->SetTuple2(0, -0.5, 0.0);
  baker->SetInputData(0, outside);
  auto obs = Watch(baker);
  baker->Update();
  EXPECT_EQ(obs->Errors, 0);
  EXPECT_NE(obs->Messages.find("outside [0,1] (cells 0, 1)"), std::string::npos) << obs->Messages;
  // Coordinates far beyond any int's range of texels: still only a warning.
  outside->GetPointData()->GetTCoords()->SetTuple2(0, 1e30, -1e30);
  outside->Modified();
  obs->Messages.clear();
  baker->Update();
  EXPECT_EQ(obs->Errors, 0);
  EXPECT_NE(obs->Messages.find("outside [0,1] (cells 0, 1)"), std::string::npos) << obs->Messages;

  // Two triangles, apart in space, with the same texture coordinates.
  vtkNew<vtkPolyData> overlap;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkFloatArray> tc;
  tc->SetNumberOfComponents(2);
  for (double x : { -1.0, 0.0 })
  {
    const vtkIdType base = points->GetNumberOfPoints();
    points->InsertNextPoint(x, -1, 0);
    points->InsertNextPoint(x + 1, -1, 0);
    points->InsertNextPoint(x, 0, 0);
    tc->InsertNextTuple2(0, 0);
    tc->InsertNextTuple2(1, 0);
    tc->InsertNextTuple2(0, 1);
    const vtkIdType ids[3] = { base, base + 1, base + 2 };
    polys->InsertNextCell(3, ids);
  }
  overlap->SetPoints(points);
  overlap->SetPolys(polys);
  overlap->GetPointData()->SetTCoords(tc);
  baker->SetInputData(0, overlap);
  obs->Messages.clear();
  obs->Warnings = 0;
  baker->Update();
  EXPECT_EQ(obs->Errors, 0);
  EXPECT_GE(obs->Warnings, 2); // the tangents computed, and the overlap
  // Centres strictly inside the shared triangle (s + t < 1, away from its edges).
  EXPECT_GT(baker->GetNumberOfOverlappingTexels(), 32 * 31 / 2 - 3 * 32);
  EXPECT_LE(baker->GetNumberOfOverlappingTexels(), 32 * 31 / 2);
  EXPECT_NE(obs->Messages.find("overlapping islands), e.g. by cells 0, 1"), std::string::npos)
    << obs->Messages;
}

// Every refused input: an error, empty outputs, the inputs as they were.
TEST(NormalMapBaker, BadInputIsAnErrorWithEmptyOutput)
{
  const Surface s = Rectangle();
  vtkSmartPointer<vtkPolyData> coarse = MakeMesh(s, 4, 4, false);
  vtkSmartPointer<vtkPolyData> detailed = MakeMesh(s, 8, 8, false);
  vtkNew<vtkPolyData> noTCoords;
  noTCoords->DeepCopy(coarse);
  noTCoords->GetPointData()->SetTCoords(nullptr);
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkPolyData> badIds;
  badIds->DeepCopy(detailed);
  badIds->GetPolys()->GetConnectivityArray()->SetComponent(0, 0, 1000);

  struct Case
  {
    std::string Name;
    vtkPolyData* Coarse;
    vtkPolyData* Detailed;
    int Size;
    double Distance;
  };
  const Case cases[] = { { "no texture coordinates", noTCoords, detailed, 16, 0.1 },
    { "empty detailed mesh", coarse, empty, 16, 0.1 },
    { "empty coarse mesh", empty, detailed, 16, 0.1 },
    { "point ids out of range", coarse, badIds, 16, 0.1 },
    { "zero texture size", coarse, detailed, 0, 0.1 },
    { "zero ray distance", coarse, detailed, 16, 0.0 },
    { "NaN ray distance", coarse, detailed, 16, std::nan("") } };
  for (const Case& c : cases)
  {
    const vtkMTimeType before[2] = { c.Coarse->GetMTime(), c.Detailed->GetMTime() };
    const vtkIdType points = c.Coarse->GetNumberOfPoints();
    vtkNew<vtkNormalMapBaker> baker;
    baker->SetInputData(0, c.Coarse);
    baker->SetInputData(1, c.Detailed);
    baker->SetTextureSize(c.Size, c.Size);
    baker->SetMaxRayDistance(c.Distance);
    baker->BakeHeightOn();
    auto obs = Watch(baker);
    baker->Update();
    EXPECT_GE(obs->Errors, 1) << c.Name;
    EXPECT_EQ(baker->GetOutput()->GetNumberOfPoints(), 0) << c.Name;
    EXPECT_EQ(baker->GetHeightOutput()->GetNumberOfPoints(), 0) << c.Name;
    EXPECT_EQ(c.Coarse->GetMTime(), before[0]) << c.Name;
    EXPECT_EQ(c.Detailed->GetMTime(), before[1]) << c.Name;
    EXPECT_EQ(c.Coarse->GetNumberOfPoints(), points) << c.Name;
  }
  // A good run after a bad one fills the outputs again.
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, coarse);
  baker->SetInputData(1, detailed);
  baker->SetTextureSize(0, 8);
  auto obs = Watch(baker);
  baker->Update();
  EXPECT_GE(obs->Errors, 1);
  baker->SetTextureSize(8, 8);
  baker->Update();
  EXPECT_EQ(baker->GetOutput()->GetNumberOfPoints(), 64);
  EXPECT_EQ(baker->GetHeightOutput()->GetNumberOfPoints(), 0); // BakeHeight is off
  std::ostringstream print;
  baker->Print(print);
  EXPECT_NE(print.str().find("Space: Tangent"), std::string::npos);
  EXPECT_NE(print.str().find("NumberOfCoveredTexels: 64"), std::string::npos);
}
} // namespace
