// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The study's image error measures (SurfaceDetailImageMetrics.h) against values worked out by
// hand from Wang et al.'s definitions, and against the properties SSIM is made to have:
// identical images score exactly 1, a change of mean brightness costs far less than noise of
// the same RMSE, an inverted pattern scores near -1.

#include "SurfaceDetailImageMetrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
namespace M = SurfaceDetailImageMetrics;

std::vector<double> RandomTexture(
  int width, int height, unsigned seed, double low = 40.0, double high = 215.0)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> level(low, high);
  std::vector<double> image(static_cast<size_t>(width) * height);
  for (double& v : image)
  {
    v = level(random);
  }
  return image;
}

// An 8x8 image, left half @a left, right half @a right: with the 8x8 window exactly one
// pixel (column 3, row 3) has its window inside.
std::vector<double> Halves(double left, double right)
{
  std::vector<double> image(64);
  for (int j = 0; j < 8; ++j)
  {
    for (int i = 0; i < 8; ++i)
    {
      image[j * 8 + i] = i < 4 ? left : right;
    }
  }
  return image;
}
} // namespace

TEST(SurfaceDetailImageMetrics, IdenticalImagesScoreOne)
{
  const std::vector<double> a = RandomTexture(40, 30, 1);
  EXPECT_NEAR(M::MeanSSIM(a, a, 40, 30), 1.0, 1e-12);
  EXPECT_NEAR(M::MeanSSIM(a, a, 40, 30, nullptr, M::Window::Uniform8), 1.0, 1e-12);
}

// Both images constant: the variances vanish and SSIM is the luminance term alone,
// (2*100*110 + C1) / (100^2 + 110^2 + C1) with C1 = (0.01*255)^2 = 6.5025.
TEST(SurfaceDetailImageMetrics, ConstantImagesGiveTheLuminanceTerm)
{
  const std::vector<double> a(30 * 20, 100.0), b(30 * 20, 110.0);
  const double expected = 22006.5025 / 22106.5025;
  EXPECT_NEAR(M::MeanSSIM(a, b, 30, 20), expected, 1e-12);
  EXPECT_NEAR(M::MeanSSIM(a, b, 30, 20, nullptr, M::Window::Uniform8), expected, 1e-12);
}

// One 8x8 window over two halves: a = 0 | 100, b = 0 | 50. Means 50 and 25, variances 2500 and
// 625, covariance 1250 (weights 1/64), C2 = (0.03*255)^2 = 58.5225:
// (2*50*25 + C1)(2*1250 + C2) / ((50^2 + 25^2 + C1)(2500 + 625 + C2))
//   = 2506.5025 * 2558.5225 / (3131.5025 * 3183.5225) = 0.6432750338.
TEST(SurfaceDetailImageMetrics, HandComputedWindow)
{
  const double ssim =
    M::MeanSSIM(Halves(0, 100), Halves(0, 50), 8, 8, nullptr, M::Window::Uniform8);
  EXPECT_NEAR(ssim, 0.6432750338, 1e-9);
  // The pattern inverted: covariance -2500, so (5000 + C1)(-5000 + C2) / ((5000 + C1)(5000 + C2)).
  const double inverted =
    M::MeanSSIM(Halves(0, 100), Halves(100, 0), 8, 8, nullptr, M::Window::Uniform8);
  EXPECT_NEAR(inverted, (-5000 + 58.5225) / (5000 + 58.5225), 1e-12);
  const std::vector<double> map =
    M::SSIMMap(Halves(0, 100), Halves(0, 50), 8, 8, M::Window::Uniform8);
  for (int p = 0; p < 64; ++p)
  {
    EXPECT_EQ(std::isnan(map[p]), p != 3 * 8 + 3) << "pixel " << p;
  }
}

// A constant shift keeps structure and contrast; noise of the same RMSE does not. The texture
// has a standard deviation of about 10 levels (uniform over 35), as strong as the noise, so
// SSIM should fall to about (2*100 + C2) / (2*100 + 100 + C2) = 0.72 with it.
TEST(SurfaceDetailImageMetrics, ShiftCostsLessThanNoiseOfTheSameRMSE)
{
  const int w = 64, h = 48;
  const std::vector<double> a = RandomTexture(w, h, 2, 90.0, 125.0);
  std::vector<double> shifted(a), noisy(a);
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 10.0);
  for (size_t p = 0; p < a.size(); ++p)
  {
    shifted[p] += 10.0;
    noisy[p] += noise(random);
  }
  const double shift = M::MeanSSIM(a, shifted, w, h);
  const double noise10 = M::MeanSSIM(a, noisy, w, h);
  EXPECT_LT(shift, 1.0);
  EXPECT_GT(shift, 0.99);
  EXPECT_LT(noise10, 0.9);
  EXPECT_NEAR(M::MeanSSIM(noisy, a, w, h), noise10, 1e-12) << "SSIM is symmetric";
}

// The mean is taken only where the mask says: a damaged corner counts or not.
TEST(SurfaceDetailImageMetrics, MaskSelectsThePixels)
{
  const int w = 40, h = 40;
  const std::vector<double> a = RandomTexture(w, h, 4);
  std::vector<double> b(a);
  std::vector<bool> left(w * h), right(w * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      left[j * w + i] = i < 15;
      right[j * w + i] = i >= 25;
      if (i >= 25)
      {
        b[j * w + i] = 255.0 - b[j * w + i];
      }
    }
  }
  EXPECT_NEAR(M::MeanSSIM(a, b, w, h, &left), 1.0, 1e-12);
  EXPECT_LT(M::MeanSSIM(a, b, w, h, &right), 0.0);
  const double all = M::MeanSSIM(a, b, w, h);
  EXPECT_LT(all, 1.0);
  EXPECT_GT(all, M::MeanSSIM(a, b, w, h, &right));
}

TEST(SurfaceDetailImageMetrics, RMSEAndPSNR)
{
  const unsigned char a[6] = { 0, 0, 0, 10, 20, 30 };
  const unsigned char b[6] = { 10, 10, 10, 10, 20, 30 };
  EXPECT_DOUBLE_EQ(M::RMSE(a, b, 2), std::sqrt(300.0 / 6.0));
  const std::vector<bool> first = { true, false };
  EXPECT_DOUBLE_EQ(M::RMSE(a, b, 2, &first), 10.0);
  EXPECT_NEAR(M::PSNR(10.0), 20.0 * std::log10(25.5), 1e-12);
  EXPECT_TRUE(std::isinf(M::PSNR(0.0)));
  const unsigned char white[3] = { 255, 255, 255 };
  EXPECT_NEAR(M::Luminance(white, 1, 1)[0], 255.0, 1e-9);
}
