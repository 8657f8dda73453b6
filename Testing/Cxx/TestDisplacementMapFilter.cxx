// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter: sampling against an independent OpenGL-spec reference, seams,
// poles, threads, pieces, Scale 0, stress (huge Scale, 1x1 / 2x2 / 8192x8192 / constant /
// NaN height maps) and bad input.

#include "DisplacementTestSurfaces.h"
#include "RenumberedPointsTestHelpers.h"
#include "TangentFrameTestHelpers.h"

#include "vtkDisplacementMapFilter.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMath.h>
#include <vtkMinimalStandardRandomSequence.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkRTAnalyticSource.h>
#include <vtkSMPTools.h>
#include <vtkSphereSource.h>
#include <vtkTexture.h>
#include <vtkTrivialProducer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnsignedShortArray.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sys/mman.h> // mmap, a guard page after a connectivity array
#include <unistd.h>   // sysconf
#endif

using namespace DisplacementTest;

namespace
{
// Counts error and warning events and keeps the last message.
class Observer : public vtkCommand
{
public:
  static Observer* New() { return new Observer; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)++;
    this->Message += data ? static_cast<const char*>(data) : "";
  }
  int Errors = 0;
  int Warnings = 0;
  std::string Message; // all messages, in order
};

vtkSmartPointer<Observer> Watch(vtkAlgorithm* algorithm)
{
  auto obs = vtkSmartPointer<Observer>::New();
  algorithm->AddObserver(vtkCommand::ErrorEvent, obs);
  algorithm->AddObserver(vtkCommand::WarningEvent, obs);
  algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, obs);
  return obs;
}

vtkSmartPointer<vtkImageData> RandomImage(int W, int H, int seed)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(seed);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* data = static_cast<float*>(image->GetScalarPointer());
  for (int k = 0; k < W * H; ++k)
  {
    data[k] = static_cast<float>(random->GetNextValue());
  }
  return image;
}

// A flat patch z = 0 with one point per (s,t) sample, normal +z, dPdu = +x, dPdv = +y, so
// that the output z is the sampled height and the output normal the height's gradient.
vtkSmartPointer<vtkPolyData> Probes(const std::vector<std::array<double, 2>>& st)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals, tcoords, du, dv;
  normals->SetNumberOfComponents(3);
  tcoords->SetNumberOfComponents(2);
  du->SetName("dPdu");
  du->SetNumberOfComponents(3);
  dv->SetName("dPdv");
  dv->SetNumberOfComponents(3);
  for (const auto& x : st)
  {
    points->InsertNextPoint(x[0], x[1], 0.0);
    normals->InsertNextTuple3(0, 0, 1);
    tcoords->InsertNextTuple2(x[0], x[1]);
    du->InsertNextTuple3(1, 0, 0);
    dv->InsertNextTuple3(0, 1, 0);
  }
  poly->SetPoints(points);
  poly->GetPointData()->SetNormals(normals);
  poly->GetPointData()->SetTCoords(tcoords);
  poly->GetPointData()->AddArray(du);
  poly->GetPointData()->AddArray(dv);
  return poly;
}

// OpenGL 4.5 spec, 8.14.2 and table 8.20, written out again independently of the
// conventions header: the texel a wrap mode reads for integer coordinate i of size n.
int GLWrap(int i, int n, int mode)
{
  if (mode == vtkDisplacementMapFilter::Repeat)
  {
    return ((i % n) + n) % n;
  }
  if (mode == vtkDisplacementMapFilter::MirroredRepeat)
  {
    // mirror(a) = a for a >= 0, -(1 + a) otherwise; (n - 1) - mirror((i mod 2n) - n)
    const int a = (((i % (2 * n)) + 2 * n) % (2 * n)) - n;
    const int mirror = a >= 0 ? a : -(1 + a);
    return (n - 1) - mirror;
  }
  return i < 0 ? 0 : (i >= n ? n - 1 : i);
}

// ClampToBorder's border value (a texture's border colour), in heights.
constexpr double BorderValue = 0.37;

// The value OpenGL reads at integer texel coordinates (i, j): the wrapped texel, or under
// ClampToBorder the border outside the image (8.14.2: the border colour for texels outside).
double GLTexel(const float* img, int W, int H, int mode, int i, int j)
{
  if (mode == vtkDisplacementMapFilter::ClampToBorder)
  {
    return i < 0 || i >= W || j < 0 || j >= H ? BorderValue : img[j * W + i];
  }
  return img[GLWrap(j, H, mode) * W + GLWrap(i, W, mode)];
}

double GLLinear(const float* img, int W, int H, int mode, double s, double t)
{
  const double u = s * W, v = t * H;
  const int i0 = static_cast<int>(std::floor(u - 0.5)), j0 = static_cast<int>(std::floor(v - 0.5));
  const double a = (u - 0.5) - std::floor(u - 0.5), b = (v - 0.5) - std::floor(v - 0.5);
  auto T = [&](int i, int j) { return GLTexel(img, W, H, mode, i, j); };
  return (1 - a) * (1 - b) * T(i0, j0) + a * (1 - b) * T(i0 + 1, j0) + (1 - a) * b * T(i0, j0 + 1) +
    a * b * T(i0 + 1, j0 + 1);
}

// @a count texture coordinates drawn from @a random in [-2.3, 3.1]^2: outside [0,1] too, where
// the wrap modes differ.
std::vector<std::array<double, 2>> RandomCoordinates(
  vtkMinimalStandardRandomSequence* random, int count)
{
  std::vector<std::array<double, 2>> st;
  for (int k = 0; k < count; ++k)
  {
    const double s = random->GetNextRangeValue(-2.3, 3.1);
    const double t = random->GetNextRangeValue(-2.3, 3.1);
    st.push_back({ s, t });
  }
  return st;
}

double GLNearest(const float* img, int W, int H, int mode, double s, double t)
{
  const int i = static_cast<int>(std::floor(s * W)), j = static_cast<int>(std::floor(t * H));
  return GLTexel(img, W, H, mode, i, j);
}

vtkSmartPointer<vtkPolyData> Displace(vtkPolyData* mesh, vtkImageData* image, int mode,
  double scale = 0.1, double mid = 0.5, int interp = vtkDisplacementMapFilter::Linear,
  int wrap = vtkDisplacementMapFilter::Repeat)
{
  vtkNew<vtkDisplacementMapFilter> f;
  f->SetInputData(0, mesh);
  f->SetInputData(1, image);
  f->SetNormalMode(mode);
  f->SetScaleFactor(scale);
  f->SetMidlevel(mid);
  f->SetInterpolation(interp);
  f->SetWrap(wrap);
  f->SetBorderHeight(BorderValue); // read under ClampToBorder only
  f->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(f->GetOutput());
  return out;
}

// Points, normals and (where there are) tangents all finite.
bool AllFinite(vtkPolyData* out)
{
  auto tangents = TangentFrame(out);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3], n[3], t[4] = { 0.0, 0.0, 0.0, 0.0 };
    out->GetPoint(i, p);
    out->GetPointData()->GetNormals()->GetTuple(i, n);
    if (tangents)
    {
      tangents->GetTuple(i, t);
    }
    for (int k = 0; k < 3; ++k)
    {
      if (!std::isfinite(p[k]) || !std::isfinite(n[k]) || !std::isfinite(t[k]))
      {
        return false;
      }
    }
    if (!std::isfinite(t[3]))
    {
      return false;
    }
  }
  return true;
}

bool SameBits(vtkDataArray* a, vtkDataArray* b)
{
  if (a->GetDataType() != b->GetDataType() || a->GetNumberOfValues() != b->GetNumberOfValues())
  {
    return false;
  }
  return std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0),
           a->GetNumberOfValues() * a->GetDataTypeSize()) == 0;
}

const int AllModes[4] = { vtkDisplacementMapFilter::Input, vtkDisplacementMapFilter::Approximate,
  vtkDisplacementMapFilter::Exact, vtkDisplacementMapFilter::Mesh };

// Adds spherical texture coordinates to vtkSphereSource's output, piece by piece.
class SphereTCoords : public vtkPolyDataAlgorithm
{
public:
  static SphereTCoords* New();
  vtkTypeMacro(SphereTCoords, vtkPolyDataAlgorithm);

protected:
  int RequestData(vtkInformation*, vtkInformationVector** in, vtkInformationVector* out) override
  {
    vtkPolyData* input = vtkPolyData::GetData(in[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(out, 0);
    output->ShallowCopy(input);
    vtkNew<vtkDoubleArray> tc;
    tc->SetNumberOfComponents(2);
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      double p[3];
      input->GetPoint(i, p);
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      tc->InsertNextTuple2(std::atan2(p[1], p[0]) / (2 * Pi) + 0.5, std::acos(p[2] / r) / Pi);
    }
    output->GetPointData()->SetTCoords(tc);
    return 1;
  }
};
vtkStandardNewMacro(SphereTCoords);
} // namespace

// The wrap modes are vtkTexture's, value for value, so that a texture's GetWrap() can be passed
// to SetWrap().
static_assert(static_cast<int>(vtkDisplacementMapFilter::ClampToEdge) ==
      static_cast<int>(vtkTexture::ClampToEdge) &&
    static_cast<int>(vtkDisplacementMapFilter::Repeat) == static_cast<int>(vtkTexture::Repeat) &&
    static_cast<int>(vtkDisplacementMapFilter::MirroredRepeat) ==
      static_cast<int>(vtkTexture::MirroredRepeat) &&
    static_cast<int>(vtkDisplacementMapFilter::ClampToBorder) ==
      static_cast<int>(vtkTexture::ClampToBorder),
  "vtkDisplacementMapFilter's Wrap values must be vtkTexture's");

// The Linear and Nearest samples equal an independent transcription of OpenGL's sampling
// rules for every wrap mode, inside and outside [0,1] (so the CPU displacement matches
// what a vtkTexture shows).
TEST(DisplacementMapFilter, SamplingMatchesOpenGLRules)
{
  const int W = 7, H = 5;
  auto image = RandomImage(W, H, 3);
  const float* img = static_cast<float*>(image->GetScalarPointer());
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  std::vector<std::array<double, 2>> st = RandomCoordinates(random, 400);
  st.push_back({ 0.0, 0.0 });
  st.push_back({ 1.0, 1.0 });
  st.push_back({ 0.5 / W, 0.5 / H });
  auto probes = Probes(st);
  for (int wrap : { vtkDisplacementMapFilter::ClampToEdge, vtkDisplacementMapFilter::Repeat,
         vtkDisplacementMapFilter::MirroredRepeat, vtkDisplacementMapFilter::ClampToBorder })
  {
    for (int interp : { vtkDisplacementMapFilter::Nearest, vtkDisplacementMapFilter::Linear })
    {
      auto out = Displace(probes, image, vtkDisplacementMapFilter::Input, 1.0, 0.0, interp, wrap);
      for (size_t k = 0; k < st.size(); ++k)
      {
        const double expected = interp == vtkDisplacementMapFilter::Linear
          ? GLLinear(img, W, H, wrap, st[k][0], st[k][1])
          : GLNearest(img, W, H, wrap, st[k][0], st[k][1]);
        double p[3];
        out->GetPoint(static_cast<vtkIdType>(k), p);
        ASSERT_NEAR(p[2], expected, 1e-12) << "wrap " << wrap << " interp " << interp << " at ("
                                           << st[k][0] << ", " << st[k][1] << ")";
      }
    }
  }
}

// Cubic is Catmull-Rom: it reproduces a quadratic exactly (away from clamped edges), so
// height and slope, hence the normal of z = Scale h, are exact; Linear is exact for a
// bilinear ramp.
TEST(DisplacementMapFilter, CubicAndLinearReproducePolynomials)
{
  const int W = 16, H = 12;
  auto quad = [](double s, double t)
  { return 0.2 + 0.3 * s - 0.1 * t + 0.4 * s * s + 0.25 * s * t - 0.3 * t * t; };
  auto grad = [](double s, double t) {
    return std::array<double, 2>{ 0.3 + 0.8 * s + 0.25 * t, -0.1 + 0.25 * s - 0.6 * t };
  };
  vtkNew<vtkImageData> image;
  image->SetDimensions(W, H, 1);
  image->AllocateScalars(VTK_DOUBLE, 1);
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      image->SetScalarComponentFromDouble(i, j, 0, 0, quad((i + 0.5) / W, (j + 0.5) / H));
    }
  }
  std::vector<std::array<double, 2>> st;
  for (int k = 0; k < 50; ++k)
  {
    st.push_back(
      { 0.2 + 0.6 * std::fmod(k * 0.618034, 1.0), 0.2 + 0.6 * std::fmod(k * 0.41421, 1.0) });
  }
  auto probes = Probes(st);
  const double scale = 0.7;
  for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact })
  {
    auto out = Displace(probes, image, mode, scale, 0.0, vtkDisplacementMapFilter::Cubic,
      vtkDisplacementMapFilter::ClampToEdge);
    for (size_t k = 0; k < st.size(); ++k)
    {
      double p[3], n[3];
      out->GetPoint(static_cast<vtkIdType>(k), p);
      out->GetPointData()->GetNormals()->GetTuple(static_cast<vtkIdType>(k), n);
      EXPECT_NEAR(p[2], scale * quad(st[k][0], st[k][1]), 1e-12);
      const auto g = grad(st[k][0], st[k][1]);
      const Vec truth = Unit({ -scale * g[0], -scale * g[1], 1.0 });
      EXPECT_LT(AngleDeg({ n[0], n[1], n[2] }, truth), 1e-9);
    }
  }
}

