// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The donut, z up: P = ((R + r cos 2 pi v) cos 2 pi u, (R + r cos 2 pi v) sin 2 pi u,
// r sin 2 pi v) with Data/checkerboard.png, dark square at (0,0). Seen from outside, s runs
// along the ring and t round the tube; the checks stay square and meet across both seams
// (VTK's vtkParametricTorus is the same surface mirrored).
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkParametricDonut.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "Donut",
        "The donut with a checkerboard: the checks stay square and meet across both seams."))
  {
    return 0;
  }
  vtkNew<vtkParametricDonut> donut;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(donut);
  source->SetUResolution(128);
  source->SetVResolution(48);
  source->SetTextureRepeat(5, 2); // square checks: the ring is 2.5 times the tube

  vtkSmartPointer<vtkTexture> checks = ExampleScene::LoadTexture("checkerboard.png");
  if (!checks)
  {
    return 1;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(checks);
  actor->GetProperty()->SetAmbient(0.3);
  actor->GetProperty()->SetDiffuse(0.8);
  actor->RotateX(-90); // the donut's z up becomes the scene's y up

  const double eye[3] = { 1.0, 2.2, 4.0 };
  const double focus[3] = { 0, 0, 0 };
  return ExampleScene::WritePicture(
    ExampleScene::ViewActor(actor, eye, focus), ExampleScene::OutputFolder(argc, argv), "Donut");
}
