// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The analytic scene of the mapper tests: an orthographic camera looks at a rectangle lit by
// one directional scene light; the expected picture is computed on the CPU from closed forms
// (see TestSurfaceDetailMapper.cxx). Shared by the tests of both surface-detail mappers.
#ifndef SurfaceDetailMapperAnalyticScene_h
#define SurfaceDetailMapperAnalyticScene_h

#include "TangentFrameTestHelpers.h"
#include "vtkSurfaceDetailMapper.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageAlgorithm.h>
#include <vtkImageData.h>
#include <vtkImageShiftScale.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkLight.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataTangents.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

namespace
{
constexpr int WindowSize = 200;
constexpr double Pi = 3.14159265358979323846;
using Vec3 = std::array<double, 3>;

inline Vec3 Normalized(const Vec3& v)
{
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / l, v[1] / l, v[2] / l };
}
inline double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The test surface: h(s,t) = 0.5 + 0.2 sin(2 pi s) + 0.15 sin(4 pi t + 1), periodic on the
// unit square, with different slopes along s and t so that swapped axes show.
inline double Height(double s, double t)
{
  return 0.5 + 0.2 * std::sin(2 * Pi * s) + 0.15 * std::sin(4 * Pi * t + 1.0);
}
inline void HeightGradient(double s, double t, double& hs, double& ht)
{
  hs = 0.4 * Pi * std::cos(2 * Pi * s);
  ht = 0.6 * Pi * std::cos(4 * Pi * t + 1.0);
}
constexpr double Strength = 0.25; // the normal map is that of z = Strength*h(s,t)

// Tangent-space normal of z = k*h(s,t).
inline Vec3 TangentSpaceNormal(double s, double t, double k = Strength)
{
  double hs, ht;
  HeightGradient(s, t, hs, ht);
  return Normalized({ -k * hs, -k * ht, 1.0 });
}

// A (cells x cells) grid over [-1,1]^2 at z = 0 with normal +z, texture coordinates
// (s,t) = ((x+1)/2, (y+1)/2), or s mirrored (s = (1-x)/2, tangent -x, w = -1).
inline vtkSmartPointer<vtkPolyData> MakeRectangle(
  bool mirrored, bool tangents = true, bool tcoords = true, bool normals = true)
{
  constexpr int cells = 8;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> n;
  n->SetNumberOfComponents(3);
  n->SetName("Normals");
  vtkNew<vtkFloatArray> tc;
  tc->SetNumberOfComponents(2);
  tc->SetName("TCoords");
  vtkNew<vtkFloatArray> tg;
  tg->SetNumberOfComponents(4);
  tg->SetName("Tangents");
  for (int j = 0; j <= cells; ++j)
  {
    for (int i = 0; i <= cells; ++i)
    {
      const double x = -1.0 + 2.0 * i / cells, y = -1.0 + 2.0 * j / cells;
      points->InsertNextPoint(x, y, 0.0);
      n->InsertNextTuple3(0, 0, 1);
      tc->InsertNextTuple2(mirrored ? (1.0 - x) / 2 : (x + 1) / 2, (y + 1) / 2);
      const float t4[4] = { mirrored ? -1.0f : 1.0f, 0, 0, mirrored ? -1.0f : 1.0f };
      tg->InsertNextTypedTuple(t4);
    }
  }
  vtkNew<vtkCellArray> polys;
  for (int j = 0; j < cells; ++j)
  {
    for (int i = 0; i < cells; ++i)
    {
      const vtkIdType a = j * (cells + 1) + i, b = a + 1, c = a + cells + 2, d = a + cells + 1;
      const vtkIdType t1[3] = { a, b, c }, t2[3] = { a, c, d };
      polys->InsertNextCell(3, t1);
      polys->InsertNextCell(3, t2);
    }
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  if (normals)
  {
    poly->GetPointData()->SetNormals(n);
  }
  if (tcoords)
  {
    poly->GetPointData()->SetTCoords(tc);
  }
  if (tangents)
  {
    SetTangentFrame(poly, tg);
  }
  return poly;
}

// A float texture of f(s,t) sampled at texel centres, linear filtering, repeat.
inline vtkSmartPointer<vtkTexture> MakeTexture(
  int size, int comps, const std::function<void(double, double, double*)>& f)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_FLOAT, comps);
  auto* p = static_cast<float*>(image->GetScalarPointer());
  std::vector<double> value(comps);
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      f((i + 0.5) / size, (j + 0.5) / size, value.data());
      for (int c = 0; c < comps; ++c)
      {
        *p++ = static_cast<float>(value[c]);
      }
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->RepeatOn();
  texture->SetColorModeToDirectScalars();
  return texture;
}

inline vtkSmartPointer<vtkTexture> MakeNormalMap(bool greenUp = true)
{
  return MakeTexture(256, 3,
    [greenUp](double s, double t, double* rgb)
    {
      Vec3 n = TangentSpaceNormal(s, t);
      rgb[0] = 0.5 * n[0] + 0.5;
      rgb[1] = 0.5 * (greenUp ? n[1] : -n[1]) + 0.5;
      rgb[2] = 0.5 * n[2] + 0.5;
    });
}

