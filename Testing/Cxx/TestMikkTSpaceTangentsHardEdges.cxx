// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkMikkTSpaceTangents at a hard edge. MikkTSpace welds corners by value, and its key is the
// position, the normal and the texture coordinate: corners on the two sides of a hard edge
// share position and texture coordinate but not the normal, and must stay apart. Joined, they
// would form one vertex with one normal, whose tangent averages both faces' directions and is
// orthogonal to only one of the two normals.
//
// The surface is a sheet folded along the x axis: a floor (z = 0, normal +z) and a wall
// rising from it at an angle theta, with one affine texture map across the fold, continuous
// at it. Each face is planar with an affine map, so its tangent is the closed form
// normalize(dP/ds) (dP/ds lies in the face), with w = +1 (triangles counter-clockwise in
// texture space and around the normal). The directions differ between the faces after
// projection onto either face's plane, so a joined vertex would show on both sides.

#include "MikkTSpaceTestMeshes.h"
#include "TangentFrameTestHelpers.h"

#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkMath.h"
#include "vtkMikkTSpaceTangents.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

namespace
{
using namespace mikktest;
using Vec = std::array<double, 3>;

// The fold: floor points (x, v, 0) for v in [-1, 0], wall points (x, v cos theta, v sin theta)
// for v in [0, 1], texture coordinates (s, t) = (x, v + x/2) on both.
struct Fold
{
  double Theta; // radians

  Vec FloorNormal() const { return { 0.0, 0.0, 1.0 }; }
  Vec WallNormal() const { return { 0.0, -std::sin(this->Theta), std::cos(this->Theta) }; }
  // x = s, v = t - s/2: dP/ds = (1, -1/2, 0) on the floor, (1, -cos/2, -sin/2) on the wall.
  Vec FloorTangent() const { return Normalized({ 1.0, -0.5, 0.0 }); }
  Vec WallTangent() const
  {
    return Normalized({ 1.0, -0.5 * std::cos(this->Theta), -0.5 * std::sin(this->Theta) });
  }
};

// An n x 2n grid over x in [0,1], v in [-1, 1], triangles counter-clockwise in (x, v) (and so
// in (s,t)). @a splitEdge: the points of the row v = 0 are made twice, once for each face,
// with each face's normal (what a modeller's hard edge or vtkPolyDataNormals' splitting
// gives); otherwise the row is shared and the mesh has no normals.
vtkSmartPointer<vtkPolyData> MakeFold(const Fold& fold, int n, bool splitEdge)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto normals = NewFloatArray("Normals", 3);
  auto tcoords = NewFloatArray("TCoords", 2);
  // Rows 0..n are the floor (v = -1 .. 0); then the wall, from v = 0 again when the edge is
  // split, from v = 1/n otherwise.
  const int rows = splitEdge ? 2 * n + 2 : 2 * n + 1;
  for (int j = 0; j < rows; ++j)
  {
    const bool wall = j > n;
    const double v = splitEdge && wall ? static_cast<double>(j - n - 1) / n : -1.0 + j / double(n);
    for (int i = 0; i <= n; ++i)
    {
      const double x = static_cast<double>(i) / n;
      const Vec p =
        wall ? Vec{ x, v * std::cos(fold.Theta), v * std::sin(fold.Theta) } : Vec{ x, v, 0.0 };
      points->InsertNextPoint(p.data());
      const Vec nn = wall ? fold.WallNormal() : fold.FloorNormal();
      normals->InsertNextTuple(nn.data());
      tcoords->InsertNextTuple2(x, v + 0.5 * x);
    }
  }
  vtkNew<vtkCellArray> polys;
  auto id = [n](int i, int j) { return static_cast<vtkIdType>(j * (n + 1) + i); };
  for (int j = 0; j + 1 < rows; ++j)
  {
    if (splitEdge && j == n)
    {
      continue; // rows n and n+1 are the same place, one for each face
    }
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      const vtkIdType t1[3] = { a, b, c }, t2[3] = { a, c, d };
      polys->InsertNextCell(3, t1);
      polys->InsertNextCell(3, t2);
    }
  }
  vtkSmartPointer<vtkPolyData> mesh = MakeSurface(points, polys, normals, tcoords);
  if (!splitEdge)
  {
    mesh->GetPointData()->SetNormals(nullptr);
  }
  return mesh;
}

class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  int Count = 0;
};

vtkSmartPointer<vtkPolyData> Tangents(vtkPolyData* mesh)
{
  vtkNew<vtkMikkTSpaceTangents> filter;
  vtkNew<ErrorCounter> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->SetInputData(mesh);
  filter->Update();
  EXPECT_EQ(errors->Count, 0);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(filter->GetOutput());
  return out;
}

double AngleDeg(const Vec& a, const Vec& b)
{
  const Vec c = CrossD(a, b);
  return std::atan2(vtkMath::Norm(c.data()), vtkMath::Dot(a.data(), b.data())) * 180.0 / Pi;
}

