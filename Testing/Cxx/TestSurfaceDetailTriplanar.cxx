// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Triplanar mapping in vtkSurfaceDetailMapper, against two independent truths:
// - An axis-aligned box without texture coordinates or tangents, mapped triplanar, against the
//   same box given per-face texture coordinates and tangents by the rules of
//   vtkSurfaceDetail::TriplanarProject and drawn by the mapper's ordinary (planar) normal and
//   bump mapping and VTK's own colour texturing: the same picture on all six faces (strict
//   comparison), seen from two sides. Each rule changed in the reference (one axis's s and t
//   swapped, or its s mirrored) must make the pictures differ.
// - A sphere against a CPU evaluation of the triplanar formulas (the conventions header's
//   functions, the closed-form normal map, VTK's Phong): PSNR >= 40 dB everywhere and in the
//   bands where the dominant axis changes; without the reorientation of the frames, or with
//   one axis mirrored, the CPU picture no longer matches.

#include "SurfaceDetailImageComparison.h"
#include "SurfaceDetailMapperAnalyticScene.h"
#include "vtkDisplacementMapFilter.h"
#include "vtkParametricSphere.h"
#include "vtkParametricSurfaceSource.h"
#include "vtkSurfaceDetailConventions.h"

#include <vtkTransform.h>

namespace
{
constexpr double BoxHalf = 0.55;
const Vec3 BoxCentre{ 0.15, -0.1, 0.05 };
constexpr double Scale = 0.8; // texture squares per unit

// A wrong rule for the reference: on face axis Axis, s and t swapped or s mirrored.
struct Rule
{
  int Axis = -1;
  bool Swap = false;
  bool MirrorS = false;
};

// The six faces of the box, each a grid of its own points with the face's normal; with
// @a planar, texture coordinates and a tangent frame by the triplanar rules (or @a rule's).
vtkSmartPointer<vtkPolyData> MakeBox(bool planar, const Rule& rule = Rule())
{
  constexpr int cells = 4;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetName("Normals");
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  tcoords->SetName("TCoords");
  vtkNew<vtkFloatArray> frame;
  frame->SetNumberOfComponents(4);
  frame->SetName("Tangents");
  vtkNew<vtkCellArray> polys;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (double sigma : { 1.0, -1.0 })
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const vtkIdType first = points->GetNumberOfPoints();
      double n[3] = { 0, 0, 0 };
      n[axis] = sigma;
      for (int j = 0; j <= cells; ++j)
      {
        for (int i = 0; i <= cells; ++i)
        {
          double p[3];
          p[axis] = BoxCentre[axis] + sigma * BoxHalf;
          p[u] = BoxCentre[u] + BoxHalf * (-1.0 + 2.0 * i / cells);
          p[v] = BoxCentre[v] + BoxHalf * (-1.0 + 2.0 * j / cells);
          points->InsertNextPoint(p);
          normals->InsertNextTuple(n);
          double st[2], T[3], B[3];
          vtkSurfaceDetail::TriplanarProject(axis, p, n, Scale, st, T, B);
          if (rule.Axis == axis && rule.Swap)
          {
            std::swap(st[0], st[1]);
            std::swap(T, B);
          }
          if (rule.Axis == axis && rule.MirrorS)
          {
            st[0] = -st[0];
            T[0] = -T[0], T[1] = -T[1], T[2] = -T[2];
          }
          // The handedness that the (possibly wrong) coordinates imply: sign((N x T).dP/dt).
          const double NxT[3] = { n[1] * T[2] - n[2] * T[1], n[2] * T[0] - n[0] * T[2],
            n[0] * T[1] - n[1] * T[0] };
          const double w = NxT[0] * B[0] + NxT[1] * B[1] + NxT[2] * B[2] < 0 ? -1.0 : 1.0;
          tcoords->InsertNextTuple(st);
          frame->InsertNextTuple4(T[0], T[1], T[2], w);
        }
      }
      for (int j = 0; j < cells; ++j)
      {
        for (int i = 0; i < cells; ++i)
        {
          const vtkIdType a = first + j * (cells + 1) + i, b = a + 1, c = a + cells + 2,
                          d = a + cells + 1;
          // Counter-clockwise seen from outside: u x v is +axis, so flip on the - faces.
          const vtkIdType t1[3] = { a, sigma > 0 ? b : c, sigma > 0 ? c : b };
          const vtkIdType t2[3] = { a, sigma > 0 ? c : d, sigma > 0 ? d : c };
          polys->InsertNextCell(3, t1);
          polys->InsertNextCell(3, t2);
        }
      }
    }
  }
  auto box = vtkSmartPointer<vtkPolyData>::New();
  box->SetPoints(points);
  box->SetPolys(polys);
  box->GetPointData()->SetNormals(normals);
  if (planar)
  {
    box->GetPointData()->SetTCoords(tcoords);
    SetTangentFrame(box, frame);
  }
  return box;
}

