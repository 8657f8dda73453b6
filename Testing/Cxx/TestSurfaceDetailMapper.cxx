// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Analytic image tests for vtkSurfaceDetailMapper. An orthographic camera looks at a
// rectangle lit by one directional scene light; the expected picture is computed on the
// CPU from closed forms: the normal of a known height function h(s,t) in tangent space,
// taken through the actor's transform as a normal (inverse transpose), and VTK 9.1's Phong
// formula (vtkOpenGLPolyDataMapper's light-kit shader):
//   ambient*Ca + diffuse*Cd*max(0, n.-L) + specular*Cs*sign(df)*max(0, r.v)^power,
//   r = reflect(L, n), v = normalize(-vertexVC).
// Images must match with PSNR >= 40 dB; each test also shows that a plausible mistake
// (ignoring handedness, the wrong green direction, no transform, no parallax) is caught.

#include "SurfaceDetailMapperAnalyticScene.h"

// A uniform-only setting (no shader rebuild) still modifies the mapper for the pipeline and its
// observers, and a change of one of its maps' textures shows in its MTime, as a texture on a
// vtkProperty shows in the actor's.
TEST(vtkSurfaceDetailMapper, MTimeFollowsSettingsAndMaps)
{
  vtkNew<vtkSurfaceDetailMapper> mapper;
  int events = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&events);
  count->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  mapper->AddObserver(vtkCommand::ModifiedEvent, count);
  // Each setter, with a value other than its current one.
  const std::vector<std::function<void()>> settings = { [&]
    { mapper->SetNormalScale(mapper->GetNormalScale() + 1.0); },
    [&] { mapper->SetBumpScale(mapper->GetBumpScale() + 1.0); },
    [&] { mapper->SetDepthScale(mapper->GetDepthScale() + 1.0); },
    [&] { mapper->SetLinearSearchSteps(mapper->GetLinearSearchSteps() + 1); },
    [&] { mapper->SetBinarySearchSteps(mapper->GetBinarySearchSteps() + 1); },
    [&] { mapper->SetGreenUp(!mapper->GetGreenUp()); },
    [&] { mapper->SetAdaptiveSteps(!mapper->GetAdaptiveSteps()); } };
  for (const auto& change : settings)
  {
    const vtkMTimeType before = mapper->GetMTime();
    const int heard = events;
    change();
    EXPECT_GT(mapper->GetMTime(), before);
    EXPECT_EQ(events, heard + 1);
  }
  // The same value again is no change.
  const int heard = events;
  mapper->SetBumpScale(mapper->GetBumpScale());
  mapper->SetGreenUp(mapper->GetGreenUp());
  EXPECT_EQ(events, heard);
  vtkNew<vtkTexture> normal, height, relief;
  mapper->SetNormalMap(normal);
  mapper->SetHeightMap(height);
  mapper->SetReliefMap(relief);
  for (vtkTexture* map : { normal.Get(), height.Get(), relief.Get() })
  {
    const vtkMTimeType before = mapper->GetMTime();
    map->SetRepeat(!map->GetRepeat());
    EXPECT_GT(mapper->GetMTime(), before);
  }
}

TEST(vtkSurfaceDetailMapper, NormalMapMatchesAnalyticShading)
{
  auto mapper = MakeMapper(MakeRectangle(false));
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  const auto image = scene.Render();
  EXPECT_EQ(mapper->GetActiveTechnique(), vtkSurfaceDetailMapper::NormalMapping);
  EXPECT_GE(PSNR(image, scene.Actor, DetailNormal(false), scene.Mat), 40.0);
  // The flat rectangle is a different picture: the test can see the detail.
  EXPECT_LT(PSNR(image, scene.Actor, FlatNormal(), scene.Mat), 30.0);
}

TEST(vtkSurfaceDetailMapper, NormalMapMirroredUsesHandedness)
{
  auto mapper = MakeMapper(MakeRectangle(true));
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  const auto image = scene.Render();
  EXPECT_GE(PSNR(image, scene.Actor, DetailNormal(true), scene.Mat), 40.0);
  // What a frame that ignores w (B = cross(N,T)) would show: bumps lit from below in t.
  NormalField ignoringW = [](double x, double y)
  {
    const Vec3 n = TangentSpaceNormal((1.0 - x) / 2, (y + 1) / 2);
    return Vec3{ -n[0], -n[1], n[2] };
  };
  EXPECT_LT(PSNR(image, scene.Actor, ignoringW, scene.Mat), 30.0);
}

// Double tangents (which VTK 9.1 does not upload itself) shade as float ones do.
TEST(vtkSurfaceDetailMapper, NormalMapDoubleTangents)
{
  auto poly = MakeRectangle(true);
  vtkNew<vtkDoubleArray> tangents;
  tangents->DeepCopy(poly->GetPointData()->GetTangents());
  poly->GetPointData()->SetTangents(tangents);
  auto mapper = MakeMapper(poly);
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  EXPECT_GE(PSNR(scene.Render(), scene.Actor, DetailNormal(true), scene.Mat), 40.0);
}

// VTK's own normal mapping (vtkProperty::SetNormalTexture) reads SurfaceDetail's tangents,
// since they are the TANGENTS attribute: on the unmirrored rectangle it draws what our
// NormalMapping draws. It ignores the handedness, so on the mirrored one it shows the bumps
// lit from the wrong side, which our mapper does not.
TEST(vtkSurfaceDetailMapper, VTKNormalTextureReadsTheTangents)
{
  for (bool mirrored : { false, true })
  {
    SCOPED_TRACE(mirrored ? "mirrored" : "not mirrored");
    vtkNew<vtkOpenGLPolyDataMapper> plain;
    plain->SetInputData(MakeRectangle(mirrored));
    Scene scene(plain);
    scene.Actor->GetProperty()->SetInterpolationToPhong();
    scene.Actor->GetProperty()->SetNormalTexture(MakeNormalMap());
    const auto image = scene.Render();
    NormalField ignoringW = [](double x, double y)
    {
      const Vec3 n = TangentSpaceNormal((1.0 - x) / 2, (y + 1) / 2);
      return Vec3{ -n[0], -n[1], n[2] };
    };
    EXPECT_GE(
      PSNR(image, scene.Actor, mirrored ? ignoringW : DetailNormal(false), scene.Mat), 40.0);
    // Without the tangents VTK draws no detail: the picture shows that it read them.
    EXPECT_LT(PSNR(image, scene.Actor, FlatNormal(), scene.Mat), 30.0);
  }
}

