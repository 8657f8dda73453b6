// vtkMikkTSpaceTangents: closed-form frames, bad input, degenerate input (stress), kept
// arrays and cells, thread-count independence.
#include "EveryBuildTestHelpers.h"
#include "MikkTSpaceTestMeshes.h"
#include "RenumberedPointsTestHelpers.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMikkTSpaceTangents.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkParametricCylinder.h"
#include "vtkParametricDonut.h"
#include "vtkParametricSphere.h"
#include "vtkParametricSurfaceSource.h"
#include "vtkParametricTorus.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkTexturedSphereSource.h"

#include <gtest/gtest.h>

#if defined(__SSE__) || defined(__x86_64__) || defined(_M_X64)
#include <xmmintrin.h> // _mm_getcsr
#endif

#ifdef __linux__
#include <sys/mman.h> // mmap, a guard page after a points array
#include <unistd.h>   // sysconf
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace mikktest;

class EventCounter : public vtkCommand
{
public:
  static EventCounter* New() { return new EventCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  int Count = 0;
};

struct FilterRun
{
  vtkNew<vtkMikkTSpaceTangents> Filter;
  vtkNew<EventCounter> Errors, Warnings;
  explicit FilterRun(vtkDataObject* input)
  {
    this->Filter->AddObserver(vtkCommand::ErrorEvent, this->Errors);
    this->Filter->AddObserver(vtkCommand::WarningEvent, this->Warnings);
    this->Filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Errors);
    this->Filter->SetInputData(input);
    this->Filter->Update();
  }
  vtkPolyData* Output() { return this->Filter->GetOutput(); }
};

// Every output frame: finite, unit, orthogonal to the (unit) normal, w = +-1.
void ExpectValidFrames(vtkPolyData* out)
{
  vtkDataArray* tangents = out->GetPointData()->GetArray("Tangents");
  ASSERT_NE(tangents, nullptr);
  ASSERT_EQ(tangents->GetNumberOfComponents(), 4);
  ASSERT_EQ(tangents->GetNumberOfTuples(), out->GetNumberOfPoints());
  EXPECT_STREQ(tangents->GetName(), "Tangents");
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  int bad = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double t[4], n[3];
    tangents->GetTuple(i, t);
    normals->GetTuple(i, n);
    const bool finite = std::isfinite(t[0]) && std::isfinite(t[1]) && std::isfinite(t[2]);
    const bool unit = std::abs(vtkMath::Norm(t) - 1.0) < 1e-5;
    const bool sign = t[3] == 1.0 || t[3] == -1.0;
    bool orthogonal = true;
    const double nl = vtkMath::Norm(n);
    if (std::isfinite(nl) && nl > 0.0)
    {
      orthogonal = std::abs(vtkMath::Dot(t, n)) / nl < 1e-5;
    }
    if (!(finite && unit && sign && orthogonal) && bad++ < 5)
    {
      ADD_FAILURE() << "point " << i << ": tangent (" << t[0] << ", " << t[1] << ", " << t[2]
                    << ", " << t[3] << "), normal (" << n[0] << ", " << n[1] << ", " << n[2] << ")";
    }
  }
  EXPECT_EQ(bad, 0);
}

// A flat grid in z = 0 with texture coordinates A*(x, y): dP/ds is the first column of
// A^-1, and the handedness is the sign of det A.
vtkSmartPointer<vtkPolyData> AffinePlane(int n, const double A[2][2])
{
  return MakeGrid(n, n,
    [A](double u, double v)
    {
      return Sample{ { u, v, 0.0 }, { 0.0, 0.0, 1.0 },
        { A[0][0] * u + A[0][1] * v, A[1][0] * u + A[1][1] * v } };
    });
}

void ExpectAffineFrames(vtkPolyData* out, const double A[2][2])
{
  const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
  double dPds[3] = { A[1][1] / det, -A[1][0] / det, 0.0 };
  vtkMath::Normalize(dPds);
  vtkDataArray* tangents = out->GetPointData()->GetArray("Tangents");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double t[4];
    tangents->GetTuple(i, t);
    ASSERT_NEAR(t[0], dPds[0], 1e-5) << "point " << i;
    ASSERT_NEAR(t[1], dPds[1], 1e-5) << "point " << i;
    ASSERT_NEAR(t[2], 0.0, 1e-6) << "point " << i;
    ASSERT_EQ(t[3], det > 0 ? 1.0 : -1.0) << "point " << i;
  }
}
} // namespace

TEST(vtkMikkTSpaceTangents, PrintSelf)
{
  vtkNew<vtkMikkTSpaceTangents> filter;
  EXPECT_EQ(filter->GetAngularThreshold(), 180.0);
  filter->SetAngularThreshold(400.0);
  EXPECT_EQ(filter->GetAngularThreshold(), 180.0);
  filter->SetAngularThreshold(90.0);
  std::ostringstream os;
  filter->Print(os);
  EXPECT_NE(os.str().find("AngularThreshold: 90"), std::string::npos);
}

TEST(vtkMikkTSpaceTangents, AffinePlaneClosedForm)
{
  const double A[2][2] = { { 2.0, 0.5 }, { -0.3, 1.5 } };
  FilterRun run(AffinePlane(8, A));
  EXPECT_EQ(run.Errors->Count, 0);
  ExpectValidFrames(run.Output());
  ExpectAffineFrames(run.Output(), A);
}

TEST(vtkMikkTSpaceTangents, MirroredAffinePlaneIsLeftHanded)
{
  const double A[2][2] = { { -1.0, 0.2 }, { 0.1, 1.0 } };
  FilterRun run(AffinePlane(8, A));
  ExpectValidFrames(run.Output());
  ExpectAffineFrames(run.Output(), A);
}

TEST(vtkMikkTSpaceTangents, QuadsStripsPolygonsVertsLinesAndCellData)
{
  // z = 0 with s = x, t = y: every frame is (1, 0, 0, +1) if every triangle is wound the
  // right way (a strip's odd triangles, a triangulated hexagon, quads).
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals, tcoords;
  normals->SetNumberOfComponents(3);
  tcoords->SetNumberOfComponents(2);
  auto add = [&](double x, double y)
  {
    points->InsertNextPoint(x, y, 0.0);
    normals->InsertNextTuple3(0.0, 0.0, 1.0);
    tcoords->InsertNextTuple2(x, y);
    return points->GetNumberOfPoints() - 1;
  };
  // strip along y = 0..1, x = 0..4
  std::vector<vtkIdType> strip;
  for (int k = 0; k < 5; ++k)
  {
    // top first: the strip's first triangle is then counter-clockwise
    strip.push_back(add(k, 1.0));
    strip.push_back(add(k, 0.0));
  }
  // hexagon at (10, 0), a quad at (20, 0), a lone vertex and a line
  std::vector<vtkIdType> hexagon;
  for (int k = 0; k < 6; ++k)
  {
    hexagon.push_back(add(10 + std::cos(k * Pi / 3), std::sin(k * Pi / 3)));
  }
  const vtkIdType quad[4] = { add(20, 0), add(21, 0), add(21, 1), add(20, 1) };
  const vtkIdType lone = add(30, 0);
  const vtkIdType line[2] = { add(40, 0), add(41, 0) };
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->GetPointData()->SetNormals(normals);
  pd->GetPointData()->SetTCoords(tcoords);
  vtkNew<vtkCellArray> verts, lines, polys, strips;
  verts->InsertNextCell(1, &lone);
  lines->InsertNextCell(2, line);
  polys->InsertNextCell(6, hexagon.data());
  polys->InsertNextCell(4, quad);
  strips->InsertNextCell(static_cast<vtkIdType>(strip.size()), strip.data());
  pd->SetVerts(verts);
  pd->SetLines(lines);
  pd->SetPolys(polys);
  pd->SetStrips(strips);
  vtkNew<vtkIdTypeArray> cellIds;
  cellIds->SetName("CellId");
  for (vtkIdType c = 0; c < 5; ++c)
  {
    cellIds->InsertNextValue(c);
  }
  pd->GetCellData()->AddArray(cellIds);

  FilterRun run(pd);
  EXPECT_EQ(run.Errors->Count, 0);
  vtkPolyData* out = run.Output();
  ExpectValidFrames(out);
  EXPECT_EQ(out->GetNumberOfPoints(), pd->GetNumberOfPoints());
  EXPECT_EQ(out->GetNumberOfVerts(), 1);
  EXPECT_EQ(out->GetNumberOfLines(), 1);
  EXPECT_EQ(out->GetNumberOfStrips(), 0);
  // hexagon -> 4 triangles, quad kept, strip of 10 points -> 8 triangles
  ASSERT_EQ(out->GetNumberOfPolys(), 4 + 1 + 8);
  auto* outIds = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("CellId"));
  ASSERT_NE(outIds, nullptr);
  const vtkIdType expected[15] = { 0, 1, 2, 2, 2, 2, 3, 4, 4, 4, 4, 4, 4, 4, 4 };
  ASSERT_EQ(outIds->GetNumberOfValues(), 15);
  for (vtkIdType c = 0; c < 15; ++c)
  {
    EXPECT_EQ(outIds->GetValue(c), expected[c]) << "cell " << c;
  }
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    if (i == lone || i == line[0] || i == line[1])
    {
      continue;
    }
    double t[4];
    out->GetPointData()->GetArray("Tangents")->GetTuple(i, t);
    EXPECT_NEAR(t[0], 1.0, 1e-6) << "point " << i;
    EXPECT_EQ(t[3], 1.0) << "point " << i;
  }
}

