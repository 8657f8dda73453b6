// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter on surfaces with hard edges: a cube (vtkCubeSource) and a faceted
// sphere (vtkSphereSource through vtkPolyDataNormals with splitting). At a hard edge several
// points share a position but not a normal. With MergeSeams on, they must move together (by
// the mean of their own displacements, so that no crack opens) while each keeps the normal of
// its own side: merging their normals would bend every face at its border.
//
// The height is affine in (s,t) and every texture coordinate lies inside the texel centres'
// hull, so Linear interpolation reproduces it exactly, with its exact slope. Each face of
// these meshes is planar and its texture coordinates are affine on it. The truth is then
// closed form, computed here from the input's own faces:
// - positions: p + mean over the coincident points k of Scale (h(s_k, t_k) - Midlevel) n_k;
// - Approximate and Exact: the normal of the face displaced by its own height,
//   (P_s + d_s n) x (P_t + d_t n), with P_s, P_t the face's own derivatives (a face's normal
//   does not change across it, so Exact's d n_s terms vanish);
// - Mesh: the sum of the vector areas of the displaced polygons around the point, each
//   oriented as the input normals of its points.

#include "DisplacementTestSurfaces.h"

#include "vtkDisplacementMapFilter.h"

#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkCubeSource.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
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

// h(s,t) = H0 + Hs s + Ht t.
struct AffineHeight
{
  double H0, Hs, Ht;
  double operator()(double s, double t) const { return this->H0 + this->Hs * s + this->Ht * t; }
};

const int NormalModes[3] = { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
  vtkDisplacementMapFilter::Mesh };

const char* ModeName(int mode)
{
  switch (mode)
  {
    case vtkDisplacementMapFilter::Approximate:
      return "Approximate";
    case vtkDisplacementMapFilter::Exact:
      return "Exact";
    case vtkDisplacementMapFilter::Mesh:
      return "Mesh";
    default:
      return "Input";
  }
}

Vec PointOf(vtkPolyData* mesh, vtkIdType id)
{
  Vec p;
  mesh->GetPoint(id, p.data());
  return p;
}

Vec TupleOf(vtkDataArray* array, vtkIdType id)
{
  Vec v{ 0.0, 0.0, 0.0 };
  for (int k = 0; k < std::min(3, array->GetNumberOfComponents()); ++k)
  {
    v[k] = array->GetComponent(id, k);
  }
  return v;
}

std::vector<std::vector<vtkIdType>> CellPoints(vtkPolyData* mesh)
{
  std::vector<std::vector<vtkIdType>> cells;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    cells.emplace_back(ids->begin(), ids->end());
  }
  return cells;
}

// The vector area of a polygon, 1/2 sum p_k x p_k+1: the area-weighted normal of any
// triangulation of it, planar or not.
Vec VectorArea(const std::vector<Vec>& corners)
{
  Vec sum{ 0.0, 0.0, 0.0 };
  for (size_t k = 0; k < corners.size(); ++k)
  {
    sum = Add(sum, CrossV(corners[k], corners[(k + 1) % corners.size()]), 0.5);
  }
  return sum;
}

// The groups of points at exactly one place (the meshes here copy coordinates exactly when
// they split a point).
std::vector<std::vector<vtkIdType>> CoincidentGroups(vtkPolyData* mesh)
{
  std::map<Vec, std::vector<vtkIdType>> byPosition;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    byPosition[PointOf(mesh, i)].push_back(i);
  }
  std::vector<std::vector<vtkIdType>> groups;
  for (auto& entry : byPosition)
  {
    groups.push_back(entry.second);
  }
  return groups;
}

