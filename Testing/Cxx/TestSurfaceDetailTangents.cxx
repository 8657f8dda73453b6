// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The tangent frame as vtkSurfaceDetailTangents stores it (the TANGENTS attribute and a
// handedness array beside it) is one that VTK's own filters carry, copy flags govern and
// readers can check: split exactly, kept through interpolating filters, and a clear problem
// text when a VTK filter replaces the tangents or drops the handedness.

#include "vtkNormalMapBaker.h"
#include "vtkParametricSphere.h"
#include "vtkParametricSurfaceSource.h"
#include "vtkSurfaceDetailTangents.h"

#include <vtkCleanPolyData.h>
#include <vtkClipPolyData.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPassArrays.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataTangents.h>
#include <vtkTransform.h>
#include <vtkTransformFilter.h>
#include <vtkTriangleFilter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{
// A textured sphere with its frame; TextureRepeat -1 in s mirrors the texture (w = -1).
vtkSmartPointer<vtkPolyData> Sphere(bool mirrored)
{
  vtkNew<vtkParametricSphere> sphere;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->SetUResolution(24);
  source->SetVResolution(12);
  source->GenerateNormalsOn();
  source->GenerateTextureCoordinatesOn();
  source->GenerateTangentsOn();
  source->SetTextureRepeat(mirrored ? -1.0 : 1.0, 1.0);
  source->SetTextureOffset(mirrored ? 1.0 : 0.0, 0.0);
  source->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(source->GetOutput());
  return out;
}

bool Marked(vtkDataArray* tangents)
{
  return tangents->GetInformation()->Has(vtkSurfaceDetailTangents::WITH_HANDEDNESS()) &&
    tangents->GetInformation()->Get(vtkSurfaceDetailTangents::WITH_HANDEDNESS()) == 1;
}

struct WarningCounter : public vtkCommand
{
  static WarningCounter* New() { return new WarningCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Count;
    this->Last = data ? static_cast<const char*>(data) : "";
  }
  int Count = 0;
  std::string Last;
};
} // namespace

// A 4-component frame, float or double, becomes the two float arrays value for value; arrays
// of the same names that were there before are replaced, not kept beside.
TEST(vtkSurfaceDetailTangents, SplitsAFrameExactly)
{
  for (bool doubles : { false, true })
  {
    vtkSmartPointer<vtkDataArray> frame;
    if (doubles)
    {
      frame = vtkSmartPointer<vtkDoubleArray>::New();
    }
    else
    {
      frame = vtkSmartPointer<vtkFloatArray>::New();
    }
    frame->SetNumberOfComponents(4);
    frame->SetNumberOfTuples(1000);
    for (vtkIdType i = 0; i < 1000; ++i)
    {
      const double a = 0.01 * i;
      frame->SetTuple4(i, std::cos(a), std::sin(a), 0.0, i % 7 == 3 ? -1.0 : 1.0);
    }
    vtkNew<vtkPointData> pd;
    vtkNew<vtkFloatArray> stale;
    stale->SetName("TangentHandedness");
    pd->AddArray(stale);
    vtkSurfaceDetailTangents::SetFrameFromXYZW(pd, frame);
    EXPECT_EQ(pd->GetNumberOfArrays(), 2);
    vtkDataArray* t = pd->GetTangents();
    vtkDataArray* w = vtkSurfaceDetailTangents::GetHandedness(pd);
    ASSERT_TRUE(t && w);
    EXPECT_STREQ(t->GetName(), "Tangents");
    EXPECT_EQ(t->GetNumberOfComponents(), 3);
    EXPECT_EQ(t->GetDataType(), VTK_FLOAT);
    EXPECT_EQ(w->GetDataType(), VTK_FLOAT);
    EXPECT_TRUE(Marked(t));
    EXPECT_EQ(vtkSurfaceDetailTangents::GetHandednessProblem(pd), "");
    for (vtkIdType i = 0; i < 1000; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        ASSERT_EQ(t->GetComponent(i, c), static_cast<float>(frame->GetComponent(i, c))) << i;
      }
      ASSERT_EQ(w->GetComponent(i, 0), frame->GetComponent(i, 3)) << i;
    }
  }
}

