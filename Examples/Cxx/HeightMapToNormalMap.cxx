// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// A bump map made a normal map: a procedural height map (a raised bump, a sunken
// crater and a band of ridges) becomes a normal map with vtkHeightMapToNormalMap, and the
// normal map lights a flat square through VTK's own normal mapping, the light coming from
// the right. Writes, into the folder given as the only argument:
//   HeightMapToNormalMap_height.png  the heights (white = high)
//   HeightMapToNormalMap_normal.png  the encoded normal map (green up: a raised bump is
//                                    redder on its right flank, greener on its top flank)
//   HeightMapToNormalMap.png         the lit square
// and the same for the project's brick wall height map (Data/brick_height.png):
//   HeightMapToNormalMap_bricks_normal.png, HeightMapToNormalMap_bricks.png

#include "vtkHeightMapToNormalMap.h"
#include "vtkOIIOImageReader.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkImageShiftScale.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataTangents.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkTriangleFilter.h>
#include <vtkWindowToImageFilter.h>
#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
// Heights in [0,1] on the unit texture square: base 0.5, a bump up, a crater down, ridges.
double Height(double s, double t)
{
  const double bump = std::exp(-((s - 0.3) * (s - 0.3) + (t - 0.62) * (t - 0.62)) / 0.012);
  const double r = std::hypot(s - 0.72, t - 0.6);
  const double crater =
    std::exp(-(r - 0.0) * (r - 0.0) / 0.006) - 0.5 * std::exp(-(r - 0.13) * (r - 0.13) / 0.0015);
  const double ridges = t < 0.3
    ? 0.08 * std::sin(2.0 * 3.14159265358979 * 8.0 * s) * std::sin(3.14159265358979 * t / 0.3)
    : 0.0;
  return 0.5 + 0.4 * bump - 0.3 * crater + ridges;
}

void Write(vtkAlgorithmOutput* port, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(port);
  writer->SetFileName(path.c_str());
  writer->Write();
}
// A unit square facing +z, texture coordinates (s,t) along (x,y), with tangents for VTK's
// normal mapping (tbn = (T, N x T, N), so +t is the map's +Y: green up), lit from the right.
void RenderLit(vtkAlgorithmOutput* normalMap, const std::string& path)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkPolyDataTangents> tangents;
  tangents->SetInputConnection(triangles->GetOutputPort());

  vtkNew<vtkTexture> normalTexture;
  normalTexture->SetInputConnection(normalMap);
  normalTexture->InterpolateOn();

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(tangents->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToPhong();
  actor->GetProperty()->SetNormalTexture(normalTexture);
  actor->GetProperty()->SetColor(0.85, 0.8, 0.72);
  actor->GetProperty()->SetAmbient(0.1);
  actor->GetProperty()->SetDiffuse(0.9);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.12);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light; // from the right, a little above and in front
  light->SetLightTypeToSceneLight();
  light->SetPositional(false);
  light->SetPosition(1.0, 0.2, 0.7);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(light);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(1.0);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(512, 512);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  Write(capture->GetOutputPort(), path);
}
} // namespace

int main(int argc, char* argv[])
{
  const bool help =
    argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0);
  if (argc != 2 || help)
  {
    (help ? std::cout : std::cerr)
      << "Usage: HeightMapToNormalMap <output folder>\n\n"
         "A procedural height map made a normal map by vtkHeightMapToNormalMap, and a flat\n"
         "square lit through it; then the same for Data/brick_height.png. Writes\n"
         "HeightMapToNormalMap_height.png, _normal.png, .png, _bricks_normal.png and\n"
         "_bricks.png (each name begins HeightMapToNormalMap) into the folder.\n";
    return help ? 0 : 1;
  }
  const std::string folder = argv[1];

  constexpr int size = 512;
  vtkNew<vtkImageData> heights;
  heights->SetDimensions(size, size, 1);
  vtkNew<vtkFloatArray> h;
  h->SetName("height");
  h->SetNumberOfTuples(size * size);
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      h->SetValue(j * size + i, static_cast<float>(Height((i + 0.5) / size, (j + 0.5) / size)));
    }
  }
  heights->GetPointData()->SetScalars(h);

  vtkNew<vtkHeightMapToNormalMap> toNormals;
  toNormals->SetInputData(heights);
  toNormals->SetDifferenceSchemeToSobel();
  toNormals->SetBumpScale(0.15);
  toNormals->SetWrapToClampToEdge();
  toNormals->SetOutputScalarTypeToUnsignedChar();

  vtkNew<vtkImageShiftScale> grey;
  grey->SetInputData(heights);
  grey->SetScale(255.0);
  grey->SetOutputScalarTypeToUnsignedChar();
  grey->ClampOverflowOn();
  Write(grey->GetOutputPort(), folder + "/HeightMapToNormalMap_height.png");
  Write(toNormals->GetOutputPort(), folder + "/HeightMapToNormalMap_normal.png");

  RenderLit(toNormals->GetOutputPort(), folder + "/HeightMapToNormalMap.png");

  // The project's brick wall (Data/brick_height.png, 16-bit, tiles): read as 0..1 by type
  // range; Repeat, as the wall is meant to be tiled.
  const std::string bricks = SURFACEDETAIL_DATA_DIR "/brick_height.png";
  if (vtksys::SystemTools::FileExists(bricks))
  {
    vtkNew<vtkOIIOImageReader> reader;
    reader->SetFileName(bricks.c_str());
    vtkNew<vtkHeightMapToNormalMap> brickNormals;
    brickNormals->SetInputConnection(reader->GetOutputPort());
    brickNormals->SetDifferenceSchemeToSobel();
    brickNormals->SetBumpScale(0.015);
    brickNormals->SetWrapToRepeat();
    Write(brickNormals->GetOutputPort(), folder + "/HeightMapToNormalMap_bricks_normal.png");
    RenderLit(brickNormals->GetOutputPort(), folder + "/HeightMapToNormalMap_bricks.png");
  }
  return 0;
}
