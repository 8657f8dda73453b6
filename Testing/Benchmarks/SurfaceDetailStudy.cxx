// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Run time against error for every way of showing surface detail, scene by scene.
//
// Each scene (a brick wall head-on and at 70 degrees, a bumpy sphere, a torus with sharp
// bricks) has a ground truth: the surface displaced by vtkDisplacementMapFilter (Scale =
// depth, Midlevel 1, Exact normals) on a dense mesh, drawn by VTK's plain mapper; the same
// truth at twice the resolution shows how far it is from converged. Against it every
// technique at several settings: displaced meshes (resolutions x NormalModes), normal mapping
// from the height map and baked (vtkNormalMapBaker) from a displaced mesh at half the truth's
// resolution, bump mapping (forward, central, tangent free), parallax, relief
// mapping at several (linear, binary) step pairs and by cone stepping, with and without
// self-shadowing, and the coarse mesh with no detail at all. For each: median frame time, first frame, CPU
// preparation (the filters that make its mesh and maps; the height map and the detailed mesh
// a map is baked from are inputs, not preparation), memory of its mesh and detail
// textures, and the image error over the object's pixels (RMSE, PSNR, SSIM).
//
// Frame times: every variant of a scene is an actor of one renderer, shown one at a time and
// interleaved frame by frame, so that a shared machine's load falls on all alike; each frame
// is Render + WaitForCompletion. Then the CPU filter studies run (SurfaceDetailStudyFilters).
//
// Usage: SurfaceDetailStudy --out <folder> [--rounds N] [--size N] [--repeats N]
//          [--scenes wall-head-on,wall-70,sphere-bumps,torus-sharp] [--no-filters] [--no-render]
//          [--images <folder>]
// Writes <folder>/study-rendering.csv, study-filters.csv, study-tables.md and <scene>.png (the
// plots); with --images, every rendered picture as <scene>-<variant>.png, for looking at.

#include "SurfaceDetailStudy.h"
#include "vtkSurfaceDetailTangents.h"

#include "BrickTextures.h"
#include "SurfaceDetailImageMetrics.h"
#include "SurfaceDetailTruthScenes.h"
#include "vtkSurfaceDetailMapper.h"

#include <vtkActor.h>
#include <vtkDisplacementMapFilter.h>
#include <vtkHeightMapToConeMap.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkImageData.h>
#include <vtkImageWrapPad.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkNormalMapBaker.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPNGWriter.h>
#include <vtkParametricDonut.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricSphere.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtksys/SystemTools.hxx>

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <sstream>

namespace
{
using namespace SurfaceDetailStudy;
using namespace SurfaceDetailTruthScenes;
namespace Metrics = SurfaceDetailImageMetrics;
using SDM = vtkSurfaceDetailMapper;
using Clock = std::chrono::steady_clock;

double MsSince(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// ---- Scenes -------------------------------------------------------------------------------

enum class Height
{
  Bricks,
  Bumps
};

// A surface, its height field and colours, and how it is seen.
struct Scene : Surface
{
  Height Field;
  BrickTextures::Layout Bricks;
  ViewAngles Angles;
};

ViewAngles Seen(double tilt, double azimuth, double elevation, double zoom, bool lightByNormal)
{
  ViewAngles angles;
  angles.Tilt = tilt;
  angles.Azimuth = azimuth;
  angles.Elevation = elevation;
  angles.Zoom = zoom;
  angles.LightByNormal = lightByNormal;
  return angles;
}

BrickTextures::Layout Bricks(double mortar, double bevel)
{
  BrickTextures::Layout layout;
  layout.Size = 128;
  layout.Mortar = mortar;
  layout.Bevel = bevel;
  return layout;
}

std::vector<Scene> AllScenes()
{
  auto rectangle = [] {
    return vtkSmartPointer<vtkParametricFunction>(vtkSmartPointer<vtkParametricRectangle>::New());
  };
  auto sphere = []
  { return vtkSmartPointer<vtkParametricFunction>(vtkSmartPointer<vtkParametricSphere>::New()); };
  auto donut = []
  { return vtkSmartPointer<vtkParametricFunction>(vtkSmartPointer<vtkParametricDonut>::New()); };
  // Smooth bevels on the wall (a dense mesh converges), hard ones on the torus.
  return {
    { { "wall-head-on", rectangle, { 2, 2 }, { 16, 16 }, { 512, 512 }, 0.12 }, Height::Bricks,
      Bricks(0.01, 0.04), Seen(0, 0, 0, 1.15, true) },
    { { "wall-70", rectangle, { 2, 2 }, { 16, 16 }, { 512, 512 }, 0.12 }, Height::Bricks,
      Bricks(0.01, 0.04), Seen(0, 70, 0, 1.15, true) },
    { { "sphere-bumps", sphere, { 4, 2 }, { 64, 32 }, { 1024, 512 }, 0.08 }, Height::Bumps,
      Bricks(0.01, 0.04), Seen(0, 40, 20, 1.3, false) },
    { { "torus-sharp", donut, { 6, 2 }, { 96, 32 }, { 1536, 512 }, 0.04 }, Height::Bricks,
      Bricks(0.012, 0.012), Seen(-55, 40, 20, 1.3, false) },
  };
}

// Round bumps, 3 x 3 per texture square, smooth everywhere: h in [0,1].
double Bump(double s, double t)
{
  const double k = 2.0 * vtkMath::Pi() * 3.0;
  return 0.25 * (1.0 - std::cos(k * s)) * (1.0 - std::cos(k * t));
}

vtkSmartPointer<vtkImageData> Heights(const Scene& scene)
{
  if (scene.Field == Height::Bricks)
  {
    return BrickTextures::Heights(scene.Bricks);
  }
  const int n = 128;
  auto image = BrickTextures::MakeImage(scene.Bricks, VTK_FLOAT, 1);
  auto* h = static_cast<float*>(image->GetScalarPointer());
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      h[j * n + i] = static_cast<float>(Bump((i + 0.5) / n, (j + 0.5) / n));
    }
  }
  return image;
}