// vtkPolyDataTangents replaces the tangents and leaves the handedness beside them: the mapper
// warns once and still shades the mirrored rectangle right (its tangents follow dP/ds, as
// ours). Dropping the handedness is warned about too, and then w = +1 as VTK takes it.
TEST(vtkSurfaceDetailMapper, ReplacedTangentsWarnOnce)
{
  vtkNew<vtkPolyDataTangents> vtkTangents;
  vtkTangents->SetInputData(MakeRectangle(true));
  vtkTangents->Update();
  auto replaced = vtkSmartPointer<vtkPolyData>::New();
  replaced->ShallowCopy(vtkTangents->GetOutput());
  auto mapper = MakeMapper(replaced);
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(MakeNormalMap());
  vtkNew<ErrorCounter> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->AddObserver(vtkCommand::WarningEvent, errors);
  Scene scene(mapper);
  const auto image = scene.Render();
  scene.Render();
  EXPECT_EQ(errors->Warnings, 1) << errors->Last;
  EXPECT_EQ(errors->Errors, 0);
  EXPECT_NE(errors->Last.find("vtkPolyDataTangents"), std::string::npos) << errors->Last;
  EXPECT_GE(PSNR(image, scene.Actor, DetailNormal(true), scene.Mat), 40.0);

  auto dropped = MakeRectangle(true);
  dropped->GetPointData()->RemoveArray("TangentHandedness");
  mapper->SetInputData(dropped);
  scene.Render();
  EXPECT_EQ(errors->Warnings, 2) << errors->Last;
  EXPECT_NE(errors->Last.find("gone"), std::string::npos) << errors->Last;
}

// Three-component tangents, set as the point data's active tangents, are taken with w = +1.
TEST(vtkSurfaceDetailMapper, NormalMapThreeComponentTangents)
{
  auto poly = MakeRectangle(false, false);
  vtkNew<vtkFloatArray> t3;
  t3->SetName("T3");
  t3->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    t3->InsertNextTuple3(1, 0, 0);
  }
  poly->GetPointData()->SetTangents(t3);
  auto mapper = MakeMapper(poly);
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  EXPECT_GE(PSNR(scene.Render(), scene.Actor, DetailNormal(false), scene.Mat), 40.0);
  EXPECT_EQ(mapper->GetActiveTechnique(), vtkSurfaceDetailMapper::NormalMapping);
}

TEST(vtkSurfaceDetailMapper, NormalMapGreenDown)
{
  auto mapper = MakeMapper(MakeRectangle(false));
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(MakeNormalMap(false));
  mapper->GreenUpOff();
  Scene scene(mapper);
  const auto image = scene.Render();
  EXPECT_GE(PSNR(image, scene.Actor, DetailNormal(false), scene.Mat), 40.0);
  mapper->GreenUpOn(); // reading the same map green-up must be wrong
  const auto wrong = scene.Render();
  EXPECT_LT(PSNR(wrong, scene.Actor, DetailNormal(false), scene.Mat), 30.0);
}

TEST(vtkSurfaceDetailMapper, NormalMapStrength)
{
  auto mapper = MakeMapper(MakeRectangle(false));
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(MakeNormalMap());
  mapper->SetNormalScale(2.0); // the map of z = 2k*h
  Scene scene(mapper);
  EXPECT_GE(PSNR(scene.Render(), scene.Actor, DetailNormal(false, 2 * Strength), scene.Mat), 40.0);
}

TEST(vtkSurfaceDetailMapper, NormalMapSpecular)
{
  auto mapper = MakeMapper(MakeRectangle(false));
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  scene.Mat.Diffuse = 0.6;
  scene.Mat.Specular = 0.6;
  scene.Mat.SpecularPower = 12.0;
  const auto image = scene.Render();
  EXPECT_GE(PSNR(image, scene.Actor, DetailNormal(false), scene.Mat), 40.0);
  Material noSpecular = scene.Mat;
  noSpecular.Specular = 0.0;
  EXPECT_LT(PSNR(image, scene.Actor, DetailNormal(false), noSpecular), 30.0);
}

TEST(vtkSurfaceDetailMapper, NormalMapRotatedNonUniformScale)
{
  auto mapper = MakeMapper(MakeRectangle(true));
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  scene.Actor->SetScale(0.8, 0.45, 1.7);
  scene.Actor->RotateZ(25);
  scene.Actor->RotateX(-35);
  scene.Actor->RotateY(20);
  scene.Mat.Specular = 0.4;
  const auto image = scene.Render();
  EXPECT_GE(PSNR(image, scene.Actor, DetailNormal(true), scene.Mat), 40.0);
}

TEST(vtkSurfaceDetailMapper, NormalMapPositionalSpotLight)
{
  Spot.Enabled = true;
  auto mapper = MakeMapper(MakeRectangle(true));
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  scene.Mat.Specular = 0.5;
  const auto image = scene.Render();
  EXPECT_GE(PSNR(image, scene.Actor, DetailNormal(true), scene.Mat), 40.0);
  Spot.Enabled = false; // the directional light's picture is another one
  EXPECT_LT(PSNR(image, scene.Actor, DetailNormal(true), scene.Mat), 30.0);
}

TEST(vtkSurfaceDetailMapper, BumpForwardDifferences)
{
  auto mapper = MakeMapper(MakeRectangle(false));
  mapper->SetTechniqueToBumpMapping();
  mapper->SetDifferenceSchemeToForward();
  mapper->SetHeightMap(MakeHeightMap());
  mapper->SetBumpScale(Strength);
  Scene scene(mapper);
  const auto image = scene.Render();
  EXPECT_GE(PSNR(image, scene.Actor, DetailNormal(false), scene.Mat), 40.0);
  mapper->SetBumpScale(-Strength); // sunk instead of raised is another picture
  EXPECT_LT(PSNR(scene.Render(), scene.Actor, DetailNormal(false), scene.Mat), 30.0);
}

