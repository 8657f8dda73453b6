// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Frame-time harness: vtkSurfaceDetailMapper (each technique, relief at several settings)
// against VTK's plain vtkOpenGLPolyDataMapper, the same textured surface filling the window.
// All variants are actors of one renderer, shown one at a time and interleaved frame by
// frame (round robin), so that the load of a shared machine falls on all of them alike;
// each frame is Render + WaitForCompletion (the GPU work is inside the timing). Shaders,
// buffers and textures are made in warm-up frames before timing starts. Prints the median
// frame time of each variant and its ratio to the plain mapper as a Markdown table, and for
// the relief variants the image error (RMSE in 8-bit levels over the surface's pixels)
// against relief with 256 linear and 16 binary steps, so that settings compare at equal
// error.
// Usage: SurfaceDetailMapperFrameTimes [rounds] [--size N] [--scene sphere|wall|caps|triplanar]
//   rounds: default 60. --size: the window's side, default 1024 (a real GPU needs 4096 for
//   the surface shading to outweigh a frame's fixed cost). --scene: a sphere filling most of
//   the window (default), a wall seen head-on filling all of it, a wall with a 4 x 4 grid of
//   round caps on a 1024 x 1024 height map seen obliquely (where rays cross many texels), or
//   the sphere without texture coordinates mapped triplanar (colour, colour + normal map,
//   bump) at several blend sharpnesses, with the share of its pixels that read one, two or
//   three projections. Relief runs with the linear and binary search and with cone stepping
//   (the heights' cone map, made before the frames: its build time is printed).

#include "RoundCaps.h"
#include "SurfaceDetailTruthScenes.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailMapper.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkHeightMapToConeMap.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

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
  return SurfaceDetailTruthScenes::RepeatedTexture(image);
}

struct Variant
{
  const char* Name;
  int Technique; // -1: the plain vtkOpenGLPolyDataMapper
  bool TangentFree = false;
  int LinearSteps = 32; // relief only
  bool Adaptive = true;
  int BinarySteps = 8;
  bool Shadows = false;
  bool DepthCorrection = false;
  double TriplanarSharpness = 0.0; // 0: texture coordinates; else triplanar, this sharpness
  int Cones = 0; // relief by cone stepping: Relaxed + 1 or Conservative + 1 (its cone type)
};

// The heights' cone map, and how long it took to make.
vtkSmartPointer<vtkTexture> ConeTexture(vtkImageData* heights, int type, double& seconds)
{
  const auto start = std::chrono::steady_clock::now();
  vtkNew<vtkHeightMapToConeMap> cones;
  cones->SetInputData(heights);
  cones->SetConeType(type);
  cones->Update();
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return SurfaceDetailTruthScenes::RepeatedTexture(cones->GetOutput());
}

// Texture squares per unit when the sphere is mapped triplanar: about the size of the texture
// squares its texture coordinates give it.
constexpr double TriplanarScale = 0.7;

// The height map's relief map: normals of the relief DepthScale deep on a texture square
// about as large as the scene's, depth in alpha.
vtkSmartPointer<vtkTexture> ReliefTexture(vtkImageData* heights, double depth, double textureSide)
{
  vtkNew<vtkHeightMapToNormalMap> relief;
  relief->SetInputData(heights);
  relief->SetBumpScale(depth / textureSide);
  relief->OutputReliefOn();
  relief->Update();
  return SurfaceDetailTruthScenes::RepeatedTexture(relief->GetOutput());
}

vtkSmartPointer<vtkActor> MakeActor(vtkAlgorithmOutput* surface, const Variant& variant,
  vtkTexture* relief, vtkTexture* const cones[2], double depth)
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
    detail->SetReliefMap(relief);
    detail->SetConeMap(variant.Cones ? cones[variant.Cones - 1] : nullptr);
    detail->SetDepthScale(depth);
    detail->SetLinearSearchSteps(variant.LinearSteps);
    detail->SetAdaptiveSteps(variant.Adaptive);
    detail->SetBinarySearchSteps(variant.BinarySteps);
    detail->SetSelfShadowing(variant.Shadows);
    detail->SetDepthCorrection(variant.DepthCorrection);
    detail->SetTriplanar(variant.TriplanarSharpness > 0.0);
    detail->SetTriplanarSharpness(std::max(variant.TriplanarSharpness, 1.0));
    detail->SetTriplanarScale(TriplanarScale);
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

// RMSE (levels) over the pixels where either image differs from the background pixel.
double SurfaceRMSE(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  double sum = 0;
  size_t count = 0;
  for (size_t p = 0; p + 2 < a.size(); p += 3)
  {
    const bool background =
      std::equal(&a[p], &a[p] + 3, &a[0]) && std::equal(&b[p], &b[p] + 3, &a[0]);
    if (background)
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const double d = a[p + c] - b[p + c];
      sum += d * d;
    }
    ++count;
  }
  return count ? std::sqrt(sum / (3.0 * count)) : 0.0;
}

