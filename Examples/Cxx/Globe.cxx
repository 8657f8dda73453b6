// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The Earth: an equirectangular map on vtkParametricSphere, whose texture coordinates
// (theta / 2 pi, 1 - alpha / pi) put the north pole at the top of the image and longitude 0
// (s = 0.5) on -x. The map is Debian's xplanet-images earth.jpg; where it is missing, or with
// --procedural-map, a map drawn here: continents as ellipses at their places, ice caps and a
// 30-degree graticule, so that north, east and the seam can still be checked.
//
// Usage: Globe [--procedural-map] [<output folder>]   (writes Globe.png)
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkJPEGReader.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <cstring>
#include <fstream>

namespace
{
constexpr const char* EarthMap = "/usr/share/xplanet/images/earth.jpg";

// Longitude, latitude of the centre and the half-widths, in degrees.
constexpr double Continents[][4] = { { -100, 45, 35, 20 }, { -60, -15, 15, 28 }, { 15, 52, 20, 10 },
  { 20, 5, 20, 32 }, { 95, 50, 45, 20 }, { 135, -25, 17, 10 } };

vtkSmartPointer<vtkImageData> ProceduralEarth(int width, int height)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      // Row 0 is the bottom of the map: the south pole.
      const double lon = -180.0 + 360.0 * (i + 0.5) / width;
      const double lat = -90.0 + 180.0 * (j + 0.5) / height;
      double c[3] = { 0.10, 0.25, 0.55 };
      for (const auto& e : Continents)
      {
        const double x = (lon - e[0]) / e[2], y = (lat - e[1]) / e[3];
        if (x * x + y * y < 1.0)
        {
          c[0] = 0.30;
          c[1] = lat > 45 ? 0.45 : 0.55;
          c[2] = 0.22;
        }
      }
      if (lat > 78 || lat < -70)
      {
        c[0] = c[1] = c[2] = 0.95;
      }
      const double gridLon = std::abs(std::remainder(lon, 30.0));
      const double gridLat = std::abs(std::remainder(lat, 30.0));
      if (gridLon < 0.4 || gridLat < 0.4)
      {
        for (double& v : c)
        {
          v = 0.5 * v + 0.5;
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        rgb[3 * (j * width + i) + k] = static_cast<unsigned char>(std::lround(255.0 * c[k]));
      }
    }
  }
  return image;
}
} // namespace

int main(int argc, char* argv[])
{
  if (ExampleScene::AskedForHelp(argc, argv))
  {
    std::cout << "Usage: Globe [--procedural-map] [output folder]\n\n"
                 "The Earth on vtkParametricSphere, north up and longitude 0 on -x. The map is\n"
              << EarthMap
              << "; with --procedural-map, or where it is missing, a\n"
                 "map drawn by the program.\n\n"
                 "Writes <output folder>/Globe.png (default: the current folder).\n";
    return 0;
  }
  bool procedural = false;
  std::string folder = ".";
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--procedural-map") == 0)
    {
      procedural = true;
    }
    else
    {
      folder = argv[i];
    }
  }

  vtkNew<vtkTexture> texture;
  vtkNew<vtkJPEGReader> reader;
  if (!procedural && std::ifstream(EarthMap))
  {
    reader->SetFileName(EarthMap);
    texture->SetInputConnection(reader->GetOutputPort());
  }
  else
  {
    if (!procedural)
    {
      std::cout << EarthMap << " is missing (Debian: xplanet-images); using a procedural map\n";
    }
    texture->SetInputData(ProceduralEarth(1024, 512));
  }
  texture->InterpolateOn();
  texture->MipmapOn();
  // Not Repeat: at the poles, t = 1 would blend in the south pole's row. The map's left and
  // right columns are neighbours on the globe, so clamping leaves no visible seam either.
  texture->SetWrap(vtkTexture::ClampToEdge);

  vtkNew<vtkParametricSphere> sphere;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->SetUResolution(128);
  source->SetVResolution(64);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> globe;
  globe->SetMapper(mapper);
  globe->SetTexture(texture);
  globe->GetProperty()->SetAmbient(0.25);
  globe->GetProperty()->SetDiffuse(0.85);

  // Longitude 0 faces -x and east is +z: from there, a little north and west, Europe and
  // Africa face the camera with the seam (longitude 180) behind the globe.
  const double eye[3] = { -4.0, 1.6, -1.2 };
  const double focus[3] = { 0, 0, 0 };
  return ExampleScene::WritePicture(ExampleScene::ViewActor(globe, eye, focus), folder, "Globe");
}