// Texture seams and poles: coincident points move identically and (same input normal)
// get identical normals, in every mode, even where the height map itself disagrees across
// the seam (ClampToEdge, random texels). Without MergeSeams they would not.
TEST(DisplacementMapFilter, SeamsAndPolesAreWatertight)
{
  const Surface s = Sphere(0.2);
  auto mesh = MakeMesh(s, 24, 16, false);
  auto image = RandomImage(32, 16, 5);
  const int U = 24, V = 16;
  // Coincident points move by one displacement: outputs as far apart as the inputs were
  // (the closed form puts seam and pole duplicates up to 1e-16 apart), exactly equal when
  // the inputs were; and exactly one normal (None keeps the input normals).
  auto check = [&](vtkPolyData* out, bool normalsToo, bool expectIdentical)
  {
    int differing = 0;
    for (int j = 0; j <= V; ++j)
    {
      const vtkIdType a = static_cast<vtkIdType>(j) * (U + 1), b = a + U; // u = 0 and u = 1
      std::vector<vtkIdType> group = { b };
      if (j == 0 || j == V)
      {
        for (int i = 1; i < U; ++i)
        {
          group.push_back(a + i); // the whole pole row
        }
      }
      double pa[3], na[3], ia[3];
      out->GetPoint(a, pa);
      mesh->GetPoint(a, ia);
      out->GetPointData()->GetNormals()->GetTuple(a, na);
      for (vtkIdType g : group)
      {
        double pb[3], nb[3], ib[3];
        out->GetPoint(g, pb);
        mesh->GetPoint(g, ib);
        out->GetPointData()->GetNormals()->GetTuple(g, nb);
        const double din = std::sqrt(vtkMath::Distance2BetweenPoints(ia, ib));
        const double dout = std::sqrt(vtkMath::Distance2BetweenPoints(pa, pb));
        // Exactly equal values (+0 and -0 are the same place).
        const bool samePoint = din == 0.0 ? dout == 0.0 : dout <= din + 1e-15;
        const bool sameNormal = !normalsToo || (na[0] == nb[0] && na[1] == nb[1] && na[2] == nb[2]);
        differing += samePoint && sameNormal ? 0 : 1;
        if (expectIdentical)
        {
          EXPECT_TRUE(samePoint) << "row " << j << " point " << g << ": " << dout << " vs " << din;
          EXPECT_TRUE(sameNormal) << "row " << j << " point " << g;
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_TRUE(std::isfinite(na[k]));
      }
    }
    return differing;
  };
  // Float arrays too, whose outputs are rounded to float.
  for (bool floatPoints : { false, true })
  {
    mesh = MakeMesh(s, 24, 16, false, floatPoints);
    for (int wrap : { vtkDisplacementMapFilter::Repeat, vtkDisplacementMapFilter::ClampToEdge })
    {
      for (int mode : AllModes)
      {
        SCOPED_TRACE(std::string("mode ") + std::to_string(mode) + " wrap " + std::to_string(wrap) +
          (floatPoints ? " float" : " double"));
        auto out = Displace(mesh, image, mode, 0.2, 0.5, vtkDisplacementMapFilter::Cubic, wrap);
        check(out, mode != vtkDisplacementMapFilter::Input, true);
        EXPECT_TRUE(AllFinite(out));
      }
    }
  }
  // The same with MergeSeams off shows cracks: the test can fail.
  vtkNew<vtkDisplacementMapFilter> f;
  f->SetInputData(0, mesh);
  f->SetInputData(1, image);
  f->SetWrapToClampToEdge();
  f->SetScaleFactor(0.2);
  f->MergeSeamsOff();
  f->Update();
  EXPECT_GT(check(f->GetOutput(), true, false), 0);
  // Pole normals are finite and point along the axis (the height is radial there).
  auto out = Displace(MakeMesh(s, 24, 16, false), MakeHeightImage(s.Height, 256, 128),
    vtkDisplacementMapFilter::Exact, 0.2, 0.5, vtkDisplacementMapFilter::Cubic);
  double n[3];
  out->GetPointData()->GetNormals()->GetTuple(0, n);
  EXPECT_LT(AngleDeg({ n[0], n[1], n[2] }, { 0, -1, 0 }), 1.0);
}

// A seam point where two boundary fans meet (a bowtie: two triangles touching only at it) must be
// found by the seam sweep whatever its neighbours' ids. The sweep sums, per point, a hash of each
// corner's next point minus one of its previous point; here those sums are h(117) - h(422) +
// h(1199) - h(894), and 117 + 1199 = 422 + 894, so a hash that is nearly additive (one multiply
// and an xor-shift: it cancels for these ids) misses the point: it then moves by its own height,
// not its duplicate's, and the surface cracks.
TEST(DisplacementMapFilter, BowtieSeamPointMerges)
{
  const vtkIdType p = 1200, q = 1201;
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_DOUBLE);
  points->SetNumberOfPoints(q + 1);
  vtkNew<vtkDoubleArray> normals, tcoords;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(q + 1);
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(q + 1);
  for (vtkIdType i = 0; i <= q; ++i)
  {
    // Points no polygon uses, apart from one another and from the triangles.
    points->SetPoint(i, 3.0 + static_cast<double>(i), 5.0, 0.0);
    normals->SetTuple3(i, 0.0, 0.0, 1.0);
    tcoords->SetTuple2(i, 0.5, 0.5);
  }
  // p and q at one place on either side of a texture seam (s = 0.25 and 0.75).
  points->SetPoint(p, 0.0, 0.0, 0.0);
  points->SetPoint(q, 0.0, 0.0, 0.0);
  tcoords->SetTuple2(p, 0.25, 0.5);
  tcoords->SetTuple2(q, 0.75, 0.5);
  points->SetPoint(117, 1.0, 0.0, 0.0);
  points->SetPoint(422, 0.0, 1.0, 0.0);
  points->SetPoint(1199, -1.0, 0.0, 0.0);
  points->SetPoint(894, 0.0, -1.0, 0.0);
  points->SetPoint(0, 1.0, -1.0, 0.0);
  points->SetPoint(1, 1.0, -0.5, 0.0);
  vtkNew<vtkCellArray> tris;
  for (const std::array<vtkIdType, 3>& t : { std::array<vtkIdType, 3>{ p, 117, 422 },
         std::array<vtkIdType, 3>{ p, 1199, 894 }, std::array<vtkIdType, 3>{ q, 0, 1 } })
  {
    tris->InsertNextCell(3, t.data());
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(tris);
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->SetTCoords(tcoords);
  // Heights growing with s: p's and q's own differ.
  auto image = MakeHeightImage([](double s, double) { return s; }, 8, 4);
  for (int mode : AllModes)
  {
    for (bool merge : { true, false })
    {
      SCOPED_TRACE(std::string("mode ") + std::to_string(mode) + (merge ? " merged" : " apart"));
      vtkNew<vtkDisplacementMapFilter> f;
      f->SetInputData(0, mesh);
      f->SetInputData(1, image);
      f->SetNormalMode(mode);
      f->SetMergeSeams(merge);
      auto obs = Watch(f);
      f->Update();
      ASSERT_EQ(obs->Errors, 0) << obs->Message;
      double xp[3], xq[3];
      f->GetOutput()->GetPoint(p, xp);
      f->GetOutput()->GetPoint(q, xq);
      // Merged, both move by the mean of their heights (0.25 and 0.75: the image is linear in s).
      if (merge)
      {
        EXPECT_EQ(xp[2], xq[2]);
        EXPECT_NEAR(xp[2], 0.5, 1e-12);
      }
      else
      {
        EXPECT_NEAR(xq[2] - xp[2], 0.5, 1e-12);
      }
    }
  }
}

// Results do not depend on the number of threads, bit for bit.
TEST(DisplacementMapFilter, SameResultAtAnyThreadCount)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  // Double arrays and float ones: a mesh big enough to be split between threads, with points
  // that need a fallback (a zero and a NaN normal, a tangent along the normal) near the start
  // and the middle.
  for (bool floatPoints : { false, true })
  {
    auto mesh = MakeMesh(s, 256, 128, false, floatPoints);
    vtkDataArray* normals = mesh->GetPointData()->GetNormals();
    auto tangents = TangentFrame(mesh);
    const vtkIdType middle = mesh->GetNumberOfPoints() / 2;
    normals->SetTuple3(5, 0.0, 0.0, 0.0);
    normals->SetTuple3(middle, std::nan(""), 0.0, 1.0);
    double n[3];
    normals->GetTuple(middle + 1, n);
    tangents->SetTuple4(middle + 1, n[0], n[1], n[2], 1.0);
    for (int mode : AllModes)
    {
      vtkSMPTools::Initialize(1);
      auto one = Displace(mesh, image, mode, 0.1, 0.5, vtkDisplacementMapFilter::Cubic);
      vtkSMPTools::Initialize(2);
      ASSERT_EQ(vtkSMPTools::GetEstimatedNumberOfThreads(), 2);
      auto two = Displace(mesh, image, mode, 0.1, 0.5, vtkDisplacementMapFilter::Cubic);
      EXPECT_TRUE(SameBits(one->GetPoints()->GetData(), two->GetPoints()->GetData()))
        << mode << " " << floatPoints;
      EXPECT_TRUE(SameBits(one->GetPointData()->GetNormals(), two->GetPointData()->GetNormals()))
        << mode << " " << floatPoints;
      EXPECT_TRUE(SameBits(one->GetPointData()->GetTangents(), two->GetPointData()->GetTangents()))
        << mode << " " << floatPoints;
      // (None passes the NaN normal through.)
      EXPECT_TRUE(mode == vtkDisplacementMapFilter::Input || AllFinite(one))
        << mode << " " << floatPoints;
    }
  }
  // Back to every core (VTK 9.1 keeps 1 thread on Initialize(0) after Initialize(1)).
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
}

// Re-execution: whatever changes after a first execution (Scale, points, texture coordinates,
// normals, connectivity, in place or by new objects), the output must be, to the bit, that of a
// fresh filter; and each change must matter (the output moves), so that stale data would show.
TEST(DisplacementMapFilter, ReExecutionMatchesFreshFilter)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  const int U = 48, V = 24;
  auto same = [](vtkPolyData* a, vtkPolyData* b)
  {
    return SameBits(a->GetPoints()->GetData(), b->GetPoints()->GetData()) &&
      SameBits(a->GetPointData()->GetNormals(), b->GetPointData()->GetNormals()) &&
      SameBits(a->GetPointData()->GetTangents(), b->GetPointData()->GetTangents());
  };
  for (int mode : AllModes)
  {
    for (bool releaseData : { false, true })
    {
      auto mesh = MakeMesh(s, U, V, false, true);
      vtkNew<vtkDisplacementMapFilter> f;
      f->SetInputData(0, mesh);
      f->SetInputData(1, image);
      f->SetNormalMode(mode);
      f->SetMidlevel(0.5);
      f->SetReleaseDataFlag(releaseData);
      auto check = [&](double scale, const char* what)
      {
        auto before = vtkSmartPointer<vtkPolyData>::New();
        if (f->GetOutput()->GetPoints())
        {
          before->DeepCopy(f->GetOutput());
        }
        f->SetScaleFactor(scale);
        f->Update();
        auto fresh = Displace(mesh, image, mode, scale, 0.5);
        EXPECT_TRUE(same(f->GetOutput(), fresh)) << what << ", mode " << mode;
        if (before->GetPoints())
        {
          EXPECT_FALSE(same(before, fresh)) << what << " changed nothing, mode " << mode;
        }
      };
      check(0.1, "first execution");
      check(0.2, "Scale");

      // Points moved in place: one seam duplicate pulled off its twin (the groups change).
      vtkDataArray* pts = mesh->GetPoints()->GetData();
      pts->SetComponent(5 * (U + 1) + U, 2, pts->GetComponent(5 * (U + 1) + U, 2) + 0.05);
      pts->Modified();
      check(0.2, "points in place");

      // (Stretched, not only shifted: Exact's fits are derivatives in texture space.)
      vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
      for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
      {
        tc->SetComponent(i, 0, 1.01 * tc->GetComponent(i, 0) + 0.01);
      }
      tc->Modified();
      check(0.2, "texture coordinates in place");

      vtkDataArray* nrm = mesh->GetPointData()->GetNormals();
      for (vtkIdType i = 0; i < nrm->GetNumberOfTuples(); i += 7)
      {
        nrm->SetComponent(i, 1, nrm->GetComponent(i, 1) + 0.01);
      }
      nrm->Modified();
      check(0.2, "normals in place");

      // Normals reversed in place: every polygon's orientation (Mesh) flips with them.
      for (vtkIdType i = 0; i < nrm->GetNumberOfTuples(); ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          nrm->SetComponent(i, k, -nrm->GetComponent(i, k));
        }
      }
      nrm->Modified();
      check(0.2, "normals reversed in place");

      // Connectivity changed in place: the seam closed (polygons use the first column
      // instead of its duplicates), so the links and the boundary change.
      vtkDataArray* conn = mesh->GetPolys()->GetConnectivityArray();
      for (vtkIdType k = 0; k < conn->GetNumberOfValues(); ++k)
      {
        const vtkIdType id = static_cast<vtkIdType>(conn->GetComponent(k, 0));
        if (id % (U + 1) == U)
        {
          conn->SetComponent(k, 0, static_cast<double>(id - U));
        }
      }
      // (vtkCellArray's MTime does not include its arrays': the pipeline needs both.)
      conn->Modified();
      mesh->GetPolys()->Modified();
      check(0.2, "connectivity in place");

      // New objects in the same input: points and polygons of another mesh.
      auto other = MakeMesh(s, U, V, false, true);
      vtkNew<vtkPoints> newPoints;
      newPoints->DeepCopy(other->GetPoints());
      mesh->SetPoints(newPoints);
      vtkNew<vtkCellArray> newPolys;
      newPolys->DeepCopy(other->GetPolys());
      mesh->SetPolys(newPolys);
      check(0.3, "new points and polygons");
    }
  }
}

