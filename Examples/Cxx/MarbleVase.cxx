// Seed 004's marble vase: a Bézier profile (radius, height) turned about +y by
// vtkParametricRevolution, in Data/marble.png. Arc-length parameterisation spreads it evenly along
// the profile even where its control points bunch up; the base closes on the axis (a pole).
#include "ParametricExampleHelpers.h"

#include <vtkBezierProfile.h>
#include <vtkParametricRevolution.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTexture.h>

int main(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";
  vtkNew<vtkParametricRevolution> vase; // the default profile is the vase
  vase->GetProfile()->ArcLengthParameterizationOn();
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(vase);
  source->SetUResolution(128);
  source->SetVResolution(96);
  source->SetTextureRepeat(3, 1);

  vtkSmartPointer<vtkTexture> texture = LoadTexture("marble.png");
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
  actor->GetProperty()->SetSpecular(0.2);

  const double eye[3] = { 4.5, 3.0, 4.5 };
  const double focus[3] = { 0, 0.95, 0 };
  return RenderExample(actor, folder, "ParametricVase", eye, focus);
}