// Bricks: their own colours. Bumps: sand on top, slate in the hollows, so that a colour
// drawn at the wrong place (no parallax) shows in the error as well as the shading.
vtkSmartPointer<vtkImageData> Colours(const Scene& scene)
{
  if (scene.Field == Height::Bricks)
  {
    return BrickTextures::Colours(scene.Bricks);
  }
  const int n = 128;
  auto image = BrickTextures::MakeImage(scene.Bricks, VTK_UNSIGNED_CHAR, 3);
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer());
  const double top[3] = { 222, 196, 140 }, hollow[3] = { 70, 84, 104 };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double h = Bump((i + 0.5) / n, (j + 0.5) / n);
      for (int c = 0; c < 3; ++c)
      {
        rgb[3 * (j * n + i) + c] = static_cast<unsigned char>(hollow[c] + h * (top[c] - hollow[c]));
      }
    }
  }
  return image;
}

// What a renderer needs of a mesh, and nothing else, so that memory compares fairly: points,
// triangles, normals, texture coordinates and (when asked) the tangent frame.
vtkSmartPointer<vtkPolyData> Trim(vtkPolyData* mesh, bool tangents)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(mesh->GetPoints());
  out->SetPolys(mesh->GetPolys());
  out->GetPointData()->SetNormals(mesh->GetPointData()->GetNormals());
  out->GetPointData()->SetTCoords(mesh->GetPointData()->GetTCoords());
  if (tangents)
  {
    vtkPointData* pd = mesh->GetPointData();
    vtkSurfaceDetailTangents::SetFrame(
      out->GetPointData(), pd->GetTangents(), vtkSurfaceDetailTangents::GetHandedness(pd));
  }
  return out;
}

vtkSmartPointer<vtkPolyData> Displace(
  const Scene& scene, vtkImageData* heights, const int resolution[2], int normalMode)
{
  return Trim(Displaced(scene, heights, resolution, normalMode), false);
}

vtkSmartPointer<vtkImageData> NormalMap(
  vtkImageData* heights, double strength, int scheme, bool relief)
{
  vtkNew<vtkHeightMapToNormalMap> maps;
  maps->SetInputData(heights);
  maps->SetBumpScale(strength);
  maps->SetDifferenceScheme(scheme);
  maps->SetWrapToRepeat();
  maps->SetOutputRelief(relief);
  maps->Update();
  return maps->GetOutput();
}

// A baked map covers the surface once: the texture square is the whole [0,1] x [0,1], so
// the coarse mesh that carries it has its texture repeated once and the colours, tiled to
// the scene's repeat, are one image of the same extent.
Surface Atlas(const Scene& scene)
{
  Surface atlas = scene;
  atlas.Repeat[0] = atlas.Repeat[1] = 1.0;
  return atlas;
}

vtkSmartPointer<vtkImageData> Tiled(vtkImageData* image, const double repeat[2])
{
  int dims[3];
  image->GetDimensions(dims);
  vtkNew<vtkImageWrapPad> tile;
  tile->SetInputData(image);
  tile->SetOutputWholeExtent(0, static_cast<int>(repeat[0] * dims[0]) - 1, 0,
    static_cast<int>(repeat[1] * dims[1]) - 1, 0, 0);
  tile->Update();
  return tile->GetOutput();
}

