// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Relief mapping (Policarpo, Oliveira & Comba 2005) on the brick wall,
// beside normal mapping with the same normals. The wall is one flat rectangle of two
// triangles' worth of detail: normal mapping only tilts the shading, so the mortar joints
// stay visible however obliquely the wall is seen. Relief mapping marches each view ray
// through a box 0.1 units deep under the wall: the bricks hide the joints behind them, and
// with self-shadowing they cast shadows into the joints away from the light (upper right).
// The relief map (normal in RGB, depth in alpha) is made from Data/brick_height.png by
// vtkHeightMapToNormalMap with the strength that matches the depth on this wall.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkLight.h>
#include <vtkOIIOImageReader.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkProperty.h>
#include <vtkSurfaceDetailMapper.h>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "ReliefBricks",
        "Relief mapping on the brick wall beside normal mapping with the same normals."))
  {
    return 0;
  }
  vtkNew<vtkParametricRectangle> wall; // x in [-2,2], y in [0,3.5]
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(wall);
  source->SetUResolution(8);
  source->SetVResolution(8);
  source->GenerateTangentsOn(); // the frame the relief map's normals are stored in

  constexpr double depth = 0.1; // the joints lie 0.1 units behind the bricks' faces
  vtkNew<vtkOIIOImageReader> heights;
  heights->SetFileName(SURFACEDETAIL_DATA_DIR "/brick_height.png");
  vtkNew<vtkHeightMapToNormalMap> relief;
  relief->SetInputConnection(heights->GetOutputPort());
  relief->SetBumpScale(depth / 3.75); // the texture square is 4 x 3.5 units on the wall
  relief->OutputReliefOn();
  vtkNew<vtkTexture> reliefMap;
  reliefMap->SetInputConnection(relief->GetOutputPort());
  reliefMap->InterpolateOn();
  reliefMap->RepeatOn();
  vtkSmartPointer<vtkTexture> colours = ExampleScene::LoadTexture("brick_color.png");

  auto window = ExampleScene::MakeWindow(1200, 560);
  const int techniques[2] = { vtkSurfaceDetailMapper::NormalMapping,
    vtkSurfaceDetailMapper::ReliefMapping };
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkSurfaceDetailMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    mapper->SetTechnique(techniques[k]);
    mapper->SetNormalMap(reliefMap); // its RGB is the normal map
    mapper->SetReliefMap(reliefMap);
    mapper->SetDepthScale(depth);
    mapper->SelfShadowingOn();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(colours);
    actor->GetProperty()->SetAmbient(0.12);
    actor->GetProperty()->SetDiffuse(0.9);
    actor->GetProperty()->SetSpecular(0.2);
    actor->GetProperty()->SetSpecularPower(25);

    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.5 * k, 0, 0.5 * (k + 1), 1);
    renderer->SetBackground(0.16, 0.18, 0.22);
    renderer->AddActor(actor);
    renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> light; // upper right, in front of the wall
    light->SetLightTypeToSceneLight();
    light->PositionalOn();
    light->SetConeAngle(180);
    light->SetPosition(5.0, 5.5, 3.0);
    light->SetFocalPoint(0, 1.75, 0);
    renderer->AddLight(light);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.2, 1.6, 0);
    camera->SetPosition(-3.2, 2.4, 3.4);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(42);
    renderer->ResetCameraClippingRange();
    ExampleScene::AddLabel(renderer, k == 0 ? "NormalMapping" : "ReliefMapping, SelfShadowing");
    window->AddRenderer(renderer);
  }
  return ExampleScene::WritePicture(window, ExampleScene::OutputFolder(argc, argv), "ReliefBricks");
}
