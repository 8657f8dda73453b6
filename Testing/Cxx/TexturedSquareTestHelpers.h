// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The scene of the image tests that check where a texture's rows land on screen
// (TestTexturedRectangle, TestOIIOReaderTestCard): the texture, unshaded, on a square that
// fills a 256x256 window, texture coordinates (0,0) bottom-left to (1,1) top-right, seen
// through a parallel camera; the picture is compared with the baseline given by -V.
#ifndef TexturedSquareTestHelpers_h
#define TexturedSquareTestHelpers_h

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include "SurfaceDetailImageComparison.h"

/// Renders @a texture (its input and interpolation set by the caller) and returns the
/// exit code of main(): 0 when the picture matches the baseline.
inline int RenderTexturedSquareAndCompare(int argc, char* argv[], vtkTexture* texture)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(texture);
  // The texture's own colours: lighting would shade them and hide what is being checked.
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.1);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(1.0);

  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(256, 256);
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();

  const int result = SurfaceDetailImageComparison::RegressionTest(argc, argv, window);
  if (result == SurfaceDetailImageComparison::Interact)
  {
    interactor->Start();
  }
  return !result;
}

#endif
