// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Bump mapping (Blinn 1978) on a torus: the surface stays smooth, only
// its normals are tilted by the slopes of a height map, at every pixel. Left: the plain
// torus; right: vtkSurfaceDetailMapper's BumpMapping with a quilt of round bumps, lit from
// the upper right, so each bump is bright on its upper right side. The silhouette stays
// round: bump mapping moves no geometry (DisplacedSphere does).
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkParametricDonut.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkProperty.h>
#include <vtkSurfaceDetailMapper.h>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "BumpyTorus",
        "Bump mapping on a torus: plain (left) and with vtkSurfaceDetailMapper's bump\nmapping of "
        "a quilt of round bumps (right), lit from the upper right."))
  {
    return 0;
  }
  vtkNew<vtkParametricDonut> donut;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(donut);
  source->SetUResolution(128);
  source->SetVResolution(48);
  source->GenerateTangentsOn(); // the frame the height map's slopes are taken in

  vtkNew<vtkTexture> heights;
  heights->SetInputData(ExampleScene::QuiltHeights(1024, 512, 24, 10));
  heights->InterpolateOn();
  heights->SetWrap(vtkTexture::Repeat);

  auto window = ExampleScene::MakeWindow(1200, 520);
  const int techniques[2] = { vtkSurfaceDetailMapper::Plain, vtkSurfaceDetailMapper::BumpMapping };
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkSurfaceDetailMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    mapper->SetHeightMap(heights);
    mapper->SetTechnique(techniques[k]);
    mapper->SetBumpScale(0.004); // the bumps of z = 0.004 h over the unit texture square
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.85, 0.62, 0.32);
    actor->GetProperty()->SetAmbient(0.15);
    actor->GetProperty()->SetDiffuse(0.85);
    actor->GetProperty()->SetSpecular(0.3);
    actor->GetProperty()->SetSpecularPower(30);
    actor->RotateX(-90); // the donut's z up becomes the scene's y up

    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.5 * k, 0, 0.5 * (k + 1), 1);
    renderer->SetBackground(0.12, 0.13, 0.16);
    renderer->AddActor(actor);
    ExampleScene::AddKeyLight(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.8, 2.4, 3.6);
    camera->SetFocalPoint(0, -0.1, 0);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(35);
    renderer->ResetCameraClippingRange();
    ExampleScene::AddLabel(renderer, mapper->GetTechniqueAsString());
    window->AddRenderer(renderer);
  }
  return ExampleScene::WritePicture(window, ExampleScene::OutputFolder(argc, argv), "BumpyTorus");
}