// The derivatives (P_s, P_t) of the affine map over the triangle a, b, c from its positions
// and texture coordinates.
void FaceDerivatives(vtkPolyData* mesh, vtkIdType a, vtkIdType b, vtkIdType c, Vec& ps, Vec& pt)
{
  vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
  const Vec e1 = Add(PointOf(mesh, b), PointOf(mesh, a), -1.0);
  const Vec e2 = Add(PointOf(mesh, c), PointOf(mesh, a), -1.0);
  const double s1 = tc->GetComponent(b, 0) - tc->GetComponent(a, 0);
  const double t1 = tc->GetComponent(b, 1) - tc->GetComponent(a, 1);
  const double s2 = tc->GetComponent(c, 0) - tc->GetComponent(a, 0);
  const double t2 = tc->GetComponent(c, 1) - tc->GetComponent(a, 1);
  // [e1 e2] = [ps pt] [[s1 s2] [t1 t2]]
  const double det = s1 * t2 - s2 * t1;
  ps = Add(Vec{ e1[0] * t2 / det, e1[1] * t2 / det, e1[2] * t2 / det }, e2, -t1 / det);
  pt = Add(Vec{ e2[0] * s1 / det, e2[1] * s1 / det, e2[2] * s1 / det }, e1, -s2 / det);
}

struct Truth
{
  std::vector<Vec> Positions;
  std::vector<Vec> Normals; // for the mode asked
};

Truth ExpectedSurface(vtkPolyData* mesh, const AffineHeight& h, double scale, double midlevel,
  int mode, const std::vector<std::vector<vtkIdType>>& groups)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
  std::vector<Vec> unit(n);
  std::vector<double> d(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    unit[i] = Unit(TupleOf(normals, i));
    d[i] = scale * (h(tc->GetComponent(i, 0), tc->GetComponent(i, 1)) - midlevel);
  }
  Truth truth;
  truth.Positions.resize(n);
  for (const auto& group : groups)
  {
    Vec mean{ 0.0, 0.0, 0.0 };
    for (vtkIdType k : group)
    {
      mean = Add(mean, unit[k], d[k] / static_cast<double>(group.size()));
    }
    for (vtkIdType k : group)
    {
      truth.Positions[k] = Add(PointOf(mesh, k), mean);
    }
  }
  const auto cells = CellPoints(mesh);
  truth.Normals.assign(n, Vec{ 0.0, 0.0, 0.0 });
  if (mode == vtkDisplacementMapFilter::Mesh)
  {
    for (const auto& cell : cells)
    {
      std::vector<Vec> input, moved;
      Vec normalSum{ 0.0, 0.0, 0.0 };
      for (vtkIdType id : cell)
      {
        input.push_back(PointOf(mesh, id));
        moved.push_back(truth.Positions[id]);
        normalSum = Add(normalSum, unit[id]);
      }
      const double side = DotV(VectorArea(input), normalSum) < 0.0 ? -1.0 : 1.0;
      for (vtkIdType id : cell)
      {
        truth.Normals[id] = Add(truth.Normals[id], VectorArea(moved), side);
      }
    }
    for (Vec& m : truth.Normals)
    {
      m = Unit(m);
    }
    return truth;
  }
  // Approximate and Exact: each point's face, from the first polygon that uses it.
  std::vector<char> done(n, 0);
  for (const auto& cell : cells)
  {
    Vec ps, pt;
    FaceDerivatives(mesh, cell[0], cell[1], cell[2], ps, pt);
    for (vtkIdType id : cell)
    {
      if (done[id])
      {
        continue;
      }
      done[id] = 1;
      const Vec& nn = unit[id];
      const Vec a = Add(Add(ps, nn, -DotV(ps, nn)), nn, scale * h.Hs);
      const Vec b = Add(Add(pt, nn, -DotV(pt, nn)), nn, scale * h.Ht);
      const Vec m = CrossV(a, b);
      const double side = DotV(CrossV(ps, pt), nn) < 0.0 ? -1.0 : 1.0;
      truth.Normals[id] = Unit(Vec{ side * m[0], side * m[1], side * m[2] });
    }
  }
  return truth;
}

vtkSmartPointer<vtkPolyData> Displace(
  vtkPolyData* mesh, const AffineHeight& h, double scale, double midlevel, int mode)
{
  vtkNew<vtkDisplacementMapFilter> filter;
  filter->SetInputData(0, mesh);
  filter->SetInputData(1, MakeHeightImage(h, 16, 16));
  filter->SetScaleFactor(scale);
  filter->SetMidlevel(midlevel);
  filter->SetInterpolationToLinear();
  filter->SetWrapToClampToEdge();
  filter->SetNormalMode(mode);
  vtkNew<ErrorCounter> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->Update();
  EXPECT_EQ(errors->Count, 0);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(filter->GetOutput());
  return out;
}

