// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The marble vase: a Bezier profile (radius, height) turned about +y by
// vtkParametricRevolution, in Data/marble.png (procedural marble: veins along
// sin(2 pi (2s + t + turbulence))). Arc-length parameterisation spreads the marble evenly
// along the profile even where its control points bunch up; the base closes on the axis.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkBezierProfile.h>
#include <vtkParametricRevolution.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "MarbleVase",
        "A Bezier profile turned by vtkParametricRevolution, in procedural marble."))
  {
    return 0;
  }
  vtkNew<vtkParametricRevolution> vase; // the default profile is the vase
  vase->GetProfile()->ArcLengthParameterizationOn();
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(vase);
  source->SetUResolution(128);
  source->SetVResolution(96);
  source->SetTextureRepeat(3, 1);

  vtkSmartPointer<vtkTexture> marble = ExampleScene::LoadTexture("marble.png");
  if (!marble)
  {
    return 1;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(marble);
  actor->GetProperty()->SetAmbient(0.3);
  actor->GetProperty()->SetDiffuse(0.8);
  actor->GetProperty()->SetSpecular(0.2);

  const double eye[3] = { 4.5, 3.0, 4.5 };
  const double focus[3] = { 0, 0.95, 0 };
  return ExampleScene::WritePicture(ExampleScene::ViewActor(actor, eye, focus),
    ExampleScene::OutputFolder(argc, argv), "MarbleVase");
}