// Outputs equal to the bit: points, normals and tangents (when there are any).
bool SameOutput(vtkPolyData* a, vtkPolyData* b)
{
  auto ta = TangentFrame(a);
  auto tb = TangentFrame(b);
  return SameBits(a->GetPoints()->GetData(), b->GetPoints()->GetData()) &&
    SameBits(a->GetPointData()->GetNormals(), b->GetPointData()->GetNormals()) &&
    ((!ta && !tb) || (ta && tb && SameBits(ta, tb)));
}

// Runs @a change on the input of a filter that has executed, re-executes, and expects the output
// of a fresh filter (and a different one than before, so that stale data would show).
template <typename Change>
void ExpectFreshAfter(vtkDisplacementMapFilter* f, const char* what, Change&& change)
{
  auto before = vtkSmartPointer<vtkPolyData>::New();
  f->Update();
  before->DeepCopy(f->GetOutput());
  change();
  f->Update();
  vtkNew<vtkDisplacementMapFilter> fresh;
  fresh->SetInputData(0, f->GetInputDataObject(0, 0));
  fresh->SetInputData(1, f->GetInputDataObject(1, 0));
  fresh->SetNormalMode(f->GetNormalMode());
  fresh->SetScaleFactor(f->GetScaleFactor());
  fresh->SetMidlevel(f->GetMidlevel());
  fresh->SetHeightComponent(f->GetHeightComponent());
  fresh->SetWrap(f->GetWrap());
  fresh->SetInterpolation(f->GetInterpolation());
  fresh->SetMergeSeams(f->GetMergeSeams());
  fresh->SetSeamTolerance(f->GetSeamTolerance());
  fresh->Update();
  const int mode = f->GetNormalMode();
  EXPECT_TRUE(SameOutput(f->GetOutput(), fresh->GetOutput())) << what << ", mode " << mode;
  EXPECT_FALSE(SameOutput(before, fresh->GetOutput())) << what << " changed nothing, mode " << mode;
}

// VTK's contract for data changed in place is that some object the pipeline sees is Modified():
// the polydata or its point data will do (vtkPoints::SetPoint and vtkDataArray::SetComponent
// leave the MTimes alone). The output must follow such a change as the pipeline does.
TEST(DisplacementMapFilter, ReExecutionAfterContainerModified)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  const int U = 48, V = 24;
  for (int mode : AllModes)
  {
    auto mesh = MakeMesh(s, U, V, false, true);
    vtkNew<vtkDisplacementMapFilter> f;
    f->SetInputData(0, mesh);
    f->SetInputData(1, image);
    f->SetNormalMode(mode);
    f->SetMidlevel(0.5);
    f->SetScaleFactor(0.2);
    ExpectFreshAfter(f, "points in place, then the polydata Modified()",
      [&]()
      {
        // One seam duplicate pulled off its twin, and the points near it moved.
        vtkPoints* pts = mesh->GetPoints();
        for (vtkIdType i = 4 * (U + 1) + 1; i < 6 * (U + 1); ++i)
        {
          double p[3];
          pts->GetPoint(i, p);
          p[2] += 0.05;
          pts->SetPoint(i, p);
        }
        mesh->Modified();
      });
    ExpectFreshAfter(f, "normals in place, then the point data Modified()",
      [&]()
      {
        vtkDataArray* nrm = mesh->GetPointData()->GetNormals();
        for (vtkIdType i = 0; i < nrm->GetNumberOfTuples(); ++i)
        {
          for (int k = 0; k < 3; ++k)
          {
            nrm->SetComponent(i, k, -nrm->GetComponent(i, k));
          }
        }
        mesh->GetPointData()->Modified();
      });
    ExpectFreshAfter(f, "texture coordinates in place, then the polydata Modified()",
      [&]()
      {
        vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
        for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
        {
          tc->SetComponent(i, 0, 1.01 * tc->GetComponent(i, 0) + 0.01);
        }
        mesh->Modified();
      });
  }
}

// The derivative scale (texture coordinates against dPdu/dPdv) must follow dPdu, dPdv and the
// texture coordinates changed in place. Each change moves the scale
// away from 1 and so turns the analytic normals (the factors are not powers of 2, whose change the
// estimate would undo to the bit). With the scale's freshness check removed, all 12 cases fail.
TEST(DisplacementMapFilter, ReExecutionAfterDerivativesModified)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  const int U = 48, V = 24;
  for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact })
  {
    for (bool useFloat : { false, true })
    {
      auto mesh = MakeMesh(s, U, V, true, useFloat);
      vtkNew<vtkDisplacementMapFilter> f;
      f->SetInputData(0, mesh);
      f->SetInputData(1, image);
      f->SetNormalMode(mode);
      f->SetMidlevel(0.5);
      f->SetScaleFactor(0.2);
      vtkPointData* pd = mesh->GetPointData();
      auto scaleInPlace = [](vtkDataArray* a, double factor)
      {
        for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
        {
          a->SetComponent(i / a->GetNumberOfComponents(), i % a->GetNumberOfComponents(),
            factor *
              a->GetComponent(i / a->GetNumberOfComponents(), i % a->GetNumberOfComponents()));
        }
      };
      ExpectFreshAfter(f, "dPdu scaled in place, then the array Modified()",
        [&]()
        {
          scaleInPlace(pd->GetArray("dPdu"), 1.3);
          pd->GetArray("dPdu")->Modified();
        });
      ExpectFreshAfter(f, "dPdv scaled in place, then the point data Modified()",
        [&]()
        {
          scaleInPlace(pd->GetArray("dPdv"), 0.7);
          pd->Modified();
        });
      ExpectFreshAfter(f, "texture coordinates stretched in place, then the array Modified()",
        [&]()
        {
          vtkDataArray* tc = pd->GetTCoords();
          for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
          {
            tc->SetComponent(i, 1, 1.5 * tc->GetComponent(i, 1));
          }
          tc->Modified();
        });
    }
  }
}

// Re-execution against every other way the input can change between executions: a new
// input object (which may reuse a freed one's address), a copy of another mesh into the same
// object, another active array, dPdu/dPdv appearing and going, another precision, another thread
// count, another piece.
TEST(DisplacementMapFilter, ReExecutionAfterInputReplaced)
{
  const Surface torus = Torus(), sphere = Sphere();
  auto image = MakeHeightImage(torus.Height, 128, 64);
  const int U = 48, V = 24;
  for (int mode : AllModes)
  {
    vtkNew<vtkDisplacementMapFilter> f;
    f->SetInputData(1, image);
    f->SetNormalMode(mode);
    f->SetMidlevel(0.5);
    f->SetScaleFactor(0.2);
    auto mesh = MakeMesh(torus, U, V, false);
    f->SetInputData(0, mesh);
    // The first input and everything that refers to it freed before the next one is made, so
    // that its objects may come back at the same addresses.
    ExpectFreshAfter(f, "a new input object",
      [&]()
      {
        f->SetInputData(0, nullptr);
        f->GetOutput()->Initialize();
        mesh = nullptr;
        mesh = MakeMesh(sphere, U, V, false);
        f->SetInputData(0, mesh);
      });
    ExpectFreshAfter(f, "another mesh deep-copied into the input",
      [&]() { mesh->DeepCopy(MakeMesh(torus, U, V, false)); });
    ExpectFreshAfter(f, "another mesh shallow-copied into the input",
      [&]() { mesh->ShallowCopy(MakeMesh(sphere, U, V, false)); });
    ExpectFreshAfter(f, "other texture coordinates made active by name",
      [&]()
      {
        vtkNew<vtkDoubleArray> tc;
        tc->DeepCopy(mesh->GetPointData()->GetTCoords());
        tc->SetName("Stretched");
        for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
        {
          tc->SetComponent(i, 1, 0.9 * tc->GetComponent(i, 1) + 0.02);
        }
        mesh->GetPointData()->AddArray(tc);
        mesh->GetPointData()->SetActiveTCoords("Stretched");
      });
    ExpectFreshAfter(f, "other normals made active by name",
      [&]()
      {
        vtkNew<vtkDoubleArray> nrm;
        nrm->DeepCopy(mesh->GetPointData()->GetNormals());
        nrm->SetName("Reversed");
        for (vtkIdType i = 0; i < nrm->GetNumberOfValues(); ++i)
        {
          nrm->SetValue(i, -nrm->GetValue(i));
        }
        mesh->GetPointData()->AddArray(nrm);
        mesh->GetPointData()->SetActiveNormals("Reversed");
      });
    // dPdu/dPdv are read in the analytic modes only, tangents in all but None.
    const bool analytic =
      mode == vtkDisplacementMapFilter::Approximate || mode == vtkDisplacementMapFilter::Exact;
    auto withDerivatives = MakeMesh(sphere, U, V, true);
    if (analytic)
    {
      // (The analytic dPdu/dPdv differ from the fitted P_s, P_t, so the output moves.)
      ExpectFreshAfter(f, "dPdu and dPdv added",
        [&]()
        {
          mesh->GetPointData()->AddArray(withDerivatives->GetPointData()->GetArray("dPdu"));
          mesh->GetPointData()->AddArray(withDerivatives->GetPointData()->GetArray("dPdv"));
        });
      ExpectFreshAfter(f, "dPdu and dPdv removed",
        [&]()
        {
          mesh->GetPointData()->RemoveArray("dPdu");
          mesh->GetPointData()->RemoveArray("dPdv");
        });
    }
    ExpectFreshAfter(f, "a float mesh",
      [&]()
      {
        mesh = MakeMesh(torus, U, V, false, true);
        f->SetInputData(0, mesh);
      });
    if (mode != vtkDisplacementMapFilter::Input)
    {
      ExpectFreshAfter(f, "float input made double by a double tangent array",
        [&]()
        {
          vtkNew<vtkDoubleArray> tangents;
          tangents->DeepCopy(mesh->GetPointData()->GetTangents());
          mesh->GetPointData()->SetTangents(tangents);
        });
      // Back to float.
      ExpectFreshAfter(f, "double input made float again by a float tangent array",
        [&]()
        {
          vtkNew<vtkFloatArray> tangents;
          tangents->DeepCopy(mesh->GetPointData()->GetTangents());
          mesh->GetPointData()->SetTangents(tangents);
        });
    }
    ExpectFreshAfter(f, "another thread count",
      [&]()
      {
        vtkSMPTools::Initialize(1);
        f->Update();
        vtkSMPTools::Initialize(2);
        f->SetScaleFactor(0.25);
      });
    vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
  }
}

// Re-execution against every setting changed between executions.
TEST(DisplacementMapFilter, ReExecutionAfterSettingsChange)
{
  const Surface s = Torus();
  const int U = 48, V = 24;
  // Two channels: the torus' heights, and another smooth field.
  auto first = MakeHeightImage(s.Height, 128, 64);
  auto second = MakeHeightImage([](double u, double v)
    { return 0.5 + 0.4 * std::sin(6 * Pi * u) * std::cos(2 * Pi * v); },
    128, 64);
  vtkNew<vtkImageData> image;
  image->SetDimensions(128, 64, 1);
  image->AllocateScalars(VTK_DOUBLE, 2);
  for (vtkIdType k = 0; k < 128 * 64; ++k)
  {
    image->GetPointData()->GetScalars()->SetComponent(
      k, 0, first->GetPointData()->GetScalars()->GetComponent(k, 0));
    image->GetPointData()->GetScalars()->SetComponent(
      k, 1, second->GetPointData()->GetScalars()->GetComponent(k, 0));
  }
  auto mesh = MakeMesh(s, U, V, false);
  // One seam duplicate 1e-4 off its twin: merged or not by SeamTolerance.
  vtkDataArray* pts = mesh->GetPoints()->GetData();
  pts->SetComponent(5 * (U + 1) + U, 2, pts->GetComponent(5 * (U + 1) + U, 2) + 1e-4);
  for (int mode : AllModes)
  {
    vtkNew<vtkDisplacementMapFilter> f;
    f->SetInputData(0, mesh);
    f->SetInputData(1, image);
    f->SetNormalMode(mode);
    f->SetMidlevel(0.5);
    f->SetScaleFactor(0.2);
    for (int other : AllModes)
    {
      if (other != mode)
      {
        ExpectFreshAfter(f, "NormalMode", [&]() { f->SetNormalMode(other); });
      }
    }
    ExpectFreshAfter(f, "NormalMode back", [&]() { f->SetNormalMode(mode); });
    ExpectFreshAfter(f, "Interpolation", [&]() { f->SetInterpolationToCubic(); });
    ExpectFreshAfter(f, "Wrap", [&]() { f->SetWrapToClampToEdge(); });
    ExpectFreshAfter(f, "HeightComponent", [&]() { f->SetHeightComponent(1); });
    ExpectFreshAfter(f, "SeamTolerance", [&]() { f->SetSeamTolerance(1e-3); });
    ExpectFreshAfter(f, "MergeSeams off", [&]() { f->MergeSeamsOff(); });
    ExpectFreshAfter(f, "MergeSeams on", [&]() { f->MergeSeamsOn(); });
    ExpectFreshAfter(f, "SeamTolerance back", [&]() { f->SetSeamTolerance(1e-6); });
  }
}

// Pieces: each piece is a new input; nothing may leak from one piece to the next.
TEST(DisplacementMapFilter, ReExecutionAfterPieceChange)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(40);
  source->SetPhiResolution(20);
  vtkNew<SphereTCoords> tcoords;
  tcoords->SetInputConnection(source->GetOutputPort());
  auto image = MakeHeightImage(Sphere().Height, 64, 32);
  for (int mode : AllModes)
  {
    vtkNew<vtkDisplacementMapFilter> f;
    f->SetInputConnection(0, tcoords->GetOutputPort());
    f->SetInputData(1, image);
    f->SetNormalMode(mode);
    f->SetScaleFactor(0.05);
    f->SetMidlevel(0.5);
    f->UpdatePiece(0, 2, 0);
    auto first = vtkSmartPointer<vtkPolyData>::New();
    first->DeepCopy(f->GetOutput());
    f->UpdatePiece(1, 2, 0);
    auto piece = vtkSmartPointer<vtkPolyData>::New();
    piece->DeepCopy(tcoords->GetOutput());
    auto fresh = Displace(piece, image, mode, 0.05, 0.5);
    ASSERT_EQ(first->GetNumberOfPoints(), piece->GetNumberOfPoints());
    EXPECT_TRUE(SameOutput(f->GetOutput(), fresh)) << "mode " << mode;
    EXPECT_FALSE(SameOutput(first, fresh)) << "mode " << mode;
  }
}

