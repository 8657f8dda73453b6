// Frame time of vtkSurfaceDetailMapper against VTK's plain vtkOpenGLPolyDataMapper, in one
// run: the same brick-textured sphere filling a 1024x1024 window, one frame per iteration
// (Render + WaitForCompletion, so that the GPU work is inside the timing). The scene is
// built and warmed up (shaders compiled, textures uploaded) before timing starts.
// Run under a virtual X server; BENCHMARKS.md gives the command.

#include "vtkSurfaceDetailMapper.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <benchmark/benchmark.h>

#include <cmath>

namespace
{
constexpr int Size = 256;

vtkSmartPointer<vtkTexture> Texture(int comps, bool asFloat)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(Size, Size, 1);
  image->AllocateScalars(asFloat ? VTK_FLOAT : VTK_UNSIGNED_CHAR, comps);
  for (int j = 0; j < Size; ++j)
  {
    for (int i = 0; i < Size; ++i)
    {
      const double s = (i + 0.5) / Size, t = (j + 0.5) / Size;
      const double h = 0.5 + 0.25 * std::sin(12.566 * s) * std::sin(12.566 * t);
      for (int c = 0; c < comps; ++c)
      {
        const double v = comps == 1 ? h : (c == 2 ? 1.0 : 0.5 + 0.2 * std::cos(6.28 * (c ? t : s)));
        if (asFloat)
        {
          static_cast<float*>(image->GetScalarPointer(i, j, 0))[c] = static_cast<float>(v);
        }
        else
        {
          static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0))[c] =
            static_cast<unsigned char>(255 * v);
        }
      }
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->RepeatOn();
  return texture;
}

enum Variant
{
  Plain = -1,
  None = vtkSurfaceDetailMapper::None,
  Normal = vtkSurfaceDetailMapper::NormalMapping,
  Bump = vtkSurfaceDetailMapper::BumpMapping,
  Parallax = vtkSurfaceDetailMapper::ParallaxMapping,
  BumpTangentFree = 100
};

void BM_Frame(benchmark::State& state, int variant)
{
  vtkNew<vtkParametricSurfaceSource> source;
  vtkNew<vtkParametricSphere> sphere;
  source->SetParametricFunction(sphere);
  source->SetUResolution(128);
  source->SetVResolution(64);
  source->GenerateTangentsOn();
  source->SetTextureRepeat(4, 2);

  vtkSmartPointer<vtkOpenGLPolyDataMapper> mapper;
  if (variant == Plain)
  {
    mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
  }
  else
  {
    auto detail = vtkSmartPointer<vtkSurfaceDetailMapper>::New();
    detail->SetNormalMap(Texture(3, false));
    detail->SetHeightMap(Texture(1, true));
    detail->SetBumpScale(0.05);
    detail->SetTechnique(variant == BumpTangentFree ? int(Bump) : variant);
    detail->SetTangentFree(variant == BumpTangentFree);
    mapper = detail;
  }
  mapper->SetInputConnection(source->GetOutputPort());

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(Texture(3, false));
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(20);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.4); // the sphere covers most of the window
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(1024, 1024);
  window->AddRenderer(renderer);
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  for (int i = 0; i < 3; ++i)
  {
    window->Render();
    glWindow->WaitForCompletion();
  }
  for (auto _ : state)
  {
    window->Render();
    glWindow->WaitForCompletion();
  }
}
} // namespace

BENCHMARK_CAPTURE(BM_Frame, PlainOpenGLPolyDataMapper, int(Plain))
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK_CAPTURE(BM_Frame, None, int(None))->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Frame, NormalMapping, int(Normal))
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK_CAPTURE(BM_Frame, BumpMapping, int(Bump))->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Frame, BumpMappingTangentFree, int(BumpTangentFree))
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK_CAPTURE(BM_Frame, ParallaxMapping, int(Parallax))
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();

BENCHMARK_MAIN();