// The height can live in any channel: an RGBA image with the heights in alpha and noise in
// RGB bump-maps, with HeightComponent 3, as the heights alone do; with the default channel 0
// it reads the noise, another picture.
TEST(vtkSurfaceDetailMapper, HeightComponentChoosesTheChannel)
{
  auto mapper = MakeMapper(MakeRectangle(false));
  mapper->SetTechniqueToBumpMapping();
  mapper->SetHeightMap(MakeTexture(256, 4,
    [](double s, double t, double* h)
    {
      h[0] = 0.5 + 0.5 * std::sin(40.0 * s * t);
      h[1] = h[2] = 0.0;
      h[3] = Height(s, t);
    }));
  mapper->SetBumpScale(Strength);
  EXPECT_EQ(mapper->GetHeightComponent(), 0);
  Scene scene(mapper);
  EXPECT_LT(PSNR(scene.Render(), scene.Actor, DetailNormal(false), scene.Mat), 30.0);
  mapper->SetHeightComponent(3);
  EXPECT_GE(PSNR(scene.Render(), scene.Actor, DetailNormal(false), scene.Mat), 40.0);
  mapper->SetHeightComponent(7); // clamped to the last channel an image can have
  EXPECT_EQ(mapper->GetHeightComponent(), 3);
}

TEST(vtkSurfaceDetailMapper, BumpCentralDifferencesMirroredSpecular)
{
  auto mapper = MakeMapper(MakeRectangle(true));
  mapper->SetTechniqueToBumpMapping();
  mapper->SetDifferenceSchemeToCentral();
  mapper->SetHeightMap(MakeHeightMap());
  mapper->SetBumpScale(Strength);
  Scene scene(mapper);
  scene.Mat.Specular = 0.5;
  EXPECT_GE(PSNR(scene.Render(), scene.Actor, DetailNormal(true), scene.Mat), 40.0);
}

TEST(vtkSurfaceDetailMapper, BumpRotatedNonUniformScale)
{
  // The tangent frame goes through the normal matrix like the normal: a non-uniform scale
  // must tilt the bumps as it tilts the surface they stand on.
  auto mapper = MakeMapper(MakeRectangle(true));
  mapper->SetTechniqueToBumpMapping();
  mapper->SetDifferenceSchemeToCentral();
  mapper->SetHeightMap(MakeHeightMap());
  mapper->SetBumpScale(Strength);
  Scene scene(mapper);
  scene.Actor->SetScale(0.8, 0.45, 1.7);
  scene.Actor->RotateZ(25);
  scene.Actor->RotateX(-35);
  scene.Actor->RotateY(20);
  scene.Mat.Specular = 0.4;
  EXPECT_GE(PSNR(scene.Render(), scene.Actor, DetailNormal(true), scene.Mat), 40.0);
}

TEST(vtkSurfaceDetailMapper, BumpTangentFree)
{
  // No tangent array at all: the frame comes from screen-space derivatives.
  auto mapper = MakeMapper(MakeRectangle(true, false));
  mapper->SetTechniqueToBumpMapping();
  mapper->TangentFreeOn();
  mapper->SetDifferenceSchemeToCentral();
  mapper->SetHeightMap(MakeHeightMap());
  mapper->SetBumpScale(Strength);
  Scene scene(mapper);
  scene.Actor->RotateX(-30);
  scene.Actor->RotateZ(15);
  EXPECT_GE(PSNR(scene.Render(), scene.Actor, DetailNormal(true), scene.Mat), 40.0);
  EXPECT_EQ(mapper->GetActiveTechnique(), vtkSurfaceDetailMapper::BumpMapping);
}

// Seen from behind, the bumps are the same surface: its normal there is the front normal
// negated, with or without tangents.
TEST(vtkSurfaceDetailMapper, BumpBackFaceMatchesFrontSurface)
{
  for (bool tangentFree : { false, true })
  {
    auto mapper = MakeMapper(MakeRectangle(false, !tangentFree));
    mapper->SetTechniqueToBumpMapping();
    mapper->SetTangentFree(tangentFree);
    mapper->SetDifferenceSchemeToCentral();
    mapper->SetHeightMap(MakeHeightMap());
    mapper->SetBumpScale(Strength);
    Scene scene(mapper);
    scene.Actor->RotateY(180);
    scene.Actor->RotateX(-20);
    scene.Mat.Specular = 0.3;
    const NormalField front = DetailNormal(false);
    const NormalField back = [&front](double x, double y)
    {
      const Vec3 n = front(x, y);
      return Vec3{ -n[0], -n[1], -n[2] };
    };
    const auto image = scene.Render();
    EXPECT_GE(PSNR(image, scene.Actor, back, scene.Mat), 40.0) << "tangent-free " << tangentFree;
    EXPECT_EQ(mapper->GetActiveTechnique(), vtkSurfaceDetailMapper::BumpMapping);
  }
}

// A height map with ClampToBorder: outside the texture the height is the border colour's
// first component, on the GPU's lookups and in the differences alike. A constant map of 0.5
// with border 0.1 is flat inside and ramps down within a texel of the edges; the expected
// normal is that of forward differences, W*(h(x+1) - h(x)), of OpenGL's linear filtering
// with the border outside (GL 4.5 spec, 8.14.2), over the texel grid.
TEST(vtkSurfaceDetailMapper, BumpClampToBorderEdge)
{
  constexpr int size = 16;
  constexpr double inside = 0.5, border = 0.1, k = 0.05;
  auto heights = MakeTexture(size, 1, [](double, double, double* h) { h[0] = inside; });
  heights->SetWrap(vtkTexture::ClampToBorder);
  heights->SetBorderColor(static_cast<float>(border), 0.f, 0.f, 0.f);
  auto mapper = MakeMapper(MakeRectangle(false));
  mapper->SetTechniqueToBumpMapping();
  mapper->SetDifferenceSchemeToForward();
  mapper->SetHeightMap(heights);
  mapper->SetBumpScale(k);
  Scene scene(mapper);
  // OpenGL's bilinear filtering at texel coordinates (x,y) = (s,t)*size - 0.5, with the
  // border value outside the texel grid.
  auto height = [&](double x, double y)
  {
    const double fx = std::floor(x), fy = std::floor(y);
    const int i = static_cast<int>(fx), j = static_cast<int>(fy);
    const double ax = x - fx, ay = y - fy;
    auto h = [&](int a, int b)
    { return (a < 0 || a >= size || b < 0 || b >= size) ? border : inside; };
    return (1 - ay) * ((1 - ax) * h(i, j) + ax * h(i + 1, j)) +
      ay * ((1 - ax) * h(i, j + 1) + ax * h(i + 1, j + 1));
  };
  const NormalField field = [&](double x, double y)
  {
    const double tx = (x + 1) / 2 * size - 0.5, ty = (y + 1) / 2 * size - 0.5;
    const double hs = size * (height(tx + 1, ty) - height(tx, ty));
    const double ht = size * (height(tx, ty + 1) - height(tx, ty));
    return Normalized({ -k * hs, -k * ht, 1.0 });
  };
  EXPECT_GE(PSNR(scene.Render(), scene.Actor, field, scene.Mat), 40.0);
}