// Scale 0 changes nothing, to the bit (points in every mode; normals and tangents in the
// modes that derive them from the height map).
TEST(DisplacementMapFilter, ScaleZeroIsIdentity)
{
  const Surface s = Sphere();
  for (bool floatPoints : { false, true })
  {
    auto mesh = MakeMesh(s, 32, 16, true, floatPoints);
    auto image = MakeHeightImage(s.Height, 64, 32);
    for (int mode : AllModes)
    {
      auto out = Displace(mesh, image, mode, 0.0, 0.5, vtkDisplacementMapFilter::Cubic);
      EXPECT_TRUE(SameBits(mesh->GetPoints()->GetData(), out->GetPoints()->GetData())) << mode;
      if (mode != vtkDisplacementMapFilter::Mesh)
      {
        EXPECT_TRUE(SameBits(mesh->GetPointData()->GetNormals(), out->GetPointData()->GetNormals()))
          << mode;
        EXPECT_TRUE(
          SameBits(mesh->GetPointData()->GetTangents(), out->GetPointData()->GetTangents()))
          << mode;
      }
      EXPECT_TRUE(SameBits(mesh->GetPointData()->GetTCoords(), out->GetPointData()->GetTCoords()));
    }
  }
}

// dPdu/dPdv with respect to (u,v) while the texture coordinates are s = 0.25 + 3u,
// t = 2v (a parametric source's TextureRepeat/TextureOffset): the filter finds the scale,
// so the normals equal those from derivatives it fits itself (exact on a flat patch).
TEST(DisplacementMapFilter, DerivativesWithTextureRepeat)
{
  const Surface s = Rectangle();
  auto mesh = MakeMesh(s, 40, 30, true);
  vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
  for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
  {
    tc->SetTuple2(i, 0.25 + 3.0 * tc->GetComponent(i, 0), 2.0 * tc->GetComponent(i, 1));
  }
  auto fitted = vtkSmartPointer<vtkPolyData>::New();
  fitted->DeepCopy(mesh);
  fitted->GetPointData()->RemoveArray("dPdu");
  fitted->GetPointData()->RemoveArray("dPdv");
  auto image = MakeHeightImage(s.Height, 128, 128);
  for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact })
  {
    auto a = Displace(mesh, image, mode, 0.2, 0.5, vtkDisplacementMapFilter::Cubic);
    auto b = Displace(fitted, image, mode, 0.2, 0.5, vtkDisplacementMapFilter::Cubic);
    double worst = 0.0;
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    {
      Vec na, nb;
      a->GetPointData()->GetNormals()->GetTuple(i, na.data());
      b->GetPointData()->GetNormals()->GetTuple(i, nb.data());
      worst = std::max(worst, AngleDeg(na, nb));
    }
    EXPECT_LT(worst, 1e-6) << mode;
  }
}

// Tangents come out orthogonal to the new normals, unit length, with the input's w.
TEST(DisplacementMapFilter, TangentsFollowNormals)
{
  const Surface s = Torus(0.15);
  auto mesh = MakeMesh(s, 48, 24, false);
  auto out =
    Displace(mesh, MakeHeightImage(s.Height, 128, 64), vtkDisplacementMapFilter::Exact, 0.15);
  auto t = TangentFrame(out);
  auto tin = TangentFrame(mesh);
  ASSERT_EQ(t->GetNumberOfComponents(), 4);
  double worst = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double n[3], tg[4], t0[4];
    out->GetPointData()->GetNormals()->GetTuple(i, n);
    t->GetTuple(i, tg);
    tin->GetTuple(i, t0);
    worst = std::max(worst, std::abs(n[0] * tg[0] + n[1] * tg[1] + n[2] * tg[2]));
    EXPECT_NEAR(tg[0] * tg[0] + tg[1] * tg[1] + tg[2] * tg[2], 1.0, 1e-12);
    EXPECT_EQ(tg[3], t0[3]);
  }
  EXPECT_LT(worst, 1e-12);
}

// Pieces pass through in count, and every piece gets the whole height map (the wavelet
// source would otherwise make only the piece's share of it).
TEST(DisplacementMapFilter, PiecesPassThrough)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(20);
  vtkNew<SphereTCoords> tcoords;
  tcoords->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkRTAnalyticSource> wavelet; // float scalars, streams by extent
  wavelet->SetWholeExtent(0, 63, 0, 31, 0, 0);
  vtkNew<vtkDisplacementMapFilter> f;
  f->SetInputConnection(0, tcoords->GetOutputPort());
  f->SetInputConnection(1, wavelet->GetOutputPort());
  f->SetScaleFactor(0.001);
  f->SetNormalModeToApproximate();
  tcoords->Update();
  const vtkIdType whole = tcoords->GetOutput()->GetNumberOfPoints();
  const int pieces = 3;
  vtkIdType total = 0;
  for (int p = 0; p < pieces; ++p)
  {
    f->UpdatePiece(p, pieces, 0);
    tcoords->UpdatePiece(p, pieces, 0);
    EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), tcoords->GetOutput()->GetNumberOfPoints());
    EXPECT_GT(f->GetOutput()->GetNumberOfPoints(), 0);
    int ext[6];
    wavelet->GetOutput()->GetExtent(ext);
    EXPECT_EQ(ext[1], 63);
    EXPECT_EQ(ext[3], 31);
    total += f->GetOutput()->GetNumberOfPoints();
  }
  EXPECT_GE(total, whole); // pieces share their boundary points
}

// Huge Scale: self-intersecting, but finite; float points clamp to the float range.
TEST(DisplacementMapFilter, HugeScaleStaysFinite)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  for (bool floatPoints : { false, true })
  {
    auto mesh = MakeMesh(s, 32, 16, true, floatPoints);
    for (double scale : { 1e6, 1e30, 1e300, std::numeric_limits<double>::infinity() })
    {
      for (int mode : AllModes)
      {
        auto out = Displace(mesh, image, mode, scale, 0.5, vtkDisplacementMapFilter::Cubic);
        EXPECT_TRUE(AllFinite(out)) << scale << " mode " << mode;
      }
    }
  }
}

// 1x1 is a constant (with a warning); a constant map moves every point by the same distance along
// its normal and, in Approximate/Exact, keeps the normal; 2x2 works too.
TEST(DisplacementMapFilter, TinyAndConstantHeightMaps)
{
  const Surface s = Sphere();
  auto mesh = MakeMesh(s, 16, 8, false);
  for (int size : { 1, 2 })
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(size, size, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    std::memset(image->GetScalarPointer(), 255, static_cast<size_t>(size * size));
    {
      // Valid, but a single texel is seldom meant: one warning saying what it does.
      vtkNew<vtkDisplacementMapFilter> f;
      auto obs = Watch(f);
      f->SetInputData(0, mesh);
      f->SetInputData(1, image);
      f->Update();
      EXPECT_EQ(obs->Errors, 0);
      EXPECT_EQ(obs->Warnings, size == 1 ? 1 : 0) << obs->Message;
      EXPECT_EQ(obs->Message.find("single texel") != std::string::npos, size == 1);
      EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), mesh->GetNumberOfPoints());
    }
    for (int mode : AllModes)
    {
      for (int interp : { vtkDisplacementMapFilter::Nearest, vtkDisplacementMapFilter::Linear,
             vtkDisplacementMapFilter::Cubic })
      {
        auto out = Displace(mesh, image, mode, 0.25, 0.5, interp);
        ASSERT_EQ(out->GetNumberOfPoints(), mesh->GetNumberOfPoints());
        for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
        {
          double p[3], n[3];
          out->GetPoint(i, p);
          out->GetPointData()->GetNormals()->GetTuple(i, n);
          // unit sphere: h = 1 (255 normalised), d = 0.25 (1 - 0.5)
          EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.125, 1e-12);
          if (mode != vtkDisplacementMapFilter::Mesh)
          {
            EXPECT_LT(AngleDeg({ n[0], n[1], n[2] }, { p[0], p[1], p[2] }), 1e-6);
          }
        }
      }
    }
  }
  // 2x2 with different texels: Linear at the texel centres gives the texels exactly.
  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 2, 1);
  image->AllocateScalars(VTK_UNSIGNED_SHORT, 1);
  auto* v = static_cast<unsigned short*>(image->GetScalarPointer());
  v[0] = 0;
  v[1] = 65535;
  v[2] = 13107; // 0.2
  v[3] = 32767;
  auto probes = Probes({ { 0.25, 0.25 }, { 0.75, 0.25 }, { 0.25, 0.75 }, { 0.75, 0.75 } });
  auto out = Displace(probes, image, vtkDisplacementMapFilter::Approximate, 1.0, 0.0);
  const double expected[4] = { 0.0, 1.0, 0.2, 32767.0 / 65535.0 };
  for (int k = 0; k < 4; ++k)
  {
    double p[3];
    out->GetPoint(k, p);
    EXPECT_NEAR(p[2], expected[k], 1e-12);
  }
}

// Component selects the channel: an RGB map with different values per channel.
TEST(DisplacementMapFilter, ComponentSelectsTheChannel)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* v = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < 16; ++k)
  {
    v[3 * k] = 10;
    v[3 * k + 1] = 100;
    v[3 * k + 2] = 200;
  }
  auto probes = Probes({ { 0.3, 0.6 } });
  for (int component : { 0, 1, 2 })
  {
    vtkNew<vtkDisplacementMapFilter> f;
    f->SetInputData(0, probes);
    f->SetInputData(1, image);
    f->SetHeightComponent(component);
    f->Update();
    double p[3];
    f->GetOutput()->GetPoint(0, p);
    EXPECT_NEAR(p[2], (component == 0 ? 10 : component == 1 ? 100 : 200) / 255.0, 1e-12);
  }
}

// 8192 x 8192 texels (64 MB of unsigned char): sampled where expected, in a few seconds.
TEST(DisplacementMapFilter, HugeHeightMap)
{
  const int N = 8192;
  vtkNew<vtkImageData> image;
  image->SetDimensions(N, N, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* data = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t j = 0; j < static_cast<size_t>(N); ++j)
  {
    std::memset(data + j * N, static_cast<int>((j * 256) / N), N);
  }
  std::vector<std::array<double, 2>> st;
  for (int k = 0; k < 256; ++k)
  {
    st.push_back({ 0.3, (k * 32 + 16.5) / N }); // row k*32+16, a texel centre
  }
  auto out = Displace(Probes(st), image, vtkDisplacementMapFilter::Exact, 1.0, 0.0);
  for (int k = 0; k < 256; ++k)
  {
    double p[3];
    out->GetPoint(k, p);
    EXPECT_NEAR(p[2], static_cast<double>(((k * 32 + 16) * 256) / N) / 255.0, 1e-12);
  }
}

// NaN and infinite heights count as Midlevel, with one warning naming the count.
TEST(DisplacementMapFilter, NaNHeightsAreMidlevelWithOneWarning)
{
  const int W = 8, H = 8;
  auto image = RandomImage(W, H, 9);
  auto* data = static_cast<float*>(image->GetScalarPointer());
  data[0] = std::numeric_limits<float>::quiet_NaN();
  data[9] = std::numeric_limits<float>::infinity();
  data[10] = -std::numeric_limits<float>::infinity();
  auto probes = Probes({ { 0.5 / W, 0.5 / H }, { 1.5 / W, 1.5 / H }, { 2.5 / W, 1.5 / H } });
  vtkNew<vtkDisplacementMapFilter> f;
  auto obs = Watch(f);
  f->SetInputData(0, probes);
  f->SetInputData(1, image);
  f->SetMidlevel(0.5);
  f->SetScaleFactor(1.0);
  f->SetInterpolationToNearest();
  f->Update();
  EXPECT_EQ(obs->Warnings, 1);
  EXPECT_EQ(obs->Errors, 0);
  EXPECT_NE(obs->Message.find("3 height value(s)"), std::string::npos) << obs->Message;
  // Again: one more warning; and after an edit, the new count.
  f->Modified();
  f->Update();
  EXPECT_EQ(obs->Warnings, 2);
  data[20] = std::numeric_limits<float>::quiet_NaN();
  image->Modified();
  obs->Message.clear();
  f->Update();
  EXPECT_EQ(obs->Warnings, 3);
  EXPECT_NE(obs->Message.find("4 height value(s)"), std::string::npos) << obs->Message;
  for (vtkIdType i = 0; i < 3; ++i)
  {
    double p[3];
    f->GetOutput()->GetPoint(i, p);
    EXPECT_EQ(p[2], 0.0);
  }
  // Linear and Cubic next to the non-finite texels, in every normal mode: finite, and the very
  // output of the same map with Midlevel written in their place.
  vtkNew<vtkImageData> replaced;
  replaced->DeepCopy(image);
  auto* r = static_cast<float*>(replaced->GetScalarPointer());
  for (int k = 0; k < W * H; ++k)
  {
    r[k] = std::isfinite(r[k]) ? r[k] : 0.5f;
  }
  const Surface s = Rectangle();
  auto mesh = MakeMesh(s, 16, 16, false);
  for (int interp : { vtkDisplacementMapFilter::Linear, vtkDisplacementMapFilter::Cubic })
  {
    for (int mode : AllModes)
    {
      SCOPED_TRACE("interp " + std::to_string(interp) + " mode " + std::to_string(mode));
      auto out = Displace(mesh, image, mode, 0.1, 0.5, interp);
      auto ref = Displace(mesh, replaced, mode, 0.1, 0.5, interp);
      EXPECT_TRUE(AllFinite(out));
      EXPECT_TRUE(SameBits(out->GetPoints()->GetData(), ref->GetPoints()->GetData()));
      EXPECT_TRUE(SameBits(out->GetPointData()->GetNormals(), ref->GetPointData()->GetNormals()));
    }
  }
}

