// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Scenes in which surface detail is judged against the surface it stands for: a parametric
// surface with a coarse tessellation (what the mapper draws on) and a dense one displaced by
// vtkDisplacementMapFilter with Scale = depth and Midlevel 1 (the truth,
// Documentation/Conventions.md's meaning of a relief DepthScale deep), one camera and light for
// every picture of a scene, and the pixels of a frame. TestSurfaceDetailRelief and the
// SurfaceDetailStudy program share them, so that what the test asserts and what the study reports
// are measured the same way.
#ifndef SurfaceDetailTruthScenes_h
#define SurfaceDetailTruthScenes_h

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkDisplacementMapFilter.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkParametricFunction.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace SurfaceDetailTruthScenes
{
const double Background[3] = { 0.18, 0.2, 0.24 };

struct Surface
{
  std::string Name;
  std::function<vtkSmartPointer<vtkParametricFunction>()> Function;
  double Repeat[2]; // texture squares along u and v
  int Coarse[2];    // the mesh the mapping techniques draw on
  int Dense[2];     // the truth; twice this is its convergence check
  double Depth;     // the relief's DepthScale = the displacement's Scale, object units
};

// How a scene is seen, starting from VTK's camera fitted to the coarse surface: Tilt (an
// elevation, so that a z-up surface such as the donut is seen from the side) first, then
// Azimuth and Elevation, then Zoom.
struct ViewAngles
{
  double Tilt = 0, Azimuth = 40, Elevation = 20, Zoom = 1.3;
  // Place the light by the surface's normal (+z) rather than by the camera, so that walls
  // seen from different sides are lit alike and a grazing view is not also grazing light.
  bool LightByNormal = false;
};

inline vtkSmartPointer<vtkTexture> RepeatedTexture(vtkImageData* image)
{
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->RepeatOn();
  return texture;
}

inline vtkSmartPointer<vtkPolyData> Tessellate(
  const Surface& surface, const int resolution[2], bool tangents = true, bool derivatives = true)
{
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(surface.Function());
  source->SetUResolution(resolution[0]);
  source->SetVResolution(resolution[1]);
  source->SetTextureRepeat(surface.Repeat[0], surface.Repeat[1]);
  source->SetGenerateTangents(tangents);
  source->SetGenerateDerivatives(derivatives);
  source->Update();
  return source->GetOutput();
}

// The surface displaced by its depth (Midlevel 1: height 1 is the undisplaced surface, the
// top of the relief's box). Exact normals use the source's derivatives.
inline vtkSmartPointer<vtkPolyData> Displaced(const Surface& surface, vtkImageData* heights,
  const int resolution[2], int normalMode = vtkDisplacementMapFilter::Exact)
{
  vtkNew<vtkDisplacementMapFilter> displace;
  displace->SetInputData(
    Tessellate(surface, resolution, false, normalMode == vtkDisplacementMapFilter::Exact));
  displace->SetInputData(1, heights);
  displace->SetScaleFactor(surface.Depth);
  displace->SetMidlevel(1.0);
  displace->SetWrapToRepeat();
  displace->SetInterpolationToLinear();
  displace->SetNormalMode(normalMode);
  displace->Update();
  return displace->GetOutput();
}

// The mean length on the coarse surface of one unit of texture coordinate, both directions:
// a normal or bump map of a relief d deep is the map of z = (d / this) h over the unit square.
inline double MeanTextureSide(const Surface& surface)
{
  vtkSmartPointer<vtkPolyData> mesh = Tessellate(surface, surface.Coarse, false, true);
  vtkDataArray* dPdu = mesh->GetPointData()->GetArray("dPdu");
  vtkDataArray* dPdv = mesh->GetPointData()->GetArray("dPdv");
  double sum = 0;
  for (vtkIdType id = 0; id < dPdu->GetNumberOfTuples(); ++id)
  {
    sum += vtkMath::Norm(dPdu->GetTuple3(id)) / surface.Repeat[0] +
      vtkMath::Norm(dPdv->GetTuple3(id)) / surface.Repeat[1];
  }
  return sum / (2.0 * dPdu->GetNumberOfTuples());
}

// The view of one scene: every picture of it uses this camera and a positional light above,
// right of and in front of the surface.
struct View
{
  vtkNew<vtkCamera> Camera;
  double LightPosition[3];
  double Centre[3];
};

inline void FitView(const Surface& surface, const ViewAngles& angles, View& view)
{
  vtkSmartPointer<vtkPolyData> mesh = Tessellate(surface, surface.Coarse, false, false);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->ResetCamera();
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->Elevation(angles.Tilt);
  camera->OrthogonalizeViewUp();
  camera->Azimuth(angles.Azimuth);
  camera->Elevation(angles.Elevation);
  camera->OrthogonalizeViewUp();
  renderer->ResetCamera();
  camera->Zoom(angles.Zoom);
  double bounds[6], up[3], front[3], right[3];
  mesh->GetBounds(bounds);
  const double size = std::sqrt(std::pow(bounds[1] - bounds[0], 2) +
    std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
  camera->GetViewUp(up);
  camera->GetDirectionOfProjection(front);
  vtkMath::Cross(front, up, right);
  if (angles.LightByNormal)
  {
    const double x[3] = { 1, 0, 0 }, y[3] = { 0, 1, 0 }, z[3] = { 0, 0, -1 };
    std::copy_n(x, 3, right);
    std::copy_n(y, 3, up);
    std::copy_n(z, 3, front);
  }
  for (int k = 0; k < 3; ++k)
  {
    view.Centre[k] = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
    view.LightPosition[k] = view.Centre[k] + size * (0.5 * right[k] + 0.5 * up[k] - 1.5 * front[k]);
  }
  // One clipping range for every picture of the scene, so that depths compare.
  double range[2];
  camera->GetClippingRange(range);
  camera->SetClippingRange(0.5 * range[0], 2.0 * range[1]);
  view.Camera->DeepCopy(camera);
}

// The scene's background, camera and its one light (no headlight) on @a renderer.
inline void SetUpRenderer(vtkRenderer* renderer, const View& view)
{
  renderer->SetBackground(Background[0], Background[1], Background[2]);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->PositionalOn();
  light->SetConeAngle(180);
  light->SetPosition(view.LightPosition);
  light->SetFocalPoint(view.Centre);
  renderer->AddLight(light);
  renderer->GetActiveCamera()->DeepCopy(view.Camera);
}

// The RGB pixels of the frame just rendered, bottom row first.
inline std::vector<unsigned char> GrabRGB(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto* pixels =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  return std::vector<unsigned char>(
    pixels->GetPointer(0), pixels->GetPointer(0) + pixels->GetNumberOfValues());
}

// Whether a pixel is the background colour (within rounding): the object's pixels are the
// others.
inline bool IsBackground(const unsigned char* rgb, const double background[3] = Background)
{
  for (int c = 0; c < 3; ++c)
  {
    if (std::abs(rgb[c] - 255.0 * background[c]) > 1.5)
    {
      return false;
    }
  }
  return true;
}

// The pixels where either picture shows the object (where both do, with @a both: the
// silhouettes left out). Errors are taken over these, never over the background.
inline std::vector<bool> ObjectPixels(
  const std::vector<unsigned char>& a, const std::vector<unsigned char>& b, bool both = false)
{
  std::vector<bool> object(a.size() / 3);
  for (size_t p = 0; p < object.size(); ++p)
  {
    const bool inA = !IsBackground(&a[3 * p]), inB = !IsBackground(&b[3 * p]);
    object[p] = both ? inA && inB : inA || inB;
  }
  return object;
}
} // namespace SurfaceDetailTruthScenes

#endif
