// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Relief mapping's search precision, as a number. With DepthCorrection the fragment's depth
// is that of the hit the search found, so the depth buffer tells where each view ray met the
// height field; it is compared with the analytic intersection, computed here.
//
// The scene is built so that the analytic intersection is exact and unique: a flat 2 x 2
// square (z = 0, normal +z, s = (x+1)/2, t = (y+1)/2) under a parallel camera tilted about x,
// so that every view ray moves towards +t as it goes down, by delta in t per unit of depth
// fraction; the height map is a staircase in t, read with GL_NEAREST (Interpolate off) and
// clamped at the edges: depth D(t) = 1 - h = 1 - (k + 1/2)/N on row k. Along a ray the gap
// D(t0 + d delta) - d then only decreases, so there is one first crossing, which the linear
// search brackets and the binary search narrows: with L linear steps and n binary steps the
// bracket is 1/(L 2^n) of DepthScale. The final secant stays inside the bracket and is exact
// on a texel's flat top, but not at a step's wall, where many rays end: there the error is a
// fraction of the bracket. So the worst error over the picture must stay within the bracket
// and fall with it, halving with each binary step, until float precision (the fragment's
// texture coordinate and the 24-bit depth buffer) takes over.

#include "vtkSurfaceDetailMapper.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
constexpr int Size = 240;     // pixels
constexpr int Rows = 16;      // height map rows (along t)
constexpr int Linear = 8;     // linear search steps
constexpr double Depth = 0.5; // DepthScale, object units
const double Tilt = 40.0;     // degrees between the view direction and -z
const double Distance = 10.0; // camera distance from the square's centre

// The bracket that @a binarySteps leave, as a fraction of DepthScale.
double Bracket(int binarySteps)
{
  return 1.0 / (Linear * std::ldexp(1.0, binarySteps));
}

struct Measurement
{
  int Pixels = 0;
  double Worst = 0.0; // worst |found - true| depth fraction
};

vtkSmartPointer<vtkImageData> Staircase()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(4, Rows, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* h = static_cast<float*>(image->GetScalarPointer());
  for (int k = 0; k < Rows; ++k)
  {
    for (int i = 0; i < 4; ++i)
    {
      h[k * 4 + i] = static_cast<float>((k + 0.5) / Rows);
    }
  }
  return image;
}

// The first d in [0, 1] where the ray t0 + d delta is at or under the field: the rows it
// crosses in turn, each flat, so the crossing is where the ray meets a row's top or, if it is
// already under it on entering, at the row's edge.
double TrueCrossing(const std::vector<double>& depth, double t0, double delta)
{
  int k = std::min(std::max(static_cast<int>(std::floor(t0 * Rows)), 0), Rows - 1);
  double enter = 0.0;
  while (true)
  {
    const double leave = k + 1 < Rows ? ((k + 1.0) / Rows - t0) / delta : 2.0;
    const double d = std::max(enter, depth[k]);
    if (d <= leave)
    {
      return d;
    }
    enter = leave;
    ++k;
  }
}