// The scene's own texture resolution (texels per texture square) over the whole atlas.
vtkSmartPointer<vtkImageData> Bake(
  const Scene& scene, vtkPolyData* coarse, vtkPolyData* detailed, int texelsPerSquare)
{
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputData(0, coarse);
  baker->SetInputData(1, detailed);
  baker->SetTextureSize(static_cast<int>(scene.Repeat[0] * texelsPerSquare),
    static_cast<int>(scene.Repeat[1] * texelsPerSquare));
  // The displaced surface lies between the coarse one and Depth below it.
  baker->SetMaxRayDistance(1.5 * scene.Depth);
  baker->SetMargin(4);
  baker->Update();
  return baker->GetOutput();
}

vtkSmartPointer<vtkTexture> AtlasTexture(vtkImageData* image)
{
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->EdgeClampOn();
  return texture;
}

// What every variant of a scene starts from; none of it is counted as preparation.
struct Inputs
{
  vtkSmartPointer<vtkImageData> HeightImage;
  vtkSmartPointer<vtkTexture> Heights, Colours;
  vtkSmartPointer<vtkTexture> AtlasColours; // for baked maps
  vtkSmartPointer<vtkPolyData> Detailed;    // the model a map is baked from
  double Strength;                          // of normal and bump maps from the height map
};

// ---- Variants -----------------------------------------------------------------------------

enum class Kind
{
  Plain, // the coarse mesh, no detail
  Mesh,  // a displaced mesh
  Normal,
  Baked, // normal mapping with a map baked from a displaced mesh
  Bump,
  Parallax,
  Relief
};

struct Variant
{
  std::string Family, Setting;
  Kind What;
  int Resolution[2] = { 0, 0 }; // Mesh: the tessellation
  int NormalMode = vtkDisplacementMapFilter::Exact;
  int Scheme = vtkHeightMapToNormalMap::Central; // Normal
  int Differences = SDM::Central;                // Bump
  bool TangentFree = false;
  bool WithNormalMap = true; // Parallax: shade with the normal map, else the height's bumps
  int Linear = 32, Binary = 8;
  bool Adaptive = false, Shadows = false;
  bool FromHeights = false;  // Relief: depth and normals from the height map, no relief map
  bool Cones = false;        // Relief: cone stepping, with the heights' cone map
  int TexelsPerSquare = 128; // Baked
};

const char* NormalModeName(int mode)
{
  static const char* names[] = { "Input", "Approximate", "Exact", "Mesh" };
  return names[mode];
}

std::vector<Variant> Variants(const Scene& scene)
{
  std::vector<Variant> variants;
  variants.push_back({ "no detail", "coarse mesh, plain mapper", Kind::Plain });
  for (int mode : { vtkDisplacementMapFilter::Input, vtkDisplacementMapFilter::Approximate,
         vtkDisplacementMapFilter::Exact, vtkDisplacementMapFilter::Mesh })
  {
    // The finest is a quarter of the truth's resolution, so that the truth stays well
    // ahead of what it judges.
    for (int divisor : { 32, 16, 8, 4 })
    {
      Variant v{ std::string("mesh ") + NormalModeName(mode), "", Kind::Mesh };
      v.Resolution[0] = scene.Dense[0] / divisor;
      v.Resolution[1] = scene.Dense[1] / divisor;
      v.NormalMode = mode;
      v.Setting = std::to_string(v.Resolution[0]) + "x" + std::to_string(v.Resolution[1]);
      variants.push_back(v);
    }
  }
  Variant normal{ "normal map", "from heights, Central", Kind::Normal };
  variants.push_back(normal);
  normal.Setting = "from heights, Forward";
  normal.Scheme = vtkHeightMapToNormalMap::Forward;
  variants.push_back(normal);
  for (int texels : { 128, 256 })
  {
    Variant baked{ "normal map", "", Kind::Baked };
    baked.TexelsPerSquare = texels;
    baked.Setting = "baked, " + std::to_string(texels) + " texels per square";
    variants.push_back(baked);
  }
  Variant bump{ "bump", "Forward", Kind::Bump };
  bump.Differences = SDM::Forward;
  variants.push_back(bump);
  bump.Setting = "Central";
  bump.Differences = SDM::Central;
  variants.push_back(bump);
  bump.Setting = "Central, TangentFree";
  bump.TangentFree = true;
  variants.push_back(bump);
  Variant parallax{ "parallax", "normal map shading", Kind::Parallax };
  variants.push_back(parallax);
  parallax.Setting = "bump shading";
  parallax.WithNormalMap = false;
  variants.push_back(parallax);
  for (bool shadows : { false, true })
  {
    const std::vector<std::pair<int, int>> pairs = shadows
      ? std::vector<std::pair<int, int>>{ { 16, 4 }, { 32, 8 }, { 64, 8 } }
      : std::vector<std::pair<int, int>>{ { 8, 4 }, { 16, 4 }, { 16, 8 }, { 32, 8 }, { 64, 8 } };
    for (const auto& pair : pairs)
    {
      Variant relief{ shadows ? "relief + shadows" : "relief", "", Kind::Relief };
      relief.Linear = pair.first;
      relief.Binary = pair.second;
      relief.Shadows = shadows;
      relief.Setting = std::to_string(pair.first) + " + " + std::to_string(pair.second);
      variants.push_back(relief);
    }
    Variant adaptive{ shadows ? "relief + shadows" : "relief", "adaptive, at most 32 + 8",
      Kind::Relief };
    adaptive.Adaptive = true;
    adaptive.Shadows = shadows;
    variants.push_back(adaptive);
    Variant cones = adaptive;
    cones.Family += " by cone stepping";
    cones.Setting = "at most 32 + 8";
    cones.Cones = true;
    variants.push_back(cones);
  }
  Variant fromHeights{ "relief", "32 + 8, from the height map", Kind::Relief };
  fromHeights.FromHeights = true;
  variants.push_back(fromHeights);
  return variants;
}