// Every bad input: an error naming the problem, empty output, no crash, input untouched.
TEST(DisplacementMapFilter, BadInputIsAnError)
{
  const Surface s = Rectangle();
  auto good = MakeMesh(s, 4, 4, false);
  auto image = RandomImage(4, 4, 1);
  struct Case
  {
    std::string Name, Expect;
    std::function<void(vtkDisplacementMapFilter*)> Setup;
  };
  auto noTCoords = vtkSmartPointer<vtkPolyData>::New();
  noTCoords->DeepCopy(good);
  noTCoords->GetPointData()->SetTCoords(nullptr);
  auto noNormals = vtkSmartPointer<vtkPolyData>::New();
  noNormals->DeepCopy(good);
  noNormals->GetPointData()->SetNormals(nullptr);
  // Arrays shorter than the points (read out of bounds before they were checked).
  auto shortNormals = vtkSmartPointer<vtkPolyData>::New();
  shortNormals->DeepCopy(good);
  shortNormals->GetPointData()->GetNormals()->SetNumberOfTuples(3);
  auto shortTCoords = vtkSmartPointer<vtkPolyData>::New();
  shortTCoords->DeepCopy(good);
  shortTCoords->GetPointData()->GetTCoords()->SetNumberOfTuples(3);
  vtkNew<vtkImageData> empty;
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(4, 4, 2);
  volume->AllocateScalars(VTK_FLOAT, 1);
  vtkNew<vtkImageData> ints;
  ints->SetDimensions(4, 4, 1);
  ints->AllocateScalars(VTK_INT, 1);
  const unsigned long before = good->GetMTime();
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>> inputTimes;
  for (vtkDataObject* x : std::initializer_list<vtkDataObject*>{
         noTCoords, noNormals, shortNormals, shortTCoords, empty, volume, ints, image })
  {
    inputTimes.emplace_back(x, x->GetMTime());
  }
  auto Inputs = [](vtkDataObject* surface, vtkDataObject* map)
  {
    return [=](vtkDisplacementMapFilter* f)
    {
      f->SetInputData(0, surface);
      f->SetInputData(1, map);
    };
  };
  std::vector<Case> cases = {
    { "no tcoords", "texture coordinates", Inputs(noTCoords, image) },
    { "no normals", "normals", Inputs(noNormals, image) },
    { "short normals", "Normals has 3 tuples for 25 points", Inputs(shortNormals, image) },
    { "short tcoords", "TCoords has 3 tuples for 25 points", Inputs(shortTCoords, image) },
    { "empty image", "empty", Inputs(good, empty) },
    { "volume", "2-D image", Inputs(good, volume) },
    { "int scalars", "unsigned char", Inputs(good, ints) },
    { "component", "HeightComponent 3",
      [&](vtkDisplacementMapFilter* f)
      {
        f->SetInputData(0, good);
        f->SetInputData(1, image);
        f->SetHeightComponent(3);
      } },
    { "no height map", "port 1", [&](vtkDisplacementMapFilter* f) { f->SetInputData(0, good); } },
    { "polydata on port 1", "vtkImageData", Inputs(good, good) },
    { "image on port 0", "vtkPolyData", Inputs(image, image) },
  };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.Name);
    vtkNew<vtkDisplacementMapFilter> f;
    auto obs = Watch(f);
    c.Setup(f);
    f->Update();
    EXPECT_GE(obs->Errors, 1);
    EXPECT_NE(obs->Message.find(c.Expect), std::string::npos) << obs->Message;
    EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(f->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_EQ(f->GetOutput()->GetPointData()->GetNumberOfArrays(), 0);
  }
  EXPECT_EQ(good->GetMTime(), before);
  EXPECT_EQ(good->GetNumberOfPoints(), 25);
  // The other inputs are untouched too.
  for (const auto& x : inputTimes)
  {
    EXPECT_EQ(x.first->GetMTime(), x.second) << x.first->GetClassName();
  }
  // An empty surface is not an error: empty in, empty out.
  vtkNew<vtkPolyData> nothing;
  vtkNew<vtkDisplacementMapFilter> f;
  auto obs = Watch(f);
  f->SetInputData(0, nothing);
  f->SetInputData(1, image);
  f->Update();
  EXPECT_EQ(obs->Errors, 0);
  EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
}

// A polygon naming a point the input does not have (past the end, or negative) made the
// passes read and BuildLinks write outside the point arrays. In every mode, also after a
// good execution.
TEST(DisplacementMapFilter, PointIdsOutOfRangeAreAnError)
{
  const Surface s = Rectangle();
  auto image = RandomImage(4, 4, 1);
  for (const int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
         vtkDisplacementMapFilter::Mesh, vtkDisplacementMapFilter::Input })
  {
    for (const vtkIdType bad : { vtkIdType(25), vtkIdType(-1), vtkIdType(1) << 40 })
    {
      SCOPED_TRACE(std::to_string(mode) + " " + std::to_string(bad));
      auto mesh = MakeMesh(s, 4, 4, true);
      mesh->GetPolys()->ConvertTo64BitStorage();
      vtkDataArray* conn = mesh->GetPolys()->GetConnectivityArray();
      const vtkIdType last = conn->GetNumberOfTuples() - 1;
      const double good = conn->GetComponent(last, 0);
      vtkNew<vtkDisplacementMapFilter> f;
      f->SetNormalMode(mode);
      f->SetInputData(0, mesh);
      f->SetInputData(1, image);
      auto obs = Watch(f);
      f->Update();
      ASSERT_EQ(obs->Errors, 0);
      ASSERT_EQ(f->GetOutput()->GetNumberOfPoints(), 25);

      conn->SetComponent(last, 0, static_cast<double>(bad));
      mesh->GetPolys()->Modified();
      f->Update();
      const int errors = obs->Errors;
      EXPECT_GE(errors, 1);
      EXPECT_NE(obs->Message.find("point id outside [0, 25)"), std::string::npos) << obs->Message;
      EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
      EXPECT_EQ(mesh->GetNumberOfPoints(), 25);

      conn->SetComponent(last, 0, good);
      mesh->GetPolys()->Modified();
      f->Update();
      EXPECT_EQ(obs->Errors, errors);
      EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 25);
    }
  }
}

// Where pass 1 reads no cells (None, and Approximate with dPdu/dPdv) the id check runs beside it:
// no pass may read through a bad id first (the seam sweep writes through them, the derivative-scale
// estimate reads each polygon's first two). A bad id in the first, a middle or the last polygon, or
// in a triangle strip, 32- or 64-bit connectivity, at 1 and 2 threads, seams merged or not: the
// error, an empty output and the input untouched.
TEST(DisplacementMapFilter, PointIdsOutOfRangeBesidePass1)
{
  const Surface s = Rectangle();
  auto image = RandomImage(4, 4, 1);
  for (const int threads : { 1, 2 })
  {
    vtkSMPTools::Initialize(threads);
    for (const bool ids64 : { false, true })
    {
      for (const bool strip : { false, true })
      {
        for (const vtkIdType where : { vtkIdType(0), vtkIdType(8), vtkIdType(-1) })
        {
          for (const vtkIdType bad : { vtkIdType(25), vtkIdType(-7),
                 ids64 ? vtkIdType(1) << 40 : vtkIdType(VTK_TYPE_INT32_MAX) })
          {
            for (const int mode :
              { vtkDisplacementMapFilter::Input, vtkDisplacementMapFilter::Approximate })
            {
              for (const bool merge : { true, false })
              {
                SCOPED_TRACE(std::to_string(threads) + " threads, " + (ids64 ? "64" : "32") +
                  "-bit, " + (strip ? "strip" : "polygon") + " at " + std::to_string(where) +
                  ", id " + std::to_string(bad) + ", mode " + std::to_string(mode) +
                  (merge ? ", merged" : ", apart"));
                auto mesh = MakeMesh(s, 4, 4, true);
                vtkCellArray* cells = mesh->GetPolys();
                if (strip)
                {
                  vtkNew<vtkCellArray> strips;
                  const vtkIdType ids[4] = { 0, 5, 1, 6 };
                  strips->InsertNextCell(4, ids);
                  mesh->SetStrips(strips);
                  cells = strips;
                }
                if (ids64)
                {
                  cells->ConvertTo64BitStorage();
                }
                else
                {
                  cells->ConvertTo32BitStorage();
                }
                vtkDataArray* conn = cells->GetConnectivityArray();
                const vtkIdType at = where < 0 ? conn->GetNumberOfTuples() - 1
                                               : std::min(where, conn->GetNumberOfTuples() - 1);
                const double good = conn->GetComponent(at, 0);
                vtkNew<vtkDisplacementMapFilter> f;
                f->SetNormalMode(mode);
                f->SetMergeSeams(merge);
                f->SetInputData(0, mesh);
                f->SetInputData(1, image);
                auto obs = Watch(f);
                f->Update();
                ASSERT_EQ(obs->Errors, 0) << obs->Message;
                ASSERT_EQ(f->GetOutput()->GetNumberOfPoints(), 25);

                conn->SetComponent(at, 0, static_cast<double>(bad));
                cells->Modified();
                auto pointsBefore =
                  vtkSmartPointer<vtkDataArray>::Take(mesh->GetPoints()->GetData()->NewInstance());
                pointsBefore->DeepCopy(mesh->GetPoints()->GetData());
                auto connBefore = vtkSmartPointer<vtkDataArray>::Take(conn->NewInstance());
                connBefore->DeepCopy(conn);
                f->SetScaleFactor(0.5); // a new execution either way
                f->Update();
                const int errors = obs->Errors;
                EXPECT_GE(errors, 1);
                EXPECT_NE(obs->Message.find("point id outside [0, 25)"), std::string::npos)
                  << obs->Message;
                EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
                EXPECT_EQ(f->GetOutput()->GetNumberOfCells(), 0);
                EXPECT_TRUE(SameBits(mesh->GetPoints()->GetData(), pointsBefore));
                EXPECT_TRUE(SameBits(conn, connBefore));

                conn->SetComponent(at, 0, good);
                cells->Modified();
                f->Update();
                EXPECT_EQ(obs->Errors, errors);
                EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 25);
              }
            }
          }
        }
      }
    }
  }
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
}

// The heights can be any point array of the height map, chosen by name with
// SetInputArrayToProcess as in VTK's filters: with the heights in "Height" and a colour
// array as the active scalars, the output is the one the heights give as scalars.
TEST(DisplacementMapFilter, HeightArrayChosenWithSetInputArrayToProcess)
{
  const Surface s = Torus();
  auto mesh = MakeMesh(s, 16, 8, true);
  auto asScalars = MakeHeightImage(s.Height, 32, 16);
  vtkDataArray* scalars = asScalars->GetPointData()->GetScalars();
  auto heights = vtk::TakeSmartPointer(scalars->NewInstance());
  heights->DeepCopy(scalars);
  heights->SetName("Height");
  vtkNew<vtkUnsignedCharArray> colours; // the active scalars, which must not be read
  colours->SetName("Colour");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(heights->GetNumberOfTuples());
  colours->Fill(200);
  auto named = vtkSmartPointer<vtkImageData>::New();
  named->SetDimensions(asScalars->GetDimensions());
  named->GetPointData()->SetScalars(colours);
  named->GetPointData()->AddArray(heights);

  auto want = Displace(mesh, asScalars, vtkDisplacementMapFilter::Exact);
  vtkNew<vtkDisplacementMapFilter> f;
  f->SetInputData(0, mesh);
  f->SetSourceData(named);
  f->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Height");
  f->SetScaleFactor(0.1);
  f->SetMidlevel(0.5);
  f->SetWrapToRepeat();
  f->Update();
  EXPECT_TRUE(SameBits(f->GetOutput()->GetPoints()->GetData(), want->GetPoints()->GetData()));
  EXPECT_TRUE(
    SameBits(f->GetOutput()->GetPointData()->GetNormals(), want->GetPointData()->GetNormals()));

  // A name the map does not have is an error with an empty output.
  auto messages = Watch(f);
  f->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Elevation");
  f->Update();
  EXPECT_GE(messages->Errors, 1);
  EXPECT_NE(messages->Message.find("SetInputArrayToProcess"), std::string::npos)
    << messages->Message;
  EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
}

// Other arrays pass through; None keeps normals; PrintSelf names every setting.
TEST(DisplacementMapFilter, ArraysSettingsAndPrint)
{
  const Surface s = Torus();
  auto mesh = MakeMesh(s, 8, 4, true);
  vtkNew<vtkIntArray> ids;
  ids->SetName("Ids");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    ids->InsertNextValue(static_cast<int>(i));
  }
  mesh->GetPointData()->AddArray(ids);
  auto out = Displace(mesh, MakeHeightImage(s.Height, 32, 16), vtkDisplacementMapFilter::Input);
  EXPECT_TRUE(SameBits(out->GetPointData()->GetArray("Ids"), ids));
  EXPECT_TRUE(SameBits(out->GetPointData()->GetNormals(), mesh->GetPointData()->GetNormals()));
  EXPECT_EQ(out->GetNumberOfCells(), mesh->GetNumberOfCells());

  vtkNew<vtkDisplacementMapFilter> f;
  EXPECT_EQ(f->GetNormalMode(), vtkDisplacementMapFilter::Exact);
  f->SetNormalModeToMesh();
  EXPECT_EQ(f->GetNormalMode(), vtkDisplacementMapFilter::Mesh);
  f->SetNormalModeToApproximate();
  f->SetWrapToMirroredRepeat();
  EXPECT_EQ(f->GetWrap(), vtkDisplacementMapFilter::MirroredRepeat);
  f->SetInterpolationToCubic();
  f->SetMidlevel(0.25);
  std::ostringstream os;
  f->Print(os);
  for (const char* key :
    { "ScaleFactor: 1", "Midlevel: 0.25", "HeightComponent: 0", "Wrap: MirroredRepeat",
      "Interpolation: Cubic", "NormalMode: Approximate", "MergeSeams: On", "SeamTolerance: 1e-06" })
  {
    EXPECT_NE(os.str().find(key), std::string::npos) << key;
  }
}

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

