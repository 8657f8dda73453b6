// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkHeightMapToConeMap against the bilinear surface sampled densely, an independent truth:
// the apex is the highest point over each footprint; no sampled point lies inside any
// conservative cone from any apex of its footprint, and no ray walked through a relaxed cone
// comes back out of the surface; both kinds are within a stated fraction of the widest the
// samples allow. Also closed forms (one raised texel, a ridge), thread counts and bad input.

#include "vtkHeightMapToConeMap.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMinimalStandardRandomSequence.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSMPTools.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Map
{
  int W, H;
  bool Repeat;
  std::vector<double> Height;

  // The relief's depth at texel (i, j), wrapped or clamped.
  double Texel(int i, int j) const
  {
    i = this->Repeat ? ((i % W) + W) % W : std::min(std::max(i, 0), W - 1);
    j = this->Repeat ? ((j % H) + H) % H : std::min(std::max(j, 0), H - 1);
    return 1.0 - this->Height[j * W + i];
  }

  // OpenGL's bilinear surface at texel-index position (x, y) (texel centres at integers).
  double Depth(double x, double y) const
  {
    const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
    const double fx = x - i, fy = y - j;
    return (1 - fx) * (1 - fy) * this->Texel(i, j) + fx * (1 - fy) * this->Texel(i + 1, j) +
      (1 - fx) * fy * this->Texel(i, j + 1) + fx * fy * this->Texel(i + 1, j + 1);
  }

  // Distance in texture coordinates, the nearest repeat where the pattern repeats.
  double Distance(double x0, double y0, double x1, double y1) const
  {
    double dx = std::abs(x1 - x0), dy = std::abs(y1 - y0);
    if (this->Repeat)
    {
      dx = std::fmod(dx, W);
      dy = std::fmod(dy, H);
      dx = std::min(dx, W - dx);
      dy = std::min(dy, H - dy);
    }
    return std::hypot(dx / W, dy / H);
  }
};

Map RandomMap(int w, int h, bool repeat, int seed)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(seed);
  Map m{ w, h, repeat, std::vector<double>(w * h) };
  for (double& v : m.Height)
  {
    v = random->GetValue();
    random->Next();
    v = v * v * v; // mostly low, a few tall texels: narrow and wide cones both
  }
  return m;
}

vtkSmartPointer<vtkImageData> Image(const Map& m)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(m.W, m.H, 1);
  image->AllocateScalars(VTK_DOUBLE, 1);
  std::copy(m.Height.begin(), m.Height.end(), static_cast<double*>(image->GetScalarPointer()));
  return image;
}

std::vector<float> Cones(const Map& m, double maxRatio = 1.0,
  int coneType = vtkHeightMapToConeMap::Conservative)
{
  vtkNew<vtkHeightMapToConeMap> filter;
  filter->SetConeType(coneType);
  filter->SetInputData(Image(m));
  filter->SetWrap(m.Repeat ? vtkSurfaceDetail::Repeat : vtkSurfaceDetail::ClampToEdge);
  filter->SetMaxConeRatio(maxRatio);
  filter->Update();
  auto* cones = vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetScalars());
  EXPECT_NE(cones, nullptr);
  EXPECT_EQ(std::string(cones && cones->GetName() ? cones->GetName() : ""), "ConeMap");
  return cones ? std::vector<float>(cones->GetPointer(0), cones->GetPointer(0) + 2 * m.W * m.H)
               : std::vector<float>();
}

// Dense samples of the surface: every eighth of a texel over the map (repeat), and a texel
// beyond its edges (clamp, where the edges continue).
template <typename F>
void ForSurfaceSamples(const Map& m, F&& f)
{
  const double margin = m.Repeat ? 0.0 : 1.0;
  for (double y = -margin; y < m.H + margin - (m.Repeat ? 0.0 : 1.0) + 1e-9; y += 0.125)
  {
    for (double x = -margin; x < m.W + margin - (m.Repeat ? 0.0 : 1.0) + 1e-9; x += 0.125)
    {
      f(x, y, m.Depth(x, y));
    }
  }
}

