// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The sky: a panorama on the inside of a sphere around the camera. Seen from inside,
// u (from +x towards -z) runs right to left, so the texture coordinates are mirrored,
// s = 1 - u (TextureRepeat -1, TextureOffset 1), for the panorama to read as painted. The sky
// is not lit: its texture is what the eye sees (LightingOff). The panorama is drawn here:
// ground and a mountain range below the horizon, a gradient, clouds and a sun above it.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <algorithm>

namespace
{
constexpr double Pi = 3.14159265358979323846;

double SmoothStep(double a, double b, double x)
{
  const double t = std::min(1.0, std::max(0.0, (x - a) / (b - a)));
  return t * t * (3 - 2 * t);
}

// Equirectangular: s = longitude / 360 degrees, t = 0.5 + latitude / 180 degrees.
vtkSmartPointer<vtkImageData> Panorama(int width, int height)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer());
  const double sunLon = 200.0, sunLat = 20.0;
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const double lon = 360.0 * (i + 0.5) / width;
      const double lat = -90.0 + 180.0 * (j + 0.5) / height;
      const double a = lon * Pi / 180.0;
      const double ridge =
        4.0 + 3.0 * std::sin(3 * a) + 2.0 * std::sin(7 * a + 1.3) + std::sin(17 * a + 0.4);
      double c[3];
      if (lat < 0.0)
      {
        const double f = 0.7 + 0.3 * (1.0 + lat / 90.0); // darker towards the feet
        c[0] = 0.28 * f;
        c[1] = 0.50 * f;
        c[2] = 0.22 * f;
      }
      else if (lat < ridge)
      {
        const double snow = ridge > 7.0 && lat > ridge - 1.0 ? 1.0 : 0.0;
        c[0] = 0.34 + 0.6 * snow;
        c[1] = 0.37 + 0.57 * snow;
        c[2] = 0.46 + 0.5 * snow;
      }
      else
      {
        const double f = std::sqrt(lat / 90.0);
        const double horizon[3] = { 0.85, 0.90, 0.97 }, zenith[3] = { 0.18, 0.38, 0.78 };
        const double dLon = std::remainder(lon - sunLon, 360.0) * std::cos(lat * Pi / 180.0);
        const double d2 = dLon * dLon + (lat - sunLat) * (lat - sunLat);
        const double glow = 0.35 * std::exp(-d2 / 60.0);
        const double puff =
          std::sin(5 * a + 0.15 * lat) * std::sin(0.3 * lat + 2 * std::sin(3 * a));
        const double cloud = SmoothStep(0.45, 0.8, puff) * SmoothStep(8.0, 14.0, lat) *
          (1.0 - SmoothStep(40.0, 55.0, lat));
        for (int k = 0; k < 3; ++k)
        {
          c[k] = (1 - f) * horizon[k] + f * zenith[k] + glow;
          c[k] = (1 - cloud) * c[k] + cloud * 0.96;
        }
        if (d2 < 9.0)
        {
          c[0] = 1.0;
          c[1] = 0.97;
          c[2] = 0.85;
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        rgb[3 * (j * width + i) + k] =
          static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, c[k])));
      }
    }
  }
  return image;
}
} // namespace

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(
        argc, argv, "Sky", "A panorama on the inside of a sphere around the camera."))
  {
    return 0;
  }
  vtkNew<vtkParametricSphere> sphere;
  sphere->SetRadius(50);
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->SetUResolution(128);
  source->SetVResolution(64);
  source->SetTextureRepeat(-1, 1);
  source->SetTextureOffset(1, 0);

  vtkNew<vtkTexture> texture;
  texture->SetInputData(Panorama(1024, 512));
  texture->InterpolateOn();
  texture->MipmapOn();
  texture->SetWrap(vtkTexture::ClampToEdge);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> sky;
  sky->SetMapper(mapper);
  sky->SetTexture(texture);
  sky->GetProperty()->LightingOff();

  // From the centre towards the sun: longitude 200 is at u = 1 - 200/360, a little upwards.
  const double theta = 2 * Pi * (1.0 - 200.0 / 360.0), pitch = 12.0 * Pi / 180.0;
  const double eye[3] = { 0, 0, 0 };
  const double focus[3] = { std::cos(theta) * std::cos(pitch), std::sin(pitch),
    -std::sin(theta) * std::cos(pitch) };
  return ExampleScene::WritePicture(
    ExampleScene::ViewActor(sky, eye, focus, 75.0), ExampleScene::OutputFolder(argc, argv), "Sky");
}
