// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The minification: a checkerboard floor running to the horizon, four ways side by side.
// Nearest picks one texel per pixel and shimmers into moire far away; Linear blends four
// texels but minifies the same way; Mipmapped samples a smaller copy of the texture where
// a pixel covers many texels, which turns the distance grey, too soon along the view; and
// Anisotropic takes several mipmapped samples along the pixel's long footprint, so the
// checks stay sharp further out.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "Mipmapping",
        "A checkerboard floor to the horizon: nearest, linear, mipmapped and "
        "anisotropic\nminification side by side."))
  {
    return 0;
  }
  // The floor: 100 units wide, 400 deep, in y = 0; a 2-unit tile of 8 x 8 checks.
  vtkNew<vtkParametricRectangle> floor;
  floor->SetOrigin(-50, 0, 5);
  floor->SetPoint1(50, 0, 5);
  floor->SetPoint2(-50, 0, -395);
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(floor);
  source->SetUResolution(8);
  source->SetVResolution(32);
  source->SetTextureRepeat(50, 200);

  struct Panel
  {
    const char* Label;
    bool Interpolate;
    bool Mipmap;
    float Anisotropy; // VTK's default is 4: the first three turn it off
  };
  const Panel panels[4] = { { "Nearest", false, false, 1.0f }, { "Linear", true, false, 1.0f },
    { "Mipmapped (trilinear)", true, true, 1.0f }, { "Anisotropic (16x)", true, true, 16.0f } };

  auto window = ExampleScene::MakeWindow(1000, 640);
  for (int k = 0; k < 4; ++k)
  {
    vtkSmartPointer<vtkTexture> checks = ExampleScene::LoadTexture("checkerboard.png");
    if (!checks)
    {
      return 1;
    }
    checks->SetInterpolate(panels[k].Interpolate);
    checks->SetMipmap(panels[k].Mipmap);
    checks->SetMaximumAnisotropicFiltering(panels[k].Anisotropy);

    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(checks);
    actor->GetProperty()->LightingOff(); // the texture as it is: only filtering differs

    vtkNew<vtkRenderer> renderer;
    const double x = (k % 2) * 0.5, y = (k < 2) ? 0.5 : 0.0;
    renderer->SetViewport(x, y, x + 0.5, y + 0.5);
    renderer->SetBackground(0.55, 0.7, 0.9);
    renderer->AddActor(actor);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0, 1.2, 4);
    camera->SetFocalPoint(0, -0.5, -6);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(50);
    camera->SetClippingRange(0.1, 500);
    ExampleScene::AddLabel(renderer, panels[k].Label);
    window->AddRenderer(renderer);
  }
  return ExampleScene::WritePicture(window, ExampleScene::OutputFolder(argc, argv), "Mipmapping");
}
