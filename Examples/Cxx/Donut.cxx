// Seed 000's donut, z up: P = ((R + r cos 2 pi v) cos 2 pi u, (R + r cos 2 pi v) sin 2 pi u,
// r sin 2 pi v) with Data/checkerboard.png, dark square at (0,0). Seen from outside, s runs
// to the right along the ring and t up the outer side (VTK's vtkParametricTorus mirrors it).
#include "ParametricExampleHelpers.h"

#include <vtkParametricDonut.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTexture.h>

int main(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";
  vtkNew<vtkParametricDonut> donut;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(donut);
  source->SetUResolution(128);
  source->SetVResolution(48);
  source->SetTextureRepeat(5, 2); // square checks: the ring is 2.5 times the tube

  vtkSmartPointer<vtkTexture> texture = LoadTexture("checkerboard.png");
  if (!texture)
  {
    return 1;
  }

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(texture);
  actor->GetProperty()->SetAmbient(0.3);
  actor->GetProperty()->SetDiffuse(0.8);

  // z is up in seed 000: look from the side (-y), a little above the ring's plane.
  actor->RotateX(-90); // turn seed 000's z-up donut into the scene's y up
  const double eye[3] = { 1.0, 2.2, 4.0 };
  const double focus[3] = { 0, 0, 0 };
  return RenderExample(actor, folder, "ParametricDonut", eye, focus);
}
