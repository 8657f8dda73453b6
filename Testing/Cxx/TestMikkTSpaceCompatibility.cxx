// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkMikkTSpaceTangents against the reference MikkTSpace (npm package "mikktspace", a
// WebAssembly build of the reference algorithm, run by node) on the same meshes: per
// triangle corner, the angle between the two tangents and the handedness.
#include "MikkTSpaceTestMeshes.h"
#include "TangentFrameTestHelpers.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCommand.h"
#include "vtkMath.h"
#include "vtkMikkTSpaceTangents.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricKlein.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolyDataTangents.h"
#include "vtkTexturedSphereSource.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>

namespace
{
using namespace mikktest;

class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  int Count = 0;
};

struct Agreement
{
  double MeanDeg = 0.0;
  double MaxDeg = 0.0;
  size_t HandednessMismatches = 0;
  size_t Count = 0;
  size_t ReferencePlaceholders = 0; // reference frames exactly (1, 0, 0)
  size_t ReferenceZero = 0;         // reference frames (0, 0, 0)
  size_t UnexplainedZero = 0;       // of those, corners that are not a zero-angle sliver
};

// Squared distance in single precision, the reference's LengthSquared(vsub(b, a)).
float Length2(const float* a, const float* b, int n)
{
  float s = 0.0f;
  for (int k = 0; k < n; ++k)
  {
    s += (b[k] - a[k]) * (b[k] - a[k]);
  }
  return s;
}

// The reference takes triangles only: quads are handed to it split the way the reference
// splits them itself (shorter diagonal in texture space, in position space on a tie, in
// its single precision), so that both sides see the same triangles.
void SplitQuad(vtkPolyData* pd, const vtkIdType* q, std::vector<vtkIdType>& tris)
{
  float t[4][2], p[4][3];
  for (int k = 0; k < 4; ++k)
  {
    double tc[2], x[3];
    pd->GetPointData()->GetTCoords()->GetTuple(q[k], tc);
    pd->GetPoint(q[k], x);
    std::copy(tc, tc + 2, t[k]);
    std::copy(x, x + 3, p[k]);
  }
  const float t02 = Length2(t[0], t[2], 2), t13 = Length2(t[1], t[3], 2);
  bool diag02 = t02 < t13;
  if (!(t02 < t13) && !(t13 < t02))
  {
    diag02 = !(Length2(p[1], p[3], 3) < Length2(p[0], p[2], 3));
  }
  const int a[6] = { 0, 1, 2, 0, 2, 3 }, b[6] = { 0, 1, 3, 1, 2, 3 };
  for (int k = 0; k < 6; ++k)
  {
    tris.push_back(q[diag02 ? a[k] : b[k]]);
  }
}

// The reference's weight of corner k of triangle tri (EvalTspace, in its single precision):
// the angle between the edges at the corner projected onto the normal's tangent plane.
float ReferenceCornerAngle(vtkPolyData* pd, const vtkIdType* tri, int k)
{
  float p[3][3], n[3];
  for (int j = 0; j < 3; ++j)
  {
    double x[3];
    pd->GetPoint(tri[(k + j + 2) % 3], x);
    std::copy(x, x + 3, p[j]);
  }
  double nd[3];
  pd->GetPointData()->GetNormals()->GetTuple(tri[k], nd);
  std::copy(nd, nd + 3, n);
  float e[2][3];
  for (int side = 0; side < 2; ++side)
  {
    float* v = e[side];
    for (int c = 0; c < 3; ++c)
    {
      v[c] = p[2 * side][c] - p[1][c];
    }
    const float d = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    for (int c = 0; c < 3; ++c)
    {
      v[c] = v[c] - d * n[c];
    }
    if (std::abs(v[0]) > FLT_MIN || std::abs(v[1]) > FLT_MIN || std::abs(v[2]) > FLT_MIN)
    {
      const float l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      for (int c = 0; c < 3; ++c)
      {
        v[c] = v[c] * (1.0f / l);
      }
    }
  }
  const float cosine = e[0][0] * e[1][0] + e[0][1] * e[1][1] + e[0][2] * e[1][2];
  return static_cast<float>(std::acos(std::min(1.0f, std::max(-1.0f, cosine))));
}

