// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter fed by the real vtkParametricSurfaceSource (vtkParametricSphere
// with dPdu/dPdv, dNdu/dNdv and tangents): the displaced points and normals against the closed form
// of the displaced sphere (DisplacementTestSurfaces.h), the texture seam crack-free and the
// poles finite. The source makes triangles and float arrays, the accuracy test's own meshes
// quads and doubles: this checks the two classes together as a user would chain them.

#include "DisplacementTestSurfaces.h"
#include "TangentFrameTestHelpers.h"

#include "vtkDisplacementMapFilter.h"
#include "vtkMikkTSpaceTangents.h"
#include "vtkParametricDonut.h"
#include "vtkParametricSphere.h"
#include "vtkParametricSurfaceSource.h"

#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

using namespace DisplacementTest;

namespace
{
struct Result
{
  double Position = 0.0; // max |p' - p*|
  double Angle = 0.0;    // max normal angle error, degrees
  double SeamGap = 0.0;  // max distance between the u = 0 and u = 1 copies of a point
  double SeamAngle = 0.0;
};

// @a normalDerivatives: keep the source's dNdu/dNdv (else Exact fits n_s, n_t).
Result DisplaceSourceSphere(
  int normalMode, int U, vtkImageData* image, const Surface& truth, bool normalDerivatives = true)
{
  vtkNew<vtkParametricSphere> sphere;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->SetUResolution(U);
  source->SetVResolution(U / 2);
  source->GenerateDerivativesOn();
  source->GenerateTangentsOn();
  source->Update();
  vtkNew<vtkPolyData> surface;
  surface->ShallowCopy(source->GetOutput());
  EXPECT_NE(surface->GetPointData()->GetArray("dNdu"), nullptr);
  if (!normalDerivatives)
  {
    surface->GetPointData()->RemoveArray("dNdu");
    surface->GetPointData()->RemoveArray("dNdv");
  }
  vtkNew<vtkDisplacementMapFilter> filter;
  filter->SetInputData(0, surface);
  filter->SetInputData(1, image);
  filter->SetScaleFactor(truth.Scale);
  filter->SetMidlevel(truth.Midlevel);
  filter->SetInterpolationToCubic();
  filter->SetNormalMode(normalMode);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  vtkDataArray* tc = out->GetPointData()->GetTCoords();
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  EXPECT_NE(tc, nullptr);
  EXPECT_NE(normals, nullptr);
  EXPECT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(U + 1) * (U / 2 + 1));
  Result r;
  if (!tc || !normals)
  {
    return r;
  }
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    Vec p, n;
    out->GetPoint(i, p.data());
    normals->GetTuple(i, n.data());
    EXPECT_TRUE(std::isfinite(n[0] + n[1] + n[2])) << "point " << i;
    const double u = tc->GetComponent(i, 0), v = tc->GetComponent(i, 1);
    const Vec d = Add(p, truth.Displaced(u, v), -1.0);
    r.Position = std::max(r.Position, std::sqrt(DotV(d, d)));
    // At the poles every copy has its own u, and the true normal is the limit.
    if (v > 1e-6 && v < 1.0 - 1e-6)
    {
      r.Angle = std::max(r.Angle, AngleDeg(n, truth.DisplacedNormal(u, v)));
    }
  }
  for (int j = 0; j <= U / 2; ++j)
  {
    const vtkIdType a = static_cast<vtkIdType>(j) * (U + 1), b = a + U;
    Vec pa, pb, na, nb;
    out->GetPoint(a, pa.data());
    out->GetPoint(b, pb.data());
    normals->GetTuple(a, na.data());
    normals->GetTuple(b, nb.data());
    const Vec gap = Add(pa, pb, -1.0);
    r.SeamGap = std::max(r.SeamGap, std::sqrt(DotV(gap, gap)));
    r.SeamAngle = std::max(r.SeamAngle, AngleDeg(na, nb));
  }
  return r;
}
} // namespace

TEST(DisplacementMapFilterParametric, SphereFromTheSourceMatchesTheClosedForm)
{
  const Surface truth = Sphere();
  const auto image = MakeHeightImage(truth.Height, 2048, 1024);
  const int exact = vtkDisplacementMapFilter::Exact;
  const Result exact64 = DisplaceSourceSphere(exact, 64, image, truth);
  const Result exact128 = DisplaceSourceSphere(exact, 128, image, truth);
  const Result fitted64 = DisplaceSourceSphere(exact, 64, image, truth, false);
  const Result fitted128 = DisplaceSourceSphere(exact, 128, image, truth, false);
  const Result approx128 =
    DisplaceSourceSphere(vtkDisplacementMapFilter::Approximate, 128, image, truth);
  std::printf("source sphere: position %.3e, normal error Exact (dNdu/dNdv) U=64 %.3e deg, "
              "U=128 %.3e deg, Exact (fitted n_s, n_t) U=64 %.3e deg, U=128 %.3e deg, "
              "Approximate U=128 %.3e deg, seam gap %.3e, seam angle %.3e deg\n",
    exact128.Position, exact64.Angle, exact128.Angle, fitted64.Angle, fitted128.Angle,
    approx128.Angle, exact128.SeamGap, exact128.SeamAngle);
  // Vertices: float positions of a unit sphere, and the cubic reconstruction of the map.
  EXPECT_LT(exact128.Position, 1e-6);
  EXPECT_LT(approx128.Position, 1e-6);
  // With the source's dNdu/dNdv no mesh error is left: the map's reconstruction error alone,
  // the same at both resolutions, and below the fitted normals'.
  EXPECT_LT(exact64.Angle, 1e-4);
  EXPECT_LT(exact128.Angle, 1e-4);
  EXPECT_LT(exact64.Angle, fitted64.Angle);
  EXPECT_LT(exact128.Angle, fitted128.Angle);
  // Fitted n_s and n_t converge at second order (dPdu/dPdv given).
  EXPECT_LT(fitted128.Angle, 1e-2);
  EXPECT_LT(fitted128.Angle, 0.4 * fitted64.Angle);
  // Approximate drops d dn/du: on a sphere of radius 1 with d ~ 0.1, a fixed bias.
  EXPECT_GT(approx128.Angle, 10.0 * exact128.Angle);
  // The seam's duplicated points move and turn identically: what gap remains is the
  // source's own (its u = 1 column has sin(2 pi) ~ 2.4e-16 where u = 0 has 0).
  EXPECT_LT(exact128.SeamGap, 1e-15);
  EXPECT_EQ(exact128.SeamAngle, 0.0);
  EXPECT_LT(approx128.SeamGap, 1e-15);
  EXPECT_EQ(approx128.SeamAngle, 0.0);
}