// What the CPU makes for a variant before anything is drawn.
struct Prepared
{
  vtkSmartPointer<vtkPolyData> Mesh;
  vtkSmartPointer<vtkImageData> Map; // normal or relief map, when the variant uses one
  vtkSmartPointer<vtkImageData> Cones; // cone map, for cone stepping
};

Prepared Prepare(const Scene& scene, const Variant& v, const Inputs& in)
{
  Prepared p;
  switch (v.What)
  {
    case Kind::Plain:
      p.Mesh = Trim(Tessellate(scene, scene.Coarse, false, false), false);
      break;
    case Kind::Mesh:
      p.Mesh = Displace(scene, in.HeightImage, v.Resolution, v.NormalMode);
      break;
    case Kind::Bump:
      p.Mesh = Trim(Tessellate(scene, scene.Coarse, !v.TangentFree, false), !v.TangentFree);
      break;
    case Kind::Normal:
    case Kind::Parallax:
    case Kind::Relief:
    {
      const bool map = (v.What != Kind::Parallax || v.WithNormalMap) && !v.FromHeights;
      p.Mesh = Trim(Tessellate(scene, scene.Coarse, map, false), map);
      if (map)
      {
        p.Map = NormalMap(in.HeightImage, in.Strength, v.Scheme, v.What == Kind::Relief);
      }
      if (v.Cones)
      {
        vtkNew<vtkHeightMapToConeMap> cones;
        cones->SetInputData(in.HeightImage);
        cones->Update();
        p.Cones = cones->GetOutput();
      }
      break;
    }
    case Kind::Baked:
      p.Mesh = Trim(Tessellate(Atlas(scene), scene.Coarse, true, false), true);
      p.Map = Bake(scene, p.Mesh, in.Detailed, v.TexelsPerSquare);
      break;
  }
  return p;
}

vtkSmartPointer<vtkActor> MakeActor(
  const Scene& scene, const Variant& v, const Prepared& p, const Inputs& in)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetTexture(v.What == Kind::Baked ? in.AtlasColours : in.Colours);
  actor->GetProperty()->SetAmbient(0.15);
  actor->GetProperty()->SetDiffuse(0.85);
  actor->GetProperty()->SetSpecular(0.2);
  actor->GetProperty()->SetSpecularPower(30);
  if (v.What == Kind::Plain || v.What == Kind::Mesh)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(p.Mesh);
    actor->SetMapper(mapper);
    return actor;
  }
  vtkNew<vtkSurfaceDetailMapper> mapper;
  mapper->SetInputData(p.Mesh);
  mapper->SetDepthScale(scene.Depth);
  mapper->SetBumpScale(in.Strength);
  switch (v.What)
  {
    case Kind::Normal:
      mapper->SetTechniqueToNormalMapping();
      mapper->SetNormalMap(RepeatedTexture(p.Map));
      break;
    case Kind::Baked:
      mapper->SetTechniqueToNormalMapping();
      mapper->SetNormalMap(AtlasTexture(p.Map));
      break;
    case Kind::Bump:
      mapper->SetTechniqueToBumpMapping();
      mapper->SetHeightMap(in.Heights);
      mapper->SetDifferenceScheme(v.Differences);
      mapper->SetTangentFree(v.TangentFree);
      break;
    case Kind::Parallax:
      mapper->SetTechniqueToParallaxMapping();
      mapper->SetHeightMap(in.Heights);
      if (p.Map)
      {
        mapper->SetNormalMap(RepeatedTexture(p.Map));
      }
      break;
    default:
      mapper->SetTechniqueToReliefMapping();
      if (p.Map)
      {
        mapper->SetReliefMap(RepeatedTexture(p.Map));
      }
      else
      {
        mapper->SetHeightMap(in.Heights);
      }
      mapper->SetLinearSearchSteps(v.Linear);
      mapper->SetBinarySearchSteps(v.Binary);
      mapper->SetAdaptiveSteps(v.Adaptive);
      mapper->SetSelfShadowing(v.Shadows);
      if (p.Cones)
      {
        mapper->SetConeMap(RepeatedTexture(p.Cones));
      }
      break;
  }
  actor->SetMapper(mapper);
  return actor;
}