inline vtkSmartPointer<vtkTexture> MakeHeightMap(double constant = -1.0)
{
  return MakeTexture(256, 1,
    [constant](double s, double t, double* h) { h[0] = constant >= 0 ? constant : Height(s, t); });
}

struct Material
{
  double Ambient = 0.15, Diffuse = 0.8, Specular = 0.0, SpecularPower = 20.0;
  Vec3 AmbientColor{ 1.0, 1.0, 1.0 };
  Vec3 DiffuseColor{ 0.9, 0.7, 0.5 };
  Vec3 SpecularColor{ 1.0, 1.0, 1.0 };
};

const Vec3 LightPosition{ 1.0, 0.6, 1.2 }; // light travels from here towards the origin

// A positional spot light for the positional-light test (VTK 9.1's positional shader:
// constant attenuation 1, cone test and pow(cos, exponent) fall-off).
struct SpotLight
{
  bool Enabled = false;
  Vec3 Position{ 0.6, 0.9, 1.6 };
  double ConeAngle = 60.0;
  double Exponent = 3.0;
};
SpotLight Spot;

// Everything a scene needs; Render() returns the RGB read-back, row 0 at the bottom.
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  Material Mat;

  explicit Scene(vtkPolyDataMapper* mapper)
  {
    this->Window->SetSize(WindowSize, WindowSize);
    this->Window->SetMultiSamples(0);
    this->Window->OffScreenRenderingOn();
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0, 0, 0);
    this->Renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(Spot.Enabled);
    light->SetConeAngle(Spot.ConeAngle);
    light->SetExponent(Spot.Exponent);
    light->SetAttenuationValues(1, 0, 0);
    const Vec3& position = Spot.Enabled ? Spot.Position : LightPosition;
    light->SetPosition(position[0], position[1], position[2]);
    light->SetFocalPoint(0, 0, 0);
    light->SetColor(1, 1, 1);
    light->SetIntensity(1.0);
    this->Renderer->AddLight(light);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetPosition(0, 0, 5);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    camera->SetParallelScale(1.0);
    camera->SetClippingRange(1, 10);
    this->Actor->SetMapper(mapper);
    this->Renderer->AddActor(this->Actor);
  }

  std::vector<unsigned char> Render()
  {
    vtkProperty* p = this->Actor->GetProperty();
    p->SetAmbient(this->Mat.Ambient);
    p->SetDiffuse(this->Mat.Diffuse);
    p->SetSpecular(this->Mat.Specular);
    p->SetSpecularPower(this->Mat.SpecularPower);
    p->SetAmbientColor(this->Mat.AmbientColor.data());
    p->SetDiffuseColor(this->Mat.DiffuseColor.data());
    p->SetSpecularColor(this->Mat.SpecularColor.data());
    this->Renderer->ResetCameraClippingRange(-3, 3, -3, 3, -3, 3);
    this->Window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(this->Window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    auto* data = static_cast<unsigned char*>(grab->GetOutput()->GetScalarPointer());
    return std::vector<unsigned char>(data, data + 3 * WindowSize * WindowSize);
  }
};

// Where the pixel ray of pixel (i,j) meets the actor's z = 0 plane: model (x,y), the world
// point, and whether it is inside the rectangle at least one pixel from its edges.
struct Hit
{
  double X, Y;
  Vec3 World;
  bool Inside;
};

inline Hit PixelHit(int i, int j, vtkMatrix4x4* m)
{
  const double wx = -1.0 + 2.0 * (i + 0.5) / WindowSize;
  const double wy = -1.0 + 2.0 * (j + 0.5) / WindowSize;
  // Solve m * (x, y, 0, 1) = (wx, wy, *, 1) in x, y.
  const double a = m->GetElement(0, 0), b = m->GetElement(0, 1);
  const double c = m->GetElement(1, 0), d = m->GetElement(1, 1);
  const double rx = wx - m->GetElement(0, 3), ry = wy - m->GetElement(1, 3);
  const double det = a * d - b * c;
  Hit hit;
  hit.X = (d * rx - b * ry) / det;
  hit.Y = (a * ry - c * rx) / det;
  for (int r = 0; r < 3; ++r)
  {
    hit.World[r] = m->GetElement(r, 0) * hit.X + m->GetElement(r, 1) * hit.Y + m->GetElement(r, 3);
  }
  // One pixel of margin, measured in model units along each axis.
  const double marginX = 2.0 * 2.0 / WindowSize / std::sqrt(a * a + c * c);
  const double marginY = 2.0 * 2.0 / WindowSize / std::sqrt(b * b + d * d);
  hit.Inside = std::abs(hit.X) < 1.0 - marginX && std::abs(hit.Y) < 1.0 - marginY;
  return hit;
}