// Split points carry copies of all point data; cell data and connectivity stay consistent.
TEST(vtkMikkTSpaceTangents, SplitPointsKeepPointData)
{
  auto sheet = MakeMirroredSheet(8);
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("PointId");
  for (vtkIdType i = 0; i < sheet->GetNumberOfPoints(); ++i)
  {
    ids->InsertNextValue(i);
  }
  sheet->GetPointData()->AddArray(ids);
  vtkNew<vtkFloatArray> oldTangents;
  oldTangents->SetNumberOfComponents(3);
  oldTangents->SetNumberOfTuples(sheet->GetNumberOfPoints());
  oldTangents->Fill(7.0);
  oldTangents->SetName("OldTangents");
  sheet->GetPointData()->SetTangents(oldTangents);
  const vtkIdType nIn = sheet->GetNumberOfPoints();

  FilterRun run(sheet);
  vtkPolyData* out = run.Output();
  ExpectValidFrames(out);
  ASSERT_EQ(out->GetNumberOfPoints(), nIn + 9);
  EXPECT_EQ(sheet->GetNumberOfPoints(), nIn); // input untouched
  auto* outIds = vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("PointId"));
  ASSERT_NE(outIds, nullptr);
  for (vtkIdType q = 0; q < out->GetNumberOfPoints(); ++q)
  {
    const vtkIdType p = outIds->GetValue(q);
    ASSERT_TRUE(q < nIn ? p == q : (p >= 0 && p < nIn));
    double a[3], b[3];
    out->GetPoint(q, a);
    sheet->GetPoint(p, b);
    EXPECT_EQ(vtkMath::Distance2BetweenPoints(a, b), 0.0);
    out->GetPointData()->GetTCoords()->GetTuple(q, a);
    sheet->GetPointData()->GetTCoords()->GetTuple(p, b);
    EXPECT_EQ(a[0], b[0]);
    EXPECT_EQ(a[1], b[1]);
  }
  // The split points are the mirror line's (s = 0), and the two copies differ in w.
  for (vtkIdType q = nIn; q < out->GetNumberOfPoints(); ++q)
  {
    const vtkIdType p = outIds->GetValue(q);
    double tc[2], t1[4], t2[4];
    out->GetPointData()->GetTCoords()->GetTuple(q, tc);
    EXPECT_NEAR(tc[0], 0.0, 1e-7);
    out->GetPointData()->GetArray("Tangents")->GetTuple(p, t1);
    out->GetPointData()->GetArray("Tangents")->GetTuple(q, t2);
    EXPECT_EQ(t1[3], -t2[3]);
  }
  EXPECT_EQ(out->GetPointData()->GetArray("Tangents")->GetNumberOfComponents(), 4);
  // Every corner of a triangle on the left (x < 0) is left-handed, on the right right-handed.
  vtkNew<vtkIdList> pts;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    out->GetCellPoints(c, pts);
    double centroidX = 0.0;
    for (vtkIdType k = 0; k < 3; ++k)
    {
      centroidX += out->GetPoint(pts->GetId(k))[0] / 3.0;
    }
    for (vtkIdType k = 0; k < 3; ++k)
    {
      EXPECT_EQ(out->GetPointData()->GetArray("Tangents")->GetComponent(pts->GetId(k), 3),
        centroidX > 0 ? 1.0 : -1.0);
    }
  }
}

TEST(vtkMikkTSpaceTangents, SameResultAnyThreadCount)
{
  // The torus goes the fast way (every vertex a simple fan), the others the general one.
  auto sphere = MakeUVSphere(160, 80);
  auto sheet = MakeMirroredSheet(120);
  auto torus = MakeTorus(300, 150);
  auto unwelded = Unweld(MakeTorus(60, 30));
  for (vtkPolyData* input : { sphere.Get(), sheet.Get(), torus.Get(), unwelded.Get() })
  {
    vtkSMPTools::Initialize(1);
    FilterRun one(input);
    vtkSMPTools::Initialize(2);
    FilterRun two(input);
    vtkSMPTools::Initialize(0);
    auto* t1 = vtkFloatArray::SafeDownCast(one.Output()->GetPointData()->GetArray("Tangents"));
    auto* t2 = vtkFloatArray::SafeDownCast(two.Output()->GetPointData()->GetArray("Tangents"));
    ASSERT_NE(t1, nullptr);
    ASSERT_NE(t2, nullptr);
    ASSERT_EQ(t1->GetNumberOfValues(), t2->GetNumberOfValues());
    EXPECT_EQ(0,
      std::memcmp(t1->GetPointer(0), t2->GetPointer(0), sizeof(float) * t1->GetNumberOfValues()));
    vtkDataArray* c1 = one.Output()->GetPolys()->GetConnectivityArray();
    vtkDataArray* c2 = two.Output()->GetPolys()->GetConnectivityArray();
    ASSERT_EQ(c1->GetNumberOfValues(), c2->GetNumberOfValues());
    for (vtkIdType i = 0; i < c1->GetNumberOfValues(); ++i)
    {
      ASSERT_EQ(c1->GetTuple1(i), c2->GetTuple1(i));
    }
  }
}

namespace
{
// Every point of a must get the bits that b gives point newId of it, at 1 and 2 threads,
// without errors or warnings (b: a with its points renumbered, or more points added).
void ExpectSameFramesAtNewIds(vtkPolyData* a, vtkPolyData* b, const std::vector<vtkIdType>& newId)
{
  for (int threads : { 1, 2 })
  {
    vtkSMPTools::Initialize(threads);
    FilterRun ra(a);
    FilterRun rb(b);
    EXPECT_EQ(ra.Errors->Count + rb.Errors->Count + ra.Warnings->Count + rb.Warnings->Count, 0);
    auto* ta = vtkFloatArray::SafeDownCast(ra.Output()->GetPointData()->GetArray("Tangents"));
    auto* tb = vtkFloatArray::SafeDownCast(rb.Output()->GetPointData()->GetArray("Tangents"));
    ASSERT_NE(ta, nullptr);
    ASSERT_NE(tb, nullptr);
    ASSERT_EQ(ta->GetNumberOfTuples(), a->GetNumberOfPoints());
    ASSERT_EQ(tb->GetNumberOfTuples(), b->GetNumberOfPoints());
    vtkIdType differ = 0;
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    {
      differ +=
        std::memcmp(ta->GetPointer(4 * i), tb->GetPointer(4 * newId[i]), 4 * sizeof(float)) != 0
        ? 1
        : 0;
    }
    EXPECT_EQ(differ, 0) << threads << " threads";
  }
  vtkSMPTools::Initialize(0);
}
} // namespace

// In the AVX-512 build the fast path builds its vertex lists task by task, each task from
// the triangles whose points' ids come near its own; a mesh whose points are numbered at
// random (every run of triangles spans almost all ids) takes the global vertex lists
// instead. Each point's frame depends only on its fan (its corners in triangle order), not
// on the numbering, so both must give every point the same bits, at any thread count (and
// in every build: this test runs in the -avx2 and -baseline runs too).
TEST(vtkMikkTSpaceTangents, FastPathRenumberedPointsSameFrames)
{
  auto torus = MakeTorus(300, 150);
  const std::vector<vtkIdType> newId =
    RenumberedPoints::RandomIds(torus->GetNumberOfPoints(), 4711);
  auto renumbered = RenumberedPoints::Moved(torus, newId, torus->GetNumberOfPoints());
  ExpectSameFramesAtNewIds(torus, renumbered, newId);
}

namespace
{
// The tangents of the fast path's test meshes, end to end: single and double precision,
// welded (every vertex a fan of six) and unwelded (the weld's hash finds the twins).
std::vector<float> FastPathTangents()
{
  auto torus = MakeTorus(300, 150);
  auto unwelded = Unweld(MakeTorus(60, 30));
  vtkNew<vtkPolyData> doubleTorus;
  doubleTorus->DeepCopy(MakeTorus(90, 45));
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(doubleTorus->GetPoints());
  doubleTorus->SetPoints(points);
  vtkNew<vtkDoubleArray> normals, tcoords;
  normals->DeepCopy(doubleTorus->GetPointData()->GetNormals());
  tcoords->DeepCopy(doubleTorus->GetPointData()->GetTCoords());
  doubleTorus->GetPointData()->SetNormals(normals);
  doubleTorus->GetPointData()->SetTCoords(tcoords);
  std::vector<float> all;
  for (vtkPolyData* input : { torus.Get(), unwelded.Get(), doubleTorus.Get() })
  {
    FilterRun run(input);
    auto* t = vtkFloatArray::SafeDownCast(run.Output()->GetPointData()->GetArray("Tangents"));
    if (!t)
    {
      ADD_FAILURE() << "no tangents";
      return {};
    }
    all.insert(all.end(), t->GetPointer(0), t->GetPointer(0) + t->GetNumberOfValues());
  }
  return all;
}
} // namespace

// The AVX-512, AVX2 and baseline builds of the fast path (vtkSurfaceDetailVectorize.h)
// must give the same bits: none may contract into fused multiply-adds or reorder sums. The
// build is picked once per process, so this test runs itself once per build
// (SURFACEDETAIL_MAX_ISA) and compares what the runs write; where the processor lacks a
// build, that run takes the next narrower one.
TEST(vtkMikkTSpaceTangents, SameBitsInEveryBuild)
{
  if (const char* dump = EveryBuild::DumpPath())
  {
    const std::vector<float> t = FastPathTangents();
    EveryBuild::WriteDump(
      dump, std::string(reinterpret_cast<const char*>(t.data()), t.size() * sizeof(float)));
    return;
  }
#ifdef __linux__
  const std::vector<std::string> results =
    EveryBuild::OutputsOfEveryBuild("vtkMikkTSpaceTangents.SameBitsInEveryBuild");
  ASSERT_EQ(results.size(), 3u);
  ASSERT_GT(results[0].size(), 4u * 301 * 151 * sizeof(float));
  EXPECT_TRUE(results[1] == results[0]) << "avx2 differs from the widest build";
  EXPECT_TRUE(results[2] == results[0]) << "baseline differs from the widest build";
#else
  GTEST_SKIP() << "runs itself through /proc/self/exe";
#endif
}

// Two 4-component tangent arrays of the same points: the same handedness everywhere (a failure
// otherwise, and 180 returned) and the largest angle between their directions, in degrees.
double MaxAngleSameHandedness(vtkDataArray* tf, vtkDataArray* tg, const std::string& name)
{
  if (!tf || !tg || tf->GetNumberOfTuples() != tg->GetNumberOfTuples())
  {
    ADD_FAILURE() << name << ": tangent arrays missing or of different lengths";
    return 180.0;
  }
  double maxDeg = 0.0;
  for (vtkIdType p = 0; p < tf->GetNumberOfTuples(); ++p)
  {
    double a[4], b[4];
    tf->GetTuple(p, a);
    tg->GetTuple(p, b);
    if (a[3] != b[3])
    {
      ADD_FAILURE() << name << " point " << p << ": w " << a[3] << " against " << b[3];
      return 180.0;
    }
    const double c = vtkMath::Dot(a, b) / (vtkMath::Norm(a) * vtkMath::Norm(b));
    maxDeg = std::max(maxDeg, vtkMath::DegreesFromRadians(std::acos(std::min(1.0, c))));
  }
  return maxDeg;
}