double KiB(vtkDataObject* data)
{
  return data ? static_cast<double>(data->GetActualMemorySize()) : 0.0;
}

// ---- The view and the pictures -------------------------------------------------------------

void SavePNG(const std::vector<unsigned char>& rgb, int size, const std::string& folder,
  const std::string& name)
{
  if (folder.empty())
  {
    return;
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::copy(rgb.begin(), rgb.end(), static_cast<unsigned char*>(image->GetScalarPointer()));
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName((folder + "/" + name + ".png").c_str());
  writer->Write();
}

struct Errors
{
  double RMSE, PSNR, SSIM, InteriorRMSE;
};

// Over the pixels where either picture shows the object.
Errors Compare(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b, int size)
{
  const size_t pixels = static_cast<size_t>(size) * size;
  const std::vector<bool> object = ObjectPixels(a, b), interior = ObjectPixels(a, b, true);
  Errors e;
  e.RMSE = Metrics::RMSE(a.data(), b.data(), pixels, &object);
  e.InteriorRMSE = Metrics::RMSE(a.data(), b.data(), pixels, &interior);
  e.PSNR = Metrics::PSNR(e.RMSE);
  e.SSIM = Metrics::MeanSSIM(Metrics::Luminance(a.data(), size, size),
    Metrics::Luminance(b.data(), size, size), size, size, &object);
  return e;
}

std::string FileName(std::string text)
{
  for (char& c : text)
  {
    if (!std::isalnum(static_cast<unsigned char>(c)))
    {
      c = '-';
    }
  }
  return text;
}

struct Options
{
  std::string Out;
  std::string Images; // empty: no pictures saved
  int Rounds = 31;
  int Size = 512;
  int Repeats = 3;
  std::vector<std::string> Scenes;
  bool Render = true, Filters = true;
};

struct Convergence
{
  std::string Scene;
  int Dense[2];
  Errors Doubling;
  double SmallestRMSE;
  std::string Smallest;
};

// Measures every variant of @a scene; appends their rows to @a rows.
Convergence RunScene(const Scene& scene, const Options& options, std::vector<Row>& rows)
{
  const int size = options.Size;
  std::cout << "== " << scene.Name << std::endl;
  View view;
  FitView(scene, scene.Angles, view);
  Inputs in;
  in.HeightImage = Heights(scene);
  in.Heights = RepeatedTexture(in.HeightImage);
  vtkSmartPointer<vtkImageData> colours = Colours(scene);
  in.Colours = RepeatedTexture(colours);
  in.AtlasColours = AtlasTexture(Tiled(colours, scene.Repeat));
  // Half the truth's resolution: finer than any displaced mesh judged, and not the truth.
  const int detailed[2] = { scene.Dense[0] / 2, scene.Dense[1] / 2 };
  in.Detailed = Displaced(scene, in.HeightImage, detailed);
  in.Strength = scene.Depth / MeanTextureSide(scene);

  vtkNew<vtkRenderer> renderer;
  SetUpRenderer(renderer, view);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(size, size);
  window->AddRenderer(renderer);
  window->Render();
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);

  Variant truthVariant{ "truth", "", Kind::Mesh };
  truthVariant.Resolution[0] = scene.Dense[0];
  truthVariant.Resolution[1] = scene.Dense[1];
  truthVariant.Setting =
    std::to_string(scene.Dense[0]) + "x" + std::to_string(scene.Dense[1]) + ", Exact (reference)";

  // The truth at twice the resolution, drawn once and let go: it is the largest mesh here.
  std::vector<unsigned char> doubled;
  {
    Variant twice = truthVariant;
    twice.Resolution[0] *= 2;
    twice.Resolution[1] *= 2;
    Prepared p = Prepare(scene, twice, in);
    vtkSmartPointer<vtkActor> actor = MakeActor(scene, twice, p, in);
    renderer->AddActor(actor);
    window->Render();
    doubled = GrabRGB(window);
    renderer->RemoveActor(actor);
  }

  std::vector<Variant> variants = Variants(scene);
  variants.insert(variants.begin(), truthVariant);
  const size_t first = rows.size();
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (const Variant& v : variants)
  {
    Row row;
    row.Scene = scene.Name;
    row.Family = v.Family;
    row.Setting = v.Setting;
    row.Truth = &v == &variants.front();
    std::vector<double> prep;
    Prepared p;
    for (int r = 0; r < options.Repeats; ++r)
    {
      const auto start = Clock::now();
      p = Prepare(scene, v, in);
      prep.push_back(MsSince(start));
    }
    row.PrepMs = Median(prep);
    row.MeshKiB = KiB(p.Mesh);
    row.TextureKiB = KiB(p.Map) + KiB(p.Cones);
    if (v.What == Kind::Bump || v.What == Kind::Parallax || v.FromHeights)
    {
      row.TextureKiB += KiB(in.HeightImage);
    }
    actors.push_back(MakeActor(scene, v, p, in));
    actors.back()->VisibilityOff();
    renderer->AddActor(actors.back());
    rows.push_back(row);
  }

  auto frame = [&](size_t shown)
  {
    for (size_t k = 0; k < actors.size(); ++k)
    {
      actors[k]->SetVisibility(k == shown);
    }
    const auto start = Clock::now();
    window->Render();
    glWindow->WaitForCompletion();
    return MsSince(start);
  };
  for (size_t k = 0; k < actors.size(); ++k)
  {
    rows[first + k].FirstFrameMs = frame(k);
  }
  for (int warmup = 0; warmup < 2; ++warmup)
  {
    for (size_t k = 0; k < actors.size(); ++k)
    {
      frame(k);
    }
  }
  std::vector<std::vector<double>> times(actors.size());
  for (int r = 0; r < options.Rounds; ++r)
  {
    for (size_t k = 0; k < actors.size(); ++k)
    {
      times[k].push_back(frame(k));
    }
  }

  const std::string& images = options.Images;
  frame(0);
  const std::vector<unsigned char> truth = GrabRGB(window);
  SavePNG(truth, size, images, scene.Name + "-truth");
  SavePNG(doubled, size, images, scene.Name + "-truth-doubled");
  Convergence convergence{ scene.Name, { scene.Dense[0], scene.Dense[1] },
    Compare(doubled, truth, size), 1e300, "" };
  std::vector<Row*> judged;
  for (size_t k = 0; k < actors.size(); ++k)
  {
    Row& row = rows[first + k];
    row.FrameMs = Median(times[k]);
    row.FrameQ1 = Quantile(times[k], 0.25);
    row.FrameQ3 = Quantile(times[k], 0.75);
    if (k > 0)
    {
      frame(k);
      const std::vector<unsigned char> picture = GrabRGB(window);
      const Errors e = Compare(picture, truth, size);
      row.RMSE = e.RMSE;
      row.PSNR = e.PSNR;
      row.SSIM = e.SSIM;
      row.InteriorRMSE = e.InteriorRMSE;
      SavePNG(picture, size, images, scene.Name + "-" + FileName(row.Family + "-" + row.Setting));
      if (row.RMSE < convergence.SmallestRMSE)
      {
        convergence.SmallestRMSE = row.RMSE;
        convergence.Smallest = row.Family + ", " + row.Setting;
      }
    }
    else
    {
      row.PSNR = Metrics::PSNR(0.0);
    }
    judged.push_back(&row);
    std::cout << row.Family << ", " << row.Setting << ": " << row.FrameMs << " ms, RMSE "
              << row.RMSE << ", SSIM " << row.SSIM << std::endl;
  }
  MarkParetoFront(judged);
  std::cout << "truth against twice as fine: RMSE " << convergence.Doubling.RMSE << ", SSIM "
            << convergence.Doubling.SSIM << "; smallest error judged " << convergence.SmallestRMSE
            << " (" << convergence.Smallest << ")" << std::endl;
  return convergence;
}

