// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Relief mapping against ground truth. The truth is the relief's own definition made real:
// the mesh displaced by vtkDisplacementMapFilter (Scale = DepthScale, Midlevel 1, Exact
// normals), tessellated finely enough that doubling it changes the picture much less than the
// errors judged here, drawn by VTK's plain mapper with the same colour texture, camera and
// light. Against it:
// - relief mapping (from a relief map, and from the height map alone) at default settings
//   must be much closer than normal mapping with the same normals;
// - self-shadowing must darken what a CPU ray cast on the displaced surface finds in shadow,
//   and leave what it finds lit;
// - with DepthCorrection, a sphere half sunk into a relief wall must meet it where it meets
//   the displaced wall.
// Errors are over the pixels the object covers in either picture; every figure is printed.

#include "BrickTextures.h"
#include "SurfaceDetailImageMetrics.h"
#include "SurfaceDetailTruthScenes.h"
#include "vtkSurfaceDetailMapper.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkHeightMapToConeMap.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkImageData.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkParametricDonut.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricSphere.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkObjectFactory.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkTexture.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using namespace SurfaceDetailTruthScenes;
constexpr int Size = 300;

// Smoother bricks than the regression scenes' (wider bevels), so that a displaced mesh a
// few times finer than the texels converges.
BrickTextures::Layout TruthBricks(int size = 128)
{
  BrickTextures::Layout layout;
  layout.Size = size;
  layout.Mortar = 0.01;
  layout.Bevel = 0.04;
  return layout;
}

Surface Wall()
{
  return { "wall", [] { return vtkSmartPointer<vtkParametricRectangle>::New(); }, { 2, 2 },
    { 16, 16 }, { 512, 512 }, 0.12 };
}

Surface Ball()
{
  return { "sphere", [] { return vtkSmartPointer<vtkParametricSphere>::New(); }, { 4, 2 },
    { 64, 32 }, { 1024, 512 }, 0.05 };
}

Surface Ring()
{
  return { "torus", [] { return vtkSmartPointer<vtkParametricDonut>::New(); }, { 6, 2 }, { 96, 32 },
    { 1536, 512 }, 0.04 };
}

// Every surface seen obliquely from above right; the donut (z up) from the side.
void FitView(const Surface& surface, View& view)
{
  ViewAngles angles;
  angles.Tilt = surface.Name == "torus" ? -55 : 0;
  SurfaceDetailTruthScenes::FitView(surface, angles, view);
}

enum class Look
{
  Truth,
  Normal,
  Relief,          // from a relief map
  ReliefFromHeight // from the height map alone
};

struct Options
{
  bool SelfShadowing = false;
  bool DepthCorrection = false;
  double Depth = 0.0; // 0: the surface's own
  bool CountReads = false; // draw the depth reads of each fragment (ReadCountingMapper)
  bool AdaptiveSteps = true;
  bool ConeStepping = false; // with the cone map of the heights
  int BinarySteps = -1;      // -1: the default
  int LinearSteps = -1;      // -1: the default
  int MapSize = 128;         // texels of the relief's map
  bool ZeroCones = false;    // a cone map of zero-width cones at the top of the box
  int ConeType = vtkHeightMapToConeMap::Relaxed;
  vtkSmartPointer<vtkImageData> Heights; // instead of the bricks'
};

// A test-only shader variant, the cost measure that no rasteriser's speed enters: every read
// of the relief's depth is counted, and each fragment writes its count in red (in 1/255ths,
// up to 255) and full green, which the background does not have, instead of its colour.
class ReadCountingMapper : public vtkSurfaceDetailMapper
{
public:
  static ReadCountingMapper* New();
  vtkTypeMacro(ReadCountingMapper, vtkSurfaceDetailMapper);

protected:
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::ReplaceShaderValues(shaders, ren, act);
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    if (vtkShaderProgram::Substitute(fs, "float sdReliefDepthAt(vec2 tc)\n{\n",
          "int sdDepthReads = 0;\nfloat sdReliefDepthAt(vec2 tc)\n{\n  sdDepthReads += 1;\n"))
    {
      // A cone read costs what a depth read costs.
      vtkShaderProgram::Substitute(fs, "vec3 sdReliefConeAt(vec2 tc)\n{\n",
        "vec3 sdReliefConeAt(vec2 tc)\n{\n  sdDepthReads += 1;\n");
      fs.insert(fs.rfind('}'),
        "  gl_FragData[0] = vec4(float(min(sdDepthReads, 255)) / 255.0, 1.0, 0.0, 1.0);\n");
    }
    shaders[vtkShader::Fragment]->SetSource(fs);
  }
};
vtkStandardNewMacro(ReadCountingMapper);

