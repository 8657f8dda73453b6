// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkHeightMapToNormalMap's Sobel and Scharr schemes against their published 3x3 kernels.
// Smooth heights cannot tell the cross weights apart (any symmetric smoothing of a central
// difference is second order), so the maps here have single raised texels: every texel within
// one of a raised one sees one kernel weight, the diagonal ones the cross weight alone (Sobel
// 1/8, Scharr 3/32 of a unit step), the others the centre weight (Sobel 2/8, Scharr 10/32).
//
// The kernels are written out here as they are published, for d/dx with x to the right:
//   Sobel  [-1 0 1; -2 0 2; -1 0 1] / 8      Scharr [-3 0 3; -10 0 10; -3 0 3] / 32
// (the 1/8 and 1/32 make them estimate the derivative per texel) and their transposes for
// d/dy. The filter's normal is normalize(-k W dh/dx, -k H dh/dy, 1) with k = Strength and
// W x H the map size (per unit of texture coordinate), +y = +t (GreenUp), stored as 0.5 n + 0.5.

#include "vtkHeightMapToNormalMap.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace
{
struct Kernel
{
  const char* Name;
  int Scheme;
  double X[3][3]; // [row dy + 1][column dx + 1], rows from -y to +y
};

const Kernel Sobel = { "Sobel", vtkHeightMapToNormalMap::Sobel,
  { { -1 / 8.0, 0.0, 1 / 8.0 }, { -2 / 8.0, 0.0, 2 / 8.0 }, { -1 / 8.0, 0.0, 1 / 8.0 } } };
const Kernel Scharr = { "Scharr", vtkHeightMapToNormalMap::Scharr,
  { { -3 / 32.0, 0.0, 3 / 32.0 }, { -10 / 32.0, 0.0, 10 / 32.0 }, { -3 / 32.0, 0.0, 3 / 32.0 } } };

int Wrapped(int i, int n, int wrap)
{
  if (wrap == vtkHeightMapToNormalMap::Repeat)
  {
    return ((i % n) + n) % n;
  }
  return i < 0 ? 0 : (i >= n ? n - 1 : i); // ClampToEdge (and MirroredRepeat, one texel out)
}

// A W x H map of zeros with the given texels raised to the given heights.
vtkSmartPointer<vtkImageData> RaisedTexels(
  int W, int H, const std::vector<std::pair<std::pair<int, int>, double>>& raised)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  vtkNew<vtkFloatArray> heights;
  heights->SetNumberOfTuples(static_cast<vtkIdType>(W) * H);
  heights->Fill(0.0);
  for (const auto& texel : raised)
  {
    heights->SetValue(texel.first.second * W + texel.first.first, static_cast<float>(texel.second));
  }
  image->GetPointData()->SetScalars(heights);
  return image;
}

// The kernel applied at texel (i,j), the neighbours read through the wrap mode: d/dx with
// the kernel, d/dy with its transpose.
void Convolve(
  vtkImageData* image, const Kernel& kernel, int wrap, int i, int j, double& dx, double& dy)
{
  const int W = image->GetDimensions()[0], H = image->GetDimensions()[1];
  vtkDataArray* h = image->GetPointData()->GetScalars();
  dx = dy = 0.0;
  for (int a = -1; a <= 1; ++a)
  {
    for (int b = -1; b <= 1; ++b)
    {
      const double value =
        h->GetComponent(Wrapped(j + a, H, wrap) * W + Wrapped(i + b, W, wrap), 0);
      dx += kernel.X[a + 1][b + 1] * value;
      dy += kernel.X[b + 1][a + 1] * value;
    }
  }
}