// The share of a sphere's pixels (seen along any axis: a sphere looks the same from all)
// whose blend reads one, two or three projections, for the sharpnesses timed.
void PrintProjectionShares()
{
  std::printf("\n| sharpness | pixels reading 1 projection | 2 | 3 |\n|---|---:|---:|---:|\n");
  for (const double sharpness : { 1.0, 4.0, 16.0 })
  {
    double share[3] = { 0, 0, 0 }, total = 0;
    constexpr int n = 400;
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double x = -1 + 2 * (i + 0.5) / n, y = -1 + 2 * (j + 0.5) / n;
        if (x * x + y * y >= 1)
        {
          continue;
        }
        const double normal[3] = { x, y, std::sqrt(1 - x * x - y * y) };
        double w[3];
        vtkSurfaceDetail::TriplanarWeights(normal, sharpness, w);
        const int read = (w[0] > 0) + (w[1] > 0) + (w[2] > 0);
        share[read - 1] += 1;
        total += 1;
      }
    }
    std::printf("| %g | %.0f%% | %.0f%% | %.0f%% |\n", sharpness, 100 * share[0] / total,
      100 * share[1] / total, 100 * share[2] / total);
  }
}

const char* Option(int argc, char* argv[], const char* name, const char* fallback)
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
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
    {
      std::cout
        << "Usage: SurfaceDetailMapperFrameTimes [rounds] [--size N] [--scene sphere|wall|caps|triplanar]\n\n"
           "Median frame time of each vtkSurfaceDetailMapper technique against VTK's plain\n"
           "mapper, and relief's image error against a reference, as a Markdown table.\n"
           "rounds: default 60; --size: the window's side, default 1024; --scene: a sphere\n"
           "filling most of the window (default), a wall seen head-on, a wall of round caps\n"
           "seen obliquely, or the sphere mapped triplanar (no texture coordinates) at several\n"
           "blend sharpnesses.\n";
      return 0;
    }
  }
  const int rounds = argc > 1 && argv[1][0] != '-' ? std::max(1, std::atoi(argv[1])) : 60;
  const int size = std::max(64, std::atoi(Option(argc, argv, "--size", "1024")));
  const std::string scene = Option(argc, argv, "--scene", "sphere");
  using SDM = vtkSurfaceDetailMapper;
  const int relief = SDM::ReliefMapping;
  const std::vector<Variant> triplanarVariants = {
    { "vtkOpenGLPolyDataMapper (plain, colour by texture coordinates)", -1 },
    { "NormalMapping by texture coordinates", SDM::NormalMapping },
    { "Triplanar colour, sharpness 4", SDM::Plain, false, 32, true, 8, false, false, 4.0 },
    { "Triplanar colour + NormalMapping, sharpness 1", SDM::NormalMapping, false, 32, true, 8,
      false, false, 1.0 },
    { "Triplanar colour + NormalMapping, sharpness 4", SDM::NormalMapping, false, 32, true, 8,
      false, false, 4.0 },
    { "Triplanar colour + NormalMapping, sharpness 16", SDM::NormalMapping, false, 32, true, 8,
      false, false, 16.0 },
    { "Triplanar colour + BumpMapping, sharpness 4", SDM::BumpMapping, false, 32, true, 8, false,
      false, 4.0 },
  };
  const int relaxed = vtkHeightMapToConeMap::Relaxed + 1;
  const int conservative = vtkHeightMapToConeMap::Conservative + 1;
  const std::vector<Variant> detailVariants = {
    { "vtkOpenGLPolyDataMapper (plain)", -1 },
    { "Plain", SDM::Plain },
    { "NormalMapping", SDM::NormalMapping },
    { "BumpMapping", SDM::BumpMapping },
    { "BumpMapping, TangentFree", SDM::BumpMapping, true },
    { "ParallaxMapping", SDM::ParallaxMapping },
    { "ReliefMapping (default: adaptive, at most 32 + 8)", relief },
    // One linear step and no binary search: what relief costs besides its search.
    { "ReliefMapping, fixed 1 + 0", relief, false, 1, false, 0 },
    { "ReliefMapping, fixed 8 + 8", relief, false, 8, false },
    { "ReliefMapping, fixed 16 + 8", relief, false, 16, false },
    { "ReliefMapping, fixed 32 + 8", relief, false, 32, false },
    { "ReliefMapping, SelfShadowing", relief, false, 32, true, 8, true },
    { "ReliefMapping, DepthCorrection", relief, false, 32, true, 8, false, true },
    { "ReliefMapping, cone stepping", relief, false, 32, true, 8, false, false, 0.0, relaxed },
    { "ReliefMapping, cone stepping, conservative cones", relief, false, 32, true, 8, false,
      false, 0.0, conservative },
    { "ReliefMapping, cone stepping, SelfShadowing", relief, false, 32, true, 8, true, false, 0.0,
      relaxed },
    { "ReliefMapping, reference 256 + 16", relief, false, 256, false, 16 },
  };
  const std::vector<Variant>& variants = scene == "triplanar" ? triplanarVariants : detailVariants;
  const size_t reference = variants.size() - 1;

  vtkNew<vtkParametricSurfaceSource> source;
  vtkNew<vtkParametricSphere> sphere;
  vtkNew<vtkParametricRectangle> wall; // 4 x 3.5
  double textureSide = 0.0, depth = 0.0;
  vtkSmartPointer<vtkImageData> heights = Texture(1, true)->GetInput();
  if (scene == "caps")
  {
    source->SetParametricFunction(wall);
    source->SetUResolution(16);
    source->SetVResolution(16);
    textureSide = 3.75;
    depth = 0.3;
    heights = RoundCaps(1024);
  }
  else if (scene == "wall")
  {
    source->SetParametricFunction(wall);
    source->SetUResolution(16);
    source->SetVResolution(16);
    source->SetTextureRepeat(4, 4);
    textureSide = 0.94;
    depth = 0.08;
  }
  else
  {
    source->SetParametricFunction(sphere);
    source->SetUResolution(128);
    source->SetVResolution(64);
    source->SetTextureRepeat(4, 2);
    textureSide = 1.4;
    depth = 0.05;
  }
  source->GenerateTangentsOn();
  vtkSmartPointer<vtkTexture> reliefMap = ReliefTexture(heights, depth, textureSide);
  double coneSeconds[2] = { 0.0, 0.0 };
  vtkSmartPointer<vtkTexture> coneMaps[2];
  for (int type : { vtkHeightMapToConeMap::Conservative, vtkHeightMapToConeMap::Relaxed })
  {
    coneMaps[type] = scene == "triplanar" ? nullptr : ConeTexture(heights, type, coneSeconds[type]);
  }
  vtkTexture* const cones[2] = { coneMaps[0], coneMaps[1] };
  // Triplanar variants draw the same sphere without texture coordinates (with them, VTK
  // itself would apply the colour texture by them).
  vtkNew<vtkParametricSurfaceSource> bare;
  bare->SetParametricFunction(sphere);
  bare->SetUResolution(128);
  bare->SetVResolution(64);
  bare->GenerateTextureCoordinatesOff();

  vtkNew<vtkRenderer> renderer;
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (const auto& variant : variants)
  {
    vtkAlgorithmOutput* surface =
      variant.TriplanarSharpness > 0.0 ? bare->GetOutputPort() : source->GetOutputPort();
    actors.push_back(MakeActor(surface, variant, reliefMap, cones, depth));
    renderer->AddActor(actors.back());
  }
  renderer->ResetCamera();
  // The sphere covers most of the window; the wall all of it; the caps are seen at 30 degrees
  // above the wall's plane.
  if (scene == "caps")
  {
    renderer->GetActiveCamera()->Elevation(-60);
    renderer->GetActiveCamera()->OrthogonalizeViewUp();
  }
  renderer->GetActiveCamera()->Zoom(scene == "wall" ? 2.2 : (scene == "caps" ? 2.0 : 1.4));
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(size, size);
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
  frame(reference);
  const std::vector<unsigned char> best = SurfaceDetailTruthScenes::GrabRGB(window);
  std::printf("| Variant | median frame (ms) | quartiles (ms) | ratio to plain | relief RMSE |\n");
  std::printf("|---|---|---|---|---|\n");
  for (size_t k = 0; k < variants.size(); ++k)
  {
    const double median = quantile(times[k], 0.5);
    std::printf("| %s | %.1f | %.1f - %.1f | %.3f |", variants[k].Name, median,
      quantile(times[k], 0.25), quantile(times[k], 0.75), median / plain);
    if (variants[k].Technique == relief && !variants[k].Shadows && k != reference)
    {
      frame(k);
      std::printf(" %.2f |\n", SurfaceRMSE(SurfaceDetailTruthScenes::GrabRGB(window), best));
    }
    else
    {
      std::printf("  |\n");
    }
  }
  std::printf(
    "\n%d interleaved frames per variant, %dx%d, scene %s\n", rounds, size, size, scene.c_str());
  if (cones[0])
  {
    int dims[3];
    heights->GetDimensions(dims);
    std::printf("cone maps of the %dx%d heights made in %.2f s (relaxed), %.2f s (conservative)\n",
      dims[0], dims[1], coneSeconds[vtkHeightMapToConeMap::Relaxed],
      coneSeconds[vtkHeightMapToConeMap::Conservative]);
  }
  if (scene == "triplanar")
  {
    PrintProjectionShares();
  }
  return 0;
}