// The widest cone the sampled surface allows texel (i, j) from every apex of its footprint.
double Widest(const Map& m, int i, int j, double apex, double maxRatio)
{
  double widest = maxRatio;
  ForSurfaceSamples(m,
    [&](double x, double y, double depth)
    {
      if (depth < apex)
      {
        for (double ay = j - 0.5; ay <= j + 0.5; ay += 0.25)
        {
          for (double ax = i - 0.5; ax <= i + 0.5; ax += 0.25)
          {
            widest = std::min(widest, m.Distance(ax, ay, x, y) / (apex - depth));
          }
        }
      }
    });
  return widest;
}

// Rays that follow a relaxed cone, sampled: from points of texel (i, j)'s footprint at depths
// from the top to its apex, in every direction and at slopes from steep to grazing, each step
// to the side of the cone (apex, ratio) from the ray's start, walked densely. Returns how many
// steps come back above the surface after going under it (a relaxed cone forbids that).
int StepsThatLeaveTheSurface(const Map& m, int i, int j, double apex, double ratio)
{
  const double pi = std::acos(-1.0);
  int leaving = 0;
  for (double y = j - 0.5; y <= j + 0.5; y += 0.5)
  {
    for (double x = i - 0.5; x <= i + 0.5; x += 0.5)
    {
      for (double d : { 0.0, 0.3 * apex, 0.7 * apex, 0.9 * apex, apex - 0.02, apex })
      {
        for (int a = 0; a < 32 && d >= 0.0; ++a)
        {
          const double c = std::cos(2 * pi * a / 32), s = std::sin(2 * pi * a / 32);
          for (double run : { 0.02, 0.1, 0.3, 1.0, 3.0, 10.0 }) // texture units per depth
          {
            // The cone's side: the ray has run ratio * (apex - its depth) from the start.
            const double step = ratio * (apex - d) / (run + ratio);
            const double texels = step * run * std::max(m.W, m.H);
            const int samples = std::max(64, static_cast<int>(16 * texels));
            bool under = false;
            for (int k = 0; k <= samples; ++k)
            {
              const double t = step * k / samples;
              const double field = m.Depth(x + t * run * c * m.W, y + t * run * s * m.H);
              under = under || d + t > field + 1e-9;
              if (under && d + t < field - 1e-9)
              {
                ++leaving;
                break;
              }
            }
          }
        }
      }
    }
  }
  return leaving;
}

// The same over every texel of the map, its cones made @a widen times as wide.
int StepsThatLeaveTheSurface(const Map& m, const std::vector<float>& cones, double widen)
{
  int leaving = 0;
  for (int j = 0; j < m.H; ++j)
  {
    for (int i = 0; i < m.W; ++i)
    {
      leaving += StepsThatLeaveTheSurface(
        m, i, j, cones[2 * (j * m.W + i)], widen * cones[2 * (j * m.W + i) + 1]);
    }
  }
  return leaving;
}
} // namespace

// The apex is the highest point of the surface over the footprint; no sampled point lies inside
// the cone from any apex of the footprint; and the cones are on average within a stated
// fraction of the widest the samples allow (never zero).
TEST(HeightMapToConeMap, ConesAreEmptyAndNearTheWidest)
{
  for (const bool repeat : { true, false })
  {
    const Map m = RandomMap(12, 9, repeat, repeat ? 3 : 4);
    const std::vector<float> cones = Cones(m, 4.0);
    double sum = 0.0;
    int counted = 0;
    for (int j = 0; j < m.H; ++j)
    {
      for (int i = 0; i < m.W; ++i)
      {
        const double apex = cones[2 * (j * m.W + i)], ratio = cones[2 * (j * m.W + i) + 1];
        double highest = 1e300;
        for (double y = j - 0.5; y <= j + 0.5; y += 0.125)
        {
          for (double x = i - 0.5; x <= i + 0.5; x += 0.125)
          {
            highest = std::min(highest, m.Depth(x, y));
          }
        }
        EXPECT_LE(apex, highest + 1e-12);
        EXPECT_GE(apex, highest - 1e-6) << "the apex is not the footprint's highest point";
        EXPECT_GT(ratio, 0.0) << "texel " << i << ", " << j;
        const double widest = Widest(m, i, j, apex, 4.0);
        EXPECT_LE(ratio, widest * (1 + 1e-9)) << "texel " << i << ", " << j
                                              << ": a sampled point lies inside the cone";
        if (widest < 4.0)
        {
          sum += ratio / widest;
          ++counted;
        }
      }
    }
    std::cout << (repeat ? "repeat" : "clamp") << ": the cones are on average " << sum / counted
              << " of the widest the sampled surface allows\n";
    EXPECT_GE(sum / counted, 0.45);
  }
}