// Runs every normal mode on @a mesh and compares with the closed form.
void ExpectClosedForm(vtkPolyData* mesh, const AffineHeight& h, double scale, double midlevel,
  double angleBound, const std::string& name)
{
  const auto groups = CoincidentGroups(mesh);
  size_t shared = 0;
  for (const auto& group : groups)
  {
    shared += group.size() > 1 ? 1 : 0;
  }
  EXPECT_GT(shared, 0u) << name << ": the mesh must have hard edges";
  // The truth below has no normals to merge: coincident points all differ in normal.
  for (const auto& group : groups)
  {
    for (size_t a = 0; a < group.size(); ++a)
    {
      for (size_t b = a + 1; b < group.size(); ++b)
      {
        EXPECT_GT(AngleDeg(TupleOf(mesh->GetPointData()->GetNormals(), group[a]),
                    TupleOf(mesh->GetPointData()->GetNormals(), group[b])),
          1.0)
          << name;
      }
    }
  }
  for (int mode : NormalModes)
  {
    SCOPED_TRACE(name + " " + ModeName(mode));
    auto out = Displace(mesh, h, scale, midlevel, mode);
    const Truth truth = ExpectedSurface(mesh, h, scale, midlevel, mode, groups);
    vtkDataArray* normals = out->GetPointData()->GetNormals();
    double worstPosition = 0.0, worstAngle = 0.0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      const Vec gap = Add(PointOf(out, i), truth.Positions[i], -1.0);
      worstPosition = std::max(worstPosition, std::sqrt(DotV(gap, gap)));
      worstAngle = std::max(worstAngle, AngleDeg(TupleOf(normals, i), truth.Normals[i]));
    }
    // No crack: coincident points stay exactly together.
    for (const auto& group : groups)
    {
      for (vtkIdType k : group)
      {
        const Vec a = PointOf(out, group[0]), b = PointOf(out, k);
        EXPECT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2])
          << "points " << group[0] << " and " << k << " apart";
      }
    }
    std::printf("%s, %s: worst position error %.3e, worst normal angle %.3e deg\n", name.c_str(),
      ModeName(mode), worstPosition, worstAngle);
    EXPECT_LT(worstPosition, 1e-12);
    EXPECT_LT(worstAngle, angleBound);
  }
}

// vtkCubeSource's cube (24 points, one quad per face, each face its own texture square),
// in double, with its texture coordinates moved into [0.25, 0.75]^2, inside the texel
// centres of the height map.
vtkSmartPointer<vtkPolyData> Cube()
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(1.0);
  cube->SetYLength(1.5);
  cube->SetZLength(0.75);
  cube->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  cube->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(cube->GetOutput());
  vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
  vtkNew<vtkDoubleArray> inside;
  inside->SetName("TCoords");
  inside->SetNumberOfComponents(2);
  inside->SetNumberOfTuples(tc->GetNumberOfTuples());
  for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
  {
    inside->SetTuple2(i, 0.5 + 0.25 * tc->GetComponent(i, 0), 0.5 + 0.25 * tc->GetComponent(i, 1));
  }
  mesh->GetPointData()->SetTCoords(inside);
  return mesh;
}