// The heights' cone map: the bricks' made once per size and kind (a 512² map takes a while
// under the sanitizers), and zero-width cones at the top of the box made without the filter.
vtkSmartPointer<vtkImageData> ConeMap(vtkImageData* heights, const Options& options)
{
  if (options.ZeroCones)
  {
    auto zero = vtkSmartPointer<vtkImageData>::New();
    zero->SetDimensions(heights->GetDimensions());
    zero->AllocateScalars(VTK_FLOAT, 2);
    zero->GetPointData()->GetScalars()->Fill(0.0);
    zero->GetPointData()->GetScalars()->SetName("ConeMap");
    return zero;
  }
  static std::map<std::pair<int, int>, vtkSmartPointer<vtkImageData>> bricks;
  vtkSmartPointer<vtkImageData>& made = bricks[{ options.MapSize, options.ConeType }];
  if (options.Heights || !made)
  {
    vtkNew<vtkHeightMapToConeMap> cones;
    cones->SetInputData(heights);
    cones->SetConeType(options.ConeType);
    cones->Update();
    if (options.Heights)
    {
      return cones->GetOutput();
    }
    made = cones->GetOutput();
  }
  return made;
}

vtkSmartPointer<vtkActor> SurfaceActor(
  Surface surface, Look look, const Options& options = Options())
{
  if (options.Depth > 0)
  {
    surface.Depth = options.Depth;
  }
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetTexture(RepeatedTexture(BrickTextures::Colours(TruthBricks())));
  actor->GetProperty()->SetAmbient(0.15);
  actor->GetProperty()->SetDiffuse(0.85);
  actor->GetProperty()->SetSpecular(0.2);
  actor->GetProperty()->SetSpecularPower(30);
  if (look == Look::Truth)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(Displaced(surface, BrickTextures::Heights(TruthBricks()), surface.Dense));
    actor->SetMapper(mapper);
    return actor;
  }
  vtkSmartPointer<vtkPolyData> mesh = Tessellate(surface, surface.Coarse);
  auto mapper = options.CountReads ? vtkSmartPointer<vtkSurfaceDetailMapper>(
                                       vtkSmartPointer<ReadCountingMapper>::New())
                                   : vtkSmartPointer<vtkSurfaceDetailMapper>::New();
  mapper->SetAdaptiveSteps(options.AdaptiveSteps);
  if (options.LinearSteps >= 0)
  {
    mapper->SetLinearSearchSteps(options.LinearSteps);
  }
  if (options.BinarySteps >= 0)
  {
    mapper->SetBinarySearchSteps(options.BinarySteps);
  }
  mapper->SetInputData(mesh);
  vtkSmartPointer<vtkImageData> heights =
    options.Heights ? options.Heights : BrickTextures::Heights(TruthBricks(options.MapSize));
  vtkNew<vtkHeightMapToNormalMap> maps;
  maps->SetInputData(heights);
  maps->SetBumpScale(surface.Depth / MeanTextureSide(surface));
  maps->SetDifferenceSchemeToCentral();
  maps->SetWrap(vtkHeightMapToNormalMap::Repeat);
  maps->SetOutputRelief(look == Look::Relief);
  maps->Update();
  mapper->SetDepthScale(surface.Depth);
  mapper->SetSelfShadowing(options.SelfShadowing);
  mapper->SetDepthCorrection(options.DepthCorrection);
  if (options.ConeStepping)
  {
    mapper->SetConeMap(RepeatedTexture(ConeMap(heights, options)));
  }
  switch (look)
  {
    case Look::Normal:
      mapper->SetTechniqueToNormalMapping();
      mapper->SetNormalMap(RepeatedTexture(maps->GetOutput()));
      break;
    case Look::Relief:
      mapper->SetTechniqueToReliefMapping();
      mapper->SetReliefMap(RepeatedTexture(maps->GetOutput()));
      break;
    default:
      mapper->SetTechniqueToReliefMapping();
      mapper->SetHeightMap(RepeatedTexture(heights));
      break;
  }
  actor->SetMapper(mapper);
  return actor;
}

struct Picture
{
  std::vector<unsigned char> RGB;
  std::vector<float> Z;
};

// The renderer's picture in a window of Size x Size without multisampling.
void Draw(vtkRenderer* renderer, Picture& picture, bool withDepth = false)
{
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(Size, Size);
  window->AddRenderer(renderer);
  window->Render();
  picture.RGB = GrabRGB(window);
  if (withDepth)
  {
    picture.Z.resize(Size * Size);
    vtkNew<vtkFloatArray> z;
    window->GetZbufferData(0, 0, Size - 1, Size - 1, z);
    std::copy(z->GetPointer(0), z->GetPointer(0) + Size * Size, picture.Z.begin());
  }
}

void Draw(const View& view, const std::vector<vtkSmartPointer<vtkActor>>& actors, Picture& picture,
  bool withDepth = false)
{
  vtkNew<vtkRenderer> renderer;
  for (const auto& actor : actors)
  {
    renderer->AddActor(actor);
  }
  SetUpRenderer(renderer, view);
  Draw(renderer, picture, withDepth);
}

