// Seed 004's Earth: an equirectangular map on vtkParametricSphere, whose texture
// coordinates (theta / 2 pi, 1 - alpha / pi) put the north pole at the top of the image.
// The map is Debian's xplanet-images earth.jpg, read with vtkJPEGReader.
#include "ParametricExampleHelpers.h"

#include <vtkJPEGReader.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTexture.h>

#include <fstream>

int main(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";
  const char* map = "/usr/share/xplanet/images/earth.jpg";
  if (!std::ifstream(map))
  {
    std::cerr << "ParametricEarth: " << map << " is missing; install xplanet-images "
              << "(scripts/install-deps.sh)\n";
    return 1;
  }
  vtkNew<vtkJPEGReader> reader;
  reader->SetFileName(map);

  vtkNew<vtkParametricSphere> sphere;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->SetUResolution(128);
  source->SetVResolution(64);

  vtkNew<vtkTexture> texture;
  texture->SetInputConnection(reader->GetOutputPort());
  texture->InterpolateOn();
  texture->MipmapOn();
  texture->SetWrap(vtkTexture::ClampToEdge);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(texture);
  actor->GetProperty()->SetAmbient(0.25);
  actor->GetProperty()->SetDiffuse(0.85);

  // Longitude 0 (s = 0.5) faces -x: look from there, a little north, to see Europe and Africa.
  const double eye[3] = { -4.0, 1.6, -1.2 };
  const double focus[3] = { 0, 0, 0 };
  return RenderExample(actor, folder, "ParametricEarth", eye, focus);
}