TEST(vtkSurfaceDetailMapper, PlainMatchesVTKMapper)
{
  auto poly = MakeRectangle(false);
  auto mapper = MakeMapper(poly);
  mapper->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  scene.Mat.Specular = 0.3;
  const auto ours = scene.Render();
  vtkNew<vtkOpenGLPolyDataMapper> plain;
  plain->SetInputData(poly);
  Scene reference(plain);
  reference.Mat = scene.Mat;
  EXPECT_EQ(ours, reference.Render());
  EXPECT_GE(PSNR(ours, scene.Actor, FlatNormal(), scene.Mat), 40.0);
}

// Parallax with offset limiting over a constant depth: every texture lookup moves by the
// depth d times the tangential part of the view vector, in texture units, the colour
// texture included. DepthScale D is in the mesh's units along its normal: the field is the
// rectangle moved by -D*M*z (M the actor's 3x3), so d = D*(M*z).N, N the unit world normal
// (the depth perpendicular to the surface, not the length |D*M*z|). Returns the PSNR
// against that expectation with the shift multiplied by each of shiftScales (1: the right
// picture). @a place positions the actor.
std::vector<double> ParallaxPSNRs(
  const std::function<void(vtkActor*)>& place, const std::vector<double>& shiftScales)
{
  auto mapper = MakeMapper(MakeRectangle(false, false));
  mapper->SetTechniqueToParallaxMapping();
  constexpr double depth = 0.3;
  mapper->SetHeightMap(MakeHeightMap(0.0)); // height 0: the whole field lies DepthScale deep
  mapper->SetDepthScale(depth);
  auto colour = MakeTexture(256, 3,
    [](double s, double t, double* rgb)
    {
      rgb[0] = 0.5 + 0.4 * std::sin(2 * Pi * s);
      rgb[1] = 0.5 + 0.4 * std::sin(2 * Pi * t);
      rgb[2] = 0.5;
    });
  Scene scene(mapper);
  scene.Actor->SetTexture(colour);
  place(scene.Actor);
  scene.Mat.Ambient = 1.0;
  scene.Mat.Diffuse = 0.0;
  const auto image = scene.Render();

  // World frame: dP/ds = 2*a, dP/dt = 2*b (a, b the images of the model's x and y axes),
  // c the image of its z axis; the parallel camera looks along -z, so V = (0,0,1).
  vtkMatrix4x4* m = scene.Actor->GetMatrix();
  Vec3 a, b, c;
  for (int r = 0; r < 3; ++r)
  {
    a[r] = m->GetElement(r, 0);
    b[r] = m->GetElement(r, 1);
    c[r] = m->GetElement(r, 2);
  }
  const Vec3 n =
    Normalized({ a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] });
  const double d = depth * Dot(c, n);
  const Vec3 vt{ -n[2] * n[0], -n[2] * n[1], 1.0 - n[2] * n[2] };
  // Vt = alpha*2a + beta*2b, solved through the Gram matrix of (2a, 2b).
  const double aa = 4 * Dot(a, a), ab = 4 * Dot(a, b), bb = 4 * Dot(b, b);
  const double va = 2 * Dot(vt, a), vb = 2 * Dot(vt, b);
  const double det = aa * bb - ab * ab;
  const double alpha = (bb * va - ab * vb) / det, beta = (aa * vb - ab * va) / det;
  std::vector<double> result;
  for (double shiftScale : shiftScales)
  {
    std::cout << "parallax shift x" << shiftScale << ": ";
    result.push_back(PSNRInside(image, m,
      [&](const Hit& hit)
      {
        const double s = (hit.X + 1) / 2 - shiftScale * d * alpha;
        const double t = (hit.Y + 1) / 2 - shiftScale * d * beta;
        return Vec3{ 0.5 + 0.4 * std::sin(2 * Pi * s), 0.5 + 0.4 * std::sin(2 * Pi * t), 0.5 };
      }));
  }
  return result;
}

void TiltActor(vtkActor* actor, double zScale)
{
  actor->RotateY(40);
  actor->RotateX(-25);
  actor->SetScale(1.0, 1.0, zScale);
}

TEST(vtkSurfaceDetailMapper, ParallaxShiftsColourTexture)
{
  const auto psnr = ParallaxPSNRs([](vtkActor* actor) { TiltActor(actor, 1.0); }, { 1.0, 0.0 });
  EXPECT_GE(psnr[0], 40.0);
  EXPECT_LT(psnr[1], 30.0); // without the shift the picture is clearly different
}

TEST(vtkSurfaceDetailMapper, ParallaxDepthInObjectUnits)
{
  // Scaled 2.5x along its normal, the field is 2.5 times deeper in the world.
  const auto psnr =
    ParallaxPSNRs([](vtkActor* actor) { TiltActor(actor, 2.5); }, { 1.0, 1.0 / 2.5 });
  EXPECT_GE(psnr[0], 40.0);
  EXPECT_LT(psnr[1], 30.0); // depth taken in world units instead
}

TEST(vtkSurfaceDetailMapper, ParallaxDepthUnderSkewingScale)
{
  // Tilted first, then scaled along the world axes: the model's z axis is no longer
  // perpendicular to the surface, and the depth is its part along the normal.
  const auto psnr = ParallaxPSNRs(
    [](vtkActor* actor)
    {
      TiltActor(actor, 1.0);
      vtkNew<vtkMatrix4x4> scale;
      scale->SetElement(0, 0, 1.5);
      scale->SetElement(1, 1, 0.5);
      actor->SetUserMatrix(scale);
    },
    { 1.0 });
  EXPECT_GE(psnr[0], 40.0);
}

namespace
{
// A cone map of zero-width cones at the top of the box: every step it allows is safe.
vtkSmartPointer<vtkTexture> ConeMap(int size, int components, int wrap, int type = VTK_FLOAT)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(type, components);
  image->GetPointData()->GetScalars()->Fill(0.0);
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->SetWrap(wrap);
  return texture;
}
}