vtkSmartPointer<vtkPolyData> RunFilter(vtkPolyData* input)
{
  vtkNew<vtkMikkTSpaceTangents> filter;
  vtkNew<ErrorCounter> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->SetInputData(input);
  filter->Update();
  EXPECT_EQ(errors->Count, 0);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(filter->GetOutput());
  return out;
}

using PointFilter = std::function<bool(vtkPolyData*, vtkIdType)>;

Agreement CompareWithReference(
  vtkPolyData* out, const std::string& tag, const PointFilter& skip = nullptr)
{
  Agreement a;
  std::vector<vtkIdType> tris;
  auto it = vtk::TakeSmartPointer(out->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* pts;
    it->GetCurrentCell(n, pts);
    if (n == 3)
    {
      tris.insert(tris.end(), pts, pts + 3);
    }
    else if (n == 4)
    {
      SplitQuad(out, pts, tris);
    }
    else
    {
      ADD_FAILURE() << "unexpected polygon with " << n << " points";
    }
  }
  Corners corners;
  for (vtkIdType pt : tris)
  {
    corners.Add(out, pt);
  }
  const std::vector<float> ref = ReferenceTangents(corners, tag);
  if (ref.empty())
  {
    ADD_FAILURE() << "the reference (node + npm package mikktspace in " << MIKKTSPACE_NPM_DIR
                  << ") did not run";
    a.MaxDeg = 180.0;
    return a;
  }
  auto tangents = TangentFrame(out);
  double sum = 0.0;
  for (size_t c = 0; c < tris.size(); ++c)
  {
    if (skip && skip(out, tris[c]))
    {
      continue;
    }
    double t[4], n[3];
    tangents->GetTuple(tris[c], t);
    out->GetPointData()->GetNormals()->GetTuple(tris[c], n);
    const float* r = ref.data() + 4 * c;
    // Corners that no group reaches get the reference's placeholder (1, 0, 0), which need
    // not be a tangent at all; the filter makes it orthogonal to the normal (any unit
    // orthogonal vector if it is along the normal). Compare with that.
    double rv[3] = { r[0], r[1], r[2] };
    bool comparable = true;
    if (r[0] == 1.0f && r[1] == 0.0f && r[2] == 0.0f)
    {
      ++a.ReferencePlaceholders;
      double nn[3] = { n[0], n[1], n[2] };
      vtkMath::Normalize(nn);
      const double d = vtkMath::Dot(rv, nn);
      for (int k = 0; k < 3; ++k)
      {
        rv[k] -= d * nn[k];
      }
      comparable = vtkMath::Normalize(rv) > 1e-6;
    }
    // The one place where the filter differs from the reference on purpose: the reference
    // weighs a corner by the acos of the cosine of its projected edges in single
    // precision, which is exactly 0 at a sliver (two edges within about 3e-4 radians); a
    // group made of such corners only has a weight sum of 0 and the reference returns a
    // zero vector, no direction at all. The filter's angle (atan2 in double) keeps the
    // sliver's small weight and returns the group's direction. Any other zero vector
    // would be a disagreement the rule does not explain.
    if (r[0] == 0.0f && r[1] == 0.0f && r[2] == 0.0f)
    {
      ++a.ReferenceZero;
      comparable = false;
      if (ReferenceCornerAngle(out, &tris[c - c % 3], static_cast<int>(c % 3)) != 0.0f)
      {
        ++a.UnexplainedZero;
      }
    }
    if ((t[3] > 0) != (r[3] > 0))
    {
      ++a.HandednessMismatches;
    }
    if (!comparable)
    {
      continue;
    }
    ++a.Count;
    const double cosine = vtkMath::Dot(t, rv) / (vtkMath::Norm(rv) * vtkMath::Norm(t));
    const double deg =
      vtkMath::DegreesFromRadians(std::acos(std::min(1.0, std::max(-1.0, cosine))));
    sum += deg;
    a.MaxDeg = std::max(a.MaxDeg, std::isfinite(deg) ? deg : 180.0);
  }
  a.MeanDeg = sum / static_cast<double>(a.Count);
  return a;
}