// The default (fast path where it applies) against the general algorithm, which a
// threshold below 180 degrees forces: same handedness, directions within 1e-4 degrees.
void ExpectFastPathIsGeneralPath(vtkPolyData* input, const char* name)
{
  vtkNew<vtkMikkTSpaceTangents> fast, general;
  fast->SetInputData(input);
  general->SetInputData(input);
  general->SetAngularThreshold(179.9);
  fast->Update();
  general->Update();
  EXPECT_LT(MaxAngleSameHandedness(fast->GetOutput()->GetPointData()->GetArray("Tangents"),
              general->GetOutput()->GetPointData()->GetArray("Tangents"), name),
    1e-4)
    << name;
}

// Meshes whose every vertex is a simple fan take a fast path at the default threshold; any
// other threshold takes the general algorithm, and at 179.9 degrees nothing on these
// smooth meshes separates, so both must give the same frames: same points and w, and
// directions within 1e-4 degrees (the fast path keeps the triangles' directions in single
// precision and weighs corners with a polynomial atan).
TEST(vtkMikkTSpaceTangents, FastPathAgreesWithGeneralPath)
{
  auto torus = MakeTorus(200, 100);
  auto unwelded = Unweld(MakeTorus(40, 20));
  auto plane = MakePlane(24);
  ExpectFastPathIsGeneralPath(torus, "torus");
  ExpectFastPathIsGeneralPath(unwelded, "unwelded torus");
  ExpectFastPathIsGeneralPath(plane, "plane");
}

namespace
{
// A copy of a mesh with a run of `run` points that no triangle uses (each its own position,
// normal and texture coordinates, so that none welds to another) before every `every`
// points; newId gives each old point's id.
vtkSmartPointer<vtkPolyData> WithUnusedRuns(
  vtkPolyData* in, vtkIdType every, vtkIdType run, std::vector<vtkIdType>& newId)
{
  const vtkIdType n = in->GetNumberOfPoints();
  newId.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    newId[i] = i + run * (i / every + 1);
  }
  auto out = RenumberedPoints::Moved(in, newId, newId[n - 1] + 1);
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  vtkDataArray* tcoords = out->GetPointData()->GetTCoords();
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    if (id % (every + run) < run)
    {
      const double a = 0.1 * double(id);
      out->GetPoints()->SetPoint(id, 5.0 + std::cos(a), std::sin(a), 0.001 * a);
      normals->SetTuple3(id, std::cos(a), 0.0, std::sin(a));
      tcoords->SetTuple2(id, 0.01 * a, 0.5);
    }
  }
  return out;
}
} // namespace

// In the AVX-512 build each task of the fast path gives every vertex that is not a welded
// copy a lane before it knows which have corners: the points that no triangle uses keep
// empty lanes, whole groups of lanes among them, which must change no other point's bits
// (a torus with runs of 40 unused points every 200 points against the torus, at 1 and 2
// threads) and get the general path's default frames. The task counts corners by its slots'
// cursors, which a fan larger than the fast path's runs past its group's room: at the last
// lane of a task (point 2047, a fan of 8191 triangles) the cursor runs 4 MB past the end of
// the task's slots, where the writes must stop; the general path then takes the fan.
TEST(vtkMikkTSpaceTangents, FastPathTaskSlotsKeepUnusedPointsAndHandOverLargeFans)
{
  auto torus = MakeTorus(300, 150);
  std::vector<vtkIdType> newId;
  auto spread = WithUnusedRuns(torus, 200, 40, newId);
  ExpectSameFramesAtNewIds(torus, spread, newId);
  ExpectFastPathIsGeneralPath(spread, "torus with unused points");
  // A closed fan of k triangles, its centre at point 2047 and its ring at all other points.
  const int k = 8191, centre = 2047;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  auto normals = NewFloatArray("Normals", 3);
  auto tcoords = NewFloatArray("TCoords", 2);
  for (int p = 0; p <= k; ++p)
  {
    const int i = p < centre ? p : p - 1;
    const double a = 2.0 * vtkMath::Pi() * i / k, r = p == centre ? 0.0 : 1.0;
    points->InsertNextPoint(r * std::cos(a), r * std::sin(a), 0.1 * r * std::sin(3.0 * a));
    normals->InsertNextTuple3(0.0, 0.0, 1.0);
    tcoords->InsertNextTuple2(0.5 + 0.4 * r * std::cos(a), 0.5 + 0.4 * r * std::sin(a));
  }
  auto ringId = [](int i) { return vtkIdType(i < centre ? i : i + 1); };
  for (int i = 0; i < k; ++i)
  {
    const vtkIdType t[3] = { centre, ringId(i), ringId((i + 1) % k) };
    polys->InsertNextCell(3, t);
  }
  ExpectFastPathIsGeneralPath(
    MakeSurface(points, polys, normals, tcoords), "a fan of 8191 at point 2047");
}

// In the AVX-512 and AVX2 builds (GCC) the fast path reads each corner's neighbours with one masked
// 16-byte load a point (GatherRow, GatherRowAVX2): x, y, z and, masked off, the next point's x,
// which past the last point is past the end of the array. Masked-off lanes must not be read: a
// torus whose float points end exactly at a page that cannot be read (the last point is a corner's
// neighbour) must run and give the bits of the same torus in ordinary memory, at 1 and 2 threads.
// (The other builds read three floats a point anyway; there the test shows the same of their
// loops.)
TEST(vtkMikkTSpaceTangents, FastPathReadsNoFloatPastTheLastPoint)
{
#ifdef __linux__
  auto torus = MakeTorus(120, 60);
  const vtkIdType n = torus->GetNumberOfPoints();
  bool lastUsed = false;
  {
    vtkCellArray* polys = torus->GetPolys();
    vtkNew<vtkIdList> ids;
    for (polys->InitTraversal(); polys->GetNextCell(ids);)
    {
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        lastUsed |= ids->GetId(k) == n - 1;
      }
    }
  }
  ASSERT_TRUE(lastUsed);
  vtkDataArray* xyz = torus->GetPoints()->GetData();
  ASSERT_EQ(xyz->GetDataType(), VTK_FLOAT);
  const size_t page = static_cast<size_t>(sysconf(_SC_PAGESIZE));
  const size_t bytes = (3 * sizeof(float) * static_cast<size_t>(n) + page - 1) / page * page;
  void* memory =
    mmap(nullptr, bytes + page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(memory, MAP_FAILED);
  ASSERT_EQ(mprotect(static_cast<char*>(memory) + bytes, page, PROT_NONE), 0);
  float* guarded = reinterpret_cast<float*>(static_cast<char*>(memory) + bytes) - 3 * n;
  std::memcpy(guarded, xyz->GetVoidPointer(0), 3 * sizeof(float) * static_cast<size_t>(n));
  {
    vtkNew<vtkFloatArray> guardedData;
    guardedData->SetNumberOfComponents(3);
    guardedData->SetArray(guarded, 3 * n, 1);
    vtkNew<vtkPoints> guardedPoints;
    guardedPoints->SetData(guardedData);
    vtkNew<vtkPolyData> atTheEnd;
    atTheEnd->ShallowCopy(torus);
    atTheEnd->SetPoints(guardedPoints);
    for (int threads : { 1, 2 })
    {
      vtkSMPTools::Initialize(threads);
      vtkNew<vtkMikkTSpaceTangents> a, b;
      a->SetInputData(torus);
      b->SetInputData(atTheEnd);
      a->Update();
      b->Update();
      vtkDataArray* ta = a->GetOutput()->GetPointData()->GetArray("Tangents");
      vtkDataArray* tb = b->GetOutput()->GetPointData()->GetArray("Tangents");
      ASSERT_TRUE(ta && tb);
      ASSERT_EQ(ta->GetDataType(), VTK_FLOAT);
      ASSERT_EQ(tb->GetDataType(), VTK_FLOAT);
      ASSERT_EQ(ta->GetNumberOfValues(), 4 * n);
      ASSERT_EQ(tb->GetNumberOfValues(), 4 * n);
      EXPECT_EQ(0,
        std::memcmp(ta->GetVoidPointer(0), tb->GetVoidPointer(0), 4 * sizeof(float) * size_t(n)))
        << threads << " thread(s)";
    }
    vtkSMPTools::Initialize(0);
  }
  munmap(memory, bytes + page);
#else
  GTEST_SKIP() << "needs mmap and mprotect";
#endif
}

// The fast path normalises every point's normal in a pass of its own, without branches;
// the general path normalises it where it needs it. Normals of length 3, 0 and past the
// square's range (1e200: the length overflows, so neither path scales them) must give the
// same frames both ways.
TEST(vtkMikkTSpaceTangents, FastPathAgreesWithGeneralPathOnUnnormalisedNormals)
{
  auto torus = MakeTorus(40, 20);
  vtkNew<vtkDoubleArray> normals;
  normals->DeepCopy(torus->GetPointData()->GetNormals());
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    const double scale[3] = { 3.0, 0.0, 1e200 };
    for (int c = 0; c < 3; ++c)
    {
      normals->SetComponent(i, c, normals->GetComponent(i, c) * scale[i % 3]);
    }
  }
  torus->GetPointData()->SetNormals(normals);
  ExpectFastPathIsGeneralPath(torus, "torus with unnormalised normals");
  FilterRun run(torus);
  EXPECT_EQ(run.Errors->Count, 0);
  ExpectValidFrames(run.Output());
}