// Root mean square difference (levels, over R, G, B) over the pixels where either picture
// shows the object.
double ObjectRMSE(const Picture& a, const Picture& b)
{
  const std::vector<bool> object = ObjectPixels(a.RGB, b.RGB);
  return SurfaceDetailImageMetrics::RMSE(a.RGB.data(), b.RGB.data(), object.size(), &object);
}

// With SURFACEDETAIL_TRUTH_PICTURES=<folder>, the pictures side by side, to look at.
void SaveSideBySide(const std::string& name, const std::vector<const Picture*>& pictures)
{
  const char* folder = std::getenv("SURFACEDETAIL_TRUTH_PICTURES");
  if (!folder)
  {
    return;
  }
  const int n = static_cast<int>(pictures.size());
  vtkNew<vtkImageData> image;
  image->SetDimensions(n * Size, Size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < Size; ++j)
    {
      std::copy_n(&pictures[k]->RGB[3 * j * Size], 3 * Size, out + 3 * (j * n * Size + k * Size));
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName((std::string(folder) + "/" + name + ".png").c_str());
  writer->Write();
}

void ExpectReliefCloserThanNormalMapping(const Surface& surface)
{
  View view;
  FitView(surface, view);
  Picture truth, finer, normal, relief, fromHeight;
  Draw(view, { SurfaceActor(surface, Look::Truth) }, truth);
  Surface doubled = surface;
  doubled.Dense[0] *= 2;
  doubled.Dense[1] *= 2;
  Draw(view, { SurfaceActor(doubled, Look::Truth) }, finer);
  Draw(view, { SurfaceActor(surface, Look::Normal) }, normal);
  Draw(view, { SurfaceActor(surface, Look::Relief) }, relief);
  Draw(view, { SurfaceActor(surface, Look::ReliefFromHeight) }, fromHeight);

  SaveSideBySide(surface.Name, { &truth, &relief, &fromHeight, &normal });
  const double convergence = ObjectRMSE(truth, finer);
  const double normalError = ObjectRMSE(normal, truth);
  const double reliefError = ObjectRMSE(relief, truth);
  const double heightError = ObjectRMSE(fromHeight, truth);
  std::cout << surface.Name << ": RMSE against the displaced mesh (levels) - normal mapping "
            << normalError << ", relief map " << reliefError << " (ratio "
            << reliefError / normalError << "), relief from the height map " << heightError
            << " (ratio " << heightError / normalError << "); truth against twice as fine "
            << convergence << "\n";
  // The truth has converged: doubling it moves the picture far less than relief's error.
  EXPECT_LT(convergence, 0.5 * reliefError) << surface.Name;
  EXPECT_LT(reliefError, 0.6 * normalError) << surface.Name;
  EXPECT_LT(heightError, 0.6 * normalError) << surface.Name;
}
} // namespace

TEST(SurfaceDetailRelief, WallIsCloserThanNormalMapping)
{
  ExpectReliefCloserThanNormalMapping(Wall());
}

TEST(SurfaceDetailRelief, SphereIsCloserThanNormalMapping)
{
  ExpectReliefCloserThanNormalMapping(Ball());
}

TEST(SurfaceDetailRelief, TorusIsCloserThanNormalMapping)
{
  ExpectReliefCloserThanNormalMapping(Ring());
}

namespace
{
// The world point seen at pixel (i,j) with window depth z, through the view's camera.
void PixelToWorld(const View& view, int i, int j, double z, double world[3])
{
  vtkNew<vtkMatrix4x4> inverse;
  inverse->DeepCopy(view.Camera->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0));
  inverse->Invert();
  const double ndc[4] = { 2.0 * (i + 0.5) / Size - 1.0, 2.0 * (j + 0.5) / Size - 1.0, 2.0 * z - 1.0,
    1.0 };
  double p[4];
  inverse->MultiplyPoint(ndc, p);
  for (int k = 0; k < 3; ++k)
  {
    world[k] = p[k] / p[3];
  }
}

// The truth's height field, read as vtkDisplacementMapFilter reads it (bilinear between
// texel centres, repeated).
double HeightAt(vtkImageData* heights, double s, double t)
{
  int dims[3];
  heights->GetDimensions(dims);
  const auto* h = static_cast<const float*>(heights->GetScalarPointer());
  const double x = s * dims[0] - 0.5, y = t * dims[1] - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  auto at = [&](int i, int j)
  {
    i = ((i % dims[0]) + dims[0]) % dims[0];
    j = ((j % dims[1]) + dims[1]) % dims[1];
    return static_cast<double>(h[j * dims[0] + i]);
  };
  const int i = static_cast<int>(fx), j = static_cast<int>(fy);
  const double a = x - fx, b = y - fy;
  return (1 - b) * ((1 - a) * at(i, j) + a * at(i + 1, j)) +
    b * ((1 - a) * at(i, j + 1) + a * at(i + 1, j + 1));
}

enum class Light
{
  Lit,
  Shadowed,
  Unsure
};

