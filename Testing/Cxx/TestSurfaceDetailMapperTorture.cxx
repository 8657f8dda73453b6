// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Rendering torture: normal, bump, parallax and relief mapping (with self-shadowing and
// depth correction, from a relief map, from the height map alone and by cone stepping) seen at
// grazing angles (85 to 89.9 degrees from the normal) and with the camera very close to the
// surface. Each picture is compared with the plain mapper's picture of the same scene: no pixel
// may leave the plain silhouette (the detail moves shading and texture lookups, never
// geometry), and no pixel inside it may be black where the plain one is not (a NaN or a
// zero-length normal reaching the framebuffer shows as black; the material's ambient term keeps
// every lit or unlit pixel above black otherwise).

#include "SurfaceDetailTruthScenes.h"
#include "vtkSurfaceDetailMapper.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkHeightMapToConeMap.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
constexpr int Size = 200;
const double Background[3] = { 0.2, 0.3, 0.4 };

vtkSmartPointer<vtkImageData> Heights()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(128, 128, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* h = static_cast<float*>(image->GetScalarPointer());
  for (int j = 0; j < 128; ++j)
  {
    for (int i = 0; i < 128; ++i)
    {
      // Steep bumps: the worst case for parallax offsets at grazing angles.
      const double s = (i + 0.5) / 128, t = (j + 0.5) / 128;
      h[j * 128 + i] =
        static_cast<float>(0.5 + 0.5 * std::sin(8 * 2 * M_PI * s) * std::sin(8 * 2 * M_PI * t));
    }
  }
  return image;
}

// The RGB pixels of one rendering of the wall, with the camera at @a angle degrees from its
// normal and @a distance wall sizes from its centre; technique "plain" is vtkPolyDataMapper.
std::vector<unsigned char> Render(const std::string& technique, double angle, double distance)
{
  vtkNew<vtkParametricRectangle> wall; // x in [-2,2], y in [0,3.5], normal +z
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(wall);
  source->SetUResolution(8);
  source->SetVResolution(8);
  source->GenerateTangentsOn();
  source->SetTextureRepeat(4, 4);
  source->Update();

  vtkSmartPointer<vtkImageData> heights = Heights();
  vtkNew<vtkHeightMapToNormalMap> normals;
  normals->SetInputData(heights);
  normals->SetBumpScale(0.05);
  normals->Update();

  vtkSmartPointer<vtkPolyDataMapper> mapper;
  if (technique == "plain")
  {
    mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  }
  else
  {
    auto detail = vtkSmartPointer<vtkSurfaceDetailMapper>::New();
    detail->SetNormalMap(SurfaceDetailTruthScenes::RepeatedTexture(normals->GetOutput()));
    detail->SetHeightMap(SurfaceDetailTruthScenes::RepeatedTexture(heights));
    detail->SetBumpScale(0.05);
    detail->SetDepthScale(0.1);
    if (technique == "normal")
    {
      detail->SetTechniqueToNormalMapping();
    }
    else if (technique == "bump")
    {
      detail->SetTechniqueToBumpMapping();
    }
    else if (technique == "parallax")
    {
      detail->SetTechniqueToParallaxMapping();
    }
    else
    {
      detail->SetTechniqueToReliefMapping();
      detail->SetSelfShadowing(true);
      detail->SetDepthCorrection(true);
      if (technique == "relief-cones")
      {
        // Cone stepping with the heights' cone map (and the relief's own normal).
        vtkNew<vtkHeightMapToConeMap> cones;
        cones->SetInputData(heights);
        cones->Update();
        detail->SetConeMap(SurfaceDetailTruthScenes::RepeatedTexture(cones->GetOutput()));
      }
      if (technique == "relief-map")
      {
        vtkNew<vtkHeightMapToNormalMap> relief;
        relief->SetInputData(heights);
        relief->SetBumpScale(0.05);
        relief->OutputReliefOn();
        relief->Update();
        detail->SetReliefMap(SurfaceDetailTruthScenes::RepeatedTexture(relief->GetOutput()));
      }
      else
      {
        detail->SetNormalMap(nullptr); // the relief's own normal, from the heights
      }
    }
    mapper = detail;
  }
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.8, 0.6, 0.5);
  actor->GetProperty()->SetAmbient(0.3);
  actor->GetProperty()->SetDiffuse(0.7);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(Background[0], Background[1], Background[2]);
  vtkCamera* camera = renderer->GetActiveCamera();
  const double radians = angle * M_PI / 180.0;
  const double centre[3] = { 0.0, 1.75, 0.0 };
  camera->SetFocalPoint(centre);
  camera->SetPosition(
    centre[0], centre[1] - 4.0 * distance * std::sin(radians), 4.0 * distance * std::cos(radians));
  camera->SetViewUp(0, 1, 0);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(60);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(Size, Size);
  window->AddRenderer(renderer);
  window->Render();
  return SurfaceDetailTruthScenes::GrabRGB(window);
}

bool IsBackground(const unsigned char* p)
{
  return SurfaceDetailTruthScenes::IsBackground(p, Background);
}

bool IsBlack(const unsigned char* p)
{
  return p[0] < 3 && p[1] < 3 && p[2] < 3;
}

void ExpectSoundAgainstPlain(double angle, double distance)
{
  const std::vector<unsigned char> plain = Render("plain", angle, distance);
  int inside = 0;
  for (int p = 0; p < Size * Size; ++p)
  {
    inside += !IsBackground(&plain[3 * p]);
  }
  ASSERT_GT(inside, 0) << "the plain wall is not on screen at " << angle << " degrees, distance "
                       << distance;
  for (const char* technique :
    { "normal", "bump", "parallax", "relief", "relief-map", "relief-cones" })
  {
    const std::vector<unsigned char> detail = Render(technique, angle, distance);
    int outside = 0, speckles = 0;
    for (int p = 0; p < Size * Size; ++p)
    {
      const bool plainBackground = IsBackground(&plain[3 * p]);
      outside += plainBackground && !IsBackground(&detail[3 * p]);
      speckles += !plainBackground && !IsBlack(&plain[3 * p]) && IsBlack(&detail[3 * p]);
    }
    EXPECT_EQ(outside, 0) << technique << " at " << angle << " degrees, distance " << distance
                          << ": pixels outside the plain silhouette";
    EXPECT_EQ(speckles, 0) << technique << " at " << angle << " degrees, distance " << distance
                           << ": black pixels inside the silhouette (of " << inside << ")";
  }
}
} // namespace

TEST(SurfaceDetailMapperTorture, GrazingAngles)
{
  // At 89.9 degrees from 4 units away the wall is thinner than a pixel: that angle is reached
  // from close by (CameraCloseToTheSurface), where the far part of the wall is seen at up to
  // 89.9 degrees.
  for (double angle : { 85.0, 88.0, 89.0, 89.5 })
  {
    ExpectSoundAgainstPlain(angle, 1.0);
  }
}

// The camera 0.04 units from the wall's centre: at 85 degrees it is 0.0035 above the wall,
// whose far part (2 units away) it sees at 89.9 degrees.
TEST(SurfaceDetailMapperTorture, CameraCloseToTheSurface)
{
  for (double angle : { 0.0, 60.0, 85.0 })
  {
    ExpectSoundAgainstPlain(angle, 0.01);
  }
}
