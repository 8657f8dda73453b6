// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Surface detail on the brick wall: the same flat wall (no displaced
// geometry) drawn four ways side by side, lit by a point light from the upper right: plain
// texture, normal mapping, bump mapping and parallax mapping. The textures are the
// project's Data/brick_color.png and Data/brick_height.png (16-bit); the normal map is made
// from the heights by vtkHeightMapToNormalMap.
// Usage: SurfaceDetailBricks <output folder>   (writes SurfaceDetailBricks.png there)

#include "ExampleScene.h"

#include <vtkSurfaceDetailMapper.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkOIIOImageReader.h>
#include <vtkPNGWriter.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkWindowToImageFilter.h>

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "SurfaceDetailBricks",
        "The flat brick wall four ways: plain texture, normal, bump and parallax mapping."))
  {
    return 0;
  }
  const std::string folder = ExampleScene::OutputFolder(argc, argv);

  // The wall, x in [-2,2], y in [0,3.5], tangents with handedness for the maps.
  vtkNew<vtkParametricRectangle> wall;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(wall);
  source->SetUResolution(8);
  source->SetVResolution(8);
  source->GenerateTangentsOn();
  source->SetTextureRepeat(1, 1); // 4 bricks across, 8 courses up

  vtkNew<vtkOIIOImageReader> colours;
  colours->SetFileName(SURFACEDETAIL_DATA_DIR "/brick_color.png");
  vtkNew<vtkOIIOImageReader> heights;
  heights->SetFileName(SURFACEDETAIL_DATA_DIR "/brick_height.png");
  constexpr double strength = 0.006; // bumps of z = 0.006*h over the texture square
  vtkNew<vtkHeightMapToNormalMap> normals;
  normals->SetInputConnection(heights->GetOutputPort());
  normals->SetBumpScale(strength);

  vtkNew<vtkTexture> colourTexture;
  colourTexture->SetInputConnection(colours->GetOutputPort());
  vtkNew<vtkTexture> normalTexture;
  normalTexture->SetInputConnection(normals->GetOutputPort());
  vtkNew<vtkTexture> heightTexture;
  heightTexture->SetInputConnection(heights->GetOutputPort());
  for (vtkTexture* texture : { colourTexture.Get(), normalTexture.Get(), heightTexture.Get() })
  {
    texture->InterpolateOn();
    texture->RepeatOn();
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(1600, 460);
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  const int techniques[4] = { vtkSurfaceDetailMapper::Plain, vtkSurfaceDetailMapper::NormalMapping,
    vtkSurfaceDetailMapper::BumpMapping, vtkSurfaceDetailMapper::ParallaxMapping };
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkSurfaceDetailMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    mapper->SetTechnique(techniques[k]);
    mapper->SetNormalMap(normalTexture);
    mapper->SetHeightMap(heightTexture);
    mapper->SetBumpScale(strength);
    mapper->SetDepthScale(0.1); // the joints lie 0.1 units behind the faces
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(colourTexture);
    actor->GetProperty()->SetAmbient(0.12);
    actor->GetProperty()->SetDiffuse(0.9);
    actor->GetProperty()->SetSpecular(0.2);
    actor->GetProperty()->SetSpecularPower(25);

    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(k / 4.0, 0, (k + 1) / 4.0, 1);
    renderer->SetBackground(0.16, 0.18, 0.22);
    renderer->AddActor(actor);
    renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> light; // upper right, in front of the wall
    light->SetLightTypeToSceneLight();
    light->PositionalOn();
    light->SetConeAngle(180);
    light->SetPosition(3.5, 5.0, 4.0);
    light->SetFocalPoint(0, 1.75, 0);
    renderer->AddLight(light);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.3, 1.6, 0);
    camera->SetPosition(3.4, 2.6, 4.4);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(40);
    renderer->ResetCameraClippingRange();

    vtkNew<vtkTextActor> label;
    label->SetInput(mapper->GetTechniqueAsString());
    label->GetTextProperty()->SetFontSize(22);
    label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    label->GetPositionCoordinate()->SetValue(0.04, 0.04);
    renderer->AddViewProp(label);
    window->AddRenderer(renderer);
  }
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName((folder + "/SurfaceDetailBricks.png").c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  std::cout << "wrote " << folder << "/SurfaceDetailBricks.png\n";
  return 0;
}