// Whether the displaced wall (x in [-2,2], y in [0,3.5], z = depth*(h - 1), texture
// repeated twice each way) shades the point p from a light at lightPosition: the segment
// toward the light is followed in small steps until it rises above the wall's top (z = 0)
// or leaves the wall, and the deepest it goes under the surface decides.
Light WallShadow(vtkImageData* heights, double depth, const double p[3], const double light[3])
{
  double d[3] = { light[0] - p[0], light[1] - p[1], light[2] - p[2] };
  vtkMath::Normalize(d);
  if (!(d[2] > 0))
  {
    return Light::Unsure;
  }
  const double step = 0.001;
  double deepest = -1.0;
  for (double u = 5 * step;; u += step)
  {
    const double q[3] = { p[0] + u * d[0], p[1] + u * d[1], p[2] + u * d[2] };
    if (q[2] > 0 || q[0] < -2 || q[0] > 2 || q[1] < 0 || q[1] > 3.5)
    {
      break;
    }
    const double s = 2 * (q[0] + 2) / 4, t = 2 * q[1] / 3.5;
    deepest = std::max(deepest, depth * (HeightAt(heights, s, t) - 1) - q[2]);
  }
  if (deepest > 0.2 * depth)
  {
    return Light::Shadowed;
  }
  return deepest < 0.0 ? Light::Lit : Light::Unsure;
}

double Luma(const unsigned char* p)
{
  return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
}
} // namespace

namespace
{
// Self-shadowing darkens what a ray cast on the displaced wall finds in shadow, and leaves
// what it finds lit (pixels whose 3x3 neighbourhood agrees, away from shadow edges).
void ExpectShadowsWhereTheDisplacedWallIsInShadow(const Options& search)
{
  const Surface wall = Wall();
  View view;
  FitView(wall, view);
  Picture truth, shadowed, unshadowed;
  Draw(view, { SurfaceActor(wall, Look::Truth) }, truth, true);
  Options withShadows = search;
  withShadows.SelfShadowing = true;
  Draw(view, { SurfaceActor(wall, Look::Relief, withShadows) }, shadowed);
  Draw(view, { SurfaceActor(wall, Look::Relief, search) }, unshadowed);
  SaveSideBySide("wall-shadows", { &truth, &shadowed, &unshadowed });

  vtkSmartPointer<vtkImageData> heights = BrickTextures::Heights(TruthBricks());
  std::vector<Light> light(Size * Size, Light::Unsure);
  for (int j = 0; j < Size; ++j)
  {
    for (int i = 0; i < Size; ++i)
    {
      const float z = truth.Z[j * Size + i];
      if (z < 1.0f)
      {
        double p[3];
        PixelToWorld(view, i, j, z, p);
        light[j * Size + i] = WallShadow(heights, wall.Depth, p, view.LightPosition);
      }
    }
  }
  long inShadow = 0, darkened = 0, inLight = 0, unchanged = 0;
  for (int j = 1; j + 1 < Size; ++j)
  {
    for (int i = 1; i + 1 < Size; ++i)
    {
      const Light kind = light[j * Size + i];
      bool agree = kind != Light::Unsure;
      for (int dj = -1; dj <= 1 && agree; ++dj)
      {
        for (int di = -1; di <= 1 && agree; ++di)
        {
          agree = light[(j + dj) * Size + i + di] == kind;
        }
      }
      if (!agree)
      {
        continue;
      }
      const int p = 3 * (j * Size + i);
      const double drop = Luma(&unshadowed.RGB[p]) - Luma(&shadowed.RGB[p]);
      if (kind == Light::Shadowed)
      {
        ++inShadow;
        darkened += drop > 10.0;
      }
      else
      {
        ++inLight;
        unchanged += std::abs(drop) <= 4.0;
      }
    }
  }
  std::cout << "Shadow mask from the displaced wall: " << inShadow << " pixels in shadow, "
            << darkened << " of them darkened by self-shadowing; " << inLight << " lit pixels, "
            << unchanged << " of them unchanged\n";
  ASSERT_GT(inShadow, 500) << "the scene must have shadows to judge";
  EXPECT_GT(darkened, 0.8 * inShadow);
  EXPECT_GT(unchanged, 0.95 * inLight);
}
} // namespace

TEST(SurfaceDetailRelief, SelfShadowsWhereTheDisplacedWallIsInShadow)
{
  ExpectShadowsWhereTheDisplacedWallIsInShadow(Options());
}

TEST(SurfaceDetailRelief, SelfShadowsWithConeSteppingWhereTheDisplacedWallIsInShadow)
{
  Options cones;
  cones.ConeStepping = true;
  ExpectShadowsWhereTheDisplacedWallIsInShadow(cones);
}

namespace
{
// Pixels showing the green, unlit sphere.
std::vector<bool> SphereMask(const Picture& picture)
{
  std::vector<bool> mask(Size * Size);
  for (int p = 0; p < Size * Size; ++p)
  {
    const unsigned char* rgb = &picture.RGB[3 * p];
    mask[p] = rgb[1] > 200 && rgb[0] < 60 && rgb[2] < 60;
  }
  return mask;
}

long Mismatch(const std::vector<bool>& a, const std::vector<bool>& b)
{
  long count = 0;
  for (size_t p = 0; p < a.size(); ++p)
  {
    count += a[p] != b[p];
  }
  return count;
}
} // namespace