void ExpectAgreement(vtkPolyData* input, const std::string& tag, const PointFilter& skip = nullptr)
{
  auto out = RunFilter(input);
  ASSERT_NE(out->GetPointData()->GetTangents(), nullptr);
  const Agreement a = CompareWithReference(out, tag, skip);
  std::cout << tag << ": " << a.Count << " corners, mean " << a.MeanDeg << " deg, max " << a.MaxDeg
            << " deg, handedness mismatches " << a.HandednessMismatches
            << ", reference placeholders " << a.ReferencePlaceholders << ", zero vectors "
            << a.ReferenceZero << "\n";
  EXPECT_GT(a.Count, 0u);
  EXPECT_LT(a.MeanDeg, 0.1);
  EXPECT_LT(a.MaxDeg, 1.0);
  EXPECT_EQ(a.HandednessMismatches, 0u);
  EXPECT_EQ(a.UnexplainedZero, 0u);
}
} // namespace

TEST(MikkTSpaceCompatibility, Plane)
{
  ExpectAgreement(MakePlane(24), "plane");
}

// At a pole the dP/ds directions of the fan point all round the circle and nearly cancel:
// their average is decided by their last bits, and the filter agrees with the reference
// there only because it keeps them in double (rounded to single precision they give a
// frame 172 degrees off at a pole).
TEST(MikkTSpaceCompatibility, UVSphereWithPoles)
{
  ExpectAgreement(MakeUVSphere(48, 24), "uvsphere");
}

// VTK's own textured sphere has a row of points per pole. At the north pole they coincide
// (degenerate triangles, which take their frames from a good corner the reference's way).
// At the south pole they lie on a circle of radius 6e-17 (sin(pi) in double): slivers
// whose texture orientation and usable derivatives the reference decides in single
// precision, which the filter does too; every point is compared.
TEST(MikkTSpaceCompatibility, VTKTexturedSphere)
{
  vtkNew<vtkTexturedSphereSource> sphere;
  sphere->SetThetaResolution(36);
  sphere->SetPhiResolution(18);
  sphere->Update();
  ExpectAgreement(sphere->GetOutput(), "texturedsphere");
}