// A sphere whose faces are split apart at every edge sharper than @a featureAngle by
// vtkPolyDataNormals, so that each point belongs to one facet and carries its normal. Each
// facet (a triangle, or the two coplanar triangles of a band quad) gets texture coordinates
// from an orthonormal frame in its own plane, an affine map like any UV unwrap of a flat face.
vtkSmartPointer<vtkPolyData> FacetedSphere(double featureAngle)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(10);
  sphere->SetPhiResolution(7);
  sphere->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  vtkNew<vtkPolyDataNormals> split;
  split->SetInputConnection(sphere->GetOutputPort());
  split->SplittingOn();
  split->SetFeatureAngle(featureAngle);
  split->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(split->GetOutput());

  // Facets: cells that share a point id (splitting gives cells across a sharp edge their own
  // copies of its points).
  const auto cells = CellPoints(mesh);
  std::vector<vtkIdType> parent(cells.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](vtkIdType c)
  {
    while (parent[c] != c)
    {
      c = parent[c] = parent[parent[c]];
    }
    return c;
  };
  std::vector<vtkIdType> firstCell(mesh->GetNumberOfPoints(), -1);
  for (vtkIdType c = 0; c < static_cast<vtkIdType>(cells.size()); ++c)
  {
    for (vtkIdType id : cells[c])
    {
      if (firstCell[id] < 0)
      {
        firstCell[id] = c;
      }
      parent[find(c)] = find(firstCell[id]);
    }
  }
  vtkNew<vtkDoubleArray> tc;
  tc->SetName("TCoords");
  tc->SetNumberOfComponents(2);
  tc->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    const auto& facet = cells[find(firstCell[id])];
    const Vec p0 = PointOf(mesh, facet[0]);
    const Vec n =
      Unit(CrossV(Add(PointOf(mesh, facet[1]), p0, -1.0), Add(PointOf(mesh, facet[2]), p0, -1.0)));
    const Vec axis = std::abs(n[2]) < 0.9 ? Vec{ 0.0, 0.0, 1.0 } : Vec{ 1.0, 0.0, 0.0 };
    const Vec e1 = Unit(CrossV(axis, n)), e2 = CrossV(n, e1);
    const Vec p = PointOf(mesh, id);
    tc->SetTuple2(id, 0.5 + 0.4 * DotV(p, e1), 0.5 + 0.4 * DotV(p, e2));
    // Each facet is flat, so that the map is affine on it: its points carry its normal.
    EXPECT_LT(AngleDeg(TupleOf(mesh->GetPointData()->GetNormals(), id), n), 1e-5)
      << "point " << id << " is not on a flat facet";
  }
  mesh->GetPointData()->SetTCoords(tc);
  return mesh;
}
} // namespace

// A constant height moves every face of the cube out along its own normal: the faces stay
// flat and keep their normals, in every mode. At each corner the three faces' points move
// together by the mean of their three displacements, which moves every face parallel to itself.
TEST(DisplacementMapFilterHardEdges, CubeFacesKeepTheirNormalsUnderAConstantHeight)
{
  auto cube = Cube();
  ASSERT_EQ(cube->GetNumberOfPoints(), 24);
  const AffineHeight constant{ 0.8, 0.0, 0.0 };
  ExpectClosedForm(cube, constant, 0.3, 0.1, 1e-9, "cube, constant height");
  // The closed form is the face normal itself here.
  for (int mode : NormalModes)
  {
    auto out = Displace(cube, constant, 0.3, 0.1, mode);
    for (vtkIdType i = 0; i < cube->GetNumberOfPoints(); ++i)
    {
      EXPECT_LT(AngleDeg(TupleOf(out->GetPointData()->GetNormals(), i),
                  TupleOf(cube->GetPointData()->GetNormals(), i)),
        1e-9)
        << ModeName(mode) << " point " << i;
    }
  }
}

// A sloped height: each face tilts by its own slope, whatever its neighbours across the edge.
TEST(DisplacementMapFilterHardEdges, CubeFacesTiltByTheirOwnSlope)
{
  ExpectClosedForm(Cube(), AffineHeight{ 0.2, 0.7, -0.4 }, 0.25, 0.5, 1e-9, "cube, sloped height");
}

// The faceted sphere: every point is split into one copy per facet around it (up to ten at the
// poles), each with its facet's normal; each copy's normal is its own facet's, displaced.
TEST(DisplacementMapFilterHardEdges, FacetedSphereKeepsEachFacetsNormal)
{
  auto sphere = FacetedSphere(5.0);
  ASSERT_GT(sphere->GetNumberOfPoints(), 100);
  ExpectClosedForm(
    sphere, AffineHeight{ 0.8, 0.0, 0.0 }, 0.1, 0.0, 1e-9, "faceted sphere, constant height");
  ExpectClosedForm(
    sphere, AffineHeight{ 0.3, 0.6, -0.5 }, 0.15, 0.4, 1e-9, "faceted sphere, sloped height");
}