// A plain sphere half sunk into a relief wall: with DepthCorrection the sphere shows where
// it shows against the displaced wall (the intersection curves agree); without, the wall
// hides everything behind its flat top.
TEST(SurfaceDetailRelief, DepthCorrectionMeetsGeometryLikeTheDisplacedWall)
{
  const Surface wall = Wall();
  View view;
  FitView(wall, view);
  auto sphere = []
  {
    vtkNew<vtkSphereSource> source;
    source->SetCenter(0.0, 1.75, 0.0);
    source->SetRadius(0.8);
    source->SetThetaResolution(64);
    source->SetPhiResolution(64);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0, 1, 0);
    actor->GetProperty()->SetAmbient(1);
    actor->GetProperty()->SetDiffuse(0);
    return actor;
  };
  Options deep;
  deep.Depth = 0.3;
  Options corrected = deep;
  corrected.DepthCorrection = true;
  Picture truth, withCorrection, without;
  Draw(view, { SurfaceActor(wall, Look::Truth, deep), sphere() }, truth);
  Draw(view, { SurfaceActor(wall, Look::Relief, corrected), sphere() }, withCorrection);
  Draw(view, { SurfaceActor(wall, Look::Relief, deep), sphere() }, without);
  SaveSideBySide("wall-sphere-depth", { &truth, &withCorrection, &without });

  const std::vector<bool> reference = SphereMask(truth);
  long sphereArea = 0;
  for (bool b : reference)
  {
    sphereArea += b;
  }
  const long correctedOff = Mismatch(SphereMask(withCorrection), reference);
  const long uncorrectedOff = Mismatch(SphereMask(without), reference);
  std::cout << "Sphere pixels: " << sphereArea << " against the displaced wall; pixels where "
            << "the relief wall disagrees: " << correctedOff << " with depth correction, "
            << uncorrectedOff << " without\n";
  ASSERT_GT(sphereArea, 1000);
  EXPECT_LT(correctedOff, 0.3 * uncorrectedOff);
}

namespace
{
// The coarse wall through vtkSurfaceDetailMapper, set up by @a configure.
vtkSmartPointer<vtkActor> WallActor(const std::function<void(vtkSurfaceDetailMapper*)>& configure)
{
  const Surface wall = Wall();
  vtkNew<vtkSurfaceDetailMapper> mapper;
  mapper->SetInputData(Tessellate(wall, wall.Coarse));
  mapper->SetDepthScale(wall.Depth);
  configure(mapper);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetTexture(RepeatedTexture(BrickTextures::Colours(TruthBricks())));
  actor->GetProperty()->SetAmbient(0.15);
  actor->GetProperty()->SetDiffuse(0.85);
  actor->GetProperty()->SetSpecular(0.2);
  actor->GetProperty()->SetSpecularPower(30);
  return actor;
}

// @a actor alone, seen from @a view's camera made parallel, the wall's half height in view.
void DrawParallel(const View& view, vtkActor* actor, Picture& picture)
{
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->GetActiveCamera()->DeepCopy(view.Camera);
  renderer->GetActiveCamera()->ParallelProjectionOn();
  renderer->GetActiveCamera()->SetParallelScale(2.0);
  Draw(renderer, picture);
}

int MaxDifference(const Picture& a, const Picture& b)
{
  int most = 0;
  for (size_t k = 0; k < a.RGB.size(); ++k)
  {
    most = std::max(most, std::abs(a.RGB[k] - b.RGB[k]));
  }
  return most;
}

vtkSmartPointer<vtkImageData> ReliefMap(double strength)
{
  vtkNew<vtkHeightMapToNormalMap> maps;
  maps->SetInputData(BrickTextures::Heights(TruthBricks()));
  maps->SetBumpScale(strength);
  maps->SetDifferenceSchemeToCentral();
  maps->SetWrap(vtkHeightMapToNormalMap::Repeat);
  maps->OutputReliefOn();
  maps->Update();
  return maps->GetOutput();
}
} // namespace

// A relief whose height is 1 everywhere is the mesh itself: relief mapping, its shadows and
// its depth correction must then draw exactly what the plain technique draws.
TEST(SurfaceDetailRelief, FlatReliefIsTheMesh)
{
  View view;
  FitView(Wall(), view);
  vtkNew<vtkImageData> top;
  top->SetDimensions(16, 16, 1);
  top->AllocateScalars(VTK_FLOAT, 1);
  std::fill_n(static_cast<float*>(top->GetScalarPointer()), 256, 1.0f);
  Picture plain, relief;
  Draw(view, { WallActor([](vtkSurfaceDetailMapper*) {}) }, plain);
  Draw(view,
    { WallActor(
      [&](vtkSurfaceDetailMapper* mapper)
      {
        mapper->SetTechniqueToReliefMapping();
        mapper->SetHeightMap(RepeatedTexture(top));
        mapper->SelfShadowingOn();
        mapper->DepthCorrectionOn();
      }) },
    relief);
  EXPECT_LE(MaxDifference(plain, relief), 2);
}

