// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The cylinder, a paper lantern: the picture is wrapped round the cylinder as paper is,
// u round (from +x towards -z) and v up. Data/test_card.png must read left to right and
// upright from outside, with no seam where u = 0 meets u = 1 (duplicated vertices, texture
// coordinates 0 and 1): the camera looks at that seam.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkParametricCylinder.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "Lantern",
        "The cylinder as a paper lantern wrapped in a test card, seen at its seam."))
  {
    return 0;
  }
  vtkNew<vtkParametricCylinder> cylinder; // radius 1, height 2
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(cylinder);
  source->SetUResolution(96);
  source->SetVResolution(4);
  source->SetTextureRepeat(2, 1); // the card twice round

  vtkSmartPointer<vtkTexture> paper = ExampleScene::LoadTexture("test_card.png");
  if (!paper)
  {
    return 1;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> lantern;
  lantern->SetMapper(mapper);
  lantern->SetTexture(paper);
  lantern->GetProperty()->SetAmbient(0.3);
  lantern->GetProperty()->SetDiffuse(0.8);

  const double eye[3] = { 5.0, 2.5, 3.0 };
  const double focus[3] = { 0, 1, 0 };
  return ExampleScene::WritePicture(ExampleScene::ViewActor(lantern, eye, focus),
    ExampleScene::OutputFolder(argc, argv), "Lantern");
}