namespace
{
// @a mesh (MakeMesh's triangle pairs) as quads.
vtkSmartPointer<vtkPolyData> AsQuads(vtkPolyData* mesh)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(mesh);
  vtkNew<vtkCellArray> quads;
  vtkNew<vtkIdList> t0, t1;
  for (vtkIdType c = 0; c + 1 < mesh->GetNumberOfCells(); c += 2)
  {
    // (a, b, d) and (a, d, c) -> (a, b, d, c)
    mesh->GetCellPoints(c, t0);
    mesh->GetCellPoints(c + 1, t1);
    const vtkIdType q[4] = { t0->GetId(0), t0->GetId(1), t0->GetId(2), t1->GetId(2) };
    quads->InsertNextCell(4, q);
  }
  out->SetPolys(quads);
  return out;
}

// Points, normals and tangents of @a y are those of @a x bit for bit, point i of @a x against
// point perm[i] of @a y (the same point without @a perm).
void ExpectSameOutputBits(vtkPolyData* x, vtkPolyData* y, const std::string& what,
  const std::vector<vtkIdType>* perm = nullptr)
{
  for (const char* name : { "", "Normals", "Tangents" })
  {
    vtkDataArray* u = *name ? x->GetPointData()->GetArray(name) : x->GetPoints()->GetData();
    vtkDataArray* v = *name ? y->GetPointData()->GetArray(name) : y->GetPoints()->GetData();
    ASSERT_TRUE(u && v) << name << " " << what;
    ASSERT_EQ(u->GetNumberOfValues(), v->GetNumberOfValues()) << name << " " << what;
    const size_t bytes = static_cast<size_t>(u->GetDataTypeSize()) * u->GetNumberOfComponents();
    const auto* pu = static_cast<const unsigned char*>(u->GetVoidPointer(0));
    const auto* pv = static_cast<const unsigned char*>(v->GetVoidPointer(0));
    vtkIdType differ = 0;
    for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i)
    {
      differ += std::memcmp(pu + bytes * i, pv + bytes * (perm ? (*perm)[i] : i), bytes) != 0;
    }
    EXPECT_EQ(differ, 0) << (*name ? name : "Points") << " " << what;
  }
}
}

// Mesh normals sum each point's polygons in one order of the polygons: renumbering the points
// (polygons in the same order) must give every point the bits it had, at 1 and 2 threads, on
// first and later executions, with triangles and quads.
TEST(DisplacementMapFilter, MeshNormalsDoNotDependOnPointNumbering)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  for (bool floatPoints : { false, true })
  {
    for (bool quads : { false, true })
    {
      auto mesh = MakeMesh(s, 256, 128, false, floatPoints);
      // Points that need a fallback (a zero normal, a tangent along its normal).
      vtkPointData* pd = mesh->GetPointData();
      pd->GetNormals()->SetTuple3(16383, 0.0, 0.0, 0.0);
      double n[3];
      pd->GetNormals()->GetTuple(16384, n);
      pd->GetTangents()->SetTuple3(16384, n[0], n[1], n[2]);
      if (quads)
      {
        mesh = AsQuads(mesh);
      }
      const std::vector<vtkIdType> perm = RenumberedPoints::RandomIds(mesh->GetNumberOfPoints(), 5);
      auto renumbered = RenumberedPoints::Moved(mesh, perm, mesh->GetNumberOfPoints());
      std::vector<vtkSmartPointer<vtkPolyData>> outputs;
      for (int threads : { 1, 2 })
      {
        vtkSMPTools::Initialize(threads);
        for (vtkPolyData* input : { mesh.GetPointer(), renumbered.GetPointer() })
        {
          vtkNew<vtkDisplacementMapFilter> f;
          f->SetInputData(0, input);
          f->SetInputData(1, image);
          f->SetNormalModeToMesh();
          f->SetInterpolationToCubic();
          f->MergeSeamsOff();
          f->SetMidlevel(0.5);
          for (double scale : { 0.1, 0.2 })
          {
            f->SetScaleFactor(scale);
            f->Update();
            auto out = vtkSmartPointer<vtkPolyData>::New();
            out->DeepCopy(f->GetOutput());
            outputs.push_back(out);
          }
        }
      }
      // outputs: (threads, input, scale)
      for (size_t k = 0; k < outputs.size(); ++k)
      {
        const size_t same = k % 2;
        for (const char* name : { "", "Normals", "Tangents" })
        {
          vtkDataArray* x = *name ? outputs[same]->GetPointData()->GetArray(name)
                                  : outputs[same]->GetPoints()->GetData();
          vtkDataArray* y =
            *name ? outputs[k]->GetPointData()->GetArray(name) : outputs[k]->GetPoints()->GetData();
          ASSERT_TRUE(x && y);
          // The renumbered mesh's point perm[i] against the original's point i.
          const bool moved = (k / 2) % 2 == 1;
          const int nc = x->GetNumberOfComponents();
          const size_t bytes = static_cast<size_t>(x->GetDataTypeSize()) * nc;
          size_t differ = 0;
          for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
          {
            const vtkIdType j = moved ? perm[i] : i;
            differ += std::memcmp(static_cast<const char*>(x->GetVoidPointer(0)) + bytes * i,
                        static_cast<const char*>(y->GetVoidPointer(0)) + bytes * j, bytes) != 0;
          }
          EXPECT_EQ(differ, 0u) << (*name ? name : "Points") << " output " << k << " float "
                                << floatPoints << " quads " << quads;
        }
        EXPECT_TRUE(AllFinite(outputs[k]));
      }
    }
  }
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
}

// A triangle of zero area has a zero normal and adds nothing to an area-weighted sum (nor to the
// seam test: its corners' neighbours cancel), so a torus with pairs of them, (a, b, a) and
// (a, a, c), inserted after every seventh polygon must give every output of the torus without
// them, bit for bit: with triangles only and with quads among the later polygons, at 1 and 2
// threads, on first executions and on re-executions.
TEST(DisplacementMapFilter, DegenerateTrianglePairsAddNothingToMeshNormals)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  for (bool quads : { false, true })
  {
    auto grid = MakeMesh(s, 256, 128, false, true);
    vtkCellArray* tris = grid->GetPolys();
    const vtkIdType nTris = tris->GetNumberOfCells();
    // The reference's polygons (with quads: every fifth fan pair of the second half merged into
    // the quad (a, b, d, c)) and the same with the degenerate pairs.
    vtkNew<vtkCellArray> plain, withPairs;
    vtkNew<vtkIdList> t0, t1;
    vtkIdType emitted = 0, degenerate = 0;
    auto emit = [&](vtkIdType n, const vtkIdType* ids)
    {
      plain->InsertNextCell(n, ids);
      withPairs->InsertNextCell(n, ids);
      if (++emitted % 7 == 0)
      {
        const vtkIdType a = ids[0], b = ids[1], c = ids[2];
        const vtkIdType first[3] = { a, b, a }, second[3] = { a, a, c };
        withPairs->InsertNextCell(3, first);
        withPairs->InsertNextCell(3, second);
        ++degenerate;
      }
    };
    for (vtkIdType c = 0; c < nTris; c += 2)
    {
      tris->GetCellAtId(c, t0);
      tris->GetCellAtId(c + 1, t1);
      if (quads && c >= nTris / 2 && (c / 2) % 5 == 0)
      {
        const vtkIdType quad[4] = { t0->GetId(0), t0->GetId(1), t0->GetId(2), t1->GetId(2) };
        emit(4, quad);
        continue;
      }
      emit(3, t0->GetPointer(0));
      emit(3, t1->GetPointer(0));
    }
    ASSERT_GT(degenerate, 1000);
    vtkNew<vtkPolyData> reference, augmented;
    reference->ShallowCopy(grid);
    reference->SetPolys(plain);
    augmented->ShallowCopy(grid);
    augmented->SetPolys(withPairs);
    for (int threads : { 1, 2 })
    {
      vtkSMPTools::Initialize(threads);
      vtkNew<vtkDisplacementMapFilter> a, b;
      for (vtkDisplacementMapFilter* f : { a.Get(), b.Get() })
      {
        f->SetInputData(0, f == a.Get() ? reference.Get() : augmented.Get());
        f->SetInputData(1, image);
        f->SetNormalModeToMesh();
        f->SetMidlevel(0.5);
      }
      for (double scale : { 0.1, 0.25 })
      {
        for (vtkDisplacementMapFilter* f : { a.Get(), b.Get() })
        {
          f->SetScaleFactor(scale);
          f->Update();
        }
        ExpectSameOutputBits(a->GetOutput(), b->GetOutput(),
          "quads " + std::to_string(quads) + " threads " + std::to_string(threads) + " scale " +
            std::to_string(scale));
        EXPECT_TRUE(AllFinite(b->GetOutput()));
      }
    }
    // The fits count a pair's neighbours whatever its area, so with Exact the pairs matter; the
    // points renumbered (the polygons in the same order) must give every point the bits it had,
    // with Exact as with Mesh. Seams not merged: their means add the members in id order.
    const std::vector<vtkIdType> perm =
      RenumberedPoints::RandomIds(augmented->GetNumberOfPoints(), 7);
    auto renumbered = RenumberedPoints::Moved(augmented, perm, augmented->GetNumberOfPoints());
    for (int mode : { vtkDisplacementMapFilter::Exact, vtkDisplacementMapFilter::Mesh })
    {
      for (int threads : { 1, 2 })
      {
        vtkSMPTools::Initialize(threads);
        vtkNew<vtkDisplacementMapFilter> a, b;
        for (vtkDisplacementMapFilter* f : { a.Get(), b.Get() })
        {
          f->SetInputData(0, f == a.Get() ? augmented.Get() : renumbered.Get());
          f->SetInputData(1, image);
          f->SetNormalMode(mode);
          f->SetMidlevel(0.5);
          f->SetScaleFactor(0.1);
          f->MergeSeamsOff();
          f->Update();
        }
        ExpectSameOutputBits(a->GetOutput(), b->GetOutput(),
          "mode " + std::to_string(mode) + " quads " + std::to_string(quads) + " threads " +
            std::to_string(threads),
          &perm);
        EXPECT_TRUE(AllFinite(a->GetOutput()));
      }
    }
  }
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
}

#ifdef __linux__
// A polygon with no points, last in the list, must not be read: its connectivity ends where the
// memory does (a guard page after it), and an empty polygon adds nothing, so every output is the
// same without it, bit for bit (the points renumbered, so that no point's polygons are near it).
TEST(DisplacementMapFilter, EmptyLastPolygonIsNotRead)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  auto grid = MakeMesh(s, 256, 128, false, true);
  auto mesh = RenumberedPoints::Moved(
    grid, RenumberedPoints::RandomIds(grid->GetNumberOfPoints(), 9), grid->GetNumberOfPoints());
  vtkDataArray* offsets = mesh->GetPolys()->GetOffsetsArray();
  vtkDataArray* connectivity = mesh->GetPolys()->GetConnectivityArray();
  const vtkIdType nCells = mesh->GetPolys()->GetNumberOfCells();
  const vtkIdType nConn = connectivity->GetNumberOfValues();
  const size_t page = static_cast<size_t>(sysconf(_SC_PAGESIZE));
  const size_t bytes = (nConn * sizeof(vtkIdType) + page - 1) / page * page;
  void* memory =
    mmap(nullptr, bytes + page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(memory, MAP_FAILED);
  ASSERT_EQ(mprotect(static_cast<char*>(memory) + bytes, page, PROT_NONE), 0);
  {
    vtkIdType* conn = reinterpret_cast<vtkIdType*>(static_cast<char*>(memory) + bytes) - nConn;
    for (vtkIdType k = 0; k < nConn; ++k)
    {
      conn[k] = static_cast<vtkIdType>(connectivity->GetComponent(k, 0));
    }
    vtkNew<vtkIdTypeArray> guardedOffsets, guardedConn;
    guardedOffsets->SetNumberOfValues(nCells + 2);
    for (vtkIdType c = 0; c <= nCells; ++c)
    {
      guardedOffsets->SetValue(c, static_cast<vtkIdType>(offsets->GetComponent(c, 0)));
    }
    guardedOffsets->SetValue(nCells + 1, nConn); // the empty polygon
    guardedConn->SetArray(conn, nConn, 1);
    vtkNew<vtkCellArray> polys;
    polys->SetData(guardedOffsets, guardedConn);
    vtkNew<vtkPolyData> withEmpty;
    withEmpty->ShallowCopy(mesh);
    withEmpty->SetPolys(polys);
    for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
           vtkDisplacementMapFilter::Mesh })
    {
      vtkNew<vtkDisplacementMapFilter> a, b;
      for (vtkDisplacementMapFilter* f : { a.Get(), b.Get() })
      {
        f->SetInputData(0, f == a.Get() ? mesh.Get() : withEmpty.Get());
        f->SetInputData(1, image);
        f->SetNormalMode(mode);
        f->SetScaleFactor(0.1);
        f->Update();
      }
      ExpectSameOutputBits(a->GetOutput(), b->GetOutput(), "mode " + std::to_string(mode));
    }
  }
  munmap(memory, bytes + page);
}
#endif