// Under a parallel projection the headlight shines exactly back along every view ray: each
// point the eye reaches, the light reaches too, so self-shadowing must change nothing.
TEST(SurfaceDetailRelief, HeadlightCastsNoVisibleShadow)
{
  View view;
  FitView(Wall(), view);
  auto relief = [&](bool shadows)
  {
    return WallActor(
      [&](vtkSurfaceDetailMapper* mapper)
      {
        mapper->SetTechniqueToReliefMapping();
        mapper->SetReliefMap(RepeatedTexture(ReliefMap(Wall().Depth / 2.0)));
        mapper->SetSelfShadowing(shadows);
      });
  };
  Picture lit, shadowed;
  DrawParallel(view, relief(false), lit);
  DrawParallel(view, relief(true), shadowed);
  EXPECT_LE(MaxDifference(lit, shadowed), 2);
}

// Where the whole depth is less than half a pixel the relief fades out and the picture is
// normal mapping with the same map (no search runs); a deep relief differs.
TEST(SurfaceDetailRelief, ReliefBelowAPixelIsNormalMapping)
{
  View view;
  FitView(Wall(), view);
  vtkSmartPointer<vtkImageData> map = ReliefMap(Wall().Depth / 2.0);
  auto relief = [&](double depth)
  {
    return WallActor(
      [&](vtkSurfaceDetailMapper* mapper)
      {
        mapper->SetTechniqueToReliefMapping();
        mapper->SetReliefMap(RepeatedTexture(map));
        mapper->SetDepthScale(depth);
        mapper->SelfShadowingOn();
      });
  };
  Picture normal, shallow, deep;
  Draw(view,
    { WallActor(
      [&](vtkSurfaceDetailMapper* mapper)
      {
        mapper->SetTechniqueToNormalMapping();
        mapper->SetNormalMap(RepeatedTexture(map));
      }) },
    normal);
  Draw(view, { relief(1e-4) }, shallow); // the wall is 4 units wide on 300 pixels
  Draw(view, { relief(Wall().Depth) }, deep);
  EXPECT_LE(MaxDifference(normal, shallow), 2);
  EXPECT_GT(ObjectRMSE(normal, deep), 5.0);
}

namespace
{
struct Reads
{
  double Mean = 0.0;
  int P99 = 0;
  int Max = 0;
  long Fragments = 0;
};

// The reads per fragment a ReadCountingMapper wrote into @a counted.
Reads ReadsIn(const Picture& counted)
{
  std::vector<int> counts;
  for (size_t p = 0; p + 2 < counted.RGB.size(); p += 3)
  {
    if (counted.RGB[p + 1] == 255 && counted.RGB[p + 2] == 0)
    {
      counts.push_back(counted.RGB[p]);
    }
  }
  Reads reads;
  reads.Fragments = static_cast<long>(counts.size());
  if (counts.empty())
  {
    return reads;
  }
  std::sort(counts.begin(), counts.end());
  double sum = 0.0;
  for (int c : counts)
  {
    sum += c;
  }
  reads.Mean = sum / counts.size();
  reads.P99 = counts[static_cast<size_t>(0.99 * (counts.size() - 1))];
  reads.Max = counts.back();
  return reads;
}

// The depth reads per fragment of relief mapping on @a surface, from a relief map.
Reads CountReads(const Surface& surface, Options options)
{
  options.CountReads = true;
  View view;
  FitView(surface, view);
  Picture picture;
  Draw(view, { SurfaceActor(surface, Look::Relief, options) }, picture);
  const Reads reads = ReadsIn(picture);
  std::cout << surface.Name << (options.AdaptiveSteps ? ", adaptive" : ", fixed 32 + 8")
            << ": depth reads per fragment, mean " << reads.Mean << ", 99th percentile "
            << reads.P99 << ", most " << reads.Max << " (" << reads.Fragments << " fragments)\n";
  return reads;
}
} // namespace

// The read counts follow the search: with fixed steps every fragment the relief reaches reads
// the first depth, at least one linear step and all the binary steps, and none more than
// 1 + LinearSearchSteps + BinarySearchSteps; adaptive steps read fewer on every truth scene.
TEST(SurfaceDetailRelief, DepthReadsFollowTheSearch)
{
  vtkNew<vtkSurfaceDetailMapper> defaults;
  const int most = 1 + defaults->GetLinearSearchSteps() + defaults->GetBinarySearchSteps();
  for (const Surface& surface : { Wall(), Ball(), Ring() })
  {
    Options fixed;
    fixed.AdaptiveSteps = false;
    const Reads all = CountReads(surface, fixed);
    ASSERT_GT(all.Fragments, 1000) << surface.Name;
    EXPECT_LE(all.Max, most) << surface.Name;
    EXPECT_GE(all.Mean, 2 + defaults->GetBinarySearchSteps() - 0.5) << surface.Name;
    const Reads adaptive = CountReads(surface, Options());
    EXPECT_LT(adaptive.Mean, all.Mean) << surface.Name;
    EXPECT_LE(adaptive.Max, most) << surface.Name;
  }
}