TEST(vtkSurfaceDetailMapper, BadInputRendersWithoutDetail)
{
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Poly;
    int Technique;
    vtkSmartPointer<vtkTexture> NormalMap;
    vtkSmartPointer<vtkTexture> HeightMap;
    vtkSmartPointer<vtkTexture> ReliefMap = nullptr;
    vtkSmartPointer<vtkTexture> ConeMap = nullptr;
  };
  auto twoChannel = MakeTexture(8, 2, [](double, double, double* v) { v[0] = v[1] = 0.5; });
  // A flat normal map or a mid height, in a scalar type the mapper cannot read as such.
  auto typed = [](int type, int comps, bool directScalars)
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(8, 8, 1);
    image->AllocateScalars(type, comps);
    vtkDataArray* a = image->GetPointData()->GetScalars();
    const double half = type == VTK_FLOAT ? 0.5 : 0.5 * a->GetDataTypeMax();
    for (vtkIdType k = 0; k < a->GetNumberOfTuples(); ++k)
    {
      for (int c = 0; c < comps; ++c)
      {
        a->SetComponent(k, c, c == 2 ? 2 * half : half);
      }
    }
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputData(image);
    if (directScalars)
    {
      texture->SetColorModeToDirectScalars();
    }
    return texture;
  };
  const std::vector<Case> cases = {
    { "no tangents", MakeRectangle(false, false), vtkSurfaceDetailMapper::NormalMapping,
      MakeNormalMap(), nullptr },
    { "no tcoords", MakeRectangle(false, true, false), vtkSurfaceDetailMapper::BumpMapping, nullptr,
      MakeHeightMap() },
    { "no normals", MakeRectangle(false, true, true, false), vtkSurfaceDetailMapper::NormalMapping,
      MakeNormalMap(), nullptr },
    { "no normal map", MakeRectangle(false), vtkSurfaceDetailMapper::NormalMapping, nullptr,
      nullptr },
    { "no height map", MakeRectangle(false), vtkSurfaceDetailMapper::BumpMapping, nullptr,
      nullptr },
    { "two-channel normal map", MakeRectangle(false), vtkSurfaceDetailMapper::NormalMapping,
      twoChannel, nullptr },
    { "flat interpolation", MakeRectangle(false), vtkSurfaceDetailMapper::NormalMapping,
      MakeNormalMap(), nullptr },
    // vtkOpenGLTexture sends these through a lookup table (grey) or as 0-255.
    { "unsigned short normal map", MakeRectangle(false), vtkSurfaceDetailMapper::NormalMapping,
      typed(VTK_UNSIGNED_SHORT, 3, true), nullptr },
    { "float normal map without direct scalars", MakeRectangle(false),
      vtkSurfaceDetailMapper::NormalMapping, typed(VTK_FLOAT, 3, false), nullptr },
    // Signed heights have no [0,1] reading (every height-map reader refuses them).
    { "short height map", MakeRectangle(false), vtkSurfaceDetailMapper::BumpMapping, nullptr,
      typed(VTK_SHORT, 1, true) },
    { "int height map", MakeRectangle(false, false), vtkSurfaceDetailMapper::ParallaxMapping,
      nullptr, typed(VTK_INT, 1, true) },
    // Relief needs a relief map (RGBA) or a height map, and tangents for a relief map.
    { "relief without maps", MakeRectangle(false), vtkSurfaceDetailMapper::ReliefMapping, nullptr,
      nullptr },
    { "three-channel relief map", MakeRectangle(false), vtkSurfaceDetailMapper::ReliefMapping,
      nullptr, nullptr, typed(VTK_UNSIGNED_CHAR, 3, false) },
    { "unsigned short relief map", MakeRectangle(false), vtkSurfaceDetailMapper::ReliefMapping,
      nullptr, nullptr, typed(VTK_UNSIGNED_SHORT, 4, true) },
    { "relief map without tangents", MakeRectangle(false, false),
      vtkSurfaceDetailMapper::ReliefMapping, nullptr, nullptr, typed(VTK_UNSIGNED_CHAR, 4, false) },
    { "relief from a short height map", MakeRectangle(false, false),
      vtkSurfaceDetailMapper::ReliefMapping, nullptr, typed(VTK_SHORT, 1, true) },
    // A cone map describes one relief: vtkHeightMapToConeMap's output for the same texels.
    { "one-component cone map", MakeRectangle(false), vtkSurfaceDetailMapper::ReliefMapping,
      nullptr, MakeHeightMap(), nullptr, ConeMap(256, 1, vtkTexture::Repeat) },
    { "unsigned char cone map", MakeRectangle(false), vtkSurfaceDetailMapper::ReliefMapping,
      nullptr, MakeHeightMap(), nullptr, ConeMap(256, 2, vtkTexture::Repeat, VTK_UNSIGNED_CHAR) },
    { "cone map of another size", MakeRectangle(false), vtkSurfaceDetailMapper::ReliefMapping,
      nullptr, MakeHeightMap(), nullptr, ConeMap(64, 2, vtkTexture::Repeat) },
    { "mirrored cone map", MakeRectangle(false), vtkSurfaceDetailMapper::ReliefMapping, nullptr,
      MakeHeightMap(), nullptr, ConeMap(256, 2, vtkTexture::MirroredRepeat) },
  };
  // One window for all cases: X servers under test do not like windows made in a burst.
  Scene scene(nullptr);
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.Name);
    auto mapper = MakeMapper(c.Poly);
    mapper->SetTechnique(c.Technique);
    mapper->SetNormalMap(c.NormalMap);
    mapper->SetHeightMap(c.HeightMap);
    mapper->SetReliefMap(c.ReliefMap);
    mapper->SetConeMap(c.ConeMap);
    vtkNew<ErrorCounter> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    mapper->AddObserver(vtkCommand::WarningEvent, errors);
    scene.Actor->SetMapper(mapper);
    scene.Actor->GetProperty()->SetInterpolation(
      std::string(c.Name) == "flat interpolation" ? VTK_FLAT : VTK_GOURAUD);
    const auto image = scene.Render();
    scene.Render(); // reported once, not every frame
    EXPECT_EQ(errors->Errors, 1) << errors->Last;
    EXPECT_EQ(mapper->GetActiveTechnique(), vtkSurfaceDetailMapper::Plain);
    if (c.Poly->GetPointData()->GetNormals())
    {
      EXPECT_GE(PSNR(image, scene.Actor, FlatNormal(), scene.Mat), 40.0);
    }
    else
    {
      // VTK's own fallback for meshes without normals still draws the lit rectangle.
      EXPECT_GE(PSNR(image, scene.Actor, FlatNormal(), scene.Mat), 30.0);
    }
  }
}