namespace
{
// @a mesh (MakeMesh's) with the triangle pairs of its first row made quads and one triangle made
// degenerate (a corner named twice), so that the fits meet polygons that are not three distinct
// points.
vtkSmartPointer<vtkPolyData> WithOddPolygons(vtkPolyData* mesh, int U)
{
  auto odd = vtkSmartPointer<vtkPolyData>::New();
  odd->ShallowCopy(mesh);
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> a, b;
  const vtkIdType cells = mesh->GetNumberOfCells();
  for (vtkIdType c = 0; c < cells; ++c)
  {
    mesh->GetCellPoints(c, a);
    if (c < 2 * U && c % 2 == 0)
    {
      // (a, b, d) and (a, d, c): the quad (a, b, d, c).
      mesh->GetCellPoints(c + 1, b);
      const vtkIdType quad[4] = { a->GetId(0), a->GetId(1), a->GetId(2), b->GetId(2) };
      polys->InsertNextCell(4, quad);
      ++c;
      continue;
    }
    if (c == cells / 2 + 7)
    {
      a->SetId(2, a->GetId(0));
    }
    polys->InsertNextCell(a);
  }
  odd->SetPolys(polys);
  return odd;
}

}

// The fits (Exact; Approximate without dPdu/dPdv) add each point's neighbours in one order of the
// polygons. Renumbering the points (polygons in the same order) must give every point the bits it
// had: float and double arrays, with and without dPdu/dPdv, at 1 and 2 threads, on first and later
// executions, with quads and a degenerate triangle (seams not merged: their means add the members
// in id order), and with points that need a fallback (a zero normal, a tangent along the normal).
TEST(DisplacementMapFilter, FitsDoNotDependOnPointNumbering)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  const int U = 256, V = 128;
  for (bool floatPoints : { false, true })
  {
    for (bool derivatives : { false, true })
    {
      auto mesh = WithOddPolygons(MakeMesh(s, U, V, derivatives, floatPoints), U);
      const vtkIdType count = mesh->GetNumberOfPoints();
      ASSERT_GT(count, 2 * 16384);
      vtkPointData* pd = mesh->GetPointData();
      pd->GetNormals()->SetTuple3(16384 + 3, 0.0, 0.0, 0.0);
      double n[3];
      pd->GetNormals()->GetTuple(16384 - 2, n);
      pd->GetTangents()->SetTuple3(16384 - 2, n[0], n[1], n[2]);
      const std::vector<vtkIdType> perm = RenumberedPoints::RandomIds(mesh->GetNumberOfPoints(), 5);
      auto renumbered = RenumberedPoints::Moved(mesh, perm, mesh->GetNumberOfPoints());
      for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact })
      {
        for (int threads : { 1, 2 })
        {
          vtkSMPTools::Initialize(threads);
          vtkNew<vtkDisplacementMapFilter> a, b;
          for (vtkDisplacementMapFilter* f : { a.Get(), b.Get() })
          {
            f->SetInputData(0, f == a.Get() ? mesh : renumbered);
            f->SetInputData(1, image);
            f->SetNormalMode(mode);
            f->SetScaleFactor(0.1);
            f->SetMidlevel(0.5);
            f->SetInterpolation(vtkDisplacementMapFilter::Cubic);
            // The seam groups' means add their members in id order, which renumbering changes.
            f->MergeSeamsOff();
          }
          for (int execution = 0; execution < 2; ++execution)
          {
            const std::string what = std::string(floatPoints ? "float" : "double") +
              (derivatives ? " dPdu/dPdv" : "") + " mode " + std::to_string(mode) + " threads " +
              std::to_string(threads) + " execution " + std::to_string(execution);
            a->SetScaleFactor(0.1 + 0.05 * execution);
            b->SetScaleFactor(0.1 + 0.05 * execution);
            a->Update();
            b->Update();
            vtkPolyData* x = a->GetOutput();
            vtkPolyData* y = b->GetOutput();
            vtkIdType differ = 0;
            for (const char* name : { "", "Normals", "Tangents" })
            {
              vtkDataArray* ax =
                *name ? x->GetPointData()->GetArray(name) : x->GetPoints()->GetData();
              vtkDataArray* ay =
                *name ? y->GetPointData()->GetArray(name) : y->GetPoints()->GetData();
              ASSERT_TRUE(ax && ay) << name << " " << what;
              const size_t bytes =
                static_cast<size_t>(ax->GetDataTypeSize()) * ax->GetNumberOfComponents();
              const auto* px = static_cast<const unsigned char*>(ax->GetVoidPointer(0));
              const auto* py = static_cast<const unsigned char*>(ay->GetVoidPointer(0));
              for (vtkIdType i = 0; i < count; ++i)
              {
                differ += std::memcmp(px + bytes * i, py + bytes * perm[i], bytes) != 0;
              }
            }
            EXPECT_EQ(differ, 0) << what;
            EXPECT_TRUE(AllFinite(x)) << what;
          }
        }
      }
    }
  }
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
}

namespace
{
// Catmull-Rom through p0..p3 at the fraction f of the way from p1 to p2: the value and its
// derivative in f, from the spline's polynomial form (the cardinal spline of tension 1/2),
// written independently of the filter's weights.
std::array<double, 2> CatmullRomSpline(double p0, double p1, double p2, double p3, double f)
{
  const double a = -p0 + 3 * p1 - 3 * p2 + p3, b = 2 * p0 - 5 * p1 + 4 * p2 - p3, c = p2 - p0;
  return { 0.5 * (((a * f + b) * f + c) * f + 2 * p1), 0.5 * ((3 * a * f + 2 * b) * f + c) };
}

// The bicubic Catmull-Rom interpolant through the texel centres, each of its 4x4 texels
// wrapped by GLWrap (as GLLinear wraps its 2x2): height and its derivatives in s and t.
std::array<double, 3> RefCubic(const float* img, int W, int H, int mode, double s, double t)
{
  const double u = s * W - 0.5, v = t * H - 0.5;
  const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
  const double fx = u - std::floor(u), fy = v - std::floor(v);
  auto T = [&](int i, int j) { return GLTexel(img, W, H, mode, i, j); };
  double row[4], drow[4];
  for (int l = 0; l < 4; ++l)
  {
    const int j = j0 - 1 + l;
    const auto r = CatmullRomSpline(T(i0 - 1, j), T(i0, j), T(i0 + 1, j), T(i0 + 2, j), fx);
    row[l] = r[0];
    drow[l] = r[1];
  }
  const auto h = CatmullRomSpline(row[0], row[1], row[2], row[3], fy);
  const auto hs = CatmullRomSpline(drow[0], drow[1], drow[2], drow[3], fy);
  return { h[0], W * hs[0], H * h[1] };
}

// GLLinear with its derivatives: within the 2x2 texels around (s,t) the bilinear form's
// slope, which jumps where (s,t) crosses a row or column of texel centres.
std::array<double, 3> RefLinear(const float* img, int W, int H, int mode, double s, double t)
{
  const double u = s * W - 0.5, v = t * H - 0.5;
  const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
  const double a = u - std::floor(u), b = v - std::floor(v);
  auto T = [&](int i, int j) { return GLTexel(img, W, H, mode, i, j); };
  const double t00 = T(i0, j0), t10 = T(i0 + 1, j0), t01 = T(i0, j0 + 1), t11 = T(i0 + 1, j0 + 1);
  return { GLLinear(img, W, H, mode, s, t), W * ((1 - b) * (t10 - t00) + b * (t11 - t01)),
    H * ((1 - a) * (t01 - t00) + a * (t11 - t10)) };
}
} // namespace

// Every interpolant's slope, not only its height: on the flat probes (normal +z, P_s = +x,
// P_t = +y) Approximate's normal of z = Scale h is (-Scale h_s, -Scale h_t, 1), which must
// equal the references' analytic derivatives in every wrap mode, inside and outside [0,1],
// Cubic across the borders included. Probes a millionth of a texel either side of the texel
// centres, where Linear's slope jumps, tell the interpolant's own derivative from a central
// difference with a fixed epsilon, which would blur the jump into a mean of the two slopes.
TEST(DisplacementMapFilter, SlopesMatchTheInterpolants)
{
  const int W = 7, H = 5;
  auto image = RandomImage(W, H, 3);
  const float* img = static_cast<float*>(image->GetScalarPointer());
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(17);
  std::vector<std::array<double, 2>> st = RandomCoordinates(random, 300);
  for (int i = -1; i <= W; ++i)
  {
    for (double side : { -1e-6, 1e-6 })
    {
      st.push_back({ (i + 0.5 + side) / W, random->GetNextRangeValue(-0.5, 1.5) });
      st.push_back({ random->GetNextRangeValue(-0.5, 1.5), (i % H + 0.5 + side) / H });
    }
  }
  auto probes = Probes(st);
  const double scale = 0.7;
  for (int wrap : { vtkDisplacementMapFilter::ClampToEdge, vtkDisplacementMapFilter::Repeat,
         vtkDisplacementMapFilter::MirroredRepeat, vtkDisplacementMapFilter::ClampToBorder })
  {
    // The test's own premise: the slope does jump across the texel centres probed.
    double jump = 0.0;
    for (int i = 0; i + 1 < W; ++i)
    {
      const auto left = RefLinear(img, W, H, wrap, (i + 0.5 - 1e-6) / W, 0.3);
      const auto right = RefLinear(img, W, H, wrap, (i + 0.5 + 1e-6) / W, 0.3);
      jump = std::max(jump, std::abs(left[1] - right[1]));
    }
    EXPECT_GT(jump, 1.0);
    for (int interp : { vtkDisplacementMapFilter::Nearest, vtkDisplacementMapFilter::Linear,
           vtkDisplacementMapFilter::Cubic })
    {
      auto out =
        Displace(probes, image, vtkDisplacementMapFilter::Approximate, scale, 0.0, interp, wrap);
      double worstHeight = 0.0, worstAngle = 0.0;
      for (size_t k = 0; k < st.size(); ++k)
      {
        const double s = st[k][0], t = st[k][1];
        std::array<double, 3> ref;
        if (interp == vtkDisplacementMapFilter::Nearest)
        {
          ref = { GLNearest(img, W, H, wrap, s, t), 0.0, 0.0 };
        }
        else if (interp == vtkDisplacementMapFilter::Linear)
        {
          ref = RefLinear(img, W, H, wrap, s, t);
        }
        else
        {
          ref = RefCubic(img, W, H, wrap, s, t);
        }
        double p[3], n[3];
        out->GetPoint(static_cast<vtkIdType>(k), p);
        out->GetPointData()->GetNormals()->GetTuple(static_cast<vtkIdType>(k), n);
        worstHeight = std::max(worstHeight, std::abs(p[2] - scale * ref[0]));
        worstAngle = std::max(worstAngle,
          AngleDeg({ n[0], n[1], n[2] }, Unit({ -scale * ref[1], -scale * ref[2], 1.0 })));
      }
      EXPECT_LT(worstHeight, 1e-12) << "wrap " << wrap << " interp " << interp;
      EXPECT_LT(worstAngle, 1e-9) << "wrap " << wrap << " interp " << interp;
    }
  }
}

// Mesh normals are area-weighted: on a grid whose interior points are moved at random within
// their cells (the texture coordinates with them), so that the triangles around a point differ
// in area and a few are even turned over, each output normal equals the normalised sum of the
// cross products of the displaced triangles around it, computed here from the output points,
// each triangle oriented as its corners' input normals (the sign of its input cross product
// against their sum). The same mesh's mean of unit triangle normals (vtkPolyDataNormals'
// weighting) differs from it by far more than the tolerance, so the test tells them apart.
TEST(DisplacementMapFilter, MeshNormalsAreAreaWeighted)
{
  const int U = 12;
  const Surface s = Rectangle(0.3);
  auto mesh = MakeMesh(s, U, U, false);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(29);
  vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
  for (int j = 1; j < U; ++j)
  {
    for (int i = 1; i < U; ++i)
    {
      const vtkIdType id = static_cast<vtkIdType>(j) * (U + 1) + i;
      const double u = (i + random->GetNextRangeValue(-0.35, 0.35)) / U;
      const double v = (j + random->GetNextRangeValue(-0.35, 0.35)) / U;
      const Vec p = s.P(u, v);
      mesh->GetPoints()->SetPoint(id, p.data());
      tc->SetTuple2(id, u, v);
    }
  }
  auto out = Displace(mesh, MakeHeightImage(s.Height, 64, 64), vtkDisplacementMapFilter::Mesh,
    s.Scale, s.Midlevel, vtkDisplacementMapFilter::Linear);
  const vtkIdType n = out->GetNumberOfPoints();
  std::vector<Vec> weighted(n, Vec{ 0, 0, 0 }), unweighted(n, Vec{ 0, 0, 0 });
  vtkCellArray* polys = out->GetPolys();
  vtkDataArray* normalsIn = mesh->GetPointData()->GetNormals();
  vtkNew<vtkIdList> ids;
  int turned = 0;
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
  {
    ASSERT_EQ(ids->GetNumberOfIds(), 3);
    Vec p[3], q[3], nsum{ 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      out->GetPoint(ids->GetId(k), p[k].data());
      mesh->GetPoint(ids->GetId(k), q[k].data());
      Vec nk;
      normalsIn->GetTuple(ids->GetId(k), nk.data());
      nsum = Add(nsum, nk);
    }
    Vec m = CrossV(Add(p[1], p[0], -1.0), Add(p[2], p[0], -1.0));
    if (DotV(CrossV(Add(q[1], q[0], -1.0), Add(q[2], q[0], -1.0)), nsum) < 0.0)
    {
      m = { -m[0], -m[1], -m[2] };
      ++turned;
    }
    for (int k = 0; k < 3; ++k)
    {
      weighted[ids->GetId(k)] = Add(weighted[ids->GetId(k)], m);
      unweighted[ids->GetId(k)] = Add(unweighted[ids->GetId(k)], Unit(m));
    }
  }
  double worst = 0.0, apart = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    Vec got;
    out->GetPointData()->GetNormals()->GetTuple(i, got.data());
    worst = std::max(worst, AngleDeg(got, weighted[i]));
    apart = std::max(apart, AngleDeg(weighted[i], unweighted[i]));
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(apart, 0.5);
  EXPECT_GT(turned, 0); // the orientation rule is exercised
}