// A colour texture that shows any mirroring or swap: red ramps along s, green along t.
vtkSmartPointer<vtkTexture> MakeColourTexture()
{
  auto texture = MakeTexture(128, 3,
    [](double s, double t, double* rgb)
    {
      rgb[0] = 0.3 + 0.7 * s;
      rgb[1] = 0.3 + 0.7 * t * t;
      rgb[2] = 0.5 + 0.4 * std::sin(2 * Pi * (s + 2 * t));
    });
  return texture;
}

// Turns the actor so that object direction @a d faces the camera (which looks down -z).
void Face(vtkActor* actor, const Vec3& d)
{
  const Vec3 n = Normalized(d);
  const Vec3 axis{ n[1], -n[0], 0.0 }; // n x z
  const double angle = std::acos(n[2]) * 180.0 / Pi;
  actor->SetOrientation(0, 0, 0);
  actor->RotateWXYZ(angle, axis[0], axis[1], axis[2]);
}

using Configure = std::function<void(vtkSurfaceDetailMapper*, vtkActor*)>;

std::vector<unsigned char> RenderBox(
  bool triplanar, const Vec3& facing, const Configure& configure, const Rule& rule = Rule())
{
  auto mapper = MakeMapper(MakeBox(!triplanar, rule));
  mapper->SetTriplanar(triplanar);
  mapper->SetTriplanarScale(Scale);
  Scene scene(mapper);
  scene.Mat.Specular = 0.3;
  configure(mapper, scene.Actor);
  Face(scene.Actor, facing);
  return scene.Render();
}

double FractionOver(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  long over = 0;
  for (size_t k = 0; k + 2 < a.size(); k += 3)
  {
    int largest = 0;
    for (int c = 0; c < 3; ++c)
    {
      largest = std::max(largest, std::abs(int(a[k + c]) - int(b[k + c])));
    }
    over += largest > SurfaceDetailImageComparison::Tolerance ? 1 : 0;
  }
  return static_cast<double>(over) / (a.size() / 3);
}

const std::vector<std::pair<std::string, Configure>>& BoxTechniques()
{
  static const std::vector<std::pair<std::string, Configure>> techniques = {
    { "colour", [](vtkSurfaceDetailMapper*, vtkActor* a) { a->SetTexture(MakeColourTexture()); } },
    { "normal map",
      [](vtkSurfaceDetailMapper* m, vtkActor*)
      {
        m->SetTechniqueToNormalMapping();
        m->SetNormalMap(MakeNormalMap());
      } },
    { "bump",
      [](vtkSurfaceDetailMapper* m, vtkActor*)
      {
        m->SetTechniqueToBumpMapping();
        m->SetHeightMap(MakeHeightMap());
        m->SetBumpScale(Strength);
      } },
  };
  return techniques;
}

const Vec3 FromPlus{ 1.0, 0.8, 0.6 };
const Vec3 FromMinus{ -0.7, -1.0, -0.8 };
} // namespace