// Inputs at the edges of what the fast path's division-free tests see: the general path
// (forced by a threshold below 180 degrees) drops a triangle's dP/ds when its length is not
// above FLT_MIN, and leaves a projected edge unnormalised when all its components are that
// small; the fast path must hand such meshes over rather than give other frames.
TEST(vtkMikkTSpaceTangents, FastPathHandsOverTinyDerivativesAndEdges)
{
  // A bumpy 6 x 6 grid 1e-34 across with texture coordinates 1e-3 across: each triangle's
  // unnormalised dP/ds (position edges times texture edges, ~1e-38) is about FLT_MIN, where
  // the general path drops it; a test scaled by the texture area alone lets it through.
  for (int precision : { VTK_FLOAT, VTK_DOUBLE })
  {
    const int n = 6;
    const double scale = 1e-34, tscale = 1e-3;
    vtkNew<vtkPoints> points;
    points->SetDataType(precision);
    auto normals = NewFloatArray("Normals", 3);
    auto tcoords = NewFloatArray("TCoords", 2);
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        // jitter so that no two triangles are alike
        const double x = i + 0.15 * std::sin(3.1 * i + 1.7 * j);
        const double y = j + 0.15 * std::cos(2.3 * i - 1.3 * j);
        const double z = 0.3 * std::sin(0.7 * x) * std::cos(0.5 * y);
        const double dzx = 0.21 * std::cos(0.7 * x) * std::cos(0.5 * y);
        const double dzy = -0.15 * std::sin(0.7 * x) * std::sin(0.5 * y);
        double nn[3] = { -dzx, -dzy, 1.0 };
        vtkMath::Normalize(nn);
        points->InsertNextPoint(x * scale, y * scale, z * scale);
        normals->InsertNextTuple(nn);
        tcoords->InsertNextTuple2(0.1 * x * tscale, 0.1 * y * tscale);
      }
    }
    vtkNew<vtkCellArray> polys;
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const vtkIdType a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
        const vtkIdType t1[3] = { a, b, c }, t2[3] = { a, c, d };
        polys->InsertNextCell(3, t1);
        polys->InsertNextCell(3, t2);
      }
    }
    auto grid = MakeSurface(points, polys, normals, tcoords);
    ExpectFastPathIsGeneralPath(
      grid, precision == VTK_FLOAT ? "tiny grid, float" : "tiny grid, double");
  }

  // An edge along the normal up to 1e-39: its projection onto the tangent plane is not zero
  // but below FLT_MIN in every component.
  {
    vtkNew<vtkPoints> points;
    points->SetDataType(VTK_DOUBLE);
    points->InsertNextPoint(0, 0, 0);
    points->InsertNextPoint(1e-39, 1e-39, 1);
    points->InsertNextPoint(0, 1, 0);
    points->InsertNextPoint(-1, 0, 0);
    vtkNew<vtkDoubleArray> normals;
    normals->SetNumberOfComponents(3);
    normals->SetName("Normals");
    vtkNew<vtkDoubleArray> tcoords;
    tcoords->SetNumberOfComponents(2);
    tcoords->SetName("TCoords");
    const double t[4][2] = { { 0, 0 }, { 1, -1 }, { 0, 1 }, { -1, 0.8 } };
    for (int i = 0; i < 4; ++i)
    {
      normals->InsertNextTuple3(0, 0, 1);
      tcoords->InsertNextTuple(t[i]);
    }
    vtkNew<vtkCellArray> polys;
    const vtkIdType t1[3] = { 0, 1, 2 }, t2[3] = { 0, 2, 3 };
    polys->InsertNextCell(3, t1);
    polys->InsertNextCell(3, t2);
    auto fan = MakeSurface(points, polys, normals, tcoords);
    ExpectFastPathIsGeneralPath(fan, "edge along the normal");
  }
}

// A triangle soup around one vertex: ring points around the origin (point 0) at the given
// heights, texture coordinates from x and y, normals +z.
vtkSmartPointer<vtkPolyData> FansAroundOrigin(
  const std::vector<std::array<double, 3>>& ring, const std::vector<std::array<vtkIdType, 3>>& tris)
{
  vtkNew<vtkPoints> points;
  auto normals = NewFloatArray("Normals", 3);
  auto tcoords = NewFloatArray("TCoords", 2);
  points->InsertNextPoint(0, 0, 0);
  for (const auto& x : ring)
  {
    points->InsertNextPoint(x.data());
  }
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    normals->InsertNextTuple3(0, 0, 1);
    tcoords->InsertNextTuple2(0.5 + 0.4 * x[0], 0.5 + 0.4 * x[1]);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& t : tris)
  {
    polys->InsertNextCell(3, t.data());
  }
  return MakeSurface(points, polys, normals, tcoords);
}

// The fast path takes a vertex only if its triangles make one run (one closed fan or one
// chain) in which every edge at the vertex joins two triangles or bounds the run; fans of
// up to 8 triangles are checked in vector lanes, larger ones through a hash table. Where
// the run is not one, the general algorithm splits the vertex or pairs edges its own way,
// and the default must give exactly its frames (and its number of points).
TEST(vtkMikkTSpaceTangents, FastPathHandsOverFansThatAreNotOneRun)
{
  for (int n : { 4, 6 }) // up to 2n triangles at the origin
  {
    std::vector<std::array<double, 3>> ring;
    for (int side = 0; side < 2; ++side)
    {
      for (int i = 0; i < n; ++i)
      {
        const double a = 2.0 * vtkMath::Pi() * (i + 0.3 * side) / n;
        ring.push_back({ std::cos(a), std::sin(a), side == 0 ? 0.5 : -0.5 });
      }
    }
    auto up = [&](int i) { return vtkIdType(1 + i % n); };
    auto down = [&](int i) { return vtkIdType(1 + n + i % n); };
    auto check = [&](const std::vector<std::array<vtkIdType, 3>>& tris, const char* name)
    {
      const std::string what = std::string(name) + " (" + std::to_string(tris.size()) + ")";
      ExpectFastPathIsGeneralPath(FansAroundOrigin(ring, tris), what.c_str());
    };
    // Two closed fans (a double cone): two runs.
    std::vector<std::array<vtkIdType, 3>> cone;
    for (int i = 0; i < n; ++i)
    {
      cone.push_back({ 0, up(i), up(i + 1) });
      cone.push_back({ 0, down(i), down(i + 1) });
    }
    check(cone, "double cone");
    // Two open chains.
    std::vector<std::array<vtkIdType, 3>> chains;
    for (int i = 0; i + 1 < n; ++i)
    {
      chains.push_back({ 0, up(i), up(i + 1) });
      chains.push_back({ 0, down(i), down(i + 1) });
    }
    check(chains, "two chains");
    // A closed fan and one triangle sharing an edge's direction with it (0 -> up(0) twice).
    std::vector<std::array<vtkIdType, 3>> twice;
    for (int i = 0; i < n; ++i)
    {
      twice.push_back({ 0, up(i), up(i + 1) });
    }
    twice.push_back({ 0, up(0), down(0) });
    check(twice, "edge run twice");
    // A closed fan, and one more triangle at the origin that touches it only there.
    std::vector<std::array<vtkIdType, 3>> apart(twice.begin(), twice.end() - 1);
    apart.push_back({ 0, down(0), down(1) });
    check(apart, "apart");
    // The double cone splits the origin into two points.
    auto doubleCone = FansAroundOrigin(ring, cone);
    vtkNew<vtkMikkTSpaceTangents> filter;
    filter->SetInputData(doubleCone);
    filter->Update();
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), doubleCone->GetNumberOfPoints() + 1);
  }
}

// A closed fan is taken as one run without matching its edges when its corners' angles
// all turn one way and make a full turn, and the ids after and before its corners are the
// same multiset (FastTurn in the filter); every other fan goes through the edge matching.
// Each case fails one condition: two open chains whose angles make a full turn but for a
// gap of 0.3 radians (the multisets differ; taken as one run, the vertex would not be split
// as the general algorithm splits it), and one cycle through all its ring points that winds
// twice about the vertex (angles of two turns; one run all the same, which the edge matching
// must find). Fans of 3 to 9 triangles: the small fans' lanes and the hash table.
TEST(vtkMikkTSpaceTangents, FastPathClosedFanTestHandsOverChainsAndDoubleTurns)
{
  auto generalPoints = [](vtkPolyData* input)
  {
    vtkNew<vtkMikkTSpaceTangents> general;
    general->SetInputData(input);
    general->SetAngularThreshold(179.9);
    general->Update();
    return general->GetOutput()->GetNumberOfPoints();
  };
  for (int n : { 3, 4, 6 }) // triangles per chain
  {
    const double span = vtkMath::Pi() - 0.15;
    std::vector<std::array<double, 3>> ring;
    std::vector<std::array<vtkIdType, 3>> tris;
    for (int chain = 0; chain < 2; ++chain)
    {
      const vtkIdType start = 1 + chain * (n + 1);
      for (int i = 0; i <= n; ++i)
      {
        const double a = chain * vtkMath::Pi() + span * i / n;
        ring.push_back({ std::cos(a), std::sin(a), 0.1 * std::sin(3.0 * a) });
      }
      for (int i = 0; i < n; ++i)
      {
        tris.push_back({ 0, start + i, start + i + 1 });
      }
    }
    auto chains = FansAroundOrigin(ring, tris);
    const std::string what = "two chains of " + std::to_string(n);
    ExpectFastPathIsGeneralPath(chains, what.c_str());
    EXPECT_EQ(generalPoints(chains), chains->GetNumberOfPoints() + 1) << what;
  }
  for (int m : { 5, 7, 9 }) // ring points, each angle 4 pi / m
  {
    std::vector<std::array<double, 3>> ring;
    std::vector<std::array<vtkIdType, 3>> tris;
    for (int i = 0; i < m; ++i)
    {
      const double a = 2.0 * vtkMath::Pi() * i / m;
      ring.push_back({ std::cos(a), std::sin(a), 0.1 * std::sin(3.0 * a) });
      tris.push_back({ 0, vtkIdType(1 + (2 * i) % m), vtkIdType(1 + (2 * i + 2) % m) });
    }
    auto twice = FansAroundOrigin(ring, tris);
    const std::string what = "fan winding twice, " + std::to_string(m);
    ExpectFastPathIsGeneralPath(twice, what.c_str());
    EXPECT_EQ(generalPoints(twice), twice->GetNumberOfPoints()) << what;
  }
}