// ---- Output -------------------------------------------------------------------------------

std::string Fixed(double value, int digits)
{
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(digits);
  text << value;
  return text.str();
}

void WriteRenderingCSV(const std::string& path, const std::vector<Row>& rows,
  const std::vector<Convergence>& convergence)
{
  std::FILE* csv = std::fopen(path.c_str(), "w");
  std::fprintf(csv,
    "scene,family,setting,frame_ms_median,frame_ms_q1,frame_ms_q3,first_frame_ms,prep_ms,"
    "mesh_kib,detail_texture_kib,rmse,psnr_db,ssim,rmse_interior,pareto_front\n");
  for (const Row& r : rows)
  {
    std::fprintf(csv, "%s,\"%s\",\"%s\",%.3f,%.3f,%.3f,%.1f,%.2f,%.0f,%.0f,%.4f,%.3f,%.5f,%.4f,%s\n",
      r.Scene.c_str(), r.Family.c_str(), r.Setting.c_str(), r.FrameMs, r.FrameQ1, r.FrameQ3,
      r.FirstFrameMs, r.PrepMs, r.MeshKiB, r.TextureKiB, r.RMSE, r.Truth ? 999.0 : r.PSNR, r.SSIM,
      r.InteriorRMSE, r.Truth ? "reference" : (r.OnFront ? "front" : "dominated"));
  }
  for (const Convergence& c : convergence)
  {
    std::fprintf(csv, "%s,convergence,\"truth %dx%d against %dx%d\",,,,,,,,%.4f,%.3f,%.5f,%.4f,\n",
      c.Scene.c_str(), c.Dense[0], c.Dense[1], 2 * c.Dense[0], 2 * c.Dense[1], c.Doubling.RMSE,
      c.Doubling.PSNR, c.Doubling.SSIM, c.Doubling.InteriorRMSE);
  }
  std::fclose(csv);
}

