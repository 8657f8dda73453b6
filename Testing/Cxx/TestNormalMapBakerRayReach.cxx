// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// How far vtkNormalMapBaker's rays reach. A flat coarse square at z = 0 (normal +z) is baked
// against a flat detailed square at z = offset, just inside or just outside the reach:
// - without a cage, rays go both ways from the coarse surface up to MaxRayDistance: a detailed
//   surface at |offset| < MaxRayDistance is hit, with height = offset, one beyond it is not;
// - with CageOffset d, rays start on the cage d above and go inwards to MaxRayDistance below
//   the coarse surface: hit for -MaxRayDistance < offset < d, missed outside, with the height
//   still the offset from the coarse surface (not from the cage).
// Missed texels are counted, and said in one warning.

#include "DisplacementTestSurfaces.h"

#include "vtkNormalMapBaker.h"

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

namespace
{
using namespace DisplacementTest;

class Observer : public vtkCommand
{
public:
  static Observer* New() { return new Observer; }
  void Execute(vtkObject*, unsigned long event, void*) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)++;
  }
  int Errors = 0;
  int Warnings = 0;
};

// The unit square [-1, 1]^2 (MakeMesh's rectangle) at height z, with its frame: x, y, z.
vtkSmartPointer<vtkPolyData> FlatSquare(int n, double z, double half = 1.0)
{
  vtkSmartPointer<vtkPolyData> mesh = MakeMesh(Rectangle(), n, n, false);
  vtkPoints* points = mesh->GetPoints();
  for (vtkIdType k = 0; k < points->GetNumberOfPoints(); ++k)
  {
    double p[3];
    points->GetPoint(k, p);
    points->SetPoint(k, half * p[0], half * p[1], z);
  }
  return mesh;
}

struct Bake
{
  vtkIdType Covered = 0, Unhit = 0;
  int Warnings = 0;
  double MinHeight = 0.0, MaxHeight = 0.0; // over the texels that were hit
};

constexpr int Size = 12;

Bake BakeAgainst(double offset, double reach, double cage)
{
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, FlatSquare(4, 0.0));
  // Wider than the coarse square, so that every ray could meet it.
  baker->SetInputData(1, FlatSquare(6, offset, 1.5));
  baker->SetTextureSize(Size, Size);
  baker->SetMaxRayDistance(reach);
  baker->SetCageOffset(cage);
  baker->SetOutputScalarTypeToFloat();
  baker->BakeHeightOn();
  vtkNew<Observer> observer;
  baker->AddObserver(vtkCommand::ErrorEvent, observer);
  baker->AddObserver(vtkCommand::WarningEvent, observer);
  baker->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  baker->Update();
  EXPECT_EQ(observer->Errors, 0);
  Bake result;
  result.Covered = baker->GetNumberOfCoveredTexels();
  result.Unhit = baker->GetNumberOfUnhitTexels();
  result.Warnings = observer->Warnings;
  vtkDataArray* heights = baker->GetHeightOutput()->GetPointData()->GetScalars();
  result.MinHeight = heights->GetRange(0)[0];
  result.MaxHeight = heights->GetRange(0)[1];
  return result;
}

std::string Describe(double offset, double reach, double cage)
{
  std::ostringstream os;
  os << "detailed surface at " << offset << ", MaxRayDistance " << reach << ", CageOffset " << cage;
  return os.str();
}

void ExpectHit(double offset, double reach, double cage)
{
  SCOPED_TRACE(Describe(offset, reach, cage));
  const Bake b = BakeAgainst(offset, reach, cage);
  EXPECT_EQ(b.Covered, Size * Size);
  EXPECT_EQ(b.Unhit, 0);
  EXPECT_EQ(b.Warnings, 0);
  // Every texel: the signed distance from the coarse surface along its normal.
  EXPECT_NEAR(b.MinHeight, offset, 1e-6);
  EXPECT_NEAR(b.MaxHeight, offset, 1e-6);
}

void ExpectMissed(double offset, double reach, double cage)
{
  SCOPED_TRACE(Describe(offset, reach, cage));
  const Bake b = BakeAgainst(offset, reach, cage);
  EXPECT_EQ(b.Covered, Size * Size);
  EXPECT_EQ(b.Unhit, Size * Size);
  EXPECT_EQ(b.Warnings, 1);
}
} // namespace

TEST(NormalMapBakerRayReach, BothWaysUpToMaxRayDistanceWithoutACage)
{
  for (double reach : { 0.1, 0.35 })
  {
    ExpectHit(0.98 * reach, reach, 0.0);
    ExpectHit(-0.98 * reach, reach, 0.0);
    ExpectMissed(1.02 * reach, reach, 0.0);
    ExpectMissed(-1.02 * reach, reach, 0.0);
  }
}

// A cage nearer than MaxRayDistance and one further: above the coarse surface the rays reach
// to the cage, below it to MaxRayDistance, whichever is larger.
TEST(NormalMapBakerRayReach, FromTheCageInwardsToMaxRayDistanceBelow)
{
  const double reach = 0.1;
  for (double cage : { 0.05, 0.3 })
  {
    ExpectHit(0.98 * cage, reach, cage);
    ExpectMissed(1.02 * cage, reach, cage);
    ExpectHit(-0.98 * reach, reach, cage);
    ExpectMissed(-1.02 * reach, reach, cage);
    ExpectHit(0.0, reach, cage);
  }
}