// Every face, the three facing the negative axes included: triplanar equals planar mapping.
TEST(vtkSurfaceDetailTriplanar, BoxEqualsPlanarMappingOnEveryFace)
{
  for (const auto& technique : BoxTechniques())
  {
    for (const Vec3& facing : { FromPlus, FromMinus })
    {
      const auto triplanar = RenderBox(true, facing, technique.second);
      const auto planar = RenderBox(false, facing, technique.second);
      const double over = FractionOver(triplanar, planar);
      std::cout << technique.first << " from (" << facing[0] << ", " << facing[1] << ", "
                << facing[2] << "): " << over << " of the pixels over the tolerance\n";
      EXPECT_LE(over, SurfaceDetailImageComparison::MaxFractionOver) << technique.first;
      // The texture is there: the plain box is another picture.
      const auto plain = RenderBox(false, facing, [](vtkSurfaceDetailMapper*, vtkActor*) {});
      EXPECT_GT(FractionOver(triplanar, plain), 0.05) << technique.first;
    }
  }
}

// Each rule matters: a reference built with one axis's s and t swapped, or its s mirrored,
// is another picture (the test above would catch the mapper breaking that rule).
TEST(vtkSurfaceDetailTriplanar, EveryRuleIsSeen)
{
  for (const auto& technique : BoxTechniques())
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      for (const bool swap : { true, false })
      {
        Rule rule;
        rule.Axis = axis;
        rule.Swap = swap;
        rule.MirrorS = !swap;
        double worst = 1.0;
        for (const Vec3& facing : { FromPlus, FromMinus })
        {
          const auto triplanar = RenderBox(true, facing, technique.second);
          const auto wrong = RenderBox(false, facing, technique.second, rule);
          worst = std::min(worst, FractionOver(triplanar, wrong));
        }
        EXPECT_GT(worst, 0.01) << technique.first << ": axis " << axis
                               << (swap ? " swapped" : " mirrored") << " went unseen";
      }
    }
  }
}

namespace
{
constexpr double SphereRadius = 0.9;

// How the CPU evaluation may be wrong, to show the comparison sees it.
struct Formula
{
  bool Reorient = true;
  int MirroredAxis = -1;
};

// The triplanar detail normal at point p of normal n: the conventions header's projections of
// the closed-form normal map, blended.
Vec3 TriplanarDetail(const Vec3& p, const Vec3& n, double sharpness, const Formula& formula)
{
  double w[3];
  vtkSurfaceDetail::TriplanarWeights(n.data(), sharpness, w);
  Vec3 detail{ 0, 0, 0 };
  for (int axis = 0; axis < 3; ++axis)
  {
    if (w[axis] == 0.0)
    {
      continue;
    }
    double st[2], T[3], B[3];
    vtkSurfaceDetail::TriplanarProject(axis, p.data(), n.data(), Scale, st, T, B);
    if (formula.MirroredAxis == axis)
    {
      st[0] = -st[0];
      T[0] = -T[0], T[1] = -T[1], T[2] = -T[2];
    }
    const double fs = st[0] - std::floor(st[0]), ft = st[1] - std::floor(st[1]);
    const Vec3 nTS = TangentSpaceNormal(fs, ft);
    double nA[3];
    if (formula.Reorient)
    {
      vtkSurfaceDetail::TriplanarNormal(nTS.data(), n.data(), T, nA);
    }
    else
    {
      // The projection's own frame, its normal the axis: what skipping the reorientation gives.
      const double sigma = n[axis] < 0 ? -1.0 : 1.0;
      for (int i = 0; i < 3; ++i)
      {
        nA[i] = nTS[0] * T[i] + nTS[1] * B[i] + nTS[2] * (i == axis ? sigma : 0.0);
      }
    }
    const Vec3 unit = Normalized({ nA[0], nA[1], nA[2] });
    for (int i = 0; i < 3; ++i)
    {
      detail[i] += w[axis] * unit[i];
    }
  }
  return Normalized(detail);
}

// PSNR of the picture against the CPU evaluation over the sphere's pixels (away from the
// rim, where the mesh's facets show), or only those where the two largest normal components
// are within @a band of each other (where the dominant projection changes); 0 = all.
double SpherePSNR(const std::vector<unsigned char>& image, const Material& mat,
  double sharpness, const Formula& formula, double band = 0.0)
{
  double sum = 0.0;
  long count = 0;
  for (int j = 0; j < WindowSize; ++j)
  {
    for (int i = 0; i < WindowSize; ++i)
    {
      const double x = -1.0 + 2.0 * (i + 0.5) / WindowSize;
      const double y = -1.0 + 2.0 * (j + 0.5) / WindowSize;
      const double r2 = x * x + y * y;
      if (r2 > 0.9 * 0.9 * SphereRadius * SphereRadius)
      {
        continue;
      }
      const Vec3 p{ x, y, std::sqrt(SphereRadius * SphereRadius - r2) };
      const Vec3 n = Normalized(p);
      if (band > 0.0)
      {
        std::array<double, 3> a{ std::abs(n[0]), std::abs(n[1]), std::abs(n[2]) };
        std::sort(a.begin(), a.end());
        if (a[2] - a[1] > band)
        {
          continue;
        }
      }
      const Vec3 e = Shade(TriplanarDetail(p, n, sharpness, formula), p, mat);
      for (int k = 0; k < 3; ++k)
      {
        const double diff =
          255.0 * std::min(1.0, std::max(0.0, e[k])) - image[3 * (j * WindowSize + i) + k];
        sum += diff * diff;
        ++count;
      }
    }
  }
  EXPECT_GT(count, 3 * 300) << "too few pixels compared";
  const double mse = sum / std::max(count, 1L);
  return mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 99.0;
}

vtkSmartPointer<vtkSurfaceDetailMapper> MakeSphereMapper()
{
  vtkNew<vtkParametricSphere> sphere;
  sphere->SetRadius(SphereRadius);
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->SetUResolution(256);
  source->SetVResolution(128);
  source->GenerateTextureCoordinatesOff();
  source->Update();
  auto mapper = MakeMapper(source->GetOutput());
  mapper->TriplanarOn();
  mapper->SetTriplanarScale(Scale);
  return mapper;
}
} // namespace