// VTK's Phong for one directional light, view coordinates = world shifted by the camera
// (the camera looks down -z from z = 5 with y up).
inline Vec3 Shade(const Vec3& nWorld, const Vec3& world, const Material& mat)
{
  Vec3 L = Normalized({ -LightPosition[0], -LightPosition[1], -LightPosition[2] });
  double attenuation = 1.0;
  if (Spot.Enabled)
  {
    const Vec3 axis = Normalized({ -Spot.Position[0], -Spot.Position[1], -Spot.Position[2] });
    L = Normalized(
      { world[0] - Spot.Position[0], world[1] - Spot.Position[1], world[2] - Spot.Position[2] });
    const double coneDot = Dot(L, axis);
    attenuation =
      coneDot >= std::cos(Spot.ConeAngle * Pi / 180) ? std::pow(coneDot, Spot.Exponent) : 0.0;
  }
  const Vec3 n = Normalized(nWorld);
  const double df = std::max(0.0, attenuation * -Dot(n, L));
  const double nl = Dot(n, L);
  const Vec3 r{ L[0] - 2 * nl * n[0], L[1] - 2 * nl * n[1], L[2] - 2 * nl * n[2] };
  const Vec3 v = Normalized({ -world[0], -world[1], -(world[2] - 5.0) });
  const double sf =
    (df > 0 ? 1.0 : 0.0) * attenuation * std::pow(std::max(0.0, Dot(r, v)), mat.SpecularPower);
  Vec3 c;
  for (int k = 0; k < 3; ++k)
  {
    c[k] = mat.Ambient * mat.AmbientColor[k] + mat.Diffuse * mat.DiffuseColor[k] * df +
      mat.Specular * mat.SpecularColor[k] * sf;
  }
  return c;
}

// The PSNR of an image against the expected colour (in [0,1], clamped) of every pixel well
// inside the rectangle placed by matrix m.
inline double PSNRInside(const std::vector<unsigned char>& image, vtkMatrix4x4* m,
  const std::function<Vec3(const Hit&)>& expected)
{
  double sum = 0.0;
  long count = 0;
  for (int j = 0; j < WindowSize; ++j)
  {
    for (int i = 0; i < WindowSize; ++i)
    {
      const Hit hit = PixelHit(i, j, m);
      if (!hit.Inside)
      {
        continue;
      }
      const Vec3 e = expected(hit);
      for (int k = 0; k < 3; ++k)
      {
        const double diff =
          255.0 * std::min(1.0, std::max(0.0, e[k])) - image[3 * (j * WindowSize + i) + k];
        sum += diff * diff;
        ++count;
      }
    }
  }
  EXPECT_GT(count, 3 * 1000) << "too few pixels inside the rectangle";
  const double mse = sum / std::max(count, 1L);
  const double psnr = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 99.0;
  std::cout << "PSNR " << psnr << " dB over " << count / 3 << " pixels\n";
  return psnr;
}

// The expected picture for a model-space normal field, and the PSNR of an image against it
// over the pixels well inside the rectangle.
using NormalField = std::function<Vec3(double x, double y)>;

inline double PSNR(const std::vector<unsigned char>& image, vtkActor* actor, const NormalField& field,
  const Material& mat)
{
  vtkMatrix4x4* m = actor->GetMatrix();
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(m, inverse);
  return PSNRInside(image, m,
    [&](const Hit& hit)
    {
      const Vec3 nm = field(hit.X, hit.Y);
      // Normals transform with the inverse transpose of the model matrix.
      Vec3 nw;
      for (int r = 0; r < 3; ++r)
      {
        nw[r] = inverse->GetElement(0, r) * nm[0] + inverse->GetElement(1, r) * nm[1] +
          inverse->GetElement(2, r) * nm[2];
      }
      return Shade(nw, hit.World, mat);
    });
}

// The model-space normal of the detail surface at model point (x,y) of the rectangle,
// through the frame T = (tx,0,0), B = (0,1,0), N = +z.
inline NormalField DetailNormal(bool mirrored, double k = Strength)
{
  return [mirrored, k](double x, double y)
  {
    const double s = mirrored ? (1.0 - x) / 2 : (x + 1) / 2, t = (y + 1) / 2;
    const Vec3 n = TangentSpaceNormal(s, t, k);
    return Vec3{ mirrored ? -n[0] : n[0], n[1], n[2] };
  };
}

inline NormalField FlatNormal()
{
  return [](double, double) { return Vec3{ 0, 0, 1 }; };
}

struct ErrorCounter : public vtkCommand
{
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)++;
    this->Last = data ? static_cast<const char*>(data) : "";
  }
  int Errors = 0;
  int Warnings = 0;
  std::string Last;
};

inline vtkSmartPointer<vtkSurfaceDetailMapper> MakeMapper(vtkPolyData* poly)
{
  auto mapper = vtkSmartPointer<vtkSurfaceDetailMapper>::New();
  mapper->SetInputData(poly);
  return mapper;
}
} // namespace

#endif