TEST(vtkSurfaceDetailMapper, NonFiniteHeightsWarnOnce)
{
  auto heights = MakeHeightMap();
  auto* image = vtkImageData::SafeDownCast(heights->GetInputDataObject(0, 0));
  image->GetPointData()->GetScalars()->SetComponent(3 * 256 + 7, 0, std::nan(""));
  auto mapper = MakeMapper(MakeRectangle(false));
  mapper->SetTechniqueToBumpMapping();
  mapper->SetHeightMap(heights);
  mapper->SetBumpScale(Strength);
  vtkNew<ErrorCounter> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->AddObserver(vtkCommand::WarningEvent, errors);
  Scene scene(mapper);
  const auto image1 = scene.Render();
  scene.Render();
  EXPECT_EQ(errors->Warnings, 1) << errors->Last;
  EXPECT_EQ(errors->Errors, 0);
  EXPECT_NE(errors->Last.find("non-finite"), std::string::npos);
  // One bad texel spoils a few pixels around it, not the picture.
  EXPECT_GE(PSNR(image1, scene.Actor, DetailNormal(false), scene.Mat), 35.0);
}

// A 16-bit height map (read as value/65535) gives the same picture as the float one.
TEST(vtkSurfaceDetailMapper, BumpUnsignedShortHeights)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(256, 256, 1);
  image->AllocateScalars(VTK_UNSIGNED_SHORT, 1);
  auto* p = static_cast<unsigned short*>(image->GetScalarPointer());
  for (int j = 0; j < 256; ++j)
  {
    for (int i = 0; i < 256; ++i)
    {
      p[j * 256 + i] =
        static_cast<unsigned short>(65535 * Height((i + 0.5) / 256, (j + 0.5) / 256) + 0.5);
    }
  }
  vtkNew<vtkTexture> heights;
  heights->SetInputData(image);
  heights->InterpolateOn();
  heights->RepeatOn();
  auto mapper = MakeMapper(MakeRectangle(false));
  mapper->SetTechniqueToBumpMapping();
  mapper->SetDifferenceSchemeToCentral();
  mapper->SetHeightMap(heights);
  mapper->SetBumpScale(Strength);
  Scene scene(mapper);
  EXPECT_GE(PSNR(scene.Render(), scene.Actor, DetailNormal(false), scene.Mat), 40.0);
}

// The shader program is built once, not per frame; a technique change rebuilds it, and a
// uniform (the strength) reuses the compiled program.
class CountingMapper : public vtkSurfaceDetailMapper
{
public:
  static CountingMapper* New();
  vtkTypeMacro(CountingMapper, vtkSurfaceDetailMapper);
  int Builds = 0;
  vtkMTimeType VBOTime() { return this->VBOBuildTime.GetMTime(); }
  vtkShaderProgram* TrianglesProgram() { return this->Primitives[PrimitiveTris].Program; }

protected:
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    ++this->Builds;
    this->Superclass::ReplaceShaderValues(shaders, ren, act);
  }
};
vtkStandardNewMacro(CountingMapper);

TEST(vtkSurfaceDetailMapper, ShaderBuiltOnceNotPerFrame)
{
  vtkNew<CountingMapper> mapper;
  mapper->SetInputData(MakeRectangle(false));
  mapper->SetNormalMap(MakeNormalMap());
  mapper->SetHeightMap(MakeHeightMap());
  mapper->SetTechniqueToNormalMapping();
  Scene scene(mapper);
  scene.Render();
  const int first = mapper->Builds;
  EXPECT_GE(first, 1);
  scene.Render();
  scene.Render();
  EXPECT_EQ(mapper->Builds, first) << "rebuilt in a frame where nothing changed";
  vtkShaderProgram* program = mapper->TrianglesProgram();
  const vtkMTimeType vbo = mapper->VBOTime();
  const vtkMTimeType mtime = mapper->GetMTime();
  const auto before = scene.Render();
  mapper->SetNormalScale(0.5);
  EXPECT_GT(mapper->GetMTime(), mtime) << "a setting changed and the mapper looks unmodified";
  const auto after = scene.Render();
  EXPECT_NE(before, after) << "the new strength did not reach the picture";
  EXPECT_EQ(mapper->TrianglesProgram(), program) << "a uniform change compiled a new program";
  EXPECT_EQ(mapper->Builds, first) << "a uniform change rebuilt the shader text";
  EXPECT_EQ(mapper->VBOTime(), vbo) << "a uniform change re-uploaded the vertex buffers";
  const int beforeSwitch = mapper->Builds;
  mapper->SetTechniqueToBumpMapping();
  scene.Render();
  EXPECT_GT(mapper->Builds, beforeSwitch);
  EXPECT_NE(mapper->TrianglesProgram(), program);
  const int afterSwitch = mapper->Builds;
  scene.Render();
  EXPECT_EQ(mapper->Builds, afterSwitch);
  // The other uniform-only settings, each with the technique that reads it.
  const vtkMTimeType vboBump = mapper->VBOTime();
  const auto bump = scene.Render();
  mapper->SetBumpScale(0.5);
  EXPECT_NE(scene.Render(), bump);
  EXPECT_EQ(mapper->Builds, afterSwitch) << "SetBumpScale rebuilt the shader text";
  EXPECT_EQ(mapper->VBOTime(), vboBump) << "SetBumpScale re-uploaded the vertex buffers";
  // Parallax (shading with the normal map) reads GreenUp and DepthScale; seen obliquely, so
  // that the depth shows.
  mapper->SetTechniqueToParallaxMapping();
  scene.Actor->RotateX(-40);
  scene.Render();
  const int parallax = mapper->Builds;
  const vtkMTimeType vboParallax = mapper->VBOTime();
  const auto deep = scene.Render();
  mapper->SetDepthScale(0.2);
  const auto deeper = scene.Render();
  EXPECT_NE(deeper, deep);
  mapper->SetGreenUp(false);
  EXPECT_NE(scene.Render(), deeper);
  EXPECT_EQ(mapper->Builds, parallax) << "SetDepthScale or SetGreenUp rebuilt the shader text";
  EXPECT_EQ(mapper->VBOTime(), vboParallax) << "SetDepthScale or SetGreenUp re-uploaded buffers";
  // Relief's step settings are uniforms too; self-shadowing and depth correction are code.
  mapper->SetTechniqueToReliefMapping();
  mapper->SetLinearSearchSteps(4);
  mapper->SetBinarySearchSteps(0);
  mapper->AdaptiveStepsOff();
  scene.Render();
  const int relief = mapper->Builds;
  const auto coarse = scene.Render();
  mapper->SetLinearSearchSteps(64);
  mapper->SetBinarySearchSteps(8);
  const auto fine = scene.Render();
  EXPECT_NE(fine, coarse) << "the step counts did not reach the picture";
  mapper->AdaptiveStepsOn();
  scene.Render();
  EXPECT_EQ(mapper->Builds, relief) << "a step setting rebuilt the shader text";
  // The code of a feature that is off is not in the program.
  auto fragmentHas = [&](const char* code)
  {
    return mapper->TrianglesProgram()->GetFragmentShader()->GetSource().find(code) !=
      std::string::npos;
  };
  EXPECT_TRUE(fragmentHas("sdReliefIntersect"));
  EXPECT_FALSE(fragmentHas("sdReliefShadow"));
  EXPECT_FALSE(fragmentHas("gl_FragDepth ="));
  mapper->SelfShadowingOn();
  scene.Render();
  EXPECT_GT(mapper->Builds, relief) << "self-shadowing did not change the shader";
  EXPECT_TRUE(fragmentHas("sdReliefShadow"));
  const int shadowing = mapper->Builds;
  mapper->DepthCorrectionOn();
  scene.Render();
  EXPECT_GT(mapper->Builds, shadowing) << "depth correction did not change the shader";
  EXPECT_TRUE(fragmentHas("gl_FragDepth ="));
  // Cone stepping replaces the linear search's code; without a cone map it is not there.
  EXPECT_FALSE(fragmentHas("sdReliefConeAt"));
  const int linear = mapper->Builds;
  mapper->SetConeMap(ConeMap(256, 2, vtkTexture::Repeat));
  scene.Render();
  EXPECT_GT(mapper->Builds, linear) << "a cone map did not change the shader";
  EXPECT_TRUE(fragmentHas("sdReliefConeAt"));
  EXPECT_FALSE(fragmentHas("sdReliefIntersect("));
  mapper->SetConeMap(nullptr);
  scene.Render();
  EXPECT_FALSE(fragmentHas("sdReliefConeAt"));
  EXPECT_TRUE(fragmentHas("sdReliefIntersect("));
}