// The sphere against the CPU evaluation of the same formulas, everywhere and where the
// dominant axis changes (no seam); a missing reorientation or a mirrored axis is caught.
TEST(vtkSurfaceDetailTriplanar, SphereMatchesCPUEvaluation)
{
  for (const double sharpness : { 1.0, 4.0, 16.0 })
  {
    auto mapper = MakeSphereMapper();
    mapper->SetTechniqueToNormalMapping();
    mapper->SetNormalMap(MakeNormalMap());
    mapper->SetTriplanarSharpness(sharpness);
    Scene scene(mapper);
    const auto image = scene.Render();
    const double all = SpherePSNR(image, scene.Mat, sharpness, Formula());
    const double seams = SpherePSNR(image, scene.Mat, sharpness, Formula(), 0.1);
    std::cout << "sharpness " << sharpness << ": " << all << " dB, " << seams
              << " dB where the dominant axis changes\n";
    EXPECT_GE(all, 40.0);
    EXPECT_GE(seams, 40.0);
    Formula unreoriented;
    unreoriented.Reorient = false;
    EXPECT_LT(SpherePSNR(image, scene.Mat, sharpness, unreoriented), 33.0);
    for (int axis = 0; axis < 3; ++axis)
    {
      Formula mirrored;
      mirrored.MirroredAxis = axis;
      EXPECT_LT(SpherePSNR(image, scene.Mat, sharpness, mirrored), 33.0) << "axis " << axis;
    }
  }
}

// The weights sum to one: a white colour texture projected leaves the picture as it is, and a
// grey one darkens it (the projected colour is there).
TEST(vtkSurfaceDetailTriplanar, WeightsSumToOne)
{
  auto flat = [](double value)
  {
    return MakeTexture(8, 3,
      [value](double, double, double* rgb) { rgb[0] = rgb[1] = rgb[2] = value; });
  };
  auto plainMapper = MakeSphereMapper();
  plainMapper->TriplanarOff();
  Scene plain(plainMapper);
  const auto reference = plain.Render();
  for (const double sharpness : { 1.0, 3.0, 8.0 })
  {
    auto mapper = MakeSphereMapper();
    mapper->SetTriplanarSharpness(sharpness);
    Scene white(mapper);
    white.Actor->SetTexture(flat(1.0));
    EXPECT_LE(FractionOver(white.Render(), reference), 0.0) << "sharpness " << sharpness;
    auto greyMapper = MakeSphereMapper();
    Scene grey(greyMapper);
    grey.Actor->SetTexture(flat(0.5));
    EXPECT_GT(FractionOver(grey.Render(), reference), 0.3);
  }
  for (const double sharpness : { 1.0, 4.0, 64.0 })
  {
    for (const Vec3& n : { Vec3{ 1, 0, 0 }, Normalized({ 1, -1, 0.2 }), Normalized({ 0.3, 0.5, -0.8 }) })
    {
      double w[3];
      vtkSurfaceDetail::TriplanarWeights(n.data(), sharpness, w);
      EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-12);
    }
  }
}