namespace
{
// A truth scene: a surface and where it is seen from.
struct Scene
{
  std::string Name;
  Surface Shape;
  ViewAngles Angles;
};

std::vector<Scene> ReliefTruthScenes()
{
  ViewAngles headOn;
  headOn.Azimuth = 0;
  headOn.Elevation = 0;
  ViewAngles torusAngles;
  torusAngles.Tilt = -55;
  return { { "wall head-on", Wall(), headOn }, { "wall oblique", Wall(), ViewAngles() },
    { "sphere", Ball(), ViewAngles() }, { "torus", Ring(), torusAngles } };
}

// The depth reads per fragment of a search on @a scene, from the counting shader's picture.
Reads ReadsOnly(const Scene& scene, Options options)
{
  View view;
  SurfaceDetailTruthScenes::FitView(scene.Shape, scene.Angles, view);
  options.CountReads = true;
  Picture counted;
  Draw(view, { SurfaceActor(scene.Shape, Look::Relief, options) }, counted);
  return ReadsIn(counted);
}

// A search's error against @a reference (RMSE in levels; by default the displaced mesh) and
// its depth reads per fragment.
struct SearchFigures
{
  double Error = 0.0;
  Reads Cost;
};

SearchFigures Search(const Scene& scene, const Options& options, const Options* reference = nullptr)
{
  View view;
  SurfaceDetailTruthScenes::FitView(scene.Shape, scene.Angles, view);
  Picture truth, relief, counted;
  Draw(view,
    { reference ? SurfaceActor(scene.Shape, Look::Relief, *reference)
                : SurfaceActor(scene.Shape, Look::Truth) },
    truth);
  Draw(view, { SurfaceActor(scene.Shape, Look::Relief, options) }, relief);
  SearchFigures figures;
  figures.Error = ObjectRMSE(relief, truth);
  figures.Cost = ReadsOnly(scene, options);
  return figures;
}

void Print(const std::string& what, const SearchFigures& figures)
{
  std::cout << what << ": error " << figures.Error << " levels, depth reads per fragment mean "
            << figures.Cost.Mean << ", 99th percentile " << figures.Cost.P99 << ", most "
            << figures.Cost.Max << " (" << figures.Cost.Fragments << " fragments)\n";
}

// The reference where no displaced mesh is: the linear and binary search at 256 + 16 steps.
Options DenseSearch(Options options)
{
  options.AdaptiveSteps = false;
  options.LinearSteps = 256;
  options.BinarySteps = 16;
  return options;
}

// What cone stepping must show on a truth scene against the linear and binary search at
// default settings: an error within 1% of its error and at most this share of its reads.
constexpr double ConeReadShare = 0.7;
bool ConeSteppingPays(const SearchFigures& linear, const SearchFigures& cones)
{
  return cones.Error <= 1.01 * linear.Error && cones.Cost.Mean <= ConeReadShare * linear.Cost.Mean;
}
} // namespace

// Against the displaced mesh, cone stepping draws what the linear and binary search draws,
// reading fewer depths on every truth scene; no fragment reads more than one per step, the
// bottom of the box and the secant steps, as many as the linear and binary search at most.
TEST(SurfaceDetailRelief, ConeSteppingIsAsAccurateInFewerReads)
{
  for (const Scene& scene : ReliefTruthScenes())
  {
    Options cones;
    cones.ConeStepping = true;
    const SearchFigures linear = Search(scene, Options());
    const SearchFigures stepped = Search(scene, cones);
    Print(scene.Name + ", linear + binary search", linear);
    Print(scene.Name + ", cone stepping", stepped);
    ASSERT_GT(stepped.Cost.Fragments, 1000) << scene.Name;
    EXPECT_TRUE(ConeSteppingPays(linear, stepped)) << scene.Name;
    vtkNew<vtkSurfaceDetailMapper> defaults;
    EXPECT_LE(stepped.Cost.Max,
      defaults->GetLinearSearchSteps() + 1 + defaults->GetBinarySearchSteps())
      << scene.Name;
  }
}