// The fast path takes a vertex only if all its triangles have one texture orientation: a
// closed planar fan of six triangles, the first three of them mirrored in texture space,
// while every dP/ds and dP/dt (times the orientation's sign, as MikkTSpace takes them)
// stays within 78 degrees of its vertex's first triangle's, so that the quarter-turn checks
// pass (the texture coordinates were found by a random search for that). The general
// algorithm splits the centre and two ring points by orientation, and the default must
// give exactly its points and frames.
TEST(vtkMikkTSpaceTangents, FastPathHandsOverFansOfMixedTextureOrientation)
{
  const double tc[6][2] = { { 0.236, 0.815 }, { 1.834, -0.151 }, { 0.457, -0.311 },
    { -0.206, -0.357 }, { 0.038, -1.832 }, { 1.471, -2.188 } };
  vtkNew<vtkPoints> points;
  auto normals = NewFloatArray("Normals", 3);
  auto tcoords = NewFloatArray("TCoords", 2);
  for (int k = 0; k < 6; ++k)
  {
    points->InsertNextPoint(std::cos(vtkMath::Pi() * k / 3), std::sin(vtkMath::Pi() * k / 3), 0);
    normals->InsertNextTuple3(0, 0, 1);
    tcoords->InsertNextTuple(tc[k]);
  }
  points->InsertNextPoint(0, 0, 0);
  normals->InsertNextTuple3(0, 0, 1);
  tcoords->InsertNextTuple2(0, 0);
  vtkNew<vtkCellArray> polys;
  for (vtkIdType k = 0; k < 6; ++k)
  {
    const vtkIdType t[3] = { 6, k, (k + 1) % 6 };
    polys->InsertNextCell(3, t);
  }
  auto fan = MakeSurface(points, polys, normals, tcoords);
  vtkNew<vtkMikkTSpaceTangents> general;
  general->SetInputData(fan);
  general->SetAngularThreshold(179.9);
  general->Update();
  EXPECT_GT(general->GetOutput()->GetNumberOfPoints(), fan->GetNumberOfPoints());
  ExpectFastPathIsGeneralPath(fan, "fan of mixed texture orientation");
}

// The closed-fan test's sign condition (every corner turning the same way about the
// normal) is what tells a fan of several closed walks, one of which folds back on itself,
// from one closed run: two closed walks of four triangles each around the origin, both
// folded (their corners' signed angles sum to zero turns; their sizes to 2 pi + 0.5),
// every triangle of the same texture orientation, and every dP/ds and dP/dt within a
// quarter turn of the origin's first triangle's and of their neighbours' (the fast path's
// other checks pass). Their ids after and before the corners are the same multiset. Taken
// as one run, the origin would get one frame; the general algorithm finds two groups.
// The values were found by a search for these constraints (margins 0.08 in every cosine
// and angle).
TEST(vtkMikkTSpaceTangents, FastPathClosedFanTestHandsOverFoldedWalks)
{
  const double walks[2][4][2] = { { { 1.53, 0.95 }, { -0.3, 0.33 }, { -2.3, 2.1 }, { 1.79, 1.45 } },
    { { 0.07, 0.63 }, { -0.13, 0.47 }, { -1.38, 0.19 }, { -0.18, 1.01 } } };
  const double uvs[2][4][2] = { { { 0.07, 0.03 }, { 0.19, -1.04 }, { -0.84, 0.75 },
                                  { -0.18, 2.84 } },
    { { 0.53, 0.49 }, { 0.42, -0.76 }, { -0.63, -0.62 }, { -0.7, 0.99 } } };
  for (int precision : { VTK_FLOAT, VTK_DOUBLE })
  {
    vtkNew<vtkPoints> points;
    points->SetDataType(precision);
    auto normals = NewFloatArray("Normals", 3);
    auto tcoords = NewFloatArray("TCoords", 2);
    points->InsertNextPoint(0, 0, 0);
    normals->InsertNextTuple3(0, 0, 1);
    tcoords->InsertNextTuple2(0.5, 0.5);
    vtkNew<vtkCellArray> polys;
    for (int w = 0; w < 2; ++w)
    {
      for (int i = 0; i < 4; ++i)
      {
        points->InsertNextPoint(walks[w][i][0], walks[w][i][1], 0.0);
        normals->InsertNextTuple3(0, 0, 1);
        tcoords->InsertNextTuple2(0.5 + 0.2 * uvs[w][i][0], 0.5 + 0.2 * uvs[w][i][1]);
      }
      for (int i = 0; i < 4; ++i)
      {
        const vtkIdType base = 1 + 4 * w;
        const vtkIdType t[3] = { 0, base + (i + 1) % 4, base + i };
        polys->InsertNextCell(3, t);
      }
    }
    auto folded = MakeSurface(points, polys, normals, tcoords);
    const char* what = precision == VTK_FLOAT ? "folded walks, float" : "folded walks, double";
    ExpectFastPathIsGeneralPath(folded, what);
    vtkNew<vtkMikkTSpaceTangents> general;
    general->SetInputData(folded);
    general->SetAngularThreshold(179.9);
    general->Update();
    EXPECT_EQ(general->GetOutput()->GetNumberOfPoints(), folded->GetNumberOfPoints() + 1) << what;
  }
}

// Fans whose corners all turn clockwise about the normal (normals -z under triangles
// counter-clockwise seen from +z) take the closed-fan test's other window (TurnBack per
// corner plus a full turn): there too a double cone (two closed fans, two full turns) must
// go through the edge matching and be split.
TEST(vtkMikkTSpaceTangents, FastPathClosedFanTestHandsOverTurnsTheOtherWay)
{
  for (int n : { 4, 6 })
  {
    std::vector<std::array<double, 3>> ring;
    std::vector<std::array<vtkIdType, 3>> cone;
    for (int side = 0; side < 2; ++side)
    {
      for (int i = 0; i < n; ++i)
      {
        const double a = 2.0 * vtkMath::Pi() * (i + 0.3 * side) / n;
        ring.push_back({ std::cos(a), std::sin(a), side == 0 ? 0.5 : -0.5 });
        cone.push_back({ 0, vtkIdType(1 + side * n + i), vtkIdType(1 + side * n + (i + 1) % n) });
      }
    }
    auto fans = FansAroundOrigin(ring, cone);
    vtkDataArray* normals = fans->GetPointData()->GetNormals();
    for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
    {
      normals->SetTuple3(i, 0, 0, -1);
    }
    const std::string what = "double cone turning the other way (" + std::to_string(2 * n) + ")";
    ExpectFastPathIsGeneralPath(fans, what.c_str());
    vtkNew<vtkMikkTSpaceTangents> filter;
    filter->SetInputData(fans);
    filter->Update();
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), fans->GetNumberOfPoints() + 1) << what;
  }
}

// The other side: a fan that is one run, closed or open, of every size from 1 triangle
// to past the small fans' 8 lanes (9 is the first the hash table takes), its triangles
// listed out of chain order, at point 0 (a real id next to the lanes' negative padding),
// must give the general algorithm's frames wherever the fast path finishes.
TEST(vtkMikkTSpaceTangents, FastPathOneRunFansOfEverySizeAgreeWithGeneralPath)
{
  for (int k = 1; k <= 12; ++k)
  {
    for (bool closed : { true, false })
    {
      if (closed && k < 3)
      {
        continue;
      }
      const int n = closed ? k : k + 1; // ring points
      std::vector<std::array<double, 3>> ring;
      for (int i = 0; i < n; ++i)
      {
        const double a = (closed ? 2.0 * vtkMath::Pi() : 1.5 * vtkMath::Pi()) * i / k;
        ring.push_back({ std::cos(a), std::sin(a), 0.1 * std::sin(3.0 * a) });
      }
      // Every other triangle from the last one backwards, then the rest.
      std::vector<std::array<vtkIdType, 3>> tris;
      for (int start : { k - 1, k - 2 })
      {
        for (int c = start; c >= 0; c -= 2)
        {
          tris.push_back({ 0, vtkIdType(1 + c), vtkIdType(1 + (c + 1) % n) });
        }
      }
      const std::string what =
        std::string(closed ? "closed" : "open") + " fan of " + std::to_string(k);
      ExpectFastPathIsGeneralPath(FansAroundOrigin(ring, tris), what.c_str());
    }
  }
}

