// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The point of normal maps: a detailed model and a coarse one with a normal map
// baked from it look alike, at a fraction of the polygons. The detailed model is a vase
// (vtkParametricRevolution) with a quilt of bumps displaced into its geometry by
// vtkDisplacementMapFilter; the coarse model is the same vase at a hundredth of the
// triangles, and vtkNormalMapBaker casts a ray along its normal at every texel to store the
// detailed surface's normal in its tangent frame. Left: the detailed vase, VTK's plain
// mapper; right: the coarse vase with the baked map, vtkSurfaceDetailMapper's NormalMapping.
// Only the silhouettes tell them apart.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDisplacementMapFilter.h>
#include <vtkNormalMapBaker.h>
#include <vtkParametricRevolution.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSurfaceDetailMapper.h>

#include <string>

namespace
{
vtkSmartPointer<vtkPolyData> Vase(int uResolution, int vResolution)
{
  vtkNew<vtkParametricRevolution> vase;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(vase);
  source->SetUResolution(uResolution);
  source->SetVResolution(vResolution);
  source->GenerateTangentsOn();    // the frame the baked normals are stored in
  source->GenerateDerivativesOn(); // exact normals for the displaced surface
  source->Update();
  return source->GetOutput();
}

vtkSmartPointer<vtkActor> Actor(vtkPolyDataMapper* mapper)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.78, 0.74, 0.66);
  actor->GetProperty()->SetAmbient(0.12);
  actor->GetProperty()->SetDiffuse(0.88);
  actor->GetProperty()->SetSpecular(0.25);
  actor->GetProperty()->SetSpecularPower(30);
  return actor;
}
} // namespace

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "NormalMappedModel",
        "A detailed displaced vase beside a coarse one with a normal map baked from it "
        "by\nvtkNormalMapBaker: they look alike at a fraction of the polygons."))
  {
    return 0;
  }
  vtkNew<vtkDisplacementMapFilter> displace;
  displace->SetInputData(Vase(384, 256));
  displace->SetInputData(1, ExampleScene::QuiltHeights(768, 512, 24, 16));
  displace->SetScaleFactor(0.03);
  displace->SetMidlevel(0.0);
  displace->SetInterpolationToLinear();
  displace->SetNormalModeToExact();
  displace->Update();
  vtkPolyData* detailed = displace->GetOutput();
  vtkSmartPointer<vtkPolyData> coarse = Vase(48, 24);

  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, coarse);
  baker->SetInputData(1, detailed);
  baker->SetTextureSize(1024, 1024);
  baker->SetMaxRayDistance(0.15);
  vtkNew<vtkTexture> normalMap;
  normalMap->SetInputConnection(baker->GetOutputPort());
  normalMap->InterpolateOn();

  vtkNew<vtkPolyDataMapper> plain;
  plain->SetInputData(detailed);
  vtkNew<vtkSurfaceDetailMapper> mapped;
  mapped->SetInputData(coarse);
  mapped->SetNormalMap(normalMap);
  mapped->SetTechniqueToNormalMapping();

  auto window = ExampleScene::MakeWindow(1000, 560);
  vtkPolyDataMapper* mappers[2] = { plain, mapped };
  vtkPolyData* meshes[2] = { detailed, coarse };
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.5 * k, 0, 0.5 * (k + 1), 1);
    renderer->SetBackground(0.12, 0.13, 0.16);
    renderer->AddActor(Actor(mappers[k]));
    ExampleScene::AddKeyLight(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0, 1.0, 0); // the vase stands on y = 0 and is 2 tall
    camera->SetPosition(0, 1.9, 4.6);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(32);
    renderer->ResetCameraClippingRange();
    const std::string triangles = std::to_string(meshes[k]->GetNumberOfCells()) + " triangles";
    ExampleScene::AddLabel(
      renderer, k == 0 ? "detailed, " + triangles : "coarse + baked normal map, " + triangles);
    window->AddRenderer(renderer);
  }
  return ExampleScene::WritePicture(
    window, ExampleScene::OutputFolder(argc, argv), "NormalMappedModel");
}