// VTK's interpolating filters carry both arrays and the mark: the frame is the same frame
// after a clip, a clean and a triangulation (every output point keeps its input frame, for
// points that were input points: the sphere's clip plane passes between rows).
TEST(vtkSurfaceDetailTangents, VTKFiltersCarryTheFrame)
{
  auto sphere = Sphere(true);
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.0, 0.0, 0.01);
  plane->SetNormal(0.0, 0.0, 1.0);
  vtkNew<vtkClipPolyData> clip;
  clip->SetInputData(sphere);
  clip->SetClipFunction(plane);
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(clip->GetOutputPort());
  clean->PointMergingOff();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(clean->GetOutputPort());
  triangles->Update();
  vtkPolyData* out = triangles->GetOutput();
  ASSERT_GT(out->GetNumberOfPoints(), 0);
  vtkPointData* pd = out->GetPointData();
  ASSERT_NE(pd->GetTangents(), nullptr);
  EXPECT_STREQ(pd->GetTangents()->GetName(), "Tangents");
  EXPECT_TRUE(Marked(pd->GetTangents()));
  vtkDataArray* w = vtkSurfaceDetailTangents::GetHandedness(pd);
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(vtkSurfaceDetailTangents::GetHandednessProblem(pd), "");
  // The mirrored texture's w = -1 survives interpolation.
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    ASSERT_EQ(w->GetComponent(i, 0), -1.0) << i;
  }
}

// VTK 9.1's vtkTransformFilter leaves the TANGENTS attribute unturned; told to transform
// every 3-component array as a vector it turns them but leaves them a plain array. Made the
// frame again with SetFrame (as its header says), they are the turned frame, with the
// handedness of a rotation unchanged.
TEST(vtkSurfaceDetailTangents, TransformFilterTurnsTheTangents)
{
  auto sphere = Sphere(false);
  vtkNew<vtkTransform> turn;
  turn->RotateZ(90.0);
  vtkNew<vtkTransformFilter> transform;
  transform->SetInputData(sphere);
  transform->SetTransform(turn);
  transform->TransformAllInputVectorsOn();
  transform->Update();
  vtkPointData* in = sphere->GetPointData();
  vtkPointData* out = transform->GetPolyDataOutput()->GetPointData();
  EXPECT_EQ(out->GetTangents(), nullptr);
  ASSERT_NE(out->GetArray("Tangents"), nullptr);
  ASSERT_NE(vtkSurfaceDetailTangents::GetHandedness(out), nullptr);
  vtkSurfaceDetailTangents::SetFrame(
    out, out->GetArray("Tangents"), vtkSurfaceDetailTangents::GetHandedness(out));
  ASSERT_NE(out->GetTangents(), nullptr);
  EXPECT_EQ(vtkSurfaceDetailTangents::GetHandednessProblem(out), "");
  ASSERT_NE(vtkSurfaceDetailTangents::GetHandedness(out), nullptr);
  double worst = 0.0;
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    double t[3], turned[3];
    in->GetTangents()->GetTuple(i, t);
    out->GetTangents()->GetTuple(i, turned);
    // RotateZ(90): (x, y, z) -> (-y, x, z).
    worst = std::max(
      worst, std::abs(turned[0] + t[1]) + std::abs(turned[1] - t[0]) + std::abs(turned[2] - t[2]));
    ASSERT_EQ(vtkSurfaceDetailTangents::GetHandedness(out)->GetComponent(i, 0),
      vtkSurfaceDetailTangents::GetHandedness(in)->GetComponent(i, 0));
  }
  EXPECT_LT(worst, 1e-6);
}

// The attribute copy flags govern the tangents: CopyTangentsOff leaves them out.
TEST(vtkSurfaceDetailTangents, CopyFlagsSeeTheTangents)
{
  auto sphere = Sphere(false);
  vtkNew<vtkPointData> kept, dropped;
  kept->PassData(sphere->GetPointData());
  dropped->CopyTangentsOff();
  dropped->PassData(sphere->GetPointData());
  EXPECT_NE(kept->GetTangents(), nullptr);
  EXPECT_EQ(dropped->GetTangents(), nullptr);
  EXPECT_EQ(dropped->GetArray("Tangents"), nullptr);
  EXPECT_NE(dropped->GetNormals(), nullptr);
}

