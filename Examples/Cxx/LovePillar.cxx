// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The love pillar: a heart-shaped Bezier profile in x-z extruded up +y by
// vtkParametricExtrusion, u along the profile and v up, as texturing code usually has it.
// Arc-length parameterisation keeps the card's squares the same width all round. The seam sits on
// the corner at the dip between the lobes, where the normals may differ on each side.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkBezierProfile.h>
#include <vtkParametricExtrusion.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "LovePillar",
        "A heart-shaped Bezier profile extruded by vtkParametricExtrusion, in a test card."))
  {
    return 0;
  }
  vtkNew<vtkParametricExtrusion> pillar; // the default profile is the heart, height 2
  pillar->GetProfile()->ArcLengthParameterizationOn();
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(pillar);
  source->SetUResolution(256);
  source->SetVResolution(8);
  source->SetTextureRepeat(3, 1);

  vtkSmartPointer<vtkTexture> card = ExampleScene::LoadTexture("test_card.png");
  if (!card)
  {
    return 1;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(card);
  actor->GetProperty()->SetAmbient(0.3);
  actor->GetProperty()->SetDiffuse(0.8);

  // From the tip of the heart (+z), a little above.
  const double eye[3] = { 2.5, 3.5, 5.5 };
  const double focus[3] = { 0, 1, 0 };
  return ExampleScene::WritePicture(ExampleScene::ViewActor(actor, eye, focus),
    ExampleScene::OutputFolder(argc, argv), "LovePillar");
}