void WriteRenderingTables(std::FILE* md, const std::vector<Row>& rows,
  const std::vector<Convergence>& convergence, const Options& options)
{
  std::fprintf(md, "\n## Every variant\n");
  for (const Convergence& c : convergence)
  {
    std::fprintf(md, "\n### %s\n\n", c.Scene.c_str());
    std::fprintf(md,
      "Truth %dx%d against %dx%d: RMSE %.2f, PSNR %.1f dB, SSIM %.4f. Smallest error judged: "
      "RMSE %.2f (%s): %s.\n\n",
      c.Dense[0], c.Dense[1], 2 * c.Dense[0], 2 * c.Dense[1], c.Doubling.RMSE, c.Doubling.PSNR,
      c.Doubling.SSIM, c.SmallestRMSE, c.Smallest.c_str(),
      c.Doubling.RMSE < c.SmallestRMSE ? "converged" : "NOT converged");
    std::vector<const Row*> sorted;
    for (const Row& r : rows)
    {
      if (r.Scene == c.Scene)
      {
        sorted.push_back(&r);
      }
    }
    std::sort(sorted.begin(), sorted.end(),
      [](const Row* a, const Row* b) { return a->FrameMs < b->FrameMs; });
    std::fprintf(md,
      "| technique | setting | frame ms (median) | first frame ms | prep ms | mesh KiB | "
      "texture KiB | RMSE | PSNR dB | SSIM | interior RMSE | front |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Row* r : sorted)
    {
      std::fprintf(md, "| %s | %s | %s | %s | %s | %.0f | %.0f | %s | %s | %s | %s | %s |\n",
        r->Family.c_str(), r->Setting.c_str(), Fixed(r->FrameMs, 1).c_str(),
        Fixed(r->FirstFrameMs, 0).c_str(), Fixed(r->PrepMs, 1).c_str(), r->MeshKiB, r->TextureKiB,
        r->Truth ? "0" : Fixed(r->RMSE, 2).c_str(), r->Truth ? "inf" : Fixed(r->PSNR, 1).c_str(),
        Fixed(r->SSIM, 4).c_str(), Fixed(r->InteriorRMSE, 2).c_str(),
        r->Truth ? "reference" : (r->OnFront ? "**front**" : ""));
    }
  }
  std::fprintf(md, "\n%d interleaved frames per variant after 3 warm-up rounds, %dx%d window.\n",
    options.Rounds, options.Size, options.Size);
}

// The OpenGL renderer's own name (llvmpipe and its vector width, or a GPU), for the record.
std::string RendererName()
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(8, 8);
  window->Render();
  std::istringstream report(window->ReportCapabilities());
  std::string line;
  while (std::getline(report, line))
  {
    if (line.find("renderer string") != std::string::npos)
    {
      return line.substr(line.find(':') + 1);
    }
  }
  return "unknown";
}