namespace
{
// Disjoint fans of 3 to 32 triangles (every third one open, every fourth one mirrored in
// texture space), their centres and ring points interleaved in id order (a fixed shuffle),
// so that each run of 16 vertices mixes fans of many sizes: the AVX-512 build lays a block's
// fans out in groups of 16 lanes padded to the group's largest fan, which must add nothing
// to the smaller fans' sums. Every fifth centre has a welded twin that takes every other
// triangle, every seventh fan one point no triangle uses, and the points past the fans (to
// 1001, not a multiple of 16) are copies of one more such point. Double: double points,
// normals and texture coordinates.
vtkSmartPointer<vtkPolyData> UnevenFans(bool doubles)
{
  std::vector<std::array<double, 3>> p, n;
  std::vector<std::array<double, 2>> t;
  std::vector<std::array<vtkIdType, 3>> tris;
  for (int s = 0; p.size() < 960; ++s)
  {
    const int k = 3 + (11 * s) % 30;
    const bool open = s % 3 == 2;
    const double flip = s % 4 == 3 ? -1.0 : 1.0, rot = 0.3 * s;
    auto add = [&](double x, double y)
    {
      p.push_back({ x + 3.0 * s, y, 0.1 * std::sin(2.0 * x + s) * std::cos(y) });
      n.push_back({ 0.05 * std::sin(s + x), 0.04 * std::cos(3.0 * y), 1.0 });
      t.push_back(
        { std::cos(rot) * x - std::sin(rot) * y, flip * (std::sin(rot) * x + std::cos(rot) * y) });
      return vtkIdType(p.size() - 1);
    };
    const vtkIdType centre = add(0.0, 0.0);
    vtkIdType twin = centre;
    if (s % 5 == 0)
    {
      p.push_back(p[centre]);
      n.push_back(n[centre]);
      t.push_back(t[centre]);
      twin = vtkIdType(p.size() - 1);
    }
    const int ring = open ? k + 1 : k;
    const double span = open ? 1.5 * vtkMath::Pi() : 2.0 * vtkMath::Pi();
    const vtkIdType first = vtkIdType(p.size());
    for (int i = 0; i < ring; ++i)
    {
      const double a = span * (i + 0.25 * std::sin(1.7 * i + s)) / k;
      const double r = 1.0 + 0.2 * std::sin(2.3 * i + s);
      add(r * std::cos(a), r * std::sin(a));
    }
    for (int i = 0; i < k; ++i)
    {
      tris.push_back({ i % 2 ? twin : centre, first + i, first + (i + 1) % ring });
    }
    if (s % 7 == 0)
    {
      add(0.5, 0.5);
    }
  }
  p.resize(1001, { 0.0, 0.0, -1.0 });
  n.resize(1001, { 0.0, 0.0, 1.0 });
  t.resize(1001, { 0.0, 0.0 });
  // A fixed shuffle of the ids: new id (i * 97) % 1001 for old id i (gcd(97, 1001) = 1).
  const vtkIdType np = vtkIdType(p.size());
  auto id = [np](vtkIdType i) { return (i * 97) % np; };
  vtkNew<vtkPoints> points;
  points->SetDataType(doubles ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(np);
  vtkSmartPointer<vtkDataArray> normals, tcoords;
  if (doubles)
  {
    normals = vtkSmartPointer<vtkDoubleArray>::New();
    tcoords = vtkSmartPointer<vtkDoubleArray>::New();
  }
  else
  {
    normals = vtkSmartPointer<vtkFloatArray>::New();
    tcoords = vtkSmartPointer<vtkFloatArray>::New();
  }
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(np);
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    points->SetPoint(id(i), p[i].data());
    normals->SetTuple(id(i), n[i].data());
    tcoords->SetTuple(id(i), t[i].data());
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& tri : tris)
  {
    const vtkIdType ids[3] = { id(tri[0]), id(tri[1]), id(tri[2]) };
    polys->InsertNextCell(3, ids);
  }
  return MakeSurface(points, polys, normals, tcoords);
}

std::string TangentBits(vtkPolyData* out)
{
  auto* t = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("Tangents"));
  return t ? std::string(reinterpret_cast<const char*>(t->GetPointer(0)),
               sizeof(float) * t->GetNumberOfValues())
           : std::string();
}
} // namespace

// Fans of uneven sizes in one group of lanes, float and double, on the sequential backend
// (all points one range: full blocks of 128 vertices, many cut short by their groups' slots)
// and on two threads (ranges of a few vertices): the same bits in every build (the AVX2
// and baseline builds lay the fans out corner by corner, without padding) and on both
// backends. The fast path must finish on both meshes: the general algorithm's frames agree
// within 1e-4 degrees but not bit for bit (it weighs corners in double with acos), so equal
// bits would mean the fast path handed over and tested nothing here.
TEST(vtkMikkTSpaceTangents, FastPathUnevenFansSameBitsInEveryBuild)
{
  if (const char* dump = EveryBuild::DumpPath())
  {
    std::string bits;
    const std::string backend = vtkSMPTools::GetBackend();
    for (bool doubles : { false, true })
    {
      auto mesh = UnevenFans(doubles);
      for (bool sequential : { true, false })
      {
        vtkSMPTools::SetBackend(sequential ? "Sequential" : backend.c_str());
        vtkSMPTools::Initialize(sequential ? 1 : 2);
        FilterRun run(mesh);
        bits += TangentBits(run.Output());
      }
      vtkSMPTools::Initialize(0);
    }
    EveryBuild::WriteDump(dump, bits);
    return;
  }
  for (bool doubles : { false, true })
  {
    auto mesh = UnevenFans(doubles);
    const char* name = doubles ? "uneven fans, double" : "uneven fans, float";
    vtkNew<vtkMikkTSpaceTangents> general;
    general->SetInputData(mesh);
    general->SetAngularThreshold(179.9);
    general->Update();
    FilterRun fast(mesh);
    EXPECT_EQ(fast.Errors->Count + fast.Warnings->Count, 0) << name;
    ASSERT_EQ(fast.Output()->GetNumberOfPoints(), mesh->GetNumberOfPoints()) << name;
    EXPECT_FALSE(TangentBits(fast.Output()) == TangentBits(general->GetOutput()))
      << name << ": the fast path handed over";
    ExpectFastPathIsGeneralPath(mesh, name);
  }
#ifdef __linux__
  const std::vector<std::string> results =
    EveryBuild::OutputsOfEveryBuild("vtkMikkTSpaceTangents.FastPathUnevenFansSameBitsInEveryBuild");
  ASSERT_EQ(results.size(), 3u);
  ASSERT_EQ(results[0].size(), 4u * 4 * 1001 * sizeof(float));
  const std::size_t run = results[0].size() / 4; // float, then double: sequential, 2 threads
  EXPECT_TRUE(results[0].substr(0, run) == results[0].substr(run, run))
    << "float: sequential and 2 threads differ";
  EXPECT_TRUE(results[0].substr(2 * run, run) == results[0].substr(3 * run, run))
    << "double: sequential and 2 threads differ";
  EXPECT_TRUE(results[1] == results[0]) << "avx2 differs from the widest build";
  EXPECT_TRUE(results[2] == results[0]) << "baseline differs from the widest build";
#endif
}

namespace
{
// A copy of a float mesh with every point coordinate times s (the normals and texture
// coordinates kept).
vtkSmartPointer<vtkPolyData> ScaledCopy(vtkPolyData* in, double s)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(in);
  vtkPoints* points = out->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    points->SetPoint(i, s * x[0], s * x[1], s * x[2]);
  }
  return out;
}

// An open fan of k triangles at the tip of a cone of height 1 and radius r, a fifth of it
// round, the normals nearly along the axis: for a small r, every edge at the tip is nearly
// along the normal. t runs up the cone and s round it, so that dP/ds (along the triangles'
// outer edges) lies in the tangent plane, and differs between triangles: the corners'
// weights matter.
vtkSmartPointer<vtkPolyData> ConeTip(int k, double r)
{
  vtkNew<vtkPoints> points;
  auto normals = NewFloatArray("Normals", 3);
  auto tcoords = NewFloatArray("TCoords", 2);
  double n[3] = { 0.011, -0.017, 1.0 };
  vtkMath::Normalize(n);
  points->InsertNextPoint(0, 0, 0);
  normals->InsertNextTuple(n);
  tcoords->InsertNextTuple2(0.5, 0.0);
  for (int i = 0; i <= k; ++i)
  {
    const double a = 0.4 * vtkMath::Pi() * (i + 0.3 * std::sin(1.7 * i)) / k;
    points->InsertNextPoint(r * std::cos(a), r * std::sin(a), 1.0 + 0.2 * r * std::sin(2.3 * i));
    normals->InsertNextTuple(n);
    tcoords->InsertNextTuple2(double(i) / k + 0.02 * std::sin(3.1 * i), 1.0);
  }
  vtkNew<vtkCellArray> polys;
  for (int i = 0; i < k; ++i)
  {
    const vtkIdType t[3] = { 0, vtkIdType(1 + i), vtkIdType(2 + i) };
    polys->InsertNextCell(3, t);
  }
  return MakeSurface(points, polys, normals, tcoords);
}
} // namespace

