// The scene shared by the BrickRectangle* examples (seed 004, "Texture mapping onto
// rectangles"): a rectangle given by its four corners, each with the texture coordinates
// the seed's glTexCoord2f() gives it, textured with Data/brick_color.png, rendered with a
// parallel camera looking straight at it and written to <output-folder>/<name>.png.

#ifndef BrickRectangle_h
#define BrickRectangle_h

#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <iostream>
#include <string>

/// Corners in the seed's order: top-left, bottom-left, bottom-right, top-right.
inline int RenderBrickRectangle(
  int argc, char* argv[], const char* name, const double corners[4][3], const double tcoords[4][2])
{
  if (argc != 2)
  {
    std::cerr << "usage: " << argv[0] << " <output-folder>\n";
    return 2;
  }

  vtkNew<vtkOIIOImageReader> bricks;
  bricks->SetFileName(SURFACEDETAIL_DATA_DIR "/brick_color.png");
  bricks->Update();
  if (bricks->GetErrorCode() != 0)
  {
    return 1;
  }

  // One quad, like the seed's glBegin(GL_QUADS), with the texture coordinates as given.
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> st;
  st->SetName("TextureCoordinates");
  st->SetNumberOfComponents(2);
  for (int k = 0; k < 4; ++k)
  {
    points->InsertNextPoint(corners[k]);
    st->InsertNextTuple(tcoords[k]);
  }
  vtkNew<vtkCellArray> quads;
  const vtkIdType quad[4] = { 0, 1, 2, 3 };
  quads->InsertNextCell(4, quad);
  vtkNew<vtkPolyData> rectangle;
  rectangle->SetPoints(points);
  rectangle->SetPolys(quads);
  rectangle->GetPointData()->SetTCoords(st);

  vtkNew<vtkTexture> texture;
  texture->SetInputConnection(bricks->GetOutputPort());
  texture->SetWrap(vtkTexture::Repeat); // Coordinates outside [0,1] repeat the picture.
  texture->InterpolateOn();
  texture->MipmapOn();

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(rectangle);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(texture);
  // The texture's own colours, unshaded, as the seed's glTexEnv(GL_REPLACE) shows them.
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.18, 0.2, 0.24);
  double bounds[6];
  rectangle->GetBounds(bounds);
  const double cx = 0.5 * (bounds[0] + bounds[1]), cy = 0.5 * (bounds[2] + bounds[3]);
  const double w = bounds[1] - bounds[0], h = bounds[3] - bounds[2];
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(cx, cy, 0);
  camera->SetPosition(cx, cy, 10);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(0.55 * h); // A margin of 5% of the height above and below.
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  const int heightPixels = 480;
  window->SetSize(static_cast<int>(heightPixels * (w + 0.1 * h) / (1.1 * h)), heightPixels);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  const std::string path = std::string(argv[1]) + "/" + name + ".png";
  writer->SetFileName(path.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    return 1;
  }
  std::cout << "wrote " << path << "\n";
  return 0;
}

#endif
