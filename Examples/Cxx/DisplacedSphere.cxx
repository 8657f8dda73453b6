// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Displacement mapping, p* = p + d(u,v) n, on a sphere: the points really
// move (the silhouette is bumpy), and vtkDisplacementMapFilter's four NormalModes shade the
// moved surface side by side, lit from the upper right:
// - Input keeps the sphere's normals: the bumps show only in the outline, not in the shading;
// - Approximate is the textbook formula (no d dn/du terms): close to Exact on gentle bumps;
// - Exact adds the change of the normal (from the source's dNdu, dNdv);
// - Mesh averages the displaced triangles' normals: right, but faceted where triangles are big.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDisplacementMapFilter.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "DisplacedSphere",
        "Displacement mapping on a sphere: vtkDisplacementMapFilter moves the points, and\nits "
        "four NormalModes shade the moved surface side by side."))
  {
    return 0;
  }
  vtkNew<vtkParametricSphere> sphere;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->SetUResolution(192);
  source->SetVResolution(96);
  source->GenerateDerivativesOn(); // dPdu, dPdv, dNdu, dNdv for the Exact normals

  auto window = ExampleScene::MakeWindow(1600, 460);
  const int modes[4] = { vtkDisplacementMapFilter::Input, vtkDisplacementMapFilter::Approximate,
    vtkDisplacementMapFilter::Exact, vtkDisplacementMapFilter::Mesh };
  const char* names[4] = { "Input", "Approximate", "Exact", "Mesh" };
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkDisplacementMapFilter> displace;
    displace->SetInputConnection(0, source->GetOutputPort());
    displace->SetInputData(1, ExampleScene::QuiltHeights(512, 256, 16, 8));
    displace->SetScaleFactor(0.12);
    displace->SetMidlevel(0.0);
    displace->SetWrapToRepeat();
    displace->SetInterpolationToCubic();
    displace->SetNormalMode(modes[k]);

    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(displace->GetOutputPort());
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.55, 0.7, 0.85);
    actor->GetProperty()->SetAmbient(0.12);
    actor->GetProperty()->SetDiffuse(0.85);
    actor->GetProperty()->SetSpecular(0.3);
    actor->GetProperty()->SetSpecularPower(30);
    actor->GetProperty()->SetInterpolationToPhong();

    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.25 * k, 0, 0.25 * (k + 1), 1);
    renderer->SetBackground(0.12, 0.13, 0.16);
    renderer->AddActor(actor);
    ExampleScene::AddKeyLight(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0, 1.5, 4.6);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(36);
    renderer->ResetCameraClippingRange();
    ExampleScene::AddLabel(renderer, names[k]);
    window->AddRenderer(renderer);
  }
  return ExampleScene::WritePicture(
    window, ExampleScene::OutputFolder(argc, argv), "DisplacedSphere");
}