// Bump mapping gets a gradient-only height texture, parallax (lit here by the gradient, no
// normal map) the height and the gradient: switching technique must re-upload the layout
// the new shader reads. The truth is a fresh mapper rendering each technique from scratch.
TEST(vtkSurfaceDetailMapper, TechniqueSwitchReuploadsHeightLayout)
{
  auto fresh = [](int technique)
  {
    auto mapper = MakeMapper(MakeRectangle(false));
    mapper->SetHeightMap(MakeHeightMap());
    mapper->SetTechnique(technique);
    Scene scene(mapper);
    scene.Actor->RotateX(-40);
    return scene.Render();
  };
  const auto bump = fresh(vtkSurfaceDetailMapper::BumpMapping);
  const auto parallax = fresh(vtkSurfaceDetailMapper::ParallaxMapping);
  ASSERT_NE(bump, parallax) << "the two techniques must draw different pictures to tell apart";

  auto mapper = MakeMapper(MakeRectangle(false));
  mapper->SetHeightMap(MakeHeightMap());
  mapper->SetTechniqueToBumpMapping();
  Scene scene(mapper);
  scene.Actor->RotateX(-40);
  EXPECT_EQ(scene.Render(), bump);
  mapper->SetTechniqueToParallaxMapping();
  EXPECT_EQ(scene.Render(), parallax) << "bump -> parallax kept the gradient-only texture";
  mapper->SetTechniqueToBumpMapping();
  EXPECT_EQ(scene.Render(), bump) << "parallax -> bump kept the (h, dh/ds, dh/dt) texture";
}

// A 64x64 height source of constant Value that counts the pipeline requests it receives.
class CountingHeightSource : public vtkImageAlgorithm
{
public:
  static CountingHeightSource* New();
  vtkTypeMacro(CountingHeightSource, vtkImageAlgorithm);
  vtkSetMacro(Value, double);
  int Requests = 0;
  int Executions = 0;

  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** in, vtkInformationVector* out) override
  {
    ++this->Requests;
    return this->Superclass::ProcessRequest(request, in, out);
  }

protected:
  CountingHeightSource() { this->SetNumberOfInputPorts(0); }
  int RequestInformation(
    vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    const int extent[6] = { 0, 63, 0, 63, 0, 0 };
    out->GetInformationObject(0)->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    vtkDataObject::SetPointDataActiveScalarInfo(out->GetInformationObject(0), VTK_FLOAT, 1);
    return 1;
  }
  void ExecuteDataWithInformation(vtkDataObject* output, vtkInformation* outInfo) override
  {
    ++this->Executions;
    vtkImageData* image = this->AllocateOutputData(output, outInfo);
    auto* p = static_cast<float*>(image->GetScalarPointer());
    std::fill(p, p + 64 * 64, static_cast<float>(this->Value));
  }
  double Value = 0.5;
};
vtkStandardNewMacro(CountingHeightSource);

TEST(vtkSurfaceDetailMapper, HeightProducerUpdatedOnlyWhenChanged)
{
  vtkNew<CountingHeightSource> source;
  vtkNew<vtkImageShiftScale> scale; // a stage between: upstream changes must get through
  scale->SetInputConnection(source->GetOutputPort());
  scale->SetScale(1.0);
  vtkNew<vtkTexture> heights;
  heights->SetInputConnection(scale->GetOutputPort());
  heights->InterpolateOn();
  auto mapper = MakeMapper(MakeRectangle(false, false));
  mapper->SetTechniqueToParallaxMapping();
  mapper->SetHeightMap(heights);
  mapper->SetDepthScale(0.3);
  auto colour = MakeTexture(64, 3,
    [](double s, double t, double* rgb)
    {
      rgb[0] = 0.5 + 0.4 * std::sin(2 * Pi * s);
      rgb[1] = 0.5 + 0.4 * std::sin(2 * Pi * t);
      rgb[2] = 0.5;
    });
  Scene scene(mapper);
  scene.Actor->SetTexture(colour);
  scene.Actor->RotateY(40);
  const auto first = scene.Render();
  EXPECT_EQ(source->Executions, 1);
  const int requests = source->Requests;
  scene.Render();
  scene.Render();
  EXPECT_EQ(source->Requests, requests) << "the producer was updated with nothing changed";
  source->SetValue(1.0); // height 1: no parallax shift at all
  const auto changed = scene.Render();
  EXPECT_EQ(source->Executions, 2) << "an upstream change was not picked up";
  EXPECT_NE(first, changed);
}