Measurement Measure(int binarySteps, bool print)
{
  vtkNew<vtkParametricRectangle> square;
  square->SetOrigin(-1.0, -1.0, 0.0);
  square->SetPoint1(1.0, -1.0, 0.0);
  square->SetPoint2(-1.0, 1.0, 0.0);
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(square);
  source->SetUResolution(4);
  source->SetVResolution(4);
  source->Update();

  vtkNew<vtkTexture> heights;
  heights->SetInputData(Staircase());
  heights->InterpolateOff();
  heights->MipmapOff();
  heights->SetWrap(vtkTexture::ClampToEdge);

  vtkNew<vtkSurfaceDetailMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->SetTechniqueToReliefMapping();
  mapper->SetHeightMap(heights);
  mapper->SetDepthScale(Depth);
  mapper->AdaptiveStepsOff();
  mapper->SetLinearSearchSteps(Linear);
  mapper->SetBinarySearchSteps(binarySteps);
  mapper->DepthCorrectionOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  const double tilt = Tilt * M_PI / 180.0;
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, -Distance * std::sin(tilt), Distance * std::cos(tilt));
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->OrthogonalizeViewUp();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(1.1);
  // Tight around the square and its relief box, for the depth buffer's resolution.
  camera->SetClippingRange(Distance - 2.0, Distance + 2.0);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(Size, Size);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkFloatArray> zbuffer;
  window->GetZbufferData(0, 0, Size - 1, Size - 1, zbuffer);

  // World to normalised device coordinates (z in [-1, 1]; the window's depth is (z + 1)/2),
  // and back.
  vtkNew<vtkMatrix4x4> toDevice, toWorld;
  toDevice->DeepCopy(camera->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0));
  vtkMatrix4x4::Invert(toDevice, toWorld);
  // Along the view ray (away from the camera), the hit lies d Depth below the square, so
  // d Depth / cos(tilt) along the ray; its window depth grows by this much per unit of d.
  const double dop[3] = { 0.0, std::sin(tilt), -std::cos(tilt) };
  double windowPerD = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    windowPerD += 0.5 * toDevice->GetElement(2, c) * dop[c] * Depth / std::cos(tilt);
  }
  // Per unit of d the ray moves Depth tan(tilt) in y, half that in t.
  const double delta = 0.5 * Depth * std::tan(tilt);
  std::vector<double> depth(Rows);
  for (int k = 0; k < Rows; ++k)
  {
    depth[k] = 1.0 - static_cast<double>(static_cast<float>((k + 0.5) / Rows));
  }

  Measurement m;
  for (int j = 0; j < Size; ++j)
  {
    for (int i = 0; i < Size; ++i)
    {
      // The pixel centre's ray, as two device points, meets z = 0 at the fragment.
      const double x = 2.0 * (i + 0.5) / Size - 1.0, y = 2.0 * (j + 0.5) / Size - 1.0;
      double a[4] = { x, y, -1.0, 1.0 }, b[4] = { x, y, 1.0, 1.0 }, wa[4], wb[4];
      toWorld->MultiplyPoint(a, wa);
      toWorld->MultiplyPoint(b, wb);
      const double f = wa[2] / (wa[2] - wb[2]);
      double top[3];
      for (int c = 0; c < 3; ++c)
      {
        top[c] = wa[c] + f * (wb[c] - wa[c]);
      }
      // Well inside the square: its edge pixels are partly background.
      if (std::abs(top[0]) > 0.95 || std::abs(top[1]) > 0.95)
      {
        continue;
      }
      const double t0 = 0.5 * (top[1] + 1.0);
      const double topWindow = f; // device z -1 + 2f
      const double found = (zbuffer->GetValue(j * Size + i) - topWindow) / windowPerD;
      const double truth = TrueCrossing(depth, t0, delta);
      m.Worst = std::max(m.Worst, std::abs(found - truth));
      ++m.Pixels;
    }
  }
  if (print)
  {
    std::printf("binary steps %2d: bracket %.3e, worst depth error %.3e (fraction of DepthScale) "
                "over %d pixels\n",
      binarySteps, Bracket(binarySteps), m.Worst, m.Pixels);
  }
  return m;
}
} // namespace

TEST(SurfaceDetailReliefSearchPrecision, ErrorHalvesWithEachBinaryStep)
{
  // What precision leaves with far more steps than the bracket needs: the rasteriser's
  // sub-pixel placement of the square moves each fragment's texture coordinate a little, and a
  // ray ending at a step's wall moves with it by that over delta.
  const double precision = 5e-5;
  const Measurement floor = Measure(30, true);
  ASSERT_GT(floor.Pixels, Size * Size / 2);
  EXPECT_LT(floor.Worst, precision);
  std::vector<double> worst;
  for (int n = 0; n <= 14; ++n)
  {
    const Measurement m = Measure(n, true);
    EXPECT_EQ(m.Pixels, floor.Pixels);
    // Never outside the bracket the search leaves.
    EXPECT_LT(m.Worst, Bracket(n) + precision) << n << " binary steps";
    worst.push_back(m.Worst);
  }
  // Once the bracket is shorter than a quarter of a stair (the secant no longer spans a
  // stair, and the error is a fraction of the bracket), and while it is well above the
  // precision, each step halves the worst error.
  int halvings = 0;
  for (int n = 0; n + 1 < static_cast<int>(worst.size()); ++n)
  {
    if (Bracket(n) <= 0.25 / Rows && Bracket(n + 1) >= 8 * precision)
    {
      EXPECT_LT(worst[n + 1], 0.65 * worst[n]) << n + 1 << " binary steps";
      EXPECT_GT(worst[n + 1], 0.35 * worst[n]) << n + 1 << " binary steps";
      ++halvings;
    }
  }
  EXPECT_EQ(halvings, 5);
}
