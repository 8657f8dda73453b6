// Seed 000's displacement mapping: the torus p(u,v) = ((R + r cos 2pi v) cos 2pi u,
// (R + r cos 2pi v) sin 2pi u, r sin 2pi v) is moved along its normal by a quilted height
// map, p* = p + d(u,v) n, and shaded with the displaced surface's exact normals.
//
// Usage: DisplacedTorus <output folder>   (writes DisplacedTorus.png)

#include "vtkDisplacementMapFilter.h"
#include "vtkParametricDonut.h"
#include "vtkParametricSurfaceSource.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <cmath>
#include <string>

namespace
{
constexpr double Pi = 3.14159265358979323846;

// A quilt of round bumps, 24 around the ring and 10 around the tube, as an 8-bit map.
vtkSmartPointer<vtkImageData> Quilt(int W, int H)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* h = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const double s = (i + 0.5) / W, t = (j + 0.5) / H;
      const double b = std::sin(Pi * 24 * s) * std::sin(Pi * 10 * t);
      h[j * W + i] = static_cast<unsigned char>(std::lround(255.0 * b * b));
    }
  }
  return image;
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";

  // The torus with texture coordinates (u,v), outward unit normals and the raw derivatives
  // dPdu, dPdv, which the Exact normals use.
  vtkNew<vtkParametricDonut> donut;
  donut->SetRingRadius(1.0);
  donut->SetCrossSectionRadius(0.4);
  vtkNew<vtkParametricSurfaceSource> torus;
  torus->SetParametricFunction(donut);
  torus->SetUResolution(480);
  torus->SetVResolution(200);
  torus->GenerateDerivativesOn();

  vtkNew<vtkDisplacementMapFilter> displace;
  displace->SetInputConnection(0, torus->GetOutputPort());
  displace->SetInputData(1, Quilt(1024, 512));
  displace->SetScale(0.08);
  displace->SetMidlevel(0.0);
  displace->SetWrapToRepeat();
  displace->SetInterpolationToCubic();
  displace->SetNormalModeToExact();

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(displace->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.62, 0.32);
  actor->GetProperty()->SetSpecular(0.4);
  actor->GetProperty()->SetSpecularPower(40);
  actor->GetProperty()->SetInterpolationToPhong();

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.12, 0.13, 0.16);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> key; // from the upper right, in camera space
  key->SetLightTypeToCameraLight();
  key->SetPosition(1.0, 0.6, 0.8);
  key->SetFocalPoint(0, 0, 0);
  key->SetIntensity(0.9);
  renderer->AddLight(key);
  vtkNew<vtkLight> fill;
  fill->SetLightTypeToCameraLight();
  fill->SetPosition(-0.6, -0.2, 1.0);
  fill->SetFocalPoint(0, 0, 0);
  fill->SetIntensity(0.25);
  renderer->AddLight(fill);

  vtkNew<vtkTextActor> caption;
  caption->SetInput("vtkDisplacementMapFilter: p* = p + d(u,v) n, Exact normals");
  caption->GetTextProperty()->SetFontSize(18);
  caption->GetTextProperty()->SetColor(0.9, 0.9, 0.9);
  caption->SetDisplayPosition(12, 12);
  renderer->AddViewProp(caption);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -3.9, 2.8);
  camera->SetFocalPoint(0, 0, -0.1);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(900, 640);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName((folder + "/DisplacedTorus.png").c_str());
  writer->Write();
  return 0;
}