// A non-orientable surface, as VTK makes it: vtkParametricFunctionSource's Klein bottle
// (its seam sampled twice, with join triangles whose texture coordinates jump across the
// texture) with normals from vtkPolyDataNormals, splitting off. Its seams have slivers in
// position space (points 1e-16 apart) with a texture area, near-zero texture areas whose
// sign single precision decides, and groups whose only corners are slivers; every corner
// is compared (the slivers' zero vectors under the rule in CompareWithReference).
TEST(MikkTSpaceCompatibility, KleinBottle)
{
  vtkNew<vtkParametricKlein> klein;
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(klein);
  source->SetUResolution(40);
  source->SetVResolution(20);
  source->GenerateTextureCoordinatesOn();
  source->Update();
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(source->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  ExpectAgreement(normals->GetOutput(), "klein");
}

TEST(MikkTSpaceCompatibility, Torus)
{
  ExpectAgreement(MakeTorus(48, 24), "torus");
}

// The mirror line's points are shared by triangles of both orientations: MikkTSpace gives
// them two frames, so each of the n+1 points on the line must be split once.
TEST(MikkTSpaceCompatibility, MirroredUVShell)
{
  const int n = 16;
  auto sheet = MakeMirroredSheet(n);
  ExpectAgreement(sheet, "mirrored");
  auto out = RunFilter(sheet);
  EXPECT_EQ(out->GetNumberOfPoints(), sheet->GetNumberOfPoints() + n + 1);
  EXPECT_EQ(out->GetNumberOfPolys(), sheet->GetNumberOfPolys());
}

TEST(MikkTSpaceCompatibility, TextureSeam)
{
  auto cylinder = MakeSeamCylinder(32, 8);
  ExpectAgreement(cylinder, "seam");
  // Seam points are already separate in the input: nothing to split.
  auto out = RunFilter(cylinder);
  EXPECT_EQ(out->GetNumberOfPoints(), cylinder->GetNumberOfPoints());
}

// MikkTSpace identifies vertices by value, not by index: a triangle soup with smooth
// normals must give the same frames as the indexed mesh.
TEST(MikkTSpaceCompatibility, UnweldedTorus)
{
  auto soup = Unweld(MakeTorus(24, 12));
  ExpectAgreement(soup, "soup");
}

// Quads kept as quads: the filter's internal split must be MikkTSpace's.
TEST(MikkTSpaceCompatibility, NonPlanarQuads)
{
  auto quads = MakeGrid(
    24, 12,
    [](double u, double v)
    {
      Sample s = SpherePoint(u, 0.1 + 0.8 * v);
      s.P[2] += 0.3 * std::sin(9 * u) * std::cos(5 * v);
      s.T = { u + 0.02 * std::sin(2 * Pi * 5 * v), v + 0.03 * std::sin(2 * Pi * 3 * u) };
      return s;
    },
    true);
  auto out = RunFilter(quads);
  EXPECT_EQ(out->GetNumberOfPolys(), quads->GetNumberOfPolys());
  EXPECT_EQ(out->GetPolys()->GetMaxCellSize(), 4);
  ExpectAgreement(quads, "quads");
}

// Triangles without usable texture derivatives (zero texture area) join the first group
// that reaches them and take its orientation: the reference's one order dependency.
TEST(MikkTSpaceCompatibility, ZeroAreaTextureTriangles)
{
  auto torus = MakeTorus(48, 24);
  vtkDataArray* tc = torus->GetPointData()->GetTCoords();
  for (vtkIdType i = 3; i + 1 < tc->GetNumberOfTuples(); i += 11)
  {
    tc->SetTuple(i, tc->GetTuple(i + 1));
  }
  ExpectAgreement(torus, "zerouvarea");
}

// The same on a mirrored shell, where the orientation they take matters: on the mirror
// line it depends on which group reaches them first.
TEST(MikkTSpaceCompatibility, ZeroAreaTextureTrianglesOnMirroredShell)
{
  auto sheet = MakeMirroredSheet(16);
  vtkDataArray* tc = sheet->GetPointData()->GetTCoords();
  // every other point of the mirror line (column 16 of 33) takes its right neighbour's
  // texture coordinates, and so do scattered points
  for (vtkIdType j = 0; j <= 16; j += 2)
  {
    tc->SetTuple(j * 33 + 16, tc->GetTuple(j * 33 + 17));
  }
  for (vtkIdType i = 5; i + 1 < tc->GetNumberOfTuples(); i += 13)
  {
    tc->SetTuple(i, tc->GetTuple(i + 1));
  }
  ExpectAgreement(sheet, "zerouvmirrored");
}

// A random soup on few vertices: many edges shared by three or more triangles in either
// direction (paired greedily in triangle order), duplicate triangles, triangles with a
// repeated vertex (degenerate), mixed texture orientations. Continuous random values keep
// the averages well-conditioned; handedness checks the grouping on every corner.
void ExpectAgreementOnRandomSoup(int nPoints, int nTriangles, const std::string& tag)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  auto uniform = [&random]()
  {
    random->Next();
    return random->GetValue();
  };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> normals, tcoords;
  normals->SetNumberOfComponents(3);
  tcoords->SetNumberOfComponents(2);
  for (int i = 0; i < nPoints; ++i)
  {
    points->InsertNextPoint(uniform(), uniform(), 0.3 * uniform());
    double n[3] = { 0.4 * (uniform() - 0.5), 0.4 * (uniform() - 0.5), 1.0 };
    vtkMath::Normalize(n);
    normals->InsertNextTuple(n);
    tcoords->InsertNextTuple2(uniform(), uniform());
  }
  vtkNew<vtkCellArray> polys;
  for (int t = 0; t < nTriangles; ++t)
  {
    vtkIdType ids[3];
    for (auto& id : ids)
    {
      id = std::min<vtkIdType>(nPoints - 1, static_cast<vtkIdType>(uniform() * nPoints));
    }
    polys->InsertNextCell(3, ids);
  }
  auto soup = MakeSurface(points, polys, normals, tcoords);
  ExpectAgreement(soup, tag);
}