// The cones themselves: where rays cross many texels (the bricks at 512 x 512 texels), a map
// of zero-width cones at the top of the box, which leaves the march one read per texel, reads
// far more; and cone stepping switched off does not pay.
TEST(SurfaceDetailRelief, ConeSteppingMutationsDoNotPay)
{
  const std::vector<Scene> scenes = ReliefTruthScenes();
  for (const Scene& scene : { scenes[1], scenes[2], scenes[3] })
  {
    Options zero, cones;
    zero.MapSize = cones.MapSize = 512;
    zero.ConeStepping = cones.ConeStepping = true;
    zero.ZeroCones = true;
    const Reads flat = ReadsOnly(scene, zero);
    const Reads stepped = ReadsOnly(scene, cones);
    std::cout << scene.Name << ", 512 x 512: depth reads per fragment, zero-width cones "
              << flat.Mean << ", cone stepping " << stepped.Mean << "\n";
    EXPECT_LE(stepped.Mean, 0.7 * flat.Mean) << scene.Name;
  }
  const SearchFigures linear = Search(scenes[1], Options());
  EXPECT_FALSE(ConeSteppingPays(linear, Search(scenes[1], Options())));
}

// Where a ray crosses many texels (the wall's bricks at 512 x 512 texels), cone stepping reads
// less than half the depths the linear and binary search reads; both differ from a dense search
// (256 linear and 16 binary steps) by less than two levels, a tenth of relief's own error
// against the displaced mesh. Relaxed cones reach over the bricks' edges where conservative
// ones stop at their foot: they save a tenth of the reads or more, as accurately.
TEST(SurfaceDetailRelief, ConeSteppingOnAFineMap)
{
  const Scene scene = ReliefTruthScenes()[1];
  Options linear;
  linear.MapSize = 512;
  Options relaxed = linear;
  relaxed.ConeStepping = true;
  Options conservative = relaxed;
  conservative.ConeType = vtkHeightMapToConeMap::Conservative;
  const Options dense = DenseSearch(linear);
  const SearchFigures searched = Search(scene, linear, &dense);
  const SearchFigures stepped = Search(scene, relaxed, &dense);
  const SearchFigures narrow = Search(scene, conservative, &dense);
  Print("512 x 512 bricks, linear + binary search", searched);
  Print("512 x 512 bricks, cone stepping", stepped);
  Print("512 x 512 bricks, cone stepping with conservative cones", narrow);
  EXPECT_LE(stepped.Cost.Mean, 0.5 * searched.Cost.Mean);
  EXPECT_LE(stepped.Error, 2.0);
  EXPECT_LE(searched.Error, 2.0);
  EXPECT_LE(stepped.Cost.Mean, 0.9 * narrow.Cost.Mean);
  EXPECT_LE(stepped.Error, 1.01 * narrow.Error);
}

// Thin walls (one texel of full height every eight, on a flat floor): a step that passed
// through one would draw the floor behind it. Against a dense search, cone stepping is closer
// than the linear and binary search, which steps over some of the walls' ridges.
TEST(SurfaceDetailRelief, ConeStepsDoNotPassThroughThinWalls)
{
  auto walls = vtkSmartPointer<vtkImageData>::New();
  walls->SetDimensions(64, 64, 1);
  walls->AllocateScalars(VTK_FLOAT, 1);
  auto* h = static_cast<float*>(walls->GetScalarPointer());
  for (int j = 0; j < 64; ++j)
  {
    for (int i = 0; i < 64; ++i)
    {
      h[j * 64 + i] = (i % 8 == 0 || j % 8 == 0) ? 1.0f : 0.0f;
    }
  }
  const Scene scene = ReliefTruthScenes()[1];
  Options linear;
  linear.Heights = walls;
  Options cones = linear;
  cones.ConeStepping = true;
  const Options dense = DenseSearch(linear);
  const SearchFigures searched = Search(scene, linear, &dense);
  const SearchFigures stepped = Search(scene, cones, &dense);
  Print("thin walls, linear + binary search", searched);
  Print("thin walls, cone stepping", stepped);
  EXPECT_LT(stepped.Error, searched.Error);
}

// Straight down a parallel camera no view ray runs sideways, and zero-width cones give no cone
// to step by: the march must still draw what the linear search draws.
TEST(SurfaceDetailRelief, ConeSteppingHeadOnUnderAParallelCamera)
{
  ViewAngles headOn;
  headOn.Azimuth = 0;
  headOn.Elevation = 0;
  View view;
  SurfaceDetailTruthScenes::FitView(Wall(), headOn, view);
  vtkSmartPointer<vtkImageData> heights = BrickTextures::Heights(TruthBricks());
  vtkNew<vtkHeightMapToConeMap> cones;
  cones->SetInputData(heights);
  cones->Update();
  cones->GetOutput()->GetPointData()->GetScalars()->Fill(0.0);
  auto relief = [&](bool stepped)
  {
    return WallActor(
      [&](vtkSurfaceDetailMapper* mapper)
      {
        mapper->SetTechniqueToReliefMapping();
        mapper->SetHeightMap(RepeatedTexture(heights));
        mapper->SetConeMap(stepped ? RepeatedTexture(cones->GetOutput()) : nullptr);
        mapper->DepthCorrectionOn();
      });
  };
  Picture linear, stepped;
  DrawParallel(view, relief(false), linear);
  DrawParallel(view, relief(true), stepped);
  EXPECT_LE(MaxDifference(linear, stepped), 2);
}