// Every texel of the filter's float map against the kernel's normal; returns how many texels
// have a slope (the feature must be seen).
int ExpectKernelNormals(vtkImageData* image, const Kernel& kernel, int wrap, double strength)
{
  vtkNew<vtkHeightMapToNormalMap> filter;
  filter->SetInputData(image);
  filter->SetDifferenceScheme(kernel.Scheme);
  filter->SetBumpScale(strength);
  filter->SetWrap(wrap);
  filter->SetOutputScalarTypeToFloat();
  filter->Update();
  vtkDataArray* map = filter->GetOutput()->GetPointData()->GetScalars();
  const int W = image->GetDimensions()[0], H = image->GetDimensions()[1];
  EXPECT_EQ(map->GetNumberOfTuples(), static_cast<vtkIdType>(W) * H);
  EXPECT_EQ(map->GetNumberOfComponents(), 3);
  int sloped = 0;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      double dx, dy;
      Convolve(image, kernel, wrap, i, j, dx, dy);
      double n[3] = { -strength * W * dx, -strength * H * dy, 1.0 };
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      sloped += dx != 0.0 || dy != 0.0 ? 1 : 0;
      for (int c = 0; c < 3; ++c)
      {
        const double stored = map->GetComponent(static_cast<vtkIdType>(j) * W + i, c);
        EXPECT_NEAR(stored, 0.5 * n[c] / length + 0.5, 1e-6)
          << kernel.Name << " texel (" << i << ", " << j << ") component " << c;
      }
    }
  }
  return sloped;
}
} // namespace

// One raised texel in the middle of a 7 x 5 map (so W and H scale the slopes differently): the
// eight texels around it have slopes of one kernel weight each.
TEST(HeightMapToNormalMapKernels, SingleRaisedTexelGivesTheKernelWeights)
{
  auto image = RaisedTexels(7, 5, { { { 3, 2 }, 1.0 } });
  for (const Kernel& kernel : { Sobel, Scharr })
  {
    EXPECT_EQ(ExpectKernelNormals(image, kernel, vtkHeightMapToNormalMap::Repeat, 0.05), 8);
  }
}

// Spelled out for one texel, so that the test does not rest on Convolve alone: the texel
// diagonally above right of the raised one has dh/dx = -c and dh/dy = -c per texel, c being
// the kernel's corner weight.
TEST(HeightMapToNormalMapKernels, DiagonalNeighbourSeesTheCrossWeightAlone)
{
  const int W = 7, H = 5;
  const double k = 0.05;
  auto image = RaisedTexels(W, H, { { { 3, 2 }, 1.0 } });
  for (const auto& scheme : { std::make_pair(vtkHeightMapToNormalMap::Sobel, 1.0 / 8.0),
         std::make_pair(vtkHeightMapToNormalMap::Scharr, 3.0 / 32.0) })
  {
    vtkNew<vtkHeightMapToNormalMap> filter;
    filter->SetInputData(image);
    filter->SetDifferenceScheme(scheme.first);
    filter->SetBumpScale(k);
    filter->SetOutputScalarTypeToFloat();
    filter->Update();
    vtkDataArray* map = filter->GetOutput()->GetPointData()->GetScalars();
    const double c = scheme.second;
    double n[3] = { k * W * c, k * H * c, 1.0 };
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int q = 0; q < 3; ++q)
    {
      EXPECT_NEAR(map->GetComponent(3 * W + 4, q), 0.5 * n[q] / length + 0.5, 1e-6)
        << filter->GetDifferenceSchemeAsString() << " component " << q;
    }
  }
}

// Raised texels of different heights near each other, at a corner and on an edge, so that
// stencils overlap and read across the borders (wrapped or clamped).
TEST(HeightMapToNormalMapKernels, OverlappingStencilsAcrossTheBorders)
{
  auto image = RaisedTexels(
    6, 6, { { { 0, 0 }, 0.9 }, { { 1, 1 }, 0.4 }, { { 5, 3 }, 0.7 }, { { 3, 5 }, 0.25 } });
  for (const Kernel& kernel : { Sobel, Scharr })
  {
    for (int wrap : { vtkHeightMapToNormalMap::Repeat, vtkHeightMapToNormalMap::ClampToEdge })
    {
      SCOPED_TRACE(std::string(kernel.Name) +
        (wrap == vtkHeightMapToNormalMap::Repeat ? " Repeat" : " ClampToEdge"));
      EXPECT_GE(ExpectKernelNormals(image, kernel, wrap, 0.08), 20);
    }
  }
}