// Per scene and technique family: its fastest and its most accurate setting, and which of
// its settings are on the front; the short form of the full tables, for BENCHMARKS.md.
void WriteSummary(
  std::FILE* md, const std::vector<Row>& rows, const std::vector<Convergence>& convergence)
{
  std::fprintf(md, "\n## Summary\n");
  for (const Convergence& c : convergence)
  {
    std::fprintf(md,
      "\n**%s** (truth against twice as fine: RMSE %.2f)\n\n| technique | fastest: setting, ms, "
      "RMSE | most accurate: setting, ms, RMSE, SSIM | settings on the front |\n"
      "|---|---|---|---|\n",
      c.Scene.c_str(), c.Doubling.RMSE);
    std::vector<std::string> families;
    for (const Row& r : rows)
    {
      if (r.Scene == c.Scene && !r.Truth &&
        std::find(families.begin(), families.end(), r.Family) == families.end())
      {
        families.push_back(r.Family);
      }
    }
    for (const std::string& family : families)
    {
      const Row *fastest = nullptr, *best = nullptr;
      std::string front;
      for (const Row& r : rows)
      {
        if (r.Scene != c.Scene || r.Family != family || r.Truth)
        {
          continue;
        }
        fastest = !fastest || r.FrameMs < fastest->FrameMs ? &r : fastest;
        best = !best || r.RMSE < best->RMSE ? &r : best;
        if (r.OnFront)
        {
          front += (front.empty() ? "" : "; ") + r.Setting;
        }
      }
      std::fprintf(md, "| %s | %s, %.1f, %.2f | %s, %.1f, %.2f, %.3f | %s |\n", family.c_str(),
        fastest->Setting.c_str(), fastest->FrameMs, fastest->RMSE, best->Setting.c_str(),
        best->FrameMs, best->RMSE, best->SSIM, front.empty() ? "none" : front.c_str());
    }
  }
}

std::vector<std::string> Split(const std::string& text)
{
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, ','))
  {
    parts.push_back(part);
  }
  return parts;
}

bool ParseOptions(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--no-filters")
    {
      options.Filters = false;
    }
    else if (arg == "--no-render")
    {
      options.Render = false;
    }
    else if (arg == "--out" && hasValue)
    {
      options.Out = argv[++i];
    }
    else if (arg == "--images" && hasValue)
    {
      options.Images = argv[++i];
    }
    else if (arg == "--rounds" && hasValue)
    {
      options.Rounds = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--size" && hasValue)
    {
      options.Size = std::max(64, std::atoi(argv[++i]));
    }
    else if (arg == "--repeats" && hasValue)
    {
      options.Repeats = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--scenes" && hasValue)
    {
      options.Scenes = Split(argv[++i]);
    }
    else
    {
      std::cerr << "unknown or incomplete option " << arg << "\n";
      return false;
    }
  }
  return !options.Out.empty();
}
} // namespace

int main(int argc, char* argv[])
{
  const char* usage =
    "Usage: SurfaceDetailStudy --out <folder> [--rounds N] [--size N] [--repeats N]\n"
    "                          [--scenes a,b,...] [--images <folder>] [--no-filters] "
    "[--no-render]\n\n"
    "The run time against error study: every technique at its settings, timed and compared\n"
    "with its truth; writes tables and plots into <folder>. scripts/study.sh runs it.\n";
  const bool help = argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h");
  Options options;
  if (help || !ParseOptions(argc, argv, options))
  {
    (help ? std::cout : std::cerr) << usage;
    return help ? 0 : 1;
  }
  vtksys::SystemTools::MakeDirectory(options.Out);
  if (!options.Images.empty())
  {
    vtksys::SystemTools::MakeDirectory(options.Images);
  }
  std::FILE* md = std::fopen((options.Out + "/study-tables.md").c_str(), "w");
  if (!md)
  {
    std::cerr << "cannot write to " << options.Out << "\n";
    return 1;
  }
  if (options.Render)
  {
    std::vector<Row> rows;
    std::vector<Convergence> convergence;
    std::fprintf(md, "# Rendering\n\nOpenGL renderer:%s\n", RendererName().c_str());
    for (const Scene& scene : AllScenes())
    {
      if (!options.Scenes.empty() &&
        std::find(options.Scenes.begin(), options.Scenes.end(), scene.Name) == options.Scenes.end())
      {
        continue;
      }
      convergence.push_back(RunScene(scene, options, rows));
      std::vector<const Row*> sceneRows;
      for (const Row& r : rows)
      {
        if (r.Scene == scene.Name)
        {
          sceneRows.push_back(&r);
        }
      }
      PlotScene(scene.Name, sceneRows, convergence.back().Doubling.RMSE,
        options.Out + "/" + scene.Name + ".png");
    }
    WriteRenderingCSV(options.Out + "/study-rendering.csv", rows, convergence);
    WriteSummary(md, rows, convergence);
    WriteRenderingTables(md, rows, convergence, options);
  }
  if (options.Filters)
  {
    std::FILE* csv = std::fopen((options.Out + "/study-filters.csv").c_str(), "w");
    std::fprintf(md, "\n# CPU filters\n");
    RunFilterStudies(csv, md, options.Repeats);
    std::fclose(csv);
  }
  std::fclose(md);
  return 0;
}
