// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Regression scenes for vtkSurfaceDetailMapper: one technique on one brick-textured surface
// from vtkParametricSurfaceSource, seen head-on or obliquely, under the headlight or a
// positional light. Arguments:
//   --technique none|normal|bump|bump-tangent-free|parallax|relief|relief-shadow|relief-map
//   --surface rectangle|sphere|torus|vase
//   --view head-on|oblique|grazing                 --light
//   headlight|positional|raking|spot|lightkit
//   --cones off|on                                 (relief: cone stepping with the heights' cone map)
//   --mutation none|light-10|flipped-maps|half-scale|flipped-handedness
// A mutation makes one kind of mistake on purpose (the light turned by 10 degrees about the
// camera's up axis, the height and normal maps upside down, BumpScale and DepthScale halved,
// the tangents' handedness w negated): the tests that use one expect the comparison with the
// right picture to fail.
// The bricks are a procedural height field (bricks at height 1, mortar joints at 0 with a
// bevel), a colour texture of the same layout, and the normal map vtkHeightMapToNormalMap
// makes from the heights, so all techniques show the same raised bricks. Relief mapping
// shades with the normal of the relief itself (relief, relief-shadow: the height map alone,
// the second with self-shadowing) or with a relief map from vtkHeightMapToNormalMap whose
// strength matches the depth (relief-map, self-shadowing on).

#include "BrickTextures.h"
#include "SurfaceDetailImageComparison.h"
#include "vtkSurfaceDetailMapper.h"
#include "vtkSurfaceDetailTangents.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkHeightMapToConeMap.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightKit.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkParametricDonut.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricRevolution.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
constexpr int TextureSize = 256;

// The image with its rows in reverse order: a map loaded upside down.
vtkSmartPointer<vtkImageData> FlippedRows(vtkImageData* image)
{
  auto flipped = vtkSmartPointer<vtkImageData>::New();
  flipped->DeepCopy(image);
  vtkDataArray* in = image->GetPointData()->GetScalars();
  vtkDataArray* out = flipped->GetPointData()->GetScalars();
  for (int j = 0; j < TextureSize; ++j)
  {
    for (int i = 0; i < TextureSize; ++i)
    {
      out->SetTuple(j * TextureSize + i, in->GetTuple((TextureSize - 1 - j) * TextureSize + i));
    }
  }
  return flipped;
}

vtkSmartPointer<vtkTexture> MakeTexture(vtkImageData* image)
{
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->RepeatOn();
  return texture;
}

// The mean length on the surface of a unit of texture coordinate, over both directions.
double MeanTextureSide(vtkParametricSurfaceSource* source)
{
  vtkNew<vtkParametricSurfaceSource> copy;
  copy->SetParametricFunction(source->GetParametricFunction());
  copy->SetUResolution(source->GetUResolution());
  copy->SetVResolution(source->GetVResolution());
  copy->GenerateDerivativesOn();
  copy->Update();
  vtkDataArray* dPdu = copy->GetOutput()->GetPointData()->GetArray("dPdu");
  vtkDataArray* dPdv = copy->GetOutput()->GetPointData()->GetArray("dPdv");
  double sum = 0;
  for (vtkIdType id = 0; id < dPdu->GetNumberOfTuples(); ++id)
  {
    sum += vtkMath::Norm(dPdu->GetTuple3(id)) / source->GetTextureRepeat()[0] +
      vtkMath::Norm(dPdv->GetTuple3(id)) / source->GetTextureRepeat()[1];
  }
  return sum / (2.0 * dPdu->GetNumberOfTuples());
}