// One raised texel on a flat map, n texels along a row from it: the spike's cells begin
// n - 1.5 texels from the footprint, one unit of depth up; the slope term (a texel's rise over
// a texel) is narrower only for n < 3.
TEST(HeightMapToConeMap, OneRaisedTexel)
{
  Map m{ 32, 32, true, std::vector<double>(32 * 32, 0.0) };
  m.Height[10 * 32 + 10] = 1.0;
  const std::vector<float> cones = Cones(m, 4.0);
  for (int n = 3; n <= 12; ++n)
  {
    const int i = 10 + n, j = 10;
    EXPECT_NEAR(cones[2 * (j * 32 + i)], 1.0, 1e-7);
    EXPECT_NEAR(cones[2 * (j * 32 + i) + 1], (n - 1.5) / 32.0, 1e-6) << "n = " << n;
  }
  // The spike's own texel is the top: nothing above it, the widest cone.
  EXPECT_NEAR(cones[2 * (10 * 32 + 10)], 0.0, 1e-7);
  EXPECT_FLOAT_EQ(cones[2 * (10 * 32 + 10) + 1], 4.0f);
}

// Relaxed cones, against rays walked densely: no step to a cone's side goes under the surface
// and comes back out; every relaxed cone is at least as wide as the conservative one, the same
// apex.
TEST(HeightMapToConeMap, RelaxedConesAreNeverLeftFromBelow)
{
  for (const bool repeat : { true, false })
  {
    const Map m = RandomMap(12, 9, repeat, repeat ? 5 : 6);
    const std::vector<float> conservative = Cones(m, 4.0);
    const std::vector<float> relaxed = Cones(m, 4.0, vtkHeightMapToConeMap::Relaxed);
    double wider = 0.0;
    for (size_t t = 0; t < conservative.size(); t += 2)
    {
      EXPECT_EQ(relaxed[t], conservative[t]) << "texel " << t / 2;
      EXPECT_GE(relaxed[t + 1], conservative[t + 1]) << "texel " << t / 2;
      wider += relaxed[t + 1] / conservative[t + 1];
    }
    std::cout << (repeat ? "repeat" : "clamp") << ": relaxed cones are on average "
              << 2 * wider / conservative.size() << " times as wide as conservative ones\n";
    EXPECT_EQ(StepsThatLeaveTheSurface(m, relaxed, 1.0), 0);
  }
}

// How wide relaxed cones are against the widest the walked rays allow, texel by texel (found by
// bisection): never wider, and on average within a stated fraction of it (less near the edges
// without repeat, where the search does not divide the cells that run on past the edge).
TEST(HeightMapToConeMap, RelaxedConesAreNearTheWidest)
{
  constexpr double maxRatio = 4.0;
  for (const bool repeat : { true, false })
  {
    const Map m = RandomMap(8, 6, repeat, repeat ? 5 : 6);
    const std::vector<float> cones = Cones(m, maxRatio, vtkHeightMapToConeMap::Relaxed);
    double sum = 0.0;
    int counted = 0;
    for (int t = 0; t < m.W * m.H; ++t)
    {
      const int i = t % m.W, j = t / m.W;
      const double apex = cones[2 * t], ratio = cones[2 * t + 1];
      if (StepsThatLeaveTheSurface(m, i, j, apex, maxRatio) == 0)
      {
        continue; // nothing limits the cone
      }
      double fits = 1.0, leaves = maxRatio / ratio; // how much wider the cone may be
      for (int halving = 0; halving < 8; ++halving)
      {
        const double widen = std::sqrt(fits * leaves);
        (StepsThatLeaveTheSurface(m, i, j, apex, widen * ratio) > 0 ? leaves : fits) = widen;
      }
      EXPECT_GT(leaves, 1.0) << "texel " << i << ", " << j;
      sum += 1.0 / leaves;
      ++counted;
    }
    std::cout << (repeat ? "repeat" : "clamp") << ": relaxed cones are on average "
              << sum / counted << " of the widest the walked rays allow\n";
    EXPECT_GE(sum / counted, 0.45);
  }
}

