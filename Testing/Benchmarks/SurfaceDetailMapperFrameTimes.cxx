// Frame-time harness: vtkSurfaceDetailMapper (each technique) against VTK's plain
// vtkOpenGLPolyDataMapper, the same brick-textured sphere filling a 1024x1024 window.
// All variants are actors of one renderer, shown one at a time and interleaved frame by
// frame (round robin), so that the load of a shared machine falls on all of them alike;
// each frame is Render + WaitForCompletion (the GPU work is inside the timing). Shaders,
// buffers and textures are made in warm-up frames before timing starts. Prints the median
// frame time of each variant and its ratio to the plain mapper as a Markdown table.
// Usage: SurfaceDetailMapperFrameTimes [rounds]   (default 60; BENCHMARKS.md has the command)

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

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

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

struct Variant
{
  const char* Name;
  int Technique; // -1: the plain vtkOpenGLPolyDataMapper
  bool TangentFree;
};

vtkSmartPointer<vtkActor> MakeActor(vtkAlgorithmOutput* surface, const Variant& variant)
{
  vtkSmartPointer<vtkOpenGLPolyDataMapper> mapper;
  if (variant.Technique < 0)
  {
    mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
  }
  else
  {
    auto detail = vtkSmartPointer<vtkSurfaceDetailMapper>::New();
    detail->SetNormalMap(Texture(3, false));
    detail->SetHeightMap(Texture(1, true));
    detail->SetBumpScale(0.05);
    detail->SetTechnique(variant.Technique);
    detail->SetTangentFree(variant.TangentFree);
    mapper = detail;
  }
  mapper->SetInputConnection(surface);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetTexture(Texture(3, false));
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(20);
  return actor;
}
} // namespace

int main(int argc, char* argv[])
{
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 60;
  const std::vector<Variant> variants = {
    { "vtkOpenGLPolyDataMapper (plain)", -1, false },
    { "None", vtkSurfaceDetailMapper::None, false },
    { "NormalMapping", vtkSurfaceDetailMapper::NormalMapping, false },
    { "BumpMapping", vtkSurfaceDetailMapper::BumpMapping, false },
    { "BumpMapping, TangentFree", vtkSurfaceDetailMapper::BumpMapping, true },
    { "ParallaxMapping", vtkSurfaceDetailMapper::ParallaxMapping, false },
  };

  vtkNew<vtkParametricSurfaceSource> source;
  vtkNew<vtkParametricSphere> sphere;
  source->SetParametricFunction(sphere);
  source->SetUResolution(128);
  source->SetVResolution(64);
  source->GenerateTangentsOn();
  source->SetTextureRepeat(4, 2);

  vtkNew<vtkRenderer> renderer;
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (const auto& variant : variants)
  {
    actors.push_back(MakeActor(source->GetOutputPort(), variant));
    renderer->AddActor(actors.back());
  }
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.4); // the sphere covers most of the window
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(1024, 1024);
  window->AddRenderer(renderer);
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);

  auto frame = [&](size_t shown)
  {
    for (size_t k = 0; k < actors.size(); ++k)
    {
      actors[k]->SetVisibility(k == shown);
    }
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    glWindow->WaitForCompletion();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
  };
  for (int warmup = 0; warmup < 3; ++warmup)
  {
    for (size_t k = 0; k < variants.size(); ++k)
    {
      frame(k);
    }
  }
  std::vector<std::vector<double>> times(variants.size());
  for (int r = 0; r < rounds; ++r)
  {
    for (size_t k = 0; k < variants.size(); ++k)
    {
      times[k].push_back(frame(k));
    }
  }

  auto quantile = [](std::vector<double> v, double q)
  {
    std::sort(v.begin(), v.end());
    return v[static_cast<size_t>(q * (v.size() - 1) + 0.5)];
  };
  const double plain = quantile(times[0], 0.5);
  std::printf("| Variant | median frame (ms) | quartiles (ms) | ratio to plain |\n");
  std::printf("|---|---|---|---|\n");
  for (size_t k = 0; k < variants.size(); ++k)
  {
    const double median = quantile(times[k], 0.5);
    std::printf("| %s | %.1f | %.1f - %.1f | %.3f |\n", variants[k].Name, median,
      quantile(times[k], 0.25), quantile(times[k], 0.75), median / plain);
  }
  std::printf("\n%d interleaved frames per variant, 1024x1024\n", rounds);
  return 0;
}
