// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkMikkTSpaceTangents: closed-form frames, bad input, degenerate input (stress), kept
// arrays and cells, thread-count independence.
#include "MikkTSpaceTestMeshes.h"
#include "TangentFrameTestHelpers.h"

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

#include <algorithm>
#include <array>
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
  // The frame as vtkSurfaceDetailTangents stores it.
  vtkDataArray* t3 = out->GetPointData()->GetTangents();
  ASSERT_NE(t3, nullptr);
  EXPECT_STREQ(t3->GetName(), "Tangents");
  EXPECT_EQ(t3->GetNumberOfComponents(), 3);
  ASSERT_NE(vtkSurfaceDetailTangents::GetHandedness(out->GetPointData()), nullptr);
  EXPECT_EQ(vtkSurfaceDetailTangents::GetHandednessProblem(out->GetPointData()), "");
  auto tangents = TangentFrame(out);
  ASSERT_EQ(tangents->GetNumberOfTuples(), out->GetNumberOfPoints());
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
  auto tangents = TangentFrame(out);
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

// 20000 random triangles and quads over 3000 points whose values take few distinct values
// (a seeded soup): duplicates, degenerate and non-manifold triangles, shared edges used in
// the same direction, mixed orientation.
vtkSmartPointer<vtkPolyData> RandomSoup(int seed)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(seed);
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
  return MakeSurface(points, polys, normals, tcoords);
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
  auto frame = TangentFrame(out);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    if (i == lone || i == line[0] || i == line[1])
    {
      continue;
    }
    double t[4];
    frame->GetTuple(i, t);
    EXPECT_NEAR(t[0], 1.0, 1e-6) << "point " << i;
    EXPECT_EQ(t[3], 1.0) << "point " << i;
  }
}

// Polygons of one or two points have no triangle: they pass through, and their points keep
// a valid frame.
TEST(vtkMikkTSpaceTangents, PolygonsOfFewerThanThreePointsPassThrough)
{
  auto plane = MakePlane(4);
  const vtkIdType two[2] = { 24, 3 }, one[1] = { 7 };
  plane->GetPolys()->InsertNextCell(2, two);
  plane->GetPolys()->InsertNextCell(1, one);
  FilterRun run(plane);
  EXPECT_EQ(run.Errors->Count, 0);
  EXPECT_EQ(run.Output()->GetNumberOfPolys(), plane->GetNumberOfPolys());
  EXPECT_EQ(run.Output()->GetNumberOfPoints(), plane->GetNumberOfPoints());
  ExpectValidFrames(run.Output());
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
  auto frame = TangentFrame(out);
  for (vtkIdType q = nIn; q < out->GetNumberOfPoints(); ++q)
  {
    const vtkIdType p = outIds->GetValue(q);
    double tc[2], t1[4], t2[4];
    out->GetPointData()->GetTCoords()->GetTuple(q, tc);
    EXPECT_NEAR(tc[0], 0.0, 1e-7);
    frame->GetTuple(p, t1);
    frame->GetTuple(q, t2);
    EXPECT_EQ(t1[3], -t2[3]);
  }
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
      EXPECT_EQ(frame->GetComponent(pts->GetId(k), 3), centroidX > 0 ? 1.0 : -1.0);
    }
  }
}