// The fast path weighs the corners of float meshes in single precision, with subnormals
// flushed to zero: a float square overflows past 1.8e19 and underflows below 1e-19, a
// subnormal component reads as zero, and the projection of an edge nearly along the
// normal cancels. On such meshes it must hand over to the general path or give its frames.
TEST(vtkMikkTSpaceTangents, FastPathInSinglePrecisionAgreesOnAdversarialMeshes)
{
  // Tangent frames do not depend on the mesh's scale: up to float's largest coordinates
  // (2.7e38 on this torus), the scaled torus has the unscaled one's frames.
  auto torus = MakeTorus(24, 12);
  FilterRun unscaled(torus);
  vtkDataArray* reference = unscaled.Output()->GetPointData()->GetArray("Tangents");
  for (double s : { 1e-30, 1e-20, 1e-17, 1e-15, 1e15, 1e18, 1e19, 1e20, 1e30, 1e36, 1e38, 2e38 })
  {
    std::ostringstream name;
    name << "torus scaled by " << s;
    const std::string what = name.str();
    auto scaled = ScaledCopy(torus, s);
    ExpectFastPathIsGeneralPath(scaled, what.c_str());
    FilterRun run(scaled);
    ExpectValidFrames(run.Output());
    EXPECT_LT(
      MaxAngleSameHandedness(run.Output()->GetPointData()->GetArray("Tangents"), reference, what),
      1e-4)
      << what;
  }

  // Subnormal components (1e-39 .. 1e-45) in the points, normals and texture coordinates of
  // a bumpy plane, where they stand for zeros: in its height, the normals' tilt, and the
  // texture coordinates of its corner (0, 0).
  {
    auto plane = MakeGrid(8, 8,
      [](double u, double v)
      {
        const double tiny = 1e-39 * std::sin(40 * u + 17 * v);
        const bool flat = u < 0.3 || v < 0.3;
        return Sample{ { 2 * u - 1, 2 * v - 1, flat ? tiny : 0.1 * (u - 0.3) * (v - 0.3) },
          Normalized({ flat ? tiny : -0.05 * (v - 0.3), flat ? -tiny : -0.05 * (u - 0.3), 1.0 }),
          { u + 0.3 * v * v + (u + v == 0 ? 1e-39 : 0.0),
            v - 0.2 * u - (u + v == 0 ? 3e-41 : 0.0) } };
      });
    ExpectFastPathIsGeneralPath(plane, "plane with subnormal components");
    FilterRun run(plane);
    ExpectValidFrames(run.Output());
  }

  // Cone tips, ever sharper: edges 45 to 0.6 degrees off the normal. In float, the angle
  // at the tip cancels (1 - 1e-3 in e1.e2 - (e1.n)(e2.n)); edges 1.8 to 3 degrees off gave
  // frames up to 1.6e-3 degrees off the general path's.
  for (double r : { 1.0, 0.6, 0.3, 0.1, 0.05, 0.04, 0.035, 0.03, 0.02, 0.0105 })
  {
    for (int k : { 5, 8, 12 })
    {
      const std::string what = "cone tip of " + std::to_string(k) + ", radius " + std::to_string(r);
      ExpectFastPathIsGeneralPath(ConeTip(k, r), what.c_str());
    }
  }

  // A flat fan whose vertex normal lies nearly in its plane, along its dP/ds: the
  // projections of dP/ds onto the tangent plane are short (down to 1e-3), and their float
  // lengths lose digits (frames 4e-5 degrees off with the normal 0.17 degrees off the plane).
  for (double delta : { 0.003, 0.01, 0.03, 0.1, 0.3 })
  {
    vtkNew<vtkPoints> points;
    auto normals = NewFloatArray("Normals", 3);
    auto tcoords = NewFloatArray("TCoords", 2);
    double n[3] = { 1.0, 0.0, delta };
    vtkMath::Normalize(n);
    points->InsertNextPoint(0, 0, 0);
    normals->InsertNextTuple(n);
    tcoords->InsertNextTuple2(0.5, 0.5);
    const int k = 4;
    for (int i = 0; i < k; ++i)
    {
      const double a = 2.0 * vtkMath::Pi() * (i + 0.5 + 0.07 * std::sin(2.9 * i)) / k;
      const double x = (1.0 + 0.3 * std::cos(1.3 * i)) * std::cos(a);
      const double y = (1.0 + 0.3 * std::cos(1.3 * i)) * std::sin(a);
      points->InsertNextPoint(x, y, 0.0);
      normals->InsertNextTuple3(0, 0, 1);
      tcoords->InsertNextTuple2(
        0.5 + 0.4 * x, 0.5 + 0.4 * y + 0.09 * (0.5 + 0.5 * std::sin(4.1 * i)));
    }
    vtkNew<vtkCellArray> polys;
    for (int i = 0; i < k; ++i)
    {
      const vtkIdType t[3] = { 0, vtkIdType(1 + i), vtkIdType(1 + (i + 1) % k) };
      polys->InsertNextCell(3, t);
    }
    const std::string what = "normal " + std::to_string(delta) + " off the plane";
    ExpectFastPathIsGeneralPath(MakeSurface(points, polys, normals, tcoords), what.c_str());
  }

  // Slivers: a grid 1e4 times longer than wide.
  {
    auto sliver = MakeGrid(6, 6,
      [](double u, double v)
      {
        return Sample{ { 1e4 * u + 0.3 * v, 1e-0 * v + 0.2 * std::sin(5 * u), 0.1 * u * v },
          { 0.0, 0.0, 1.0 }, { u + 0.1 * v, v + 0.05 * u } };
      });
    ExpectFastPathIsGeneralPath(sliver, "slivers");
  }
}

// The fast path flushes subnormals to zero (x86: MXCSR's FTZ and DAZ) while it weighs the
// corners of float meshes, on whichever threads run it: afterwards neither the caller's
// thread nor the pool's may keep that mode, or other work on them would silently lose
// its subnormals.
TEST(vtkMikkTSpaceTangents, FlushToZeroDoesNotOutliveTheFilter)
{
#if defined(__SSE__) || defined(__x86_64__) || defined(_M_X64)
  constexpr unsigned int FlushBits = 0x8040u; // FTZ | DAZ
  auto torus = MakeTorus(120, 60);
  for (int threads : { 1, 2 })
  {
    vtkSMPTools::Initialize(threads);
    const unsigned int before = _mm_getcsr();
    FilterRun run(torus);
    EXPECT_EQ(_mm_getcsr() & FlushBits, before & FlushBits) << threads << " threads";
    std::atomic<int> flushing(0);
    vtkSMPTools::For(0, 64, 1,
      [&](vtkIdType, vtkIdType)
      {
        if (_mm_getcsr() & FlushBits)
        {
          ++flushing;
        }
      });
    EXPECT_EQ(flushing.load(), 0) << threads << " threads";
    volatile float tiny = 1e-38f;
    EXPECT_GT(tiny * 0.01f, 0.0f) << "subnormal results flushed after the filter";
    ExpectValidFrames(run.Output());
  }
  vtkSMPTools::Initialize(0);
#else
  GTEST_SKIP() << "no MXCSR";
#endif
}

// vtkParametricSurfaceSource's analytic frames (T = dP/ds made orthogonal to N, w from
// dP/dt) and MikkTSpace's on the same tessellation agree on smooth, regular surfaces, so
// either can feed the mapper and the baker. Near a sphere's poles the parameterisation is
// singular and the discrete frame differs; those rows are left out. On a texture seam (the
// first and last columns, separate points) MikkTSpace sees only the triangles on one side,
// whose dP/ds is the chord of one column step: it is off by half a step, 180/U degrees,
// which is below 0.5 degrees from U = 360 on.
TEST(vtkMikkTSpaceTangents, AgreesWithParametricSurfaceSource)
{
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkParametricFunction> Function;
    double Repeat[2];
    double VMin, VMax; // rows compared
    int U = 96, V = 48;
  };
  std::vector<Case> cases;
  cases.push_back({ "sphere", vtkSmartPointer<vtkParametricSphere>::New(), { 1, 1 }, 0.1, 0.9 });
  cases.push_back({ "donut", vtkSmartPointer<vtkParametricDonut>::New(), { 2, 1 }, 0.0, 1.0 });
  cases.push_back(
    { "cylinder", vtkSmartPointer<vtkParametricCylinder>::New(), { 1, 3 }, 0.0, 1.0 });
  cases.push_back({ "vtk torus", vtkSmartPointer<vtkParametricTorus>::New(), { 1, 1 }, 0.0, 1.0 });
  // a mirrored texture (s decreasing): left-handed frames on both sides
  cases.push_back(
    { "mirrored donut", vtkSmartPointer<vtkParametricDonut>::New(), { -1, 1 }, 0.0, 1.0 });
  cases.push_back(
    { "fine sphere", vtkSmartPointer<vtkParametricSphere>::New(), { 1, 1 }, 0.1, 0.9, 400, 200 });
  for (const Case& c : cases)
  {
    vtkNew<vtkParametricSurfaceSource> source;
    source->SetParametricFunction(c.Function);
    source->SetUResolution(c.U);
    source->SetVResolution(c.V);
    source->GenerateNormalsOn();
    source->GenerateTextureCoordinatesOn();
    source->GenerateTangentsOn();
    source->SetTextureRepeat(c.Repeat[0], c.Repeat[1]);
    source->Update();
    vtkNew<vtkPolyData> surface;
    surface->DeepCopy(source->GetOutput());
    vtkNew<vtkFloatArray> analytic;
    analytic->DeepCopy(surface->GetPointData()->GetArray("Tangents"));
    ASSERT_EQ(analytic->GetNumberOfComponents(), 4) << c.Name;

    FilterRun run(surface);
    EXPECT_EQ(run.Errors->Count, 0) << c.Name;
    vtkPolyData* out = run.Output();
    ExpectValidFrames(out);
    ASSERT_EQ(out->GetNumberOfPoints(), surface->GetNumberOfPoints()) << c.Name;
    vtkDataArray* mikk = out->GetPointData()->GetArray("Tangents");
    double maxDeg = 0.0, maxSeamDeg = 0.0;
    vtkIdType compared = 0, handedness = 0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      const double v = static_cast<double>(i / (c.U + 1)) / c.V;
      if (v < c.VMin || v > c.VMax)
      {
        continue;
      }
      double a[4], b[4];
      analytic->GetTuple(i, a);
      mikk->GetTuple(i, b);
      const double cosine = vtkMath::Dot(a, b) / (vtkMath::Norm(a) * vtkMath::Norm(b));
      const double deg =
        vtkMath::DegreesFromRadians(std::acos(std::min(1.0, std::max(-1.0, cosine))));
      const vtkIdType column = i % (c.U + 1);
      double& m = (column == 0 || column == c.U) ? maxSeamDeg : maxDeg;
      m = std::max(m, deg);
      handedness += a[3] != b[3];
      ++compared;
    }
    std::cout << c.Name << ": " << compared << " points, max angle " << maxDeg
              << " deg, on the seam " << maxSeamDeg << " deg\n";
    EXPECT_GT(compared, 1000) << c.Name;
    EXPECT_LT(maxDeg, 0.5) << c.Name;
    EXPECT_LE(maxSeamDeg, 180.0 / c.U * 1.001) << c.Name;
    if (180.0 / c.U < 0.5)
    {
      EXPECT_LT(maxSeamDeg, 0.5) << c.Name;
    }
    EXPECT_EQ(handedness, 0) << c.Name;
  }
}

// ---- bad input -------------------------------------------------------------------------

TEST(vtkMikkTSpaceTangents, ErrorWithoutTextureCoordinates)
{
  auto plane = MakePlane(4);
  plane->GetPointData()->SetTCoords(nullptr);
  plane->GetPointData()->RemoveArray("TCoords");
  FilterRun run(plane);
  EXPECT_GT(run.Errors->Count, 0);
  EXPECT_EQ(run.Output()->GetNumberOfPoints(), 0);
  EXPECT_EQ(plane->GetNumberOfPoints(), 25);
}

TEST(vtkMikkTSpaceTangents, ErrorWithOneComponentTextureCoordinates)
{
  auto plane = MakePlane(4);
  vtkNew<vtkFloatArray> s;
  s->SetNumberOfTuples(plane->GetNumberOfPoints());
  s->Fill(0.5);
  plane->GetPointData()->SetTCoords(s);
  FilterRun run(plane);
  EXPECT_GT(run.Errors->Count, 0);
  EXPECT_EQ(run.Output()->GetNumberOfPoints(), 0);
}

TEST(vtkMikkTSpaceTangents, ErrorWithoutPoints)
{
  vtkNew<vtkPolyData> empty;
  FilterRun run(empty);
  EXPECT_GT(run.Errors->Count, 0);
  EXPECT_EQ(run.Output()->GetNumberOfPoints(), 0);
}