// vtkPolyDataTangents replaces the tangents with unmarked ones and leaves the handedness:
// the problem text says so and names the way out; the baker warns with it.
TEST(vtkSurfaceDetailTangents, ReplacedTangentsAreAProblem)
{
  auto sphere = Sphere(true);
  vtkNew<vtkPolyDataTangents> vtkTangents;
  vtkTangents->SetInputData(sphere);
  vtkTangents->Update();
  vtkPolyData* replaced = vtkTangents->GetOutput();
  ASSERT_NE(replaced->GetPointData()->GetTangents(), nullptr);
  EXPECT_FALSE(Marked(replaced->GetPointData()->GetTangents()));
  const std::string problem =
    vtkSurfaceDetailTangents::GetHandednessProblem(replaced->GetPointData());
  EXPECT_NE(problem.find("replaced"), std::string::npos) << problem;
  EXPECT_NE(problem.find("vtkMikkTSpaceTangents"), std::string::npos) << problem;

  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, replaced);
  baker->SetInputData(1, sphere);
  baker->SetTextureSize(16, 16);
  vtkNew<WarningCounter> warnings;
  baker->AddObserver(vtkCommand::WarningEvent, warnings);
  baker->Update();
  EXPECT_EQ(warnings->Count, 1);
  EXPECT_NE(warnings->Last.find(problem), std::string::npos) << warnings->Last;

  // The sphere's own frame gives the baker nothing to say.
  vtkNew<WarningCounter> none;
  baker->RemoveAllObservers();
  baker->AddObserver(vtkCommand::WarningEvent, none);
  baker->SetInputData(0, sphere);
  baker->Update();
  EXPECT_EQ(none->Count, 0) << none->Last;
}

// A filter that keeps only some arrays can drop the handedness of marked tangents, or leave
// one that no longer fits them; VTK's own tangents (no mark, no handedness) are no problem.
TEST(vtkSurfaceDetailTangents, DroppedHandednessIsAProblem)
{
  auto sphere = Sphere(true);
  vtkNew<vtkPassArrays> pass;
  pass->SetInputData(sphere);
  pass->AddPointDataArray("Normals");
  pass->AddPointDataArray("TCoords");
  pass->AddPointDataArray("Tangents");
  pass->Update();
  vtkPointData* pd = vtkPolyData::SafeDownCast(pass->GetOutput())->GetPointData();
  ASSERT_NE(pd->GetTangents(), nullptr);
  EXPECT_EQ(vtkSurfaceDetailTangents::GetHandedness(pd), nullptr);
  const std::string problem = vtkSurfaceDetailTangents::GetHandednessProblem(pd);
  EXPECT_NE(problem.find("gone"), std::string::npos) << problem;

  // A handedness array that no longer fits the tangents (here one value short) is not read:
  // readers index it by point id.
  vtkNew<vtkPolyData> shortened;
  shortened->DeepCopy(sphere);
  shortened->GetPointData()
    ->GetArray("TangentHandedness")
    ->SetNumberOfTuples(sphere->GetNumberOfPoints() - 1);
  EXPECT_EQ(vtkSurfaceDetailTangents::GetHandedness(shortened->GetPointData()), nullptr);
  EXPECT_NE(vtkSurfaceDetailTangents::GetHandednessProblem(shortened->GetPointData())
              .find("no longer matches"),
    std::string::npos);
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, shortened);
  baker->SetInputData(1, sphere);
  baker->SetTextureSize(16, 16);
  vtkNew<WarningCounter> warnings;
  baker->AddObserver(vtkCommand::WarningEvent, warnings);
  baker->Update();
  EXPECT_EQ(warnings->Count, 1) << warnings->Last;
  EXPECT_GT(baker->GetOutput()->GetNumberOfPoints(), 0);

  vtkNew<vtkPolyData> plain;
  plain->ShallowCopy(sphere);
  plain->GetPointData()->RemoveArray("TangentHandedness");
  vtkNew<vtkFloatArray> vtkOwn;
  vtkOwn->DeepCopy(sphere->GetPointData()->GetTangents());
  vtkOwn->GetInformation()->Clear();
  plain->GetPointData()->SetTangents(vtkOwn);
  EXPECT_EQ(vtkSurfaceDetailTangents::GetHandednessProblem(plain->GetPointData()), "");
}
