// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The point of baking, as a picture: on the left the detailed torus (590,000 triangles, displaced
// by vtkDisplacementMapFilter with Exact normals) through the plain vtkOpenGLPolyDataMapper; on the
// right the 48 x 24 coarse torus with the map vtkNormalMapBaker baked from it, through
// vtkSurfaceDetailMapper's NormalMapping. Same camera, same light (from the right, a little
// above and in front).
//
// Over the pixels that show the object in both halves the two must agree closely, and much
// more closely than the coarse torus without its map (the same right half with Technique
// None): both figures are printed and asserted. The side-by-side picture is then compared
// strictly with its baseline.

#include "NormalMapBakerTestFrames.h"
#include "SurfaceDetailImageComparison.h"

#include "vtkNormalMapBaker.h"
#include "vtkSurfaceDetailMapper.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <iostream>

namespace
{
using namespace DisplacementTest;
constexpr int Half = 320;
const double Background[3] = { 0.18, 0.2, 0.24 };

vtkSmartPointer<vtkRenderer> Side(vtkPolyDataMapper* mapper, double x0)
{
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.7, 0.55);
  actor->GetProperty()->SetAmbient(0.1);
  actor->GetProperty()->SetDiffuse(0.9);
  actor->GetProperty()->SetSpecular(0.2);
  actor->GetProperty()->SetSpecularPower(20);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(x0, 0.0, x0 + 0.5, 1.0);
  renderer->AddActor(actor);
  renderer->SetBackground(Background[0], Background[1], Background[2]);
  // The torus is z up: seen from the front (-y), 35 degrees above its plane.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, -5.0 * std::cos(0.61), 5.0 * std::sin(0.61));
  camera->SetViewUp(0, 0, 1);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(35);
  renderer->ResetCameraClippingRange();
  // A directional light from the right of the camera, a little above and in front: low enough
  // that the bumps cast light and shade.
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetFocalPoint(0, 0, 0);
  light->SetPosition(4.0, -1.0, 1.0);
  renderer->AddLight(light);
  return renderer;
}

vtkSmartPointer<vtkImageData> Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

struct PictureError
{
  long long Pixels = 0;       // showing the object in both halves
  double MeanLevels = 0.0;    // mean over those pixels of the mean |left - right| over RGB
  double FractionOver16 = 0.; // pixels whose largest channel difference exceeds 16 levels
};

// Left half against right half, over the pixels that are not background in either.
PictureError CompareHalves(vtkImageData* image)
{
  PictureError e;
  int dims[3];
  image->GetDimensions(dims);
  const auto* rgb = static_cast<const unsigned char*>(image->GetScalarPointer());
  const unsigned char* background = rgb; // the corner pixel
  auto isBackground = [&](const unsigned char* p)
  { return p[0] == background[0] && p[1] == background[1] && p[2] == background[2]; };
  long long over = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < Half; ++x)
    {
      const unsigned char* l = rgb + 3 * (static_cast<size_t>(y) * dims[0] + x);
      const unsigned char* r = l + 3 * Half;
      if (isBackground(l) || isBackground(r))
      {
        continue;
      }
      int sum = 0, worst = 0;
      for (int c = 0; c < 3; ++c)
      {
        const int d = std::abs(int(l[c]) - int(r[c]));
        sum += d;
        worst = std::max(worst, d);
      }
      e.MeanLevels += sum / 3.0;
      over += worst > 16;
      ++e.Pixels;
    }
  }
  e.MeanLevels /= std::max(1LL, e.Pixels);
  e.FractionOver16 = double(over) / std::max(1LL, e.Pixels);
  return e;
}
} // namespace

int main(int argc, char* argv[])
{
  // Bumps four quads of the coarse torus across (12 x 6 of them around it): far too small for
  // its geometry, what a normal map is for.
  Surface s = Torus(0.05);
  s.Height = [](double u, double v)
  { return 0.5 + 0.5 * std::sin(2 * Pi * 12 * u) * std::sin(2 * Pi * 6 * v); };
  vtkSmartPointer<vtkPolyData> coarse = MakeMesh(s, 48, 24, false);
  vtkSmartPointer<vtkPolyData> detailed = Detailed(s, 768, 384);

  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, coarse);
  baker->SetInputData(1, detailed);
  baker->SetTextureSize(1024, 1024);
  baker->SetMaxRayDistance(0.2);
  baker->Update();
  if (baker->GetNumberOfUnhitTexels() != 0)
  {
    std::cerr << "every texel's ray must reach the detailed torus\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkTexture> normalMap;
  normalMap->SetInputConnection(baker->GetOutputPort());
  normalMap->InterpolateOn();
  normalMap->RepeatOn();

  vtkNew<vtkOpenGLPolyDataMapper> plain;
  plain->SetInputData(detailed);
  vtkNew<vtkSurfaceDetailMapper> mapped;
  mapped->SetInputData(coarse);
  mapped->SetNormalMap(normalMap);
  mapped->SetTechniqueToNormalMapping();

  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(2 * Half, Half);
  window->AddRenderer(Side(plain, 0.0));
  window->AddRenderer(Side(mapped, 0.5));

  // The coarse torus without its map first: what the map has to make up for.
  mapped->SetTechniqueToPlain();
  window->Render();
  const PictureError without = CompareHalves(Grab(window));
  mapped->SetTechniqueToNormalMapping();
  window->Render();
  const PictureError with = CompareHalves(Grab(window));
  std::cout << "Detailed (left) against coarse + baked map (right), over " << with.Pixels
            << " object pixels: mean difference " << with.MeanLevels << " levels, "
            << 100.0 * with.FractionOver16
            << "% of pixels over 16 levels. The coarse torus without the map: "
            << without.MeanLevels << " levels, " << 100.0 * without.FractionOver16
            << "% over 16.\n";
  bool ok = true;
  // What remains is at the silhouettes and where the torus is seen at grazing angles: there
  // the detailed bumps stand off the coarse surface and are seen shifted (a normal map does not
  // move geometry). A wrong frame (the tangents' handedness flipped) is many times over these
  // limits, as is the coarse torus without its map.
  if (!(with.Pixels > 20000 && with.MeanLevels < 3.0 && with.FractionOver16 < 0.04))
  {
    std::cout << "The baked map does not reproduce the detailed torus closely enough.\n";
    ok = false;
  }
  if (!(with.MeanLevels < 0.25 * without.MeanLevels))
  {
    std::cout << "The baked map does not bring the coarse torus much closer to the detailed one.\n";
    ok = false;
  }

  const int result = SurfaceDetailImageComparison::RegressionTest(argc, argv, window);
  if (result == SurfaceDetailImageComparison::Interact)
  {
    vtkNew<vtkRenderWindowInteractor> interactor;
    interactor->SetRenderWindow(window);
    interactor->Start();
  }
  return ok && result != SurfaceDetailImageComparison::Failed ? EXIT_SUCCESS : EXIT_FAILURE;
}