// Tangents in every mode that makes new normals: the input tangent with its part along the new
// normal removed and normalised (Gram-Schmidt). A SurfaceDetail frame keeps its handedness
// array (w = +1 or -1) and its mark; tangents from elsewhere (no handedness) get none.
TEST(DisplacementMapFilter, TangentsAreTheInputsOrthogonalised)
{
  const Surface s = Torus(0.15);
  auto image = MakeHeightImage(s.Height, 128, 64);
  for (bool withHandedness : { true, false })
  {
    auto mesh = MakeMesh(s, 32, 16, true);
    auto t4 = TangentFrame(mesh);
    vtkNew<vtkDoubleArray> tin, win;
    tin->SetNumberOfComponents(3);
    tin->SetNumberOfTuples(mesh->GetNumberOfPoints());
    win->SetNumberOfTuples(mesh->GetNumberOfPoints());
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double t[4];
      t4->GetTuple(i, t);
      tin->SetTuple(i, t);
      // Every third point mirrored: w = -1 (a mirrored texture there).
      win->SetValue(i, i % 3 == 1 ? -1.0 : 1.0);
    }
    mesh->GetPointData()->RemoveArray("Tangents");
    mesh->GetPointData()->RemoveArray("TangentHandedness");
    if (withHandedness)
    {
      vtkSurfaceDetailTangents::SetFrame(mesh->GetPointData(), tin, win);
    }
    else
    {
      tin->SetName("VTKTangents");
      mesh->GetPointData()->SetTangents(tin);
    }
    for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
           vtkDisplacementMapFilter::Mesh })
    {
      SCOPED_TRACE(std::string(withHandedness ? "with" : "without") + " handedness, mode " +
        std::to_string(mode));
      auto out = Displace(mesh, image, mode, s.Scale);
      vtkDataArray* t = out->GetPointData()->GetTangents();
      ASSERT_NE(t, nullptr);
      ASSERT_EQ(t->GetNumberOfComponents(), 3);
      EXPECT_STREQ(t->GetName(), tin->GetName());
      EXPECT_EQ(
        t->GetInformation()->Has(vtkSurfaceDetailTangents::WITH_HANDEDNESS()), withHandedness);
      vtkDataArray* w = vtkSurfaceDetailTangents::GetHandedness(out->GetPointData());
      EXPECT_EQ(w != nullptr, withHandedness);
      double worst = 0.0, turned = 0.0;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double nn[3], got[3], in[3];
        out->GetPointData()->GetNormals()->GetTuple(i, nn);
        t->GetTuple(i, got);
        tin->GetTuple(i, in);
        const Vec normal = { nn[0], nn[1], nn[2] }, input = { in[0], in[1], in[2] };
        const Vec expected = Unit(Add(input, normal, -DotV(input, normal)));
        worst = std::max(worst, AngleDeg({ got[0], got[1], got[2] }, expected));
        turned = std::max(turned, AngleDeg(input, expected));
        EXPECT_NEAR(got[0] * got[0] + got[1] * got[1] + got[2] * got[2], 1.0, 1e-12);
        if (w)
        {
          ASSERT_EQ(w->GetComponent(i, 0), win->GetValue(i)) << i;
        }
      }
      EXPECT_LT(worst, 1e-9);
      // The premise: the new normals did turn the tangents, so keeping them would fail.
      EXPECT_GT(turned, 1.0);
    }
  }
}

// Every array but the points, normals and tangents passes through in every mode, bit for bit:
// other point arrays, dPdu and dPdv (they describe the input surface), texture coordinates and
// cell data.
TEST(DisplacementMapFilter, OtherArraysPassThroughInEveryMode)
{
  const Surface s = Torus();
  auto mesh = MakeMesh(s, 16, 8, true, false, true);
  vtkNew<vtkFloatArray> temperature;
  temperature->SetName("Temperature");
  vtkNew<vtkIntArray> material;
  material->SetName("Material");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    temperature->InsertNextValue(static_cast<float>(0.5 * i));
  }
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    material->InsertNextValue(static_cast<int>(c % 7));
  }
  mesh->GetPointData()->AddArray(temperature);
  mesh->GetCellData()->AddArray(material);
  auto image = MakeHeightImage(s.Height, 32, 16);
  vtkNew<vtkPolyData> before;
  before->DeepCopy(mesh);
  for (int mode : AllModes)
  {
    SCOPED_TRACE(mode);
    auto out = Displace(mesh, image, mode);
    vtkPointData* pd = out->GetPointData();
    for (const char* name : { "Temperature", "dPdu", "dPdv", "dNdu", "dNdv", "TCoords" })
    {
      ASSERT_NE(pd->GetArray(name), nullptr) << name;
      EXPECT_TRUE(SameBits(pd->GetArray(name), mesh->GetPointData()->GetArray(name))) << name;
    }
    EXPECT_EQ(pd->GetTCoords(), pd->GetArray("TCoords"));
    ASSERT_NE(out->GetCellData()->GetArray("Material"), nullptr);
    EXPECT_TRUE(SameBits(out->GetCellData()->GetArray("Material"), material));
    EXPECT_EQ(out->GetNumberOfCells(), mesh->GetNumberOfCells());
    // And the input is left as it was.
    EXPECT_TRUE(SameBits(mesh->GetPoints()->GetData(), before->GetPoints()->GetData()));
    for (const char* name : { "Normals", "Tangents", "TCoords", "Temperature" })
    {
      EXPECT_TRUE(
        SameBits(mesh->GetPointData()->GetArray(name), before->GetPointData()->GetArray(name)))
        << name;
    }
  }
}

// dNdu/dNdv are derivatives in the parameters of dPdu/dPdv: Exact uses them with those only, and
// Approximate (which drops the d n_s, d n_t terms) never. Where they are not used the output is
// the one without them, bit for bit; where they are, it differs (the fits are not exact).
TEST(DisplacementMapFilter, NormalDerivativesOnlyWithSurfaceDerivativesInExact)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  auto withAll = MakeMesh(s, 24, 12, true, false, true);
  auto withoutN = MakeMesh(s, 24, 12, true, false, false);
  auto onlyN = vtkSmartPointer<vtkPolyData>::New();
  onlyN->DeepCopy(withAll);
  onlyN->GetPointData()->RemoveArray("dPdu");
  onlyN->GetPointData()->RemoveArray("dPdv");
  auto none = MakeMesh(s, 24, 12, false);
  for (int mode : AllModes)
  {
    SCOPED_TRACE(mode);
    auto all = Displace(withAll, image, mode);
    EXPECT_TRUE(AllFinite(all));
    EXPECT_EQ(
      SameOutput(all, Displace(withoutN, image, mode)), mode != vtkDisplacementMapFilter::Exact);
    EXPECT_TRUE(SameOutput(Displace(onlyN, image, mode), Displace(none, image, mode)));
  }
}

// Texture coordinates that are NaN or infinite locate no texel: in every mode and interpolation,
// with dPdu/dPdv and without, the output stays finite (points, normals, tangents), no error is
// raised, every other point moves exactly as in a run without them (a position depends on its
// own coordinates only), and the normals of points two or more grid steps away from them are
// those of the clean run (the bad coordinates reach no fit or polygon beyond their neighbours).
TEST(DisplacementMapFilter, NonFiniteTextureCoordinatesStayLocal)
{
  const Surface s = Torus();
  const int U = 24, V = 12;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  // Interior points of the grid (i, j) (no seam partner), one coordinate or both bad.
  struct Spoilt
  {
    int I, J;
    double S, T;
  };
  const Spoilt spoilt[4] = { { 5, 3, nan, 0.25 }, { 11, 6, 0.5, inf }, { 17, 8, -inf, nan },
    { 3, 9, inf, -inf } };
  auto image = MakeHeightImage(s.Height, 64, 32);
  for (bool derivatives : { false, true })
  {
    auto clean = MakeMesh(s, U, V, derivatives);
    auto bad = vtkSmartPointer<vtkPolyData>::New();
    bad->DeepCopy(clean);
    for (const Spoilt& x : spoilt)
    {
      bad->GetPointData()->GetTCoords()->SetTuple2(
        static_cast<vtkIdType>(x.J) * (U + 1) + x.I, x.S, x.T);
    }
    for (int mode : AllModes)
    {
      for (int interp : { vtkDisplacementMapFilter::Nearest, vtkDisplacementMapFilter::Linear,
             vtkDisplacementMapFilter::Cubic })
      {
        SCOPED_TRACE("mode " + std::to_string(mode) + " interp " + std::to_string(interp) +
          (derivatives ? " with dPdu" : ""));
        vtkNew<vtkDisplacementMapFilter> f;
        auto obs = Watch(f);
        f->SetInputData(0, bad);
        f->SetInputData(1, image);
        f->SetNormalMode(mode);
        f->SetScaleFactor(0.1);
        f->SetMidlevel(0.5);
        f->SetInterpolation(interp);
        f->Update();
        EXPECT_EQ(obs->Errors, 0) << obs->Message;
        vtkPolyData* out = f->GetOutput();
        ASSERT_EQ(out->GetNumberOfPoints(), clean->GetNumberOfPoints());
        EXPECT_TRUE(AllFinite(out));
        auto ref = Displace(clean, image, mode, 0.1, 0.5, interp);
        vtkIdType moved = 0;
        double worst = 0.0;
        for (int j = 0; j <= V; ++j)
        {
          for (int i = 0; i <= U; ++i)
          {
            const vtkIdType id = static_cast<vtkIdType>(j) * (U + 1) + i;
            int distance = U;
            for (const Spoilt& x : spoilt)
            {
              distance = std::min(distance, std::max(std::abs(i - x.I), std::abs(j - x.J)));
            }
            double p[3], q[3], n[3], m[3];
            out->GetPoint(id, p);
            ref->GetPoint(id, q);
            moved += distance > 0 && (p[0] != q[0] || p[1] != q[1] || p[2] != q[2]);
            if (distance >= 2)
            {
              out->GetPointData()->GetNormals()->GetTuple(id, n);
              ref->GetPointData()->GetNormals()->GetTuple(id, m);
              worst = std::max(worst, AngleDeg({ n[0], n[1], n[2] }, { m[0], m[1], m[2] }));
            }
          }
        }
        EXPECT_EQ(moved, 0);
        EXPECT_LT(worst, 1e-9);
      }
    }
  }
}

// OutputPointsPrecision picks the type of the output points, normals and tangents as VTK's
// filters do; the values agree with the other precision's to float's precision.
TEST(DisplacementMapFilter, OutputPointsPrecision)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  for (const bool floatInput : { true, false })
  {
    auto mesh = MakeMesh(s, 32, 16, true, floatInput);
    vtkSmartPointer<vtkPolyData> outputs[3];
    for (int precision : { vtkAlgorithm::DEFAULT_PRECISION, vtkAlgorithm::SINGLE_PRECISION,
           vtkAlgorithm::DOUBLE_PRECISION })
    {
      vtkNew<vtkDisplacementMapFilter> f;
      f->SetInputData(mesh);
      f->SetSourceData(image);
      f->SetScaleFactor(0.1);
      f->SetMidlevel(0.5);
      f->SetOutputPointsPrecision(precision);
      f->Update();
      vtkPolyData* out = f->GetOutput();
      const int expected = precision == vtkAlgorithm::SINGLE_PRECISION ||
          (precision == vtkAlgorithm::DEFAULT_PRECISION && floatInput)
        ? VTK_FLOAT
        : VTK_DOUBLE;
      EXPECT_EQ(out->GetPoints()->GetDataType(), expected) << precision << " " << floatInput;
      EXPECT_EQ(out->GetPointData()->GetNormals()->GetDataType(), expected);
      EXPECT_EQ(out->GetPointData()->GetTangents()->GetDataType(), expected);
      outputs[precision] = vtkSmartPointer<vtkPolyData>::New();
      outputs[precision]->DeepCopy(out);
    }
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3];
      outputs[vtkAlgorithm::SINGLE_PRECISION]->GetPoint(i, a);
      outputs[vtkAlgorithm::DOUBLE_PRECISION]->GetPoint(i, b);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(a[c], b[c], 1e-6);
      }
    }
  }
}

// SetSourceConnection and SetSourceData are the height map's port, as VTK's two-input filters
// name their second input.
TEST(DisplacementMapFilter, SourceIsTheHeightMap)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  auto mesh = MakeMesh(s, 32, 16, true, true);
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(image);
  vtkNew<vtkDisplacementMapFilter> byPort, bySource;
  byPort->SetInputData(0, mesh);
  byPort->SetInputConnection(1, producer->GetOutputPort());
  bySource->SetInputData(0, mesh);
  bySource->SetSourceConnection(producer->GetOutputPort());
  byPort->Update();
  bySource->Update();
  EXPECT_EQ(bySource->GetInputConnection(1, 0), producer->GetOutputPort());
  EXPECT_TRUE(SameBits(
    byPort->GetOutput()->GetPoints()->GetData(), bySource->GetOutput()->GetPoints()->GetData()));
  EXPECT_GT(byPort->GetOutput()->GetNumberOfPoints(), 0);
}