TEST(vtkMikkTSpaceTangents, ErrorWithoutPolygons)
{
  auto plane = MakePlane(4);
  plane->SetPolys(nullptr);
  FilterRun run(plane);
  EXPECT_GT(run.Errors->Count, 0);
  EXPECT_EQ(run.Output()->GetNumberOfPoints(), 0);
}

// A polygon naming a point the input does not have (past the end, or negative) would
// make every pass read outside the point arrays.
TEST(vtkMikkTSpaceTangents, ErrorWithPointIdsOutOfRange)
{
  for (const bool wide : { true, false })
  {
    for (const vtkIdType bad : { vtkIdType(25), vtkIdType(-1), vtkIdType(1) << 40 })
    {
      if (!wide && bad > VTK_TYPE_INT32_MAX)
      {
        continue; // 32-bit connectivity cannot hold it
      }
      auto plane = MakePlane(4);
      vtkNew<vtkCellArray> polys;
      polys->DeepCopy(plane->GetPolys());
      if (wide)
      {
        polys->ConvertTo64BitStorage();
      }
      else
      {
        polys->ConvertTo32BitStorage();
      }
      vtkDataArray* conn = polys->GetConnectivityArray();
      conn->SetComponent(conn->GetNumberOfTuples() - 1, 0, static_cast<double>(bad));
      plane->SetPolys(polys);
      FilterRun run(plane);
      EXPECT_GT(run.Errors->Count, 0) << bad << (wide ? " in 64-bit" : " in 32-bit");
      EXPECT_EQ(run.Output()->GetNumberOfPoints(), 0) << bad;
      EXPECT_EQ(plane->GetNumberOfPoints(), 25);
    }
  }
  // The largest valid id passes: the check is not off by one.
  auto plane = MakePlane(4);
  FilterRun run(plane);
  EXPECT_EQ(run.Errors->Count, 0);
  EXPECT_EQ(run.Output()->GetNumberOfPoints(), 25);
}

TEST(vtkMikkTSpaceTangents, ErrorWithImageDataInput)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 1);
  FilterRun run(image);
  EXPECT_GT(run.Errors->Count, 0);
}

// ---- degenerate input (stress) -----------------------------------------------------------

TEST(vtkMikkTSpaceTangents, StressZeroAreaTriangles)
{
  auto plane = MakePlane(40);
  vtkPoints* pts = plane->GetPoints();
  // Collapse every 7th point onto its neighbour and make rows of collinear points.
  for (vtkIdType i = 7; i + 1 < pts->GetNumberOfPoints(); i += 7)
  {
    pts->SetPoint(i, pts->GetPoint(i + 1));
  }
  for (int i = 0; i <= 40; ++i)
  {
    double p[3];
    pts->GetPoint(41 * 20 + i, p);
    p[1] = pts->GetPoint(41 * 19 + i)[1];
    pts->SetPoint(41 * 20 + i, p);
  }
  FilterRun run(plane);
  EXPECT_EQ(run.Errors->Count, 0);
  ExpectValidFrames(run.Output());
}

TEST(vtkMikkTSpaceTangents, StressZeroAreaTextureTriangles)
{
  auto sphere = MakeUVSphere(40, 20);
  vtkDataArray* tc = sphere->GetPointData()->GetTCoords();
  // Every 5th point gets the texture coordinates of the next, and a band gets one value.
  for (vtkIdType i = 0; i + 1 < tc->GetNumberOfTuples(); i += 5)
  {
    tc->SetTuple(i, tc->GetTuple(i + 1));
  }
  for (vtkIdType i = 200; i < 400; ++i)
  {
    tc->SetTuple2(i, 0.25, 0.5);
  }
  FilterRun run(sphere);
  EXPECT_EQ(run.Errors->Count, 0);
  ExpectValidFrames(run.Output());
}

TEST(vtkMikkTSpaceTangents, StressCollinearAndConstantTextureCoordinates)
{
  for (int mode = 0; mode < 2; ++mode)
  {
    auto torus = MakeTorus(30, 15);
    vtkDataArray* tc = torus->GetPointData()->GetTCoords();
    for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
    {
      const double s = mode == 0 ? 0.01 * static_cast<double>(i) : 0.0;
      tc->SetTuple2(i, s, 2 * s);
    }
    FilterRun run(torus);
    EXPECT_EQ(run.Errors->Count, 0);
    ExpectValidFrames(run.Output());
  }
}

// vtkTexturedSphereSource's south pole: a row of distinct points 6e-17 apart, slivers
// whose texture derivatives vanish below rounding.
TEST(vtkMikkTSpaceTangents, StressVTKTexturedSpherePoles)
{
  vtkNew<vtkTexturedSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  sphere->Update();
  FilterRun run(sphere->GetOutput());
  EXPECT_EQ(run.Errors->Count, 0);
  ExpectValidFrames(run.Output());
}

TEST(vtkMikkTSpaceTangents, MissingNormalsAreComputedWithAWarning)
{
  const double A[2][2] = { { 1.0, 0.0 }, { 0.0, 1.0 } };
  auto plane = AffinePlane(6, A);
  plane->GetPointData()->SetNormals(nullptr);
  plane->GetPointData()->RemoveArray("Normals");
  FilterRun run(plane);
  EXPECT_EQ(run.Errors->Count, 0);
  EXPECT_GT(run.Warnings->Count, 0);
  vtkPolyData* out = run.Output();
  ASSERT_NE(out->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(out->GetNumberOfPoints(), plane->GetNumberOfPoints());
  ExpectValidFrames(out);
  ExpectAffineFrames(out, A);
  EXPECT_EQ(plane->GetPointData()->GetNormals(), nullptr); // input untouched
}

TEST(vtkMikkTSpaceTangents, StressNonFiniteCoordinates)
{
  auto torus = MakeTorus(30, 15);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  torus->GetPoints()->SetPoint(40, nan, 0.0, 0.0);
  torus->GetPoints()->SetPoint(100, inf, -inf, nan);
  torus->GetPointData()->GetTCoords()->SetTuple2(200, nan, 0.5);
  torus->GetPointData()->GetNormals()->SetTuple3(300, nan, nan, nan);
  torus->GetPointData()->GetNormals()->SetTuple3(301, 0.0, 0.0, 0.0);
  FilterRun run(torus);
  EXPECT_EQ(run.Errors->Count, 0);
  EXPECT_GT(run.Warnings->Count, 0);
  ExpectValidFrames(run.Output());
}

// Many NaN points at once (they must not be compared with each other, nor hang the weld).
TEST(vtkMikkTSpaceTangents, StressManyNaNPoints)
{
  auto plane = MakePlane(300);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (vtkIdType i = 0; i < plane->GetNumberOfPoints(); i += 2)
  {
    plane->GetPoints()->SetPoint(i, nan, nan, nan);
    plane->GetPointData()->GetNormals()->SetTuple3(i, nan, nan, nan);
    plane->GetPointData()->GetTCoords()->SetTuple2(i, nan, nan);
  }
  FilterRun run(plane);
  EXPECT_EQ(run.Errors->Count, 0);
  EXPECT_GT(run.Warnings->Count, 0);
  ExpectValidFrames(run.Output());
}

// 200000 triangles around one point, and as many meeting on one edge: no quadratic work.
TEST(vtkMikkTSpaceTangents, StressHugeFanAndEdge)
{
  const int n = 200000;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals, tcoords;
  normals->SetNumberOfComponents(3);
  tcoords->SetNumberOfComponents(2);
  auto add = [&](double x, double y, double z)
  {
    points->InsertNextPoint(x, y, z);
    normals->InsertNextTuple3(0.0, 0.0, 1.0);
    tcoords->InsertNextTuple2(x, y);
    return points->GetNumberOfPoints() - 1;
  };
  const vtkIdType centre = add(0.0, 0.0, 0.0);
  const vtkIdType end = add(1.0, 0.0, 0.0);
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ring;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2 * Pi * i / n;
    ring.push_back(add(std::cos(a), std::sin(a), 0.0));
  }
  for (int i = 0; i < n; ++i)
  {
    const vtkIdType fan[3] = { centre, ring[i], ring[(i + 1) % n] };
    polys->InsertNextCell(3, fan);
    // a book of triangles on the edge (centre, end), alternating direction
    const vtkIdType page[3] = { i % 2 ? end : centre, i % 2 ? centre : end, ring[i] };
    polys->InsertNextCell(3, page);
  }
  auto pd = MakeSurface(points, polys, normals, tcoords);
  FilterRun run(pd);
  EXPECT_EQ(run.Errors->Count, 0);
  ExpectValidFrames(run.Output());
}

// A random triangle soup over few distinct values: duplicates, degenerate and
// non-manifold triangles, shared edges used in the same direction, mixed orientation.
TEST(vtkMikkTSpaceTangents, StressRandomNonManifoldSoup)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(4);
  auto next = [&random](int n)
  {
    random->Next();
    return static_cast<int>(random->GetValue() * n) % n;
  };
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals, tcoords;
  normals->SetNumberOfComponents(3);
  tcoords->SetNumberOfComponents(2);
  for (int i = 0; i < 3000; ++i)
  {
    const double p[3] = { double(next(6)), double(next(6)), double(next(3)) };
    points->InsertNextPoint(p);
    double n[3] = { double(next(3)) - 1, double(next(3)) - 1, 1.0 };
    vtkMath::Normalize(n);
    normals->InsertNextTuple(n);
    tcoords->InsertNextTuple2(next(4) * 0.25, next(4) * 0.25);
  }
  vtkNew<vtkCellArray> polys;
  for (int t = 0; t < 20000; ++t)
  {
    const int n = 3 + next(3) % 2; // triangles and quads
    vtkIdType ids[4];
    for (int k = 0; k < n; ++k)
    {
      ids[k] = next(3000);
    }
    polys->InsertNextCell(n, ids);
  }
  auto soup = MakeSurface(points, polys, normals, tcoords);
  FilterRun run(soup);
  EXPECT_EQ(run.Errors->Count, 0);
  ExpectValidFrames(run.Output());
  EXPECT_EQ(run.Output()->GetNumberOfPolys(), 20000);
}