TEST(vtkSurfaceDetailMapper, ShallowCopyCopiesSettings)
{
  vtkNew<vtkSurfaceDetailMapper> source;
  source->SetTechniqueToParallaxMapping();
  auto heights = MakeHeightMap();
  source->SetHeightMap(heights);
  source->SetNormalScale(0.5);
  source->GreenUpOff();
  source->SetBumpScale(0.25);
  source->SetDifferenceSchemeToCentral();
  source->TangentFreeOn();
  source->SetDepthScale(0.2);
  auto relief = MakeNormalMap();
  source->SetReliefMap(relief);
  auto cones = ConeMap(8, 2, vtkTexture::Repeat);
  source->SetConeMap(cones);
  source->SetLinearSearchSteps(12);
  source->SetBinarySearchSteps(5);
  source->AdaptiveStepsOff();
  source->SelfShadowingOn();
  source->DepthCorrectionOn();
  vtkNew<vtkSurfaceDetailMapper> copy;
  copy->ShallowCopy(source);
  EXPECT_EQ(copy->GetTechnique(), vtkSurfaceDetailMapper::ParallaxMapping);
  EXPECT_EQ(copy->GetHeightMap(), heights.Get());
  EXPECT_EQ(copy->GetNormalMap(), nullptr);
  EXPECT_EQ(copy->GetNormalScale(), 0.5);
  EXPECT_FALSE(copy->GetGreenUp());
  EXPECT_EQ(copy->GetBumpScale(), 0.25);
  EXPECT_EQ(copy->GetDifferenceScheme(), vtkSurfaceDetailMapper::Central);
  EXPECT_TRUE(copy->GetTangentFree());
  EXPECT_EQ(copy->GetDepthScale(), 0.2);
  EXPECT_EQ(copy->GetReliefMap(), relief.Get());
  EXPECT_EQ(copy->GetConeMap(), cones.Get());
  EXPECT_EQ(copy->GetLinearSearchSteps(), 12);
  EXPECT_EQ(copy->GetBinarySearchSteps(), 5);
  EXPECT_FALSE(copy->GetAdaptiveSteps());
  EXPECT_TRUE(copy->GetSelfShadowing());
  EXPECT_TRUE(copy->GetDepthCorrection());
}

// Step counts stay within what a fragment can afford; depth is never negative.
TEST(vtkSurfaceDetailMapper, ReliefSettingsAreClamped)
{
  vtkNew<vtkSurfaceDetailMapper> mapper;
  mapper->SetLinearSearchSteps(0);
  EXPECT_EQ(mapper->GetLinearSearchSteps(), 1);
  mapper->SetLinearSearchSteps(100000);
  EXPECT_EQ(mapper->GetLinearSearchSteps(), 256);
  mapper->SetBinarySearchSteps(-3);
  EXPECT_EQ(mapper->GetBinarySearchSteps(), 0);
  mapper->SetBinarySearchSteps(1000);
  EXPECT_EQ(mapper->GetBinarySearchSteps(), 32);
  mapper->SetDepthScale(-1);
  EXPECT_EQ(mapper->GetDepthScale(), 0.0);
}

// With Technique Plain the triangles' program is VTK's own, to the character.
class PlainMapperProbe : public vtkOpenGLPolyDataMapper
{
public:
  static PlainMapperProbe* New();
  vtkTypeMacro(PlainMapperProbe, vtkOpenGLPolyDataMapper);
  vtkShaderProgram* TrianglesProgram() { return this->Primitives[PrimitiveTris].Program; }
};
vtkStandardNewMacro(PlainMapperProbe);

TEST(vtkSurfaceDetailMapper, PlainShaderIsVTKsShader)
{
  auto poly = MakeRectangle(false);
  vtkNew<CountingMapper> ours;
  ours->SetInputData(poly);
  ours->SetNormalMap(MakeNormalMap());
  ours->SetHeightMap(MakeHeightMap());
  Scene scene(ours);
  scene.Actor->SetTexture(MakeNormalMap());
  scene.Render();
  vtkNew<PlainMapperProbe> plain;
  plain->SetInputData(poly);
  scene.Actor->SetMapper(plain);
  scene.Render();
  ASSERT_NE(ours->TrianglesProgram(), nullptr);
  ASSERT_NE(plain->TrianglesProgram(), nullptr);
  EXPECT_EQ(ours->TrianglesProgram()->GetVertexShader()->GetSource(),
    plain->TrianglesProgram()->GetVertexShader()->GetSource());
  EXPECT_EQ(ours->TrianglesProgram()->GetFragmentShader()->GetSource(),
    plain->TrianglesProgram()->GetFragmentShader()->GetSource());
  // And with a technique on, our code is there.
  ours->SetTechniqueToNormalMapping();
  scene.Actor->SetMapper(ours);
  scene.Render();
  EXPECT_NE(ours->TrianglesProgram()->GetFragmentShader()->GetSource().find("sdNormalMapTS"),
    std::string::npos);
}

TEST(vtkSurfaceDetailMapper, PrintSelf)
{
  vtkNew<vtkSurfaceDetailMapper> mapper;
  mapper->SetTechniqueToBumpMapping();
  mapper->SetDepthScale(0.125);
  mapper->SetLinearSearchSteps(48);
  mapper->SelfShadowingOn();
  std::ostringstream os;
  mapper->Print(os);
  EXPECT_NE(os.str().find("LinearSearchSteps: 48"), std::string::npos);
  EXPECT_NE(os.str().find("SelfShadowing: On"), std::string::npos);
  EXPECT_NE(os.str().find("DepthCorrection: Off"), std::string::npos);
  EXPECT_NE(os.str().find("ReliefMap: 0"), std::string::npos);
  EXPECT_NE(os.str().find("ConeMap: 0"), std::string::npos);
  EXPECT_NE(os.str().find("Technique: BumpMapping"), std::string::npos);
  EXPECT_NE(os.str().find("DepthScale: 0.125"), std::string::npos);
  EXPECT_NE(os.str().find("TangentFree: Off"), std::string::npos);
}