// 1 thread (the sequential backend), 2 (the default backend) and 8 (STDThread, which starts
// as many threads as asked for whatever the cores): the same frames and cells, bit for bit.
TEST(vtkMikkTSpaceTangents, SameResultAnyThreadCount)
{
  // Split points (sphere poles, mirror line), welded copies (the unwelded torus), a big mesh,
  // non-manifold edges, degenerate triangles and quads (the soup).
  auto sphere = MakeUVSphere(160, 80);
  auto sheet = MakeMirroredSheet(120);
  auto torus = MakeTorus(300, 150);
  auto unwelded = Unweld(MakeTorus(60, 30));
  auto soup = RandomSoup(4);
  const std::string backend = vtkSMPTools::GetBackend();
  for (vtkPolyData* input : { sphere.Get(), sheet.Get(), torus.Get(), unwelded.Get(), soup.Get() })
  {
    vtkSMPTools::SetBackend("Sequential");
    FilterRun one(input);
    vtkSMPTools::SetBackend(backend.c_str());
    vtkSMPTools::Initialize(2);
    FilterRun two(input);
    if (!vtkSMPTools::SetBackend("STDThread"))
    {
      vtkSMPTools::SetBackend(backend.c_str());
    }
    vtkSMPTools::Initialize(8);
    FilterRun eight(input);
    vtkSMPTools::SetBackend(backend.c_str());
    vtkSMPTools::Initialize(0);
    vtkDataArray* c1 = one.Output()->GetPolys()->GetConnectivityArray();
    for (FilterRun* other : { &two, &eight })
    {
      for (const char* name : { "Tangents", "TangentHandedness" })
      {
        auto* t1 = vtkFloatArray::SafeDownCast(one.Output()->GetPointData()->GetArray(name));
        auto* t = vtkFloatArray::SafeDownCast(other->Output()->GetPointData()->GetArray(name));
        ASSERT_TRUE(t1 && t) << name;
        ASSERT_EQ(t1->GetNumberOfValues(), t->GetNumberOfValues());
        EXPECT_EQ(0,
          std::memcmp(t1->GetPointer(0), t->GetPointer(0), sizeof(float) * t->GetNumberOfValues()))
          << name;
      }
      vtkDataArray* c = other->Output()->GetPolys()->GetConnectivityArray();
      ASSERT_EQ(c1->GetNumberOfValues(), c->GetNumberOfValues());
      for (vtkIdType i = 0; i < c1->GetNumberOfValues(); ++i)
      {
        ASSERT_EQ(c1->GetTuple1(i), c->GetTuple1(i));
      }
    }
  }
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
    analytic->DeepCopy(TangentFrame(surface));
    ASSERT_EQ(analytic->GetNumberOfComponents(), 4) << c.Name;

    FilterRun run(surface);
    EXPECT_EQ(run.Errors->Count, 0) << c.Name;
    vtkPolyData* out = run.Output();
    ExpectValidFrames(out);
    ASSERT_EQ(out->GetNumberOfPoints(), surface->GetNumberOfPoints()) << c.Name;
    auto mikk = TangentFrame(out);
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

// MikkTSpace assumes unit normals; the filter normalises them first, so normals of any
// length give the frames of the unit ones (same points, same w, same directions).
TEST(vtkMikkTSpaceTangents, UnnormalisedNormalsGiveTheUnitNormalsFrames)
{
  auto torus = MakeTorus(30, 15);
  auto scaled = vtkSmartPointer<vtkPolyData>::New();
  scaled->DeepCopy(torus);
  vtkDataArray* normals = scaled->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    const double* n = normals->GetTuple3(i);
    const double s = 0.25 + (i % 7);
    normals->SetTuple3(i, s * n[0], s * n[1], s * n[2]);
  }
  FilterRun unit(torus), any(scaled);
  ASSERT_EQ(unit.Output()->GetNumberOfPoints(), any.Output()->GetNumberOfPoints());
  auto tu = TangentFrame(unit.Output());
  auto ta = TangentFrame(any.Output());
  for (vtkIdType i = 0; i < tu->GetNumberOfTuples(); ++i)
  {
    double a[4], b[4];
    tu->GetTuple(i, a);
    ta->GetTuple(i, b);
    for (int c = 0; c < 4; ++c)
    {
      EXPECT_NEAR(a[c], b[c], 1e-6) << "point " << i;
    }
  }
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

TEST(vtkMikkTSpaceTangents, StressRandomNonManifoldSoup)
{
  FilterRun run(RandomSoup(4));
  EXPECT_EQ(run.Errors->Count, 0);
  ExpectValidFrames(run.Output());
  EXPECT_EQ(run.Output()->GetNumberOfPolys(), 20000);
}