// Settings the technique cannot use are refused with a message that names them.
TEST(vtkSurfaceDetailTriplanar, ParallaxRefused)
{
  auto mapper = MakeSphereMapper();
  mapper->SetTechniqueToParallaxMapping();
  mapper->SetHeightMap(MakeHeightMap());
  vtkNew<ErrorCounter> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  Scene scene(mapper);
  scene.Render();
  EXPECT_EQ(errors->Errors, 1);
  EXPECT_NE(errors->Last.find("triplanar"), std::string::npos) << errors->Last;
  EXPECT_EQ(mapper->GetActiveTechnique(), vtkSurfaceDetailMapper::Plain);
}

// World space: the texture stays in the world. A box moved by the actor shows what the same
// box moved in its own points shows with object space.
TEST(vtkSurfaceDetailTriplanar, WorldSpaceFollowsTheWorld)
{
  const double shift[3] = { 0.21, -0.13, 0.0 };
  auto moved = [&](bool byActor)
  {
    auto box = MakeBox(false);
    if (!byActor)
    {
      vtkPoints* points = box->GetPoints();
      for (vtkIdType k = 0; k < points->GetNumberOfPoints(); ++k)
      {
        double p[3];
        points->GetPoint(k, p);
        points->SetPoint(k, p[0] + shift[0], p[1] + shift[1], p[2] + shift[2]);
      }
    }
    auto mapper = MakeMapper(box);
    mapper->TriplanarOn();
    mapper->SetTriplanarScale(Scale);
    mapper->SetTriplanarSpace(
      byActor ? vtkSurfaceDetailMapper::WorldSpace : vtkSurfaceDetailMapper::ObjectSpace);
    mapper->SetTechniqueToNormalMapping();
    mapper->SetNormalMap(MakeNormalMap());
    Scene scene(mapper);
    scene.Actor->SetTexture(MakeColourTexture());
    scene.Actor->SetPosition(byActor ? shift[0] : 0.0, byActor ? shift[1] : 0.0, 0.0);
    return scene.Render();
  };
  const auto world = moved(true);
  EXPECT_LE(FractionOver(world, moved(false)), SurfaceDetailImageComparison::MaxFractionOver);
}

