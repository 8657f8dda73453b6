// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The brick wall: the rectangle x in [-2,2], y in [0,3.5] as one quad whose corners
// carry texture coordinates, as glTexCoord2f() calls give them in classic OpenGL code (top-left,
// bottom-left, bottom-right, top-right), five ways side by side:
// - Whole: (0,1) (0,0) (1,0) (1,1), the picture once;
// - Repeated: 0..4 x 0..1.5, vtkTexture::Repeat: the picture tiles;
// - Mirrored: the same coordinates with vtkTexture::MirroredRepeat: every other tile flips;
// - Tilted photo: a picture of the wall taken askew (here: the bricks turned by 12 degrees);
// - Straightened: the quick fix, only the slanted part of that photo that holds
//   straight bricks mapped onto the rectangle, corner by corner.
// The wall is drawn unlit, as GL_REPLACE shows the texture's own colours.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageReslice.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTransform.h>

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double TiltDegrees = 12.0;

vtkSmartPointer<vtkPolyData> Wall(const double st[4][2])
{
  const double corners[4][3] = { { -2, 3.5, 0 }, { -2, 0, 0 }, { 2, 0, 0 }, { 2, 3.5, 0 } };
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TextureCoordinates");
  tcoords->SetNumberOfComponents(2);
  for (int k = 0; k < 4; ++k)
  {
    points->InsertNextPoint(corners[k]);
    tcoords->InsertNextTuple(st[k]);
  }
  vtkNew<vtkCellArray> quads;
  const vtkIdType quad[4] = { 0, 1, 2, 3 };
  quads->InsertNextCell(4, quad);
  auto wall = vtkSmartPointer<vtkPolyData>::New();
  wall->SetPoints(points);
  wall->SetPolys(quads);
  wall->GetPointData()->SetTCoords(tcoords);
  return wall;
}
} // namespace

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "BrickWall",
        "The brick wall as one textured quad, five ways side by side: the picture once,\nrepeated, "
        "mirrored, a tilted photo, and that photo straightened."))
  {
    return 0;
  }
  vtkSmartPointer<vtkTexture> bricks = ExampleScene::LoadTexture("brick_color.png");
  if (!bricks)
  {
    return 1;
  }
  vtkNew<vtkTexture> mirrored;
  mirrored->SetInputConnection(bricks->GetInputConnection(0, 0));
  mirrored->InterpolateOn();
  mirrored->MipmapOn();
  mirrored->SetWrap(vtkTexture::MirroredRepeat);

  // The askew photo: each output texel x shows the wall at c + R(-tilt) (x - c), c the centre,
  // so the bricks appear turned by +tilt; the wall continues past the picture's edges.
  const double c = 255.5; // Data/brick_color.png is 512 x 512
  vtkNew<vtkTransform> turn;
  turn->Translate(c, c, 0);
  turn->RotateZ(-TiltDegrees);
  turn->Translate(-c, -c, 0);
  vtkNew<vtkImageReslice> askew;
  askew->SetInputConnection(bricks->GetInputConnection(0, 0));
  askew->SetResliceTransform(turn);
  askew->SetInterpolationModeToCubic();
  askew->WrapOn();
  vtkNew<vtkTexture> photo;
  photo->SetInputConnection(askew->GetOutputPort());
  photo->InterpolateOn();
  photo->MipmapOn();

  // The straight part [0.125, 0.875]^2 of the wall appears in the photo at
  // 0.5 + R(tilt) (q - 0.5): those are the corners' texture coordinates.
  const double a = TiltDegrees * Pi / 180.0;
  const double part[4][2] = { { 0.125, 0.875 }, { 0.125, 0.125 }, { 0.875, 0.125 },
    { 0.875, 0.875 } };
  double straightened[4][2];
  for (int k = 0; k < 4; ++k)
  {
    const double x = part[k][0] - 0.5, y = part[k][1] - 0.5;
    straightened[k][0] = 0.5 + std::cos(a) * x - std::sin(a) * y;
    straightened[k][1] = 0.5 + std::sin(a) * x + std::cos(a) * y;
  }

  const double whole[4][2] = { { 0, 1 }, { 0, 0 }, { 1, 0 }, { 1, 1 } };
  const double repeated[4][2] = { { 0, 1.5 }, { 0, 0 }, { 4, 0 }, { 4, 1.5 } };
  struct Panel
  {
    const char* Label;
    const double (*TCoords)[2];
    vtkTexture* Texture;
  };
  const Panel panels[5] = { { "Whole", whole, bricks }, { "Repeated", repeated, bricks },
    { "Mirrored repeat", repeated, mirrored }, { "Tilted photo", whole, photo },
    { "Straightened", straightened, photo } };

  auto window = ExampleScene::MakeWindow(1500, 400);
  for (int k = 0; k < 5; ++k)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(Wall(panels[k].TCoords));
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(panels[k].Texture);
    actor->GetProperty()->LightingOff();

    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.2 * k, 0, 0.2 * (k + 1), 1);
    renderer->SetBackground(0.18, 0.2, 0.24);
    renderer->AddActor(actor);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetParallelScale(2.9); // 4.35 units across: the wall and a margin
    camera->SetFocalPoint(0, 1.35, 0);
    camera->SetPosition(0, 1.35, 10);
    camera->SetViewUp(0, 1, 0);
    renderer->ResetCameraClippingRange();
    ExampleScene::AddLabel(renderer, panels[k].Label);
    window->AddRenderer(renderer);
  }
  return ExampleScene::WritePicture(window, ExampleScene::OutputFolder(argc, argv), "BrickWall");
}
