// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The textures in Data/ are what Data/README.md says they are: sizes, types, channels,
// which way up, brick heights (mortar low, faces high, bevels rising) and seamless tiling.

#include "vtkOIIOImageReader.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{
vtkSmartPointer<vtkImageData> Load(const char* name)
{
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName((std::string(SURFACEDETAIL_DATA_DIR) + "/" + name).c_str());
  reader->Update();
  EXPECT_EQ(reader->GetErrorCode(), 0) << name;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  return image;
}

/// Mean absolute difference, over all rows and components, between columns a and b (or,
/// with rows = true, between rows a and b).
double LineDifference(vtkImageData* image, int a, int b, bool rows)
{
  const int* d = image->GetDimensions();
  const int components = image->GetNumberOfScalarComponents();
  const int n = rows ? d[0] : d[1];
  double sum = 0;
  for (int k = 0; k < n; ++k)
  {
    for (int c = 0; c < components; ++c)
    {
      const double p = rows ? image->GetScalarComponentAsDouble(k, a, 0, c)
                            : image->GetScalarComponentAsDouble(a, k, 0, c);
      const double q = rows ? image->GetScalarComponentAsDouble(k, b, 0, c)
                            : image->GetScalarComponentAsDouble(b, k, 0, c);
      sum += std::abs(p - q);
    }
  }
  return sum / (n * components);
}

/// A tiling texture changes no more across its wrap-around seam than between neighbouring
/// lines inside it on average (for the noise and the marble, a cut through the middle
/// changes 8-40 times more; the bricks meet in mortar at the seam, by construction).
void ExpectTiles(const char* name)
{
  auto image = Load(name);
  const int* d = image->GetDimensions();
  for (bool rows : { false, true })
  {
    const int n = rows ? d[1] : d[0];
    double interior = 0;
    for (int k = 0; k + 1 < n; ++k)
    {
      interior += LineDifference(image, k, k + 1, rows);
    }
    interior /= n - 1;
    EXPECT_LE(LineDifference(image, n - 1, 0, rows), interior)
      << name << (rows ? ": top/bottom seam" : ": left/right seam");
  }
}
}

TEST(TestSurfaceDetailData, LayoutAsDocumented)
{
  struct Expected
  {
    const char* Name;
    int Size, Type, Components;
  };
  const Expected files[] = { { "brick_color.png", 512, VTK_UNSIGNED_CHAR, 3 },
    { "brick_height.png", 512, VTK_UNSIGNED_SHORT, 1 },
    { "checkerboard.png", 256, VTK_UNSIGNED_CHAR, 3 },
    { "noise_height.png", 256, VTK_UNSIGNED_SHORT, 1 }, { "marble.png", 512, VTK_UNSIGNED_CHAR, 3 },
    { "test_card.png", 512, VTK_UNSIGNED_CHAR, 3 } };
  for (const Expected& e : files)
  {
    auto image = Load(e.Name);
    EXPECT_EQ(image->GetDimensions()[0], e.Size) << e.Name;
    EXPECT_EQ(image->GetDimensions()[1], e.Size) << e.Name;
    EXPECT_EQ(image->GetScalarType(), e.Type) << e.Name;
    EXPECT_EQ(image->GetNumberOfScalarComponents(), e.Components) << e.Name;
  }
}

TEST(TestSurfaceDetailData, TexturesTile)
{
  for (const char* name :
    { "brick_color.png", "brick_height.png", "noise_height.png", "marble.png" })
  {
    ExpectTiles(name);
  }
  // The checkerboard's edges are sharp everywhere, so it tiles if it repeats every two
  // squares (64 texels) across the seam too.
  auto checker = Load("checkerboard.png");
  int breaks = 0;
  for (int j = 0; j < 256; ++j)
  {
    for (int i = 0; i < 256; ++i)
    {
      breaks += checker->GetScalarComponentAsDouble(i, j, 0, 0) !=
        checker->GetScalarComponentAsDouble((i + 64) % 256, (j + 64) % 256, 0, 0);
    }
  }
  EXPECT_EQ(breaks, 0);
}

// Bricks 128 x 64 texels, courses from the bottom (row 0), odd courses shifted by 64.
TEST(TestSurfaceDetailData, BrickHeightRaisedBevelledBricks)
{
  auto image = Load("brick_height.png");
  auto h = [&image](int i, int j) { return image->GetScalarComponentAsDouble(i, j, 0, 0) / 65535; };
  EXPECT_GE(h(64, 32), 0.9);  // Middle of the first brick of course 0.
  EXPECT_GE(h(128, 96), 0.9); // Middle of a brick of course 1 (shifted by half a brick).
  EXPECT_LE(h(0, 32), 0.12);  // Vertical joint of course 0.
  EXPECT_LE(h(64, 96), 0.12); // Vertical joint of course 1.
  EXPECT_LE(h(64, 0), 0.12);  // Horizontal joint under course 0.
  EXPECT_LE(h(64, 64), 0.12); // Horizontal joint between courses 0 and 1.
  // From the joint into the brick the bevel rises, then the face is flat-ish.
  for (int i = 4; i < 10; ++i)
  {
    EXPECT_LT(h(i, 32), h(i + 1, 32)) << "bevel at column " << i;
  }
  EXPECT_LE(h(3, 32), 0.12); // Joints are 8 texels wide: texels 0-3 and 124-131 of a row.
}

// The picture's top is VTK's highest row: the checkerboard's dark square is at (0,0), the
// test card's blue quadrant top-left.
TEST(TestSurfaceDetailData, Orientation)
{
  auto checker = Load("checkerboard.png");
  EXPECT_LT(checker->GetScalarComponentAsDouble(0, 0, 0, 0), 64);
  EXPECT_GT(checker->GetScalarComponentAsDouble(40, 0, 0, 0), 192);
  auto card = Load("test_card.png");
  const double blue = card->GetScalarComponentAsDouble(100, 400, 0, 2) -
    card->GetScalarComponentAsDouble(100, 400, 0, 0);
  const double red = card->GetScalarComponentAsDouble(100, 100, 0, 0) -
    card->GetScalarComponentAsDouble(100, 100, 0, 2);
  EXPECT_GT(blue, 50); // Top-left.
  EXPECT_GT(red, 50);  // Bottom-left.
}

TEST(TestSurfaceDetailData, NoiseHeightFillsUnitRange)
{
  auto image = Load("noise_height.png");
  double range[2];
  image->GetScalarRange(range);
  EXPECT_EQ(range[0], 0.0);
  EXPECT_EQ(range[1], 65535.0);
}