// Every output point's tangent is its own face's closed form: the face is told by the point's
// normal. Both faces must be present, and the points of the edge on both sides.
void ExpectEachFacesTangent(vtkPolyData* out, const Fold& fold, const std::string& name)
{
  SCOPED_TRACE(name);
  auto tangents = TangentFrame(out);
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  ASSERT_NE(tangents, nullptr);
  ASSERT_NE(normals, nullptr);
  ASSERT_EQ(tangents->GetNumberOfComponents(), 4);
  int floorEdge = 0, wallEdge = 0, bad = 0;
  double worst = 0.0, worstDot = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double t4[4];
    Vec n, p;
    tangents->GetTuple(i, t4);
    normals->GetTuple(i, n.data());
    out->GetPoint(i, p.data());
    n = Normalized(n);
    const Vec t{ t4[0], t4[1], t4[2] };
    const bool floor = AngleDeg(n, fold.FloorNormal()) < 1e-3;
    const bool wall = AngleDeg(n, fold.WallNormal()) < 1e-3;
    ASSERT_TRUE(floor || wall) << "point " << i << " has neither face's normal";
    const bool onEdge = std::abs(p[1]) < 1e-12 && std::abs(p[2]) < 1e-12;
    floorEdge += onEdge && floor ? 1 : 0;
    wallEdge += onEdge && wall ? 1 : 0;
    const double angle = AngleDeg(t, floor ? fold.FloorTangent() : fold.WallTangent());
    const double dot = std::abs(vtkMath::Dot(t.data(), n.data()));
    worst = std::max(worst, angle);
    worstDot = std::max(worstDot, dot);
    if ((angle > 1e-3 || dot > 1e-5 || t4[3] != 1.0) && bad++ < 5)
    {
      ADD_FAILURE() << "point " << i << (onEdge ? " (on the edge)" : "") << " of the "
                    << (floor ? "floor" : "wall") << ": tangent (" << t4[0] << ", " << t4[1] << ", "
                    << t4[2] << ", " << t4[3] << "), " << angle << " deg from its face's, |T.N| "
                    << dot;
    }
  }
  std::printf(
    "%s: worst tangent angle %.3e deg, worst |T.N| %.3e\n", name.c_str(), worst, worstDot);
  EXPECT_EQ(bad, 0);
  EXPECT_GT(floorEdge, 0);
  EXPECT_EQ(floorEdge, wallEdge);
}

const double Angles[2] = { 90.0, 40.0 }; // a cube's edge, and one a 30-degree split catches
} // namespace

// The fold's edge points made once per face, with the same position and texture coordinate.
TEST(MikkTSpaceTangentsHardEdges, CornersWithDifferentNormalsAreNotWelded)
{
  for (double degrees : Angles)
  {
    const Fold fold{ vtkMath::RadiansFromDegrees(degrees) };
    vtkSmartPointer<vtkPolyData> mesh = MakeFold(fold, 6, true);
    vtkSmartPointer<vtkPolyData> out = Tangents(mesh);
    // Nothing to split: one frame per point.
    EXPECT_EQ(out->GetNumberOfPoints(), mesh->GetNumberOfPoints());
    ExpectEachFacesTangent(
      out, fold, "split edge, " + std::to_string(static_cast<int>(degrees)) + " degrees");
  }
}

// Every triangle on its own points: the weld must join the corners within each face (by
// value) and still not across the edge.
TEST(MikkTSpaceTangentsHardEdges, TriangleSoupWeldsWithinFacesOnly)
{
  for (double degrees : Angles)
  {
    const Fold fold{ vtkMath::RadiansFromDegrees(degrees) };
    vtkSmartPointer<vtkPolyData> out = Tangents(Unweld(MakeFold(fold, 6, true)));
    ExpectEachFacesTangent(
      out, fold, "triangle soup, " + std::to_string(static_cast<int>(degrees)) + " degrees");
  }
}

// The hard edge as vtkPolyDataNormals makes it: a connected sheet split at its feature edge,
// the split points carrying the shared point's texture coordinate.
TEST(MikkTSpaceTangentsHardEdges, PolyDataNormalsSplitEdgeKeepsBothSides)
{
  for (double degrees : Angles)
  {
    const Fold fold{ vtkMath::RadiansFromDegrees(degrees) };
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(MakeFold(fold, 6, false));
    normals->SplittingOn();
    normals->SetFeatureAngle(30.0);
    normals->ConsistencyOff();
    normals->Update();
    vtkPolyData* split = normals->GetOutput();
    ASSERT_EQ(split->GetNumberOfPoints(), (6 + 1) * (2 * 6 + 2)) << "the edge row is split";
    ExpectEachFacesTangent(Tangents(split), fold,
      "vtkPolyDataNormals, " + std::to_string(static_cast<int>(degrees)) + " degrees");
  }
}
