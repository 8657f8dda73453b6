// Seed 004's cylinder: a label wrapped once round a can, u round (from +x towards -z) and
// v up. Data/test_card.png must read left to right and upright from outside, with no seam where
// u = 0 meets u = 1 (duplicated vertices, texture coordinates 0 and 1).
#include "ParametricExampleHelpers.h"

#include <vtkParametricCylinder.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTexture.h>

int main(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";
  vtkNew<vtkParametricCylinder> cylinder; // the seed's: radius 1, height 2
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(cylinder);
  source->SetUResolution(96);
  source->SetVResolution(4);
  source->SetTextureRepeat(2, 1); // the card twice round

  vtkSmartPointer<vtkTexture> texture = LoadTexture("test_card.png");
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

  // Look at the seam (u = 0 at +x) from the front right.
  const double eye[3] = { 5.0, 2.5, 3.0 };
  const double focus[3] = { 0, 1, 0 };
  return RenderExample(actor, folder, "ParametricCylinder", eye, focus);
}
