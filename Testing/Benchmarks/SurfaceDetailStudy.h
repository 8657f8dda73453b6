// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Pieces shared by the files of the SurfaceDetailStudy program: the result rows, the Pareto
// front, the plot, and the CPU filter study.
#ifndef SurfaceDetailStudy_h
#define SurfaceDetailStudy_h

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace SurfaceDetailStudy
{
// One technique at one setting in one scene, measured.
struct Row
{
  std::string Scene;
  std::string Family;                           // what the plot colours by
  std::string Setting;                          // the settings within the family
  bool Truth = false;                           // the reference itself: timed, never judged
  double FrameMs = 0, FrameQ1 = 0, FrameQ3 = 0; // median and quartiles of the timed frames
  double FirstFrameMs = 0;                      // the first frame: shader compilation and uploads
  double PrepMs = 0; // CPU filters run before rendering (median of repeats)
  double MeshKiB = 0, TextureKiB = 0;
  double RMSE = 0, PSNR = 0, SSIM = 1;
  double InteriorRMSE = 0; // over the pixels both pictures cover: silhouettes left out
  bool OnFront = false;    // on the (frame time, RMSE) Pareto front of its scene
};

// Marks the rows (Truth excluded) that no other row beats in both frame time and RMSE
// (less or equal in both, less in one).
inline void MarkParetoFront(std::vector<Row*>& rows)
{
  for (Row* a : rows)
  {
    a->OnFront = !a->Truth;
    for (const Row* b : rows)
    {
      if (a == b || b->Truth || !a->OnFront)
      {
        continue;
      }
      const bool noWorse = b->FrameMs <= a->FrameMs && b->RMSE <= a->RMSE;
      const bool better = b->FrameMs < a->FrameMs || b->RMSE < a->RMSE;
      if (noWorse && better)
      {
        a->OnFront = false;
      }
    }
  }
}

// Error (RMSE) against median frame time, one colour per family, the front as a line: a PNG
// drawn by VTK's charts in an offscreen window.
void PlotScene(const std::string& title, const std::vector<const Row*>& rows,
  double convergenceRMSE, const std::string& pngPath);

// The CPU filter studies (analytic truths): source resolution, displacement normal modes,
// height-to-normal schemes. Writes CSV rows to @a csv and Markdown tables to @a markdown.
void RunFilterStudies(std::FILE* csv, std::FILE* markdown, int repeats);

// Median of a sample (by copy).
inline double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

inline double Quantile(std::vector<double> v, double q)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * (v.size() - 1) + 0.5)];
}
} // namespace SurfaceDetailStudy

#endif
