// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Image error measures for comparing a rendering with a reference over the pixels an object
// covers: RMSE and PSNR on 8-bit RGB, and SSIM (Wang, Bovik, Sheikh & Simoncelli 2004, "Image
// quality assessment: from error visibility to structural similarity") on luminance. VTK 9.1
// has no SSIM (vtkImageSSIM is 9.4+), so it is written here, once, for the study program and
// its test.
//
// SSIM follows the paper's weighted form (its equations 14-16): a window of weights w summing
// to one, local mean mu = sum w x, variance sigma^2 = sum w (x - mu)^2, covariance likewise,
// C1 = (K1 L)^2 and C2 = (K2 L)^2 with K1 = 0.01, K2 = 0.03, L = 255, and
//   SSIM = (2 mu_a mu_b + C1)(2 sigma_ab + C2) / ((mu_a^2 + mu_b^2 + C1)(sigma_a^2 + sigma_b^2 +
//   C2)).
// Windows: the paper's 11x11 circular Gaussian with sigma 1.5, or a uniform 8x8 square. The
// mean SSIM is taken over the pixels whose window lies wholly inside the image (the paper's
// "valid" region) and, when a mask is given, that the mask selects.
#ifndef SurfaceDetailImageMetrics_h
#define SurfaceDetailImageMetrics_h

#include <cmath>
#include <limits>
#include <vector>

namespace SurfaceDetailImageMetrics
{
enum class Window
{
  Gaussian11,
  Uniform8
};

// Rec. 601 luma of 8-bit RGB triples, row by row.
inline std::vector<double> Luminance(const unsigned char* rgb, int width, int height)
{
  std::vector<double> y(static_cast<size_t>(width) * height);
  for (size_t p = 0; p < y.size(); ++p)
  {
    y[p] = 0.299 * rgb[3 * p] + 0.587 * rgb[3 * p + 1] + 0.114 * rgb[3 * p + 2];
  }
  return y;
}

// The window's one-dimensional weights (both windows are separable) and the offset of its
// first tap from the pixel it is reported at.
inline std::vector<double> WindowWeights(Window window, int& first)
{
  std::vector<double> w;
  if (window == Window::Uniform8)
  {
    w.assign(8, 1.0 / 8.0);
    first = -3;
    return w;
  }
  first = -5;
  double sum = 0;
  for (int k = -5; k <= 5; ++k)
  {
    w.push_back(std::exp(-(k * k) / (2.0 * 1.5 * 1.5)));
    sum += w.back();
  }
  for (double& v : w)
  {
    v /= sum;
  }
  return w;
}

// The SSIM map: one value per pixel, NaN where the window does not lie inside the image.
inline std::vector<double> SSIMMap(const std::vector<double>& a, const std::vector<double>& b,
  int width, int height, Window window = Window::Gaussian11)
{
  int first = 0;
  const std::vector<double> w = WindowWeights(window, first);
  const int n = static_cast<int>(w.size());
  const size_t count = static_cast<size_t>(width) * height;
  // Five local moments, filtered along rows then columns (valid taps only).
  std::vector<double> source[5], rows[5], moments[5];
  for (int m = 0; m < 5; ++m)
  {
    source[m].resize(count);
    rows[m].assign(count, 0.0);
    moments[m].assign(count, 0.0);
  }
  for (size_t p = 0; p < count; ++p)
  {
    source[0][p] = a[p];
    source[1][p] = b[p];
    source[2][p] = a[p] * a[p];
    source[3][p] = b[p] * b[p];
    source[4][p] = a[p] * b[p];
  }
  auto inside = [&](int i, int size) { return i + first >= 0 && i + first + n - 1 < size; };
  for (int m = 0; m < 5; ++m)
  {
    for (int j = 0; j < height; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        if (!inside(i, width))
        {
          continue;
        }
        double sum = 0;
        for (int k = 0; k < n; ++k)
        {
          sum += w[k] * source[m][static_cast<size_t>(j) * width + i + first + k];
        }
        rows[m][static_cast<size_t>(j) * width + i] = sum;
      }
    }
    for (int j = 0; j < height; ++j)
    {
      if (!inside(j, height))
      {
        continue;
      }
      for (int i = 0; i < width; ++i)
      {
        double sum = 0;
        for (int k = 0; k < n; ++k)
        {
          sum += w[k] * rows[m][static_cast<size_t>(j + first + k) * width + i];
        }
        moments[m][static_cast<size_t>(j) * width + i] = sum;
      }
    }
  }
  const double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
  std::vector<double> map(count, std::numeric_limits<double>::quiet_NaN());
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      if (!inside(i, width) || !inside(j, height))
      {
        continue;
      }
      const size_t p = static_cast<size_t>(j) * width + i;
      const double ma = moments[0][p], mb = moments[1][p];
      const double va = moments[2][p] - ma * ma, vb = moments[3][p] - mb * mb;
      const double cov = moments[4][p] - ma * mb;
      map[p] = (2 * ma * mb + c1) * (2 * cov + c2) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
    }
  }
  return map;
}

// Mean SSIM over the valid pixels that @a mask selects (all valid pixels without a mask);
// NaN when none is selected.
inline double MeanSSIM(const std::vector<double>& a, const std::vector<double>& b, int width,
  int height, const std::vector<bool>* mask = nullptr, Window window = Window::Gaussian11)
{
  const std::vector<double> map = SSIMMap(a, b, width, height, window);
  double sum = 0;
  size_t count = 0;
  for (size_t p = 0; p < map.size(); ++p)
  {
    if (!std::isnan(map[p]) && (!mask || (*mask)[p]))
    {
      sum += map[p];
      ++count;
    }
  }
  return count ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

// Root mean square difference in 8-bit levels over R, G and B of the selected pixels.
inline double RMSE(const unsigned char* a, const unsigned char* b, size_t pixels,
  const std::vector<bool>* mask = nullptr)
{
  double sum = 0;
  size_t count = 0;
  for (size_t p = 0; p < pixels; ++p)
  {
    if (mask && !(*mask)[p])
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const double d = static_cast<double>(a[3 * p + c]) - b[3 * p + c];
      sum += d * d;
    }
    ++count;
  }
  return count ? std::sqrt(sum / (3.0 * count)) : 0.0;
}

// Peak signal-to-noise ratio (dB) of an RMSE in 8-bit levels; infinite for identical images.
inline double PSNR(double rmse)
{
  return rmse > 0 ? 20.0 * std::log10(255.0 / rmse) : std::numeric_limits<double>::infinity();
}
} // namespace SurfaceDetailImageMetrics

#endif