// A ridge eight texels wide across a flat map: from the floor n texels before it, a relaxed
// cone reaches over the ridge to where its far wall begins to fall (n + 6.5 texels away, a unit
// of depth up), a conservative one only to its near wall (n - 1.5 texels).
TEST(HeightMapToConeMap, RelaxedConesReachOverARidge)
{
  Map m{ 32, 32, true, std::vector<double>(32 * 32, 0.0) };
  for (int j = 0; j < 32; ++j)
  {
    std::fill_n(m.Height.begin() + 32 * j + 10, 8, 1.0);
  }
  const std::vector<float> conservative = Cones(m, 4.0);
  const std::vector<float> relaxed = Cones(m, 4.0, vtkHeightMapToConeMap::Relaxed);
  for (int n = 3; n <= 6; ++n)
  {
    const size_t texel = 2 * (16 * 32 + 10 - n) + 1;
    EXPECT_NEAR(conservative[texel], (n - 1.5) / 32.0, 1e-6) << "n = " << n;
    EXPECT_NEAR(relaxed[texel], (n + 6.5) / 32.0, 1e-6) << "n = " << n;
  }
}

// Maps one or two texels wide (lines without repeat): finite cones, never left from below.
TEST(HeightMapToConeMap, NarrowMaps)
{
  for (const bool repeat : { true, false })
  {
    for (const auto& size : { std::make_pair(1, 1), std::make_pair(1, 5), std::make_pair(5, 1),
           std::make_pair(2, 2), std::make_pair(2, 7) })
    {
      const Map m = RandomMap(size.first, size.second, repeat, 7);
      for (int type : { vtkHeightMapToConeMap::Conservative, vtkHeightMapToConeMap::Relaxed })
      {
        const std::vector<float> cones = Cones(m, 2.0, type);
        ASSERT_EQ(cones.size(), 2u * m.W * m.H);
        for (size_t t = 0; t < cones.size(); t += 2)
        {
          EXPECT_TRUE(cones[t] >= 0.0f && cones[t] <= 1.0f) << cones[t];
          EXPECT_TRUE(cones[t + 1] > 0.0f && cones[t + 1] <= 2.0f) << cones[t + 1];
        }
        EXPECT_EQ(StepsThatLeaveTheSurface(m, cones, 1.0), 0)
          << m.W << "x" << m.H << (repeat ? " repeat" : " clamp") << ", type " << type;
      }
    }
  }
}

TEST(HeightMapToConeMap, SameAtAnyThreadCount)
{
  const Map m = RandomMap(64, 48, true, 11);
  for (int type : { vtkHeightMapToConeMap::Conservative, vtkHeightMapToConeMap::Relaxed })
  {
    vtkSMPTools::Initialize(1);
    const std::vector<float> one = Cones(m, 1.0, type);
    vtkSMPTools::Initialize(2);
    const std::vector<float> two = Cones(m, 1.0, type);
    EXPECT_EQ(one, two);
  }
}

TEST(HeightMapToConeMap, BadInputIsAnError)
{
  std::string said;
  vtkNew<vtkCallbackCommand> listen;
  listen->SetClientData(&said);
  listen->SetCallback([](vtkObject*, unsigned long, void* client, void* data)
    { *static_cast<std::string*>(client) = static_cast<const char*>(data); });
  auto expectRefused = [&](vtkImageData* image, int wrap, const char* words)
  {
    vtkNew<vtkHeightMapToConeMap> filter;
    filter->AddObserver(vtkCommand::ErrorEvent, listen);
    filter->SetInputData(image);
    filter->SetWrap(wrap);
    said.clear();
    filter->Update();
    EXPECT_NE(said.find(words), std::string::npos) << said;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  };
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(4, 4, 4);
  volume->AllocateScalars(VTK_FLOAT, 1);
  expectRefused(volume, vtkSurfaceDetail::Repeat, "2-D image");
  vtkNew<vtkImageData> signedMap;
  signedMap->SetDimensions(4, 4, 1);
  signedMap->AllocateScalars(VTK_INT, 1);
  expectRefused(signedMap, vtkSurfaceDetail::Repeat, "vtkImageShiftScale");
  vtkSmartPointer<vtkImageData> flat = Image(Map{ 4, 4, true, std::vector<double>(16, 0.5) });
  expectRefused(flat, vtkSurfaceDetail::MirroredRepeat, "Repeat or ClampToEdge");
  flat->GetPointData()->GetScalars()->SetComponent(5, 0, std::nan(""));
  expectRefused(flat, vtkSurfaceDetail::Repeat, "non-finite");
}