TEST(MikkTSpaceCompatibility, RandomNonManifoldSoup)
{
  ExpectAgreementOnRandomSoup(300, 3000, "soup-random");
}

// About 90 triangles per vertex: the filter's large-fan path (edges paired by sorting).
TEST(MikkTSpaceCompatibility, RandomNonManifoldSoupLargeFans)
{
  ExpectAgreementOnRandomSoup(100, 3000, "soup-random-large");
}

// A disc of 600 triangles around one shared centre point, texture bent so that the
// directions vary around it: a group larger than the sub-group test's limit.
TEST(MikkTSpaceCompatibility, LargeFan)
{
  const int n = 600;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> normals, tcoords;
  normals->SetNumberOfComponents(3);
  tcoords->SetNumberOfComponents(2);
  auto add = [&](double x, double y)
  {
    points->InsertNextPoint(x, y, 0.1 * x * y);
    double nn[3] = { -0.1 * y, -0.1 * x, 1.0 };
    vtkMath::Normalize(nn);
    normals->InsertNextTuple(nn);
    tcoords->InsertNextTuple2(x + 0.2 * y * y, y + 0.1 * x);
  };
  add(0.0, 0.0);
  for (int i = 0; i < n; ++i)
  {
    add(std::cos(2 * Pi * i / n), std::sin(2 * Pi * i / n));
  }
  vtkNew<vtkCellArray> polys;
  for (int i = 0; i < n; ++i)
  {
    const vtkIdType t[3] = { 0, 1 + i, 1 + (i + 1) % n };
    polys->InsertNextCell(3, t);
  }
  auto disc = MakeSurface(points, polys, normals, tcoords);
  ExpectAgreement(disc, "largefan");
}

// The comparison must be able to fail: VTK's vtkPolyDataTangents (unweighted average, no
// handedness) on the mirrored shell is far from MikkTSpace.
TEST(MikkTSpaceCompatibility, ComparisonDetectsVTKPolyDataTangents)
{
  auto sheet = MakeMirroredSheet(16);
  vtkNew<vtkPolyDataTangents> vtkTangents;
  vtkTangents->SetInputData(sheet);
  vtkTangents->Update();
  // Its 3-component tangents without a handedness array are read with w = +1, as VTK does.
  vtkPolyData* out = vtkTangents->GetOutput();
  ASSERT_NE(out->GetPointData()->GetTangents(), nullptr);
  const Agreement a = CompareWithReference(out, "vtkpolydatatangents");
  std::cout << "vtkPolyDataTangents: mean " << a.MeanDeg << " deg, max " << a.MaxDeg
            << " deg, handedness mismatches " << a.HandednessMismatches << "\n";
  EXPECT_GT(a.MaxDeg, 1.0);
  EXPECT_GT(a.HandednessMismatches, 0u);
}
