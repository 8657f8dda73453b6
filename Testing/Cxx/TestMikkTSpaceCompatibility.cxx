// vtkMikkTSpaceTangents against the reference MikkTSpace (npm package "mikktspace", a
// WebAssembly build of the reference algorithm, run by node) on the same meshes: per
// triangle corner, the angle between the two tangents and the handedness.
#include "MikkTSpaceTestMeshes.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCommand.h"
#include "vtkMath.h"
#include "vtkMikkTSpaceTangents.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPolyDataTangents.h"
#include "vtkTexturedSphereSource.h"

#include <gtest/gtest.h>

#include <algorithm>
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
};

double Length2(const double* a, const double* b)
{
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
}

// The reference takes triangles only: quads are handed to it split the way the MikkTSpace
// description says it splits them itself (shorter diagonal in texture space, in position
// space on a tie), so that both sides see the same triangles.
void SplitQuad(vtkPolyData* pd, const vtkIdType* q, std::vector<vtkIdType>& tris)
{
  double t[4][2], p[4][3];
  for (int k = 0; k < 4; ++k)
  {
    pd->GetPointData()->GetTCoords()->GetTuple(q[k], t[k]);
    pd->GetPoint(q[k], p[k]);
  }
  const double t02 = Length2(t[0], t[2]), t13 = Length2(t[1], t[3]);
  bool diag02 = t02 < t13;
  if (t02 == t13)
  {
    const double p02 = vtkMath::Distance2BetweenPoints(p[0], p[2]);
    const double p13 = vtkMath::Distance2BetweenPoints(p[1], p[3]);
    diag02 = !(p13 < p02);
  }
  const int a[6] = { 0, 1, 2, 0, 2, 3 }, b[6] = { 0, 1, 3, 1, 2, 3 };
  for (int k = 0; k < 6; ++k)
  {
    tris.push_back(q[diag02 ? a[k] : b[k]]);
  }
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
  vtkDataArray* tangents = out->GetPointData()->GetArray("Tangents");
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
    // Where no triangle around a vertex has a direction off the normal, the reference's
    // average is a zero vector: no direction to compare (the filter gives a unit one).
    if (r[0] == 0.0f && r[1] == 0.0f && r[2] == 0.0f)
    {
      ++a.ReferenceZero;
      comparable = false;
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
  ASSERT_NE(out->GetPointData()->GetArray("Tangents"), nullptr);
  const Agreement a = CompareWithReference(out, tag, skip);
  std::cout << tag << ": " << a.Count << " corners, mean " << a.MeanDeg << " deg, max " << a.MaxDeg
            << " deg, handedness mismatches " << a.HandednessMismatches
            << ", reference placeholders " << a.ReferencePlaceholders << ", zero vectors "
            << a.ReferenceZero << "\n";
  EXPECT_GT(a.Count, 0u);
  EXPECT_LT(a.MeanDeg, 0.1);
  EXPECT_LT(a.MaxDeg, 1.0);
  EXPECT_EQ(a.HandednessMismatches, 0u);
}
} // namespace

TEST(MikkTSpaceCompatibility, Plane)
{
  ExpectAgreement(MakePlane(24), "plane");
}

TEST(MikkTSpaceCompatibility, UVSphereWithPoles)
{
  ExpectAgreement(MakeUVSphere(48, 24), "uvsphere");
}

// VTK's own textured sphere has a row of points per pole. At the north pole they coincide
// (degenerate triangles, which take their frames from a good corner the reference's way).
// At the south pole they lie on a circle of radius 6e-17 (sin(pi) in double): the slivers
// there have a dP/ds smaller than single-precision rounding of their edges, and the
// reference's frames at those points come from float cancellation noise (they differ
// from the fan triangle's direction by up to 90 degrees, and one even in handedness).
// Those 37 points are left out here; StressVTKTexturedSpherePoles checks their validity.
TEST(MikkTSpaceCompatibility, VTKTexturedSphere)
{
  vtkNew<vtkTexturedSphereSource> sphere;
  sphere->SetThetaResolution(36);
  sphere->SetPhiResolution(18);
  sphere->Update();
  ExpectAgreement(sphere->GetOutput(), "texturedsphere",
    [](vtkPolyData* pd, vtkIdType pt)
    {
      double p[3];
      pd->GetPoint(pt, p);
      return p[2] < -0.5 + 1e-9 && std::hypot(p[0], p[1]) < 1e-15;
    });
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
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(vtkTangents->GetOutput());
  vtkDataArray* t3 = out->GetPointData()->GetTangents();
  ASSERT_NE(t3, nullptr);
  vtkNew<vtkFloatArray> t4;
  t4->SetName("Tangents");
  t4->SetNumberOfComponents(4);
  t4->SetNumberOfTuples(t3->GetNumberOfTuples());
  for (vtkIdType i = 0; i < t3->GetNumberOfTuples(); ++i)
  {
    const double* t = t3->GetTuple3(i);
    t4->SetTuple4(i, t[0], t[1], t[2], 1.0);
  }
  // Removing the attribute array also clears the attribute.
  out->GetPointData()->RemoveArray(std::string(t3->GetName()).c_str());
  out->GetPointData()->AddArray(t4);
  const Agreement a = CompareWithReference(out, "vtkpolydatatangents");
  std::cout << "vtkPolyDataTangents: mean " << a.MeanDeg << " deg, max " << a.MaxDeg
            << " deg, handedness mismatches " << a.HandednessMismatches << "\n";
  EXPECT_GT(a.MaxDeg, 1.0);
  EXPECT_GT(a.HandednessMismatches, 0u);
}