// Streamed in pieces, the chain source -> displacement -> MikkTSpace gives every point what
// the whole surface gives it, bit for bit, because each filter that reads neighbours asks for
// one more ghost level (the source makes them, across the donut's v seam too); outputs asked
// for no ghost levels have no ghost cells left. The same chain fed pieces cut off without
// ghost cells must differ at the borders, or this check would be blind.
TEST(DisplacementMapFilterParametric, PiecesWithGhostCellsEqualTheWhole)
{
  vtkNew<vtkParametricDonut> donut;
  vtkNew<vtkImageData> image;
  image->SetDimensions(32, 16, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  for (int j = 0; j < 16; ++j)
  {
    for (int i = 0; i < 32; ++i)
    {
      *static_cast<float*>(image->GetScalarPointer(i, j, 0)) = static_cast<float>(
        0.5 + 0.4 * std::sin(2 * Pi * 3 * (i + 0.5) / 32) * std::cos(2 * Pi * 2 * (j + 0.5) / 16));
    }
  }
  auto run = [&](int piece, int numPieces, bool ghosts)
  {
    vtkNew<vtkParametricSurfaceSource> source;
    source->SetParametricFunction(donut);
    source->SetUResolution(24);
    source->SetVResolution(17);
    source->GenerateTangentsOn();
    vtkNew<vtkDisplacementMapFilter> displace;
    displace->SetInputConnection(source->GetOutputPort());
    displace->SetInputData(1, image);
    displace->SetScaleFactor(0.1);
    displace->SetMidlevel(0.5);
    displace->SetNormalModeToMesh();
    vtkNew<vtkPolyData> cut;
    if (!ghosts)
    {
      source->UpdatePiece(piece, numPieces, 0);
      cut->ShallowCopy(source->GetOutput());
      displace->SetInputData(cut);
    }
    vtkNew<vtkMikkTSpaceTangents> mikk;
    mikk->SetInputConnection(displace->GetOutputPort());
    mikk->UpdatePiece(piece, numPieces, 0);
    vtkSmartPointer<vtkPolyData> out = mikk->GetOutput();
    return out;
  };
  vtkSmartPointer<vtkPolyData> whole = run(0, 1, true);
  std::map<std::pair<float, float>, vtkIdType> index;
  vtkDataArray* tc = whole->GetPointData()->GetTCoords();
  for (vtkIdType i = 0; i < whole->GetNumberOfPoints(); ++i)
  {
    index[{
      static_cast<float>(tc->GetComponent(i, 0)), static_cast<float>(tc->GetComponent(i, 1)) }] = i;
  }
  ASSERT_EQ(static_cast<vtkIdType>(index.size()), whole->GetNumberOfPoints());
  for (bool ghosts : { true, false })
  {
    double largest = 0.0; // difference of any point value from the whole's
    vtkIdType owned = 0, cells = 0;
    for (int piece = 0; piece < 3; ++piece)
    {
      vtkSmartPointer<vtkPolyData> out = run(piece, 3, ghosts);
      EXPECT_EQ(out->GetCellGhostArray(), nullptr);
      vtkUnsignedCharArray* marks = out->GetPointGhostArray();
      cells += out->GetNumberOfCells();
      vtkDataArray* ptc = out->GetPointData()->GetTCoords();
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        const auto it = index.find({ static_cast<float>(ptc->GetComponent(i, 0)),
          static_cast<float>(ptc->GetComponent(i, 1)) });
        ASSERT_NE(it, index.end());
        owned += !marks || !(marks->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT);
        for (vtkDataArray* a : { out->GetPoints()->GetData(), out->GetPointData()->GetNormals(),
               out->GetPointData()->GetTangents(),
               out->GetPointData()->GetArray("TangentHandedness") })
        {
          vtkDataArray* b = whole->GetPointData()->GetArray(a->GetName());
          b = b ? b : whole->GetPoints()->GetData();
          for (int k = 0; k < a->GetNumberOfComponents(); ++k)
          {
            largest =
              std::max(largest, std::abs(a->GetComponent(i, k) - b->GetComponent(it->second, k)));
          }
        }
      }
    }
    EXPECT_EQ(cells, whole->GetNumberOfCells());
    if (ghosts)
    {
      EXPECT_EQ(owned, whole->GetNumberOfPoints());
      EXPECT_EQ(largest, 0.0);
    }
    else
    {
      EXPECT_GT(largest, 0.1); // border normals from half their triangles
    }
  }
}
