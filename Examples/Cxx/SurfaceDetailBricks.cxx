// Seed 000's surface detail on seed 004's brick wall: the same flat wall (two triangles'
// worth of detail, no displaced geometry) drawn four ways side by side, lit by a point light
// from the upper right: plain texture, normal mapping, bump mapping and parallax mapping.
// Usage: SurfaceDetailBricks <output folder>   (writes SurfaceDetailBricks.png there)

#include <vtkSurfaceDetailMapper.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace
{
constexpr int N = 512;

// Running bond: 4 courses of 2 bricks per texture square, alternate courses offset by half
// a brick. Returns the distance to the nearest joint (texture units) and the brick's index.
double JointDistance(double s, double t, int& brick)
{
  const double row = std::floor(t * 4);
  const double x = (s + (static_cast<int>(row) % 2 ? 0.25 : 0.0)) * 2;
  const double col = std::floor(x);
  brick = static_cast<int>(row * 5 + std::fmod(col, 2.0));
  const double dx = std::min(x - col, 1 - (x - col)) / 2;
  const double dy = std::min(t * 4 - row, 1 - (t * 4 - row)) / 4;
  return std::min(dx, dy);
}

void MakeBricks(vtkImageData* heights, vtkImageData* colours)
{
  heights->SetDimensions(N, N, 1);
  heights->AllocateScalars(VTK_FLOAT, 1);
  colours->SetDimensions(N, N, 1);
  colours->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* h = static_cast<float*>(heights->GetScalarPointer());
  auto* rgb = static_cast<unsigned char*>(colours->GetScalarPointer());
  for (int j = 0; j < N; ++j)
  {
    for (int i = 0; i < N; ++i)
    {
      const double s = (i + 0.5) / N, t = (j + 0.5) / N;
      int brick;
      const double d = JointDistance(s, t, brick);
      double x = std::min(1.0, std::max(0.0, (d - 0.008) / 0.02));
      x = x * x * (3 - 2 * x); // bricks at 1 with a rounded bevel down to the joints at 0
      // A little roughness on the brick faces, so the light has something to catch.
      const double grain = 0.04 * std::sin(97 * s + 13 * brick) * std::sin(61 * t + 7 * brick);
      h[j * N + i] = static_cast<float>(x * (0.96 + grain));
      const double shade = 0.85 + 0.15 * std::sin(brick * 2.3);
      const double brickRGB[3] = { 0.70 * shade, 0.30 * shade, 0.20 * shade };
      const double mortar[3] = { 0.80, 0.78, 0.72 };
      for (int c = 0; c < 3; ++c)
      {
        rgb[3 * (j * N + i) + c] =
          static_cast<unsigned char>(255 * (x * brickRGB[c] + (1 - x) * mortar[c]) + 0.5);
      }
    }
  }
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";

  // Seed 004's wall, x in [-2,2], y in [0,3.5], tangents with handedness for the maps.
  vtkNew<vtkParametricRectangle> wall;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(wall);
  source->SetUResolution(8);
  source->SetVResolution(8);
  source->GenerateTangentsOn();
  source->SetTextureRepeat(2, 2);

  vtkNew<vtkImageData> heights;
  vtkNew<vtkImageData> colours;
  MakeBricks(heights, colours);
  constexpr double strength = 0.012; // bumps of z = 0.012*h over a texture square
  vtkNew<vtkHeightMapToNormalMap> normals;
  normals->SetInputData(heights);
  normals->SetStrength(strength);
  normals->Update();

  vtkNew<vtkTexture> colourTexture;
  colourTexture->SetInputData(colours);
  vtkNew<vtkTexture> normalTexture;
  normalTexture->SetInputConnection(normals->GetOutputPort());
  vtkNew<vtkTexture> heightTexture;
  heightTexture->SetInputData(heights);
  for (vtkTexture* texture : { colourTexture.Get(), normalTexture.Get(), heightTexture.Get() })
  {
    texture->InterpolateOn();
    texture->RepeatOn();
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(1600, 460);
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  const int techniques[4] = { vtkSurfaceDetailMapper::None, vtkSurfaceDetailMapper::NormalMapping,
    vtkSurfaceDetailMapper::BumpMapping, vtkSurfaceDetailMapper::ParallaxMapping };
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkSurfaceDetailMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    mapper->SetTechnique(techniques[k]);
    mapper->SetNormalMap(normalTexture);
    mapper->SetHeightMap(heightTexture);
    mapper->SetBumpScale(strength);
    mapper->SetDepthScale(0.1); // the joints lie 0.1 units behind the faces
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(colourTexture);
    actor->GetProperty()->SetAmbient(0.12);
    actor->GetProperty()->SetDiffuse(0.9);
    actor->GetProperty()->SetSpecular(0.2);
    actor->GetProperty()->SetSpecularPower(25);

    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(k / 4.0, 0, (k + 1) / 4.0, 1);
    renderer->SetBackground(0.16, 0.18, 0.22);
    renderer->AddActor(actor);
    renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> light; // upper right, in front of the wall
    light->SetLightTypeToSceneLight();
    light->PositionalOn();
    light->SetConeAngle(180);
    light->SetPosition(3.5, 5.0, 4.0);
    light->SetFocalPoint(0, 1.75, 0);
    renderer->AddLight(light);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.3, 1.6, 0);
    camera->SetPosition(3.4, 2.6, 4.4);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(40);
    renderer->ResetCameraClippingRange();

    vtkNew<vtkTextActor> label;
    label->SetInput(vtkSurfaceDetailMapper::GetTechniqueAsString(techniques[k]));
    label->GetTextProperty()->SetFontSize(22);
    label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    label->GetPositionCoordinate()->SetValue(0.04, 0.04);
    renderer->AddViewProp(label);
    window->AddRenderer(renderer);
  }
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName((folder + "/SurfaceDetailBricks.png").c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  std::cout << "wrote " << folder << "/SurfaceDetailBricks.png\n";
  return 0;
}