const char* Arg(int argc, char* argv[], const char* name, const char* fallback)
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::strcmp(argv[i], name) == 0)
    {
      return argv[i + 1];
    }
  }
  return fallback;
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string technique = Arg(argc, argv, "--technique", "normal");
  const std::string surface = Arg(argc, argv, "--surface", "rectangle");
  const std::string view = Arg(argc, argv, "--view", "head-on");
  const std::string lightName = Arg(argc, argv, "--light", "headlight");
  const std::string mutation = Arg(argc, argv, "--mutation", "none");
  const std::string cones = Arg(argc, argv, "--cones", "off");
  if (mutation != "none" && mutation != "light-10" && mutation != "flipped-maps" &&
    mutation != "half-scale" && mutation != "flipped-handedness")
  {
    std::cerr << "unknown mutation " << mutation << "\n";
    return 1;
  }
  if (cones != "off" && cones != "on")
  {
    std::cerr << "--cones is off or on, not " << cones << "\n";
    return 1;
  }

  vtkNew<vtkParametricSurfaceSource> source;
  source->SetUResolution(64);
  source->SetVResolution(64);
  source->GenerateTangentsOn();
  double depth = 0.03;     // parallax depth, object units
  double strength = 0.012; // z = k*h over the unit texture square
  if (surface == "rectangle")
  {
    vtkNew<vtkParametricRectangle> f; // seed 004's wall: x in [-2,2], y in [0,3.5]
    source->SetParametricFunction(f);
    source->SetTextureRepeat(2, 2);
    depth = 0.08;
  }
  else if (surface == "sphere")
  {
    vtkNew<vtkParametricSphere> f;
    source->SetParametricFunction(f);
    source->SetTextureRepeat(4, 2);
  }
  else if (surface == "torus")
  {
    vtkNew<vtkParametricDonut> f;
    source->SetParametricFunction(f);
    source->SetTextureRepeat(6, 2);
    source->SetUResolution(96);
    strength = 0.008;
    depth = 0.02;
  }
  else if (surface == "vase")
  {
    vtkNew<vtkParametricRevolution> f;
    source->SetParametricFunction(f);
    source->SetTextureRepeat(4, 3);
  }
  else
  {
    std::cerr << "unknown surface " << surface << "\n";
    return 1;
  }
  source->Update();
  if (mutation == "flipped-handedness")
  {
    vtkDataArray* w = vtkSurfaceDetailTangents::GetHandedness(source->GetOutput()->GetPointData());
    for (vtkIdType id = 0; id < w->GetNumberOfTuples(); ++id)
    {
      w->SetComponent(id, 0, -w->GetComponent(id, 0));
    }
  }
  if (mutation == "half-scale")
  {
    depth *= 0.5;
    strength *= 0.5;
  }

  auto heights = BrickTextures::Heights();
  vtkNew<vtkHeightMapToNormalMap> toNormals;
  toNormals->SetInputData(heights);
  toNormals->SetBumpScale(strength);
  toNormals->SetDifferenceSchemeToCentral();
  toNormals->SetWrap(vtkHeightMapToNormalMap::Repeat);
  toNormals->Update();

  vtkNew<vtkSurfaceDetailMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  const bool flip = mutation == "flipped-maps";
  vtkSmartPointer<vtkImageData> normalMap = toNormals->GetOutput();
  mapper->SetNormalMap(MakeTexture(flip ? FlippedRows(normalMap) : normalMap));
  mapper->SetHeightMap(MakeTexture(flip ? FlippedRows(heights) : heights));
  mapper->SetBumpScale(strength);
  mapper->SetDifferenceSchemeToCentral();
  mapper->SetDepthScale(depth);
  if (technique == "normal")
  {
    mapper->SetTechniqueToNormalMapping();
  }
  else if (technique == "bump" || technique == "bump-tangent-free")
  {
    mapper->SetTechniqueToBumpMapping();
    mapper->SetTangentFree(technique == "bump-tangent-free");
  }
  else if (technique == "parallax")
  {
    mapper->SetTechniqueToParallaxMapping();
  }
  else if (technique == "relief" || technique == "relief-shadow")
  {
    mapper->SetTechniqueToReliefMapping();
    mapper->SetNormalMap(nullptr);
    mapper->SetSelfShadowing(technique == "relief-shadow");
  }
  else if (technique == "relief-map")
  {
    // The normal map of the relief itself: its strength is the depth over the texture
    // square's size on the surface (on average: the sides differ from place to place).
    vtkNew<vtkHeightMapToNormalMap> toRelief;
    toRelief->SetInputData(flip ? FlippedRows(heights) : heights);
    toRelief->SetBumpScale(depth / MeanTextureSide(source));
    toRelief->SetDifferenceSchemeToCentral();
    toRelief->SetWrap(vtkHeightMapToNormalMap::Repeat);
    toRelief->OutputReliefOn();
    toRelief->Update();
    mapper->SetTechniqueToReliefMapping();
    mapper->SetReliefMap(MakeTexture(toRelief->GetOutput()));
    mapper->SetSelfShadowing(true);
  }
  else if (technique != "none")
  {
    std::cerr << "unknown technique " << technique << "\n";
    return 1;
  }
  if (cones == "on")
  {
    vtkNew<vtkHeightMapToConeMap> toCones;
    toCones->SetInputData(flip ? FlippedRows(heights) : heights);
    toCones->Update();
    mapper->SetConeMap(MakeTexture(toCones->GetOutput()));
  }

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(MakeTexture(BrickTextures::Colours()));
  actor->GetProperty()->SetAmbient(0.15);
  actor->GetProperty()->SetDiffuse(0.85);
  actor->GetProperty()->SetSpecular(0.25);
  actor->GetProperty()->SetSpecularPower(30);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.18, 0.2, 0.24);
  renderer->ResetCamera();
  vtkCamera* camera = renderer->GetActiveCamera();
  if (surface == "torus")
  {
    camera->Elevation(-55); // the donut is z up: look at it from the side, a little above
    camera->OrthogonalizeViewUp();
  }
  if (view == "oblique")
  {
    camera->Azimuth(40);
    camera->Elevation(20);
    camera->OrthogonalizeViewUp();
  }
  else if (view == "grazing")
  {
    camera->Elevation(-80); // from below, 80 degrees from the wall's normal at its centre
    camera->OrthogonalizeViewUp();
  }
  if (lightName == "lightkit")
  {
    renderer->AutomaticLightCreationOff();
    vtkNew<vtkLightKit> kit; // key light upper left, fill, back lights and headlight
    kit->AddLightsToRenderer(renderer);
  }
  if (lightName == "positional" || lightName == "spot" || lightName == "raking")
  {
    // A point light above, right of and in front of the object as the camera sees it, at
    // twice the object's size: the lit side of every brick faces up and to the right.
    renderer->AutomaticLightCreationOff();
    double bounds[6], centre[3], right[3], up[3], front[3];
    source->GetOutput()->GetBounds(bounds);
    const double size = std::sqrt(std::pow(bounds[1] - bounds[0], 2) +
      std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
    camera->GetViewUp(up);
    camera->GetDirectionOfProjection(front);
    vtkMath::Cross(front, up, right);
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->PositionalOn();
    // The spot's cone (8 degrees, fall-off exponent 4) lights a disc in the middle.
    light->SetConeAngle(lightName == "spot" ? 8 : 180);
    light->SetExponent(4);
    double position[3];
    // The raking light comes from far to the right and above, about 60 degrees from the
    // view, so that a relief's shadows are long even head-on.
    const double side = lightName == "raking" ? 1.5 : 0.5;
    const double back = lightName == "raking" ? 0.7 : 1.5;
    for (int k = 0; k < 3; ++k)
    {
      centre[k] = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
      position[k] = centre[k] + size * (side * right[k] + 0.5 * up[k] - back * front[k]);
    }
    if (mutation == "light-10")
    {
      // The light turned by 10 degrees about the camera's up axis through the centre.
      const double angle = vtkMath::RadiansFromDegrees(10.0);
      double offset[3], rotated[3], across[3];
      for (int k = 0; k < 3; ++k)
      {
        offset[k] = position[k] - centre[k];
      }
      vtkMath::Cross(up, offset, across);
      const double along = vtkMath::Dot(up, offset);
      for (int k = 0; k < 3; ++k)
      {
        rotated[k] = std::cos(angle) * offset[k] + std::sin(angle) * across[k] +
          (1 - std::cos(angle)) * along * up[k];
        position[k] = centre[k] + rotated[k];
      }
    }
    light->SetPosition(position);
    light->SetFocalPoint(centre);
    renderer->AddLight(light);
  }
  renderer->ResetCamera();
  camera->Zoom(surface == "rectangle" && view != "oblique" ? 1.6 : 1.3);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  window->Render();

  const int result = SurfaceDetailImageComparison::RegressionTest(argc, argv, window);
  if (result == SurfaceDetailImageComparison::Interact)
  {
    // Only on request (-I): an interactor opens one more X connection per test.
    vtkNew<vtkRenderWindowInteractor> interactor;
    interactor->SetRenderWindow(window);
    interactor->Start();
  }
  return !result;
}