// A sphere displaced a little by the filter's triplanar sampling (Approximate normals, drawn
// plain) shades as the undisplaced sphere bump-mapped triplanar with the same map and
// BumpScale = ScaleFactor * TriplanarScale; bumps sunk instead of raised do not.
TEST(vtkSurfaceDetailTriplanar, DisplacementAgreesWithBumpMapping)
{
  constexpr double scaleFactor = 0.05;
  auto heights = MakeHeightMap();
  vtkNew<vtkParametricSphere> sphere;
  sphere->SetRadius(SphereRadius);
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->SetUResolution(512);
  source->SetVResolution(256);
  source->GenerateTextureCoordinatesOff();
  vtkNew<vtkDisplacementMapFilter> displace;
  displace->SetInputConnection(source->GetOutputPort());
  displace->SetSourceData(heights->GetInput());
  displace->SetWrapToRepeat();
  displace->SetScaleFactor(scaleFactor);
  displace->SetMidlevel(0.5);
  displace->SetNormalModeToApproximate();
  displace->TriplanarOn();
  displace->SetTriplanarScale(Scale);
  displace->Update();
  auto displacedMapper = MakeMapper(displace->GetOutput());
  Scene displaced(displacedMapper);
  const auto reference = displaced.Render();

  auto render = [&](double bumpScale)
  {
    auto mapper = MakeSphereMapper();
    mapper->SetTechniqueToBumpMapping();
    mapper->SetHeightMap(heights);
    mapper->SetBumpScale(bumpScale);
    Scene scene(mapper);
    return scene.Render();
  };
  auto psnr = [&](const std::vector<unsigned char>& image)
  {
    double sum = 0.0;
    long count = 0;
    for (int j = 0; j < WindowSize; ++j)
    {
      for (int i = 0; i < WindowSize; ++i)
      {
        const double x = -1.0 + 2.0 * (i + 0.5) / WindowSize;
        const double y = -1.0 + 2.0 * (j + 0.5) / WindowSize;
        if (x * x + y * y > 0.9 * 0.9 * SphereRadius * SphereRadius)
        {
          continue;
        }
        for (int k = 0; k < 3; ++k)
        {
          const double d = double(image[3 * (j * WindowSize + i) + k]) -
            reference[3 * (j * WindowSize + i) + k];
          sum += d * d;
          ++count;
        }
      }
    }
    return 10.0 * std::log10(255.0 * 255.0 / std::max(sum / count, 1e-12));
  };
  const double agree = psnr(render(scaleFactor * Scale));
  const double sunk = psnr(render(-scaleFactor * Scale));
  std::cout << "bump mapping against the displaced sphere: " << agree << " dB; sunk: " << sunk
            << " dB\n";
  EXPECT_GE(agree, 40.0);
  EXPECT_LT(sunk, 35.0);
}

namespace
{
class ProgramProbe : public vtkSurfaceDetailMapper
{
public:
  static ProgramProbe* New();
  vtkTypeMacro(ProgramProbe, vtkSurfaceDetailMapper);
  std::string FragmentSource()
  {
    vtkShaderProgram* program = this->Primitives[PrimitiveTris].Program;
    return program ? program->GetFragmentShader()->GetSource() : std::string();
  }
};
vtkStandardNewMacro(ProgramProbe);
}

// Only what is switched on is compiled: colour alone has no normal code, normal mapping no bump
// code, and triplanar off no triplanar code.
TEST(vtkSurfaceDetailTriplanar, ShaderHoldsOnlyWhatIsOn)
{
  vtkNew<ProgramProbe> mapper;
  mapper->SetInputData(MakeBox(false));
  mapper->SetNormalMap(MakeNormalMap());
  mapper->SetHeightMap(MakeHeightMap());
  mapper->TriplanarOn();
  Scene scene(mapper);
  scene.Actor->SetTexture(MakeColourTexture());
  auto has = [&](const char* what) { return mapper->FragmentSource().find(what) != std::string::npos; };
  scene.Render();
  EXPECT_TRUE(has("#define SD_TRIPLANAR_COLOR"));
  EXPECT_FALSE(has("#define SD_TRIPLANAR_NORMAL_MAP"));
  EXPECT_FALSE(has("sdTriplanarSample(sdTriplanarPositionVSOutput, sdN)"));
  mapper->SetTechniqueToNormalMapping();
  scene.Render();
  EXPECT_TRUE(has("#define SD_TRIPLANAR_NORMAL_MAP"));
  EXPECT_FALSE(has("#define SD_TRIPLANAR_BUMP"));
  EXPECT_FALSE(has("uniform sampler2D sdHeightMap"));
  mapper->SetTechniqueToBumpMapping();
  scene.Render();
  EXPECT_TRUE(has("#define SD_TRIPLANAR_BUMP"));
  EXPECT_FALSE(has("uniform sampler2D sdNormalMap"));
  scene.Actor->SetTexture(nullptr);
  scene.Render();
  EXPECT_FALSE(has("#define SD_TRIPLANAR_COLOR"));
  mapper->SetTechniqueToPlain();
  mapper->TriplanarOff(); // the box has no texture coordinates: plain, no triplanar code
  scene.Render();
  EXPECT_FALSE(has("sdTriplanar"));
}
