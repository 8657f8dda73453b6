// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHeightMapToNormalMap.h"

#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkEndian.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailProgress.h"
#include "vtkTypeTraits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkHeightMapToNormalMap);

namespace
{

// Slopes beyond this are clamped so that their squares cannot overflow a float: the normal
// is then horizontal to within 1e-18, and never NaN.
constexpr double MaxSlope = 1e18;

template <typename Real>
struct RowCache
{
  std::array<std::vector<Real>, 3> Rows;
  // The input row each cached row holds; -1 is the border row (ClampToBorder), Empty none.
  static constexpr int Empty = std::numeric_limits<int>::min();
  std::array<int, 3> Tags{ { Empty, Empty, Empty } };
  std::vector<Real> Gx, Gy, B, A;
  std::vector<uint32_t> Words32; // packed quantised texels (8-bit outputs)
  std::vector<uint64_t> Words64; // packed quantised texels (16-bit outputs)
  // What this thread saw: non-finite heights in the rows it read, and (floating-point input
  // with OutputRelief) heights outside [0,1] among the texels it wrote.
  bool NonFinite = false;
  vtkIdType OutOfRange = 0;
};

struct KernelReport
{
  bool NonFinite = false;
  vtkIdType OutOfRange = 0;
};

template <typename InT, typename Real, typename OutT>
struct NormalMapKernel
{
  const InT* In = nullptr;
  int InStride = 1; // components per input tuple: only the first is read
  int W = 0, H = 0;
  int I0 = 0, I1 = -1, J0 = 0; // requested output columns and first row, in input indices
  OutT* Out = nullptr;
  int OutComps = 3;
  int Scheme = vtkHeightMapToNormalMap::Central;
  int Wrap = vtkSurfaceDetail::Repeat;
  bool GreenUp = true;
  Real Sx = 1, Sy = 1; // k * W (or H) * height scale: texel difference -> slope
  Real HScale = 1;
  Real Border = 0; // ClampToBorder: the height outside, in the input's units
  vtkSurfaceDetail::Progress* Progress = nullptr;
  vtkSMPThreadLocal<RowCache<Real>> Cache;

  void Initialize()
  {
    RowCache<Real>& c = this->Cache.Local();
    for (auto& r : c.Rows)
    {
      r.resize(static_cast<size_t>(this->W) + 2);
    }
    const size_t n = static_cast<size_t>(this->I1 - this->I0 + 1);
    c.Gx.resize(n);
    c.Gy.resize(n);
    c.B.resize(n);
    c.A.resize(this->OutComps == 4 ? n : 0);
    c.Words32.resize(sizeof(OutT) == 1 ? n : 0);
    c.Words64.resize(sizeof(OutT) == 2 ? n : 0);
  }

  // Row r of the height map as Real, padded with the wrapped texel on each side so that the
  // stencils below never test for borders: row[k + 1] is texel k, row[0] texel -1. Row -1
  // is the border row of ClampToBorder.
  const Real* Row(RowCache<Real>& c, int r, const int keep[3])
  {
    for (int b = 0; b < 3; ++b)
    {
      if (c.Tags[b] == r)
      {
        return c.Rows[b].data();
      }
    }
    int b = 0;
    while (c.Tags[b] == keep[0] || c.Tags[b] == keep[1] || c.Tags[b] == keep[2])
    {
      ++b;
    }
    Real* row = c.Rows[b].data();
    c.Tags[b] = r;
    if (r < 0)
    {
      std::fill(row, row + this->W + 2, this->Border);
      return row;
    }
    const InT* src = this->In + static_cast<size_t>(r) * this->W * this->InStride;
    const int stride = this->InStride;
    if (stride == 1)
    {
      std::copy(src, src + this->W, row + 1); // vectorised conversion of the common case
    }
    else
    {
      for (int k = 0; k < this->W; ++k)
      {
        row[k + 1] = static_cast<Real>(src[static_cast<size_t>(k) * stride]);
      }
    }
    if constexpr (std::is_floating_point<InT>::value)
    {
      // NaN fails the comparison too; a count (not a branch) keeps the loop vectorised.
      const Real big = std::numeric_limits<Real>::max();
      int bad = 0;
      for (int k = 1; k <= this->W; ++k)
      {
        bad += std::abs(row[k]) <= big ? 0 : 1;
      }
      c.NonFinite = c.NonFinite || bad > 0;
    }
    // Under ClampToBorder WrapIndex gives -1 outside, which reads the border.
    const int before = vtkSurfaceDetail::WrapIndex(-1, this->W, this->Wrap);
    const int after = vtkSurfaceDetail::WrapIndex(this->W, this->W, this->Wrap);
    row[0] = before < 0 ? this->Border : row[before + 1];
    row[this->W + 1] = after < 0 ? this->Border : row[after + 1];
    return row;
  }

  void operator()(vtkIdType rowBegin, vtkIdType rowEnd)
  {
    RowCache<Real>& c = this->Cache.Local();
    const int n = this->I1 - this->I0 + 1;
    Real* gx = c.Gx.data();
    Real* gy = c.Gy.data();
    for (vtkIdType jj = rowBegin; jj < rowEnd && !this->Progress->Aborted(); ++jj)
    {
      this->Progress->Advance(1);
      const int j = static_cast<int>(jj);
      const int keep[3] = { vtkSurfaceDetail::WrapIndex(j - 1, this->H, this->Wrap), j,
        vtkSurfaceDetail::WrapIndex(j + 1, this->H, this->Wrap) };
      // Pointers offset so that m[i], c0[i], p[i] are texel i of rows j-1, j, j+1.
      const Real* c0 = this->Row(c, keep[1], keep) + 1 + this->I0;
      const Real* p = this->Row(c, keep[2], keep) + 1 + this->I0;
      const Real* m = this->Scheme == vtkHeightMapToNormalMap::Forward
        ? nullptr
        : this->Row(c, keep[0], keep) + 1 + this->I0;
      this->Slopes<false>(m, c0, p, n, gx, gy);
      // Finite heights near the type's limits can overflow a difference to +inf and another
      // to -inf (their sum is NaN), or meet BumpScale 0 (0*inf): rare, so checked, not avoided.
      if (this->Normals(c, n) > 0)
      {
        this->Slopes<true>(m, c0, p, n, gx, gy);
        if (this->Normals(c, n) > 0)
        {
          FlattenNaN(c, n);
        }
      }
      OutT* out = this->Out + static_cast<size_t>(j - this->J0) * n * this->OutComps;
      this->Encode(c, c0, n, out);
    }
  }

  void Reduce() {}

  // Safe: the heights are scaled by 1/64 first (exact: a power of two), so that no stencil
  // sum of finite heights overflows, and the slope is scaled back after the multiplication
  // by Sx or Sy (which may overflow to inf, clamped later, but is never 0*inf).
  template <bool Safe>
  void Slopes(const Real* m, const Real* c0, const Real* p, int n, Real* gx, Real* gy) const
  {
    const Real sx = this->Sx, sy = this->Sy;
    auto in = [](Real v)
    {
      if constexpr (Safe)
      {
        return v * Real(1.0 / 64.0);
      }
      return v;
    };
    auto out = [](Real v)
    {
      if constexpr (Safe)
      {
        return v * Real(64);
      }
      return v;
    };
    switch (this->Scheme)
    {
      case vtkHeightMapToNormalMap::Forward:
        for (int i = 0; i < n; ++i)
        {
          gx[i] = out((in(c0[i + 1]) - in(c0[i])) * sx);
          gy[i] = out((in(p[i]) - in(c0[i])) * sy);
        }
        break;
      case vtkHeightMapToNormalMap::Central:
      {
        const Real hx = sx * Real(0.5), hy = sy * Real(0.5);
        for (int i = 0; i < n; ++i)
        {
          gx[i] = out((in(c0[i + 1]) - in(c0[i - 1])) * hx);
          gy[i] = out((in(p[i]) - in(m[i])) * hy);
        }
        break;
      }
      default:
      {
        // Sobel (1,2,1) and Scharr (3,10,3) cross weights; dividing by twice their sum makes
        // both estimate the derivative itself.
        const bool sobel = this->Scheme == vtkHeightMapToNormalMap::Sobel;
        const Real a = sobel ? Real(1) : Real(3), b = sobel ? Real(2) : Real(10);
        const Real norm = Real(1) / (Real(2) * (Real(2) * a + b));
        const Real hx = sx * norm, hy = sy * norm;
        for (int i = 0; i < n; ++i)
        {
          gx[i] = out((a * (in(m[i + 1]) - in(m[i - 1])) + b * (in(c0[i + 1]) - in(c0[i - 1])) +
                        a * (in(p[i + 1]) - in(p[i - 1]))) *
            hx);
          gy[i] = out((a * (in(p[i - 1]) - in(m[i - 1])) + b * (in(p[i]) - in(m[i])) +
                        a * (in(p[i + 1]) - in(m[i + 1]))) *
            hy);
        }
        break;
      }
    }
  }

  // Two passes so that the arithmetic vectorises: unit normals into planar scratch rows
  // (Normals), then quantisation into the interleaved output (Encode). Normals returns how
  // many slopes were NaN, counted in the same loop (a NaN passes the clamps).
  int Normals(RowCache<Real>& c, int n) const
  {
    const Real lim = static_cast<Real>(MaxSlope);
    const Real half = Real(0.5);
    const Real ySign = this->GreenUp ? Real(-1) : Real(1);
    Real* r = c.Gx.data(); // the slopes are overwritten by the colours, texel by texel
    Real* g = c.Gy.data();
    Real* b = c.B.data();
    int nan = 0;
    for (int i = 0; i < n; ++i)
    {
      const Real x = -std::min(std::max(r[i], -lim), lim);
      const Real y = ySign * std::min(std::max(g[i], -lim), lim);
      // One division per texel, as GPUs normalise (v * 1/|v|): the three divisions of
      // v/|v| cost more than everything else in the loop.
      const Real inv = Real(1) / std::sqrt(x * x + y * y + Real(1));
      nan += inv == inv ? 0 : 1;
      r[i] = half * (x * inv) + half;
      g[i] = half * (y * inv) + half;
      b[i] = half * inv + half;
    }
    return nan;
  }

  // What no scaling of the heights makes finite (a stencil whose repaired heights are still
  // not finite) gets the flat normal, 0.5 n + 0.5 = (0.5, 0.5, 1), never NaN.
  static void FlattenNaN(RowCache<Real>& c, int n)
  {
    Real* r = c.Gx.data();
    Real* g = c.Gy.data();
    Real* b = c.B.data();
    for (int i = 0; i < n; ++i)
    {
      if (!(r[i] == r[i] && g[i] == g[i] && b[i] == b[i]))
      {
        r[i] = Real(0.5);
        g[i] = Real(0.5);
        b[i] = Real(1);
      }
    }
  }

  void Encode(RowCache<Real>& c, const Real* c0, int n, OutT* out) const
  {
    Real* r = c.Gx.data();
    Real* g = c.Gy.data();
    Real* b = c.B.data();
    const int nc = this->OutComps;
    Real* planes[4] = { r, g, b, c.A.data() };
    if (nc == 4)
    {
      vtkIdType outside = 0;
      for (int i = 0; i < n; ++i)
      {
        const Real depth = Real(1) - c0[i] * this->HScale;
        outside += (depth < Real(0) || depth > Real(1)) ? 1 : 0;
        // Written so that a NaN depth (heights whose scaling overflows, inf - inf) clamps
        // to 0 like the others instead of passing through std::max.
        planes[3][i] = depth > Real(0) ? std::min(depth, Real(1)) : Real(0);
      }
      c.OutOfRange += outside;
    }
    if constexpr (std::is_floating_point<OutT>::value)
    {
      for (int k = 0; k < nc; ++k)
      {
        for (int i = 0; i < n; ++i)
        {
          out[nc * i + k] = static_cast<OutT>(planes[k][i]);
        }
      }
    }
    else
    {
      // Round to nearest on the type's range (values are in [0,1]: adding 0.5 and
      // truncating rounds), packing each texel's components into one word so that both the
      // conversion and the packing vectorise and the interleaved store is one per texel.
      using Word = typename std::conditional<sizeof(OutT) == 1, uint32_t, uint64_t>::type;
      constexpr int bits = 8 * sizeof(OutT);
      const Real top = static_cast<Real>(std::numeric_limits<OutT>::max());
      Word* words = nullptr;
      if constexpr (sizeof(OutT) == 1)
      {
        words = c.Words32.data();
      }
      else
      {
        words = c.Words64.data();
      }
      for (int i = 0; i < n; ++i)
      {
        words[i] = 0;
      }
      for (int k = 0; k < nc; ++k)
      {
        const Real* src = planes[k];
        for (int i = 0; i < n; ++i)
        {
          words[i] |= static_cast<Word>(static_cast<int32_t>(src[i] * top + Real(0.5)))
            << (bits * k);
        }
      }
      this->Interleave(words, n, out);
    }
  }

  // Stores packed texels: a whole word per texel; with three components that word also
  // covers the next texel's first component, which the next store rewrites, so the last
  // texel is stored component by component.
  template <typename Word>
  void Interleave(const Word* words, int n, OutT* out) const
  {
    const int nc = this->OutComps;
    int first = 0; // the texels before it were stored whole
#ifndef VTK_WORDS_BIGENDIAN
    // Little-endian: component k is the k-th OutT of the word, in memory order.
    first = std::max(nc == 4 ? n : n - 1, 0);
    for (int i = 0; i < first; ++i)
    {
      std::memcpy(out + static_cast<size_t>(nc) * i, words + i, sizeof(Word));
    }
#endif
    for (int i = first; i < n; ++i)
    {
      for (int k = 0; k < nc; ++k)
      {
        out[static_cast<size_t>(nc) * i + k] =
          static_cast<OutT>(words[i] >> (8 * sizeof(OutT) * k));
      }
    }
  }
};

// The height that replaces non-finite texel (i,j), from the finite texels around it
// (wrapped as the filter wraps): the mean of the linear extrapolations 2*h(x+d) - h(x+2d)
// along the eight directions d where both are finite, which continues a plane exactly; or,
// with no such pair, the mean of the finite neighbours. Texels that wrap onto the texel
// itself or onto one another are counted once, so ClampToEdge corners are not biased.
template <typename Real>
double FillValue(const std::vector<Real>& h, int i, int j, int w, int hgt, int wrap)
{
  const size_t self = static_cast<size_t>(j) * w + i;
  size_t seen[8], seenPairs[8][2];
  int nSeen = 0, nPairs = 0;
  double sum = 0.0, pairSum = 0.0;
  auto index = [&](int di, int dj)
  {
    return static_cast<size_t>(vtkSurfaceDetail::WrapIndex(j + dj, hgt, wrap)) * w +
      vtkSurfaceDetail::WrapIndex(i + di, w, wrap);
  };
  for (int dj = -1; dj <= 1; ++dj)
  {
    for (int di = -1; di <= 1; ++di)
    {
      const size_t k1 = index(di, dj);
      if (k1 == self || !std::isfinite(h[k1]))
      {
        continue;
      }
      if (std::find(seen, seen + nSeen, k1) == seen + nSeen)
      {
        seen[nSeen++] = k1;
        sum += h[k1];
      }
      // Under ClampToEdge and MirroredRepeat a pair reaching past the border is not on a
      // line through the texel: only Repeat continues the image across it.
      const bool inside = wrap == vtkSurfaceDetail::Repeat ||
        (i + 2 * di >= 0 && i + 2 * di < w && j + 2 * dj >= 0 && j + 2 * dj < hgt);
      const size_t k2 = index(2 * di, 2 * dj);
      const bool known = std::any_of(
        seenPairs, seenPairs + nPairs, [&](const size_t* p) { return p[0] == k1 && p[1] == k2; });
      if (inside && k2 != self && k2 != k1 && std::isfinite(h[k2]) && !known)
      {
        seenPairs[nPairs][0] = k1;
        seenPairs[nPairs][1] = k2;
        ++nPairs;
        pairSum += 2.0 * static_cast<double>(h[k1]) - static_cast<double>(h[k2]);
      }
    }
  }
  return nPairs > 0 ? pairSum / nPairs : sum / nSeen;
}

// Fills the non-finite heights from the finite ones outward, one ring of texels at a time
// (a breadth-first fill, O(texels)): each ring is computed from the texels finite before it
// (FillValue), then made finite. Values are clamped to the range of the finite input so that
// extrapolation across a large hole cannot run away. No finite height at all: flat 0.
template <typename Real>
void RepairHeights(std::vector<Real>& h, int w, int hgt, int wrap)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Real v : h)
  {
    if (std::isfinite(v))
    {
      lo = std::min(lo, static_cast<double>(v));
      hi = std::max(hi, static_cast<double>(v));
    }
  }
  if (!(lo <= hi))
  {
    std::fill(h.begin(), h.end(), Real(0));
    return;
  }
  // Visits the texels of the 8-neighbourhood of texel k, as wrapped (itself excluded).
  auto forNeighbours = [&](size_t k, auto&& visit)
  {
    const int i = static_cast<int>(k % w), j = static_cast<int>(k / w);
    for (int dj = -1; dj <= 1; ++dj)
    {
      for (int di = -1; di <= 1; ++di)
      {
        const size_t kk = static_cast<size_t>(vtkSurfaceDetail::WrapIndex(j + dj, hgt, wrap)) * w +
          vtkSurfaceDetail::WrapIndex(i + di, w, wrap);
        if (kk != k)
        {
          visit(kk);
        }
      }
    }
  };
  std::vector<char> queued(h.size(), 0);
  std::vector<size_t> ring, next;
  for (size_t k = 0; k < h.size(); ++k)
  {
    if (!std::isfinite(h[k]))
    {
      bool touches = false;
      forNeighbours(k, [&](size_t kk) { touches = touches || std::isfinite(h[kk]); });
      if (touches)
      {
        ring.push_back(k);
        queued[k] = 1;
      }
    }
  }
  std::vector<double> values;
  while (!ring.empty())
  {
    values.resize(ring.size());
    for (size_t r = 0; r < ring.size(); ++r)
    {
      values[r] =
        FillValue(h, static_cast<int>(ring[r] % w), static_cast<int>(ring[r] / w), w, hgt, wrap);
    }
    for (size_t r = 0; r < ring.size(); ++r)
    {
      h[ring[r]] = static_cast<Real>(std::min(std::max(values[r], lo), hi));
    }
    next.clear();
    for (const size_t k : ring)
    {
      forNeighbours(k,
        [&](size_t kk)
        {
          if (!queued[kk] && !std::isfinite(h[kk]))
          {
            queued[kk] = 1;
            next.push_back(kk);
          }
        });
    }
    ring.swap(next);
  }
}

struct Job
{
  int W, H;
  int OutExt[4]; // i0, i1, j0, j1 in input indices
  int Scheme, Wrap, OutputScalarType, OutComps;
  bool GreenUp;
  double BumpScale;
  double BorderHeight;
  void* Out;
  vtkSurfaceDetail::Progress* Progress;
};

template <typename InT, typename OutT>
KernelReport RunKernel(const InT* in, int stride, const Job& job)
{
  // Double heights are differenced in double; the 8- and 16-bit and float ones fit a float.
  using Real = typename std::conditional<std::is_same<InT, double>::value, double, float>::type;
  double scale = 1.0; // integer heights: fractions of their range
  vtkSurfaceDetail::HeightMapScale(vtkTypeTraits<InT>::VTKTypeID(), scale);
  NormalMapKernel<InT, Real, OutT> kernel;
  kernel.In = in;
  kernel.InStride = stride;
  kernel.W = job.W;
  kernel.H = job.H;
  kernel.I0 = job.OutExt[0];
  kernel.I1 = job.OutExt[1];
  kernel.J0 = job.OutExt[2];
  kernel.Out = static_cast<OutT*>(job.Out);
  kernel.OutComps = job.OutComps;
  kernel.Scheme = job.Scheme;
  kernel.Wrap = job.Wrap;
  kernel.GreenUp = job.GreenUp;
  // A scale that overflows Real would turn flat texels (0 * inf) into NaN: saturate it.
  const double top = static_cast<double>(std::numeric_limits<Real>::max());
  kernel.Sx = static_cast<Real>(std::min(std::max(job.BumpScale * job.W * scale, -top), top));
  kernel.Sy = static_cast<Real>(std::min(std::max(job.BumpScale * job.H * scale, -top), top));
  kernel.HScale = static_cast<Real>(scale);
  kernel.Border = static_cast<Real>(job.BorderHeight / scale);
  kernel.Progress = job.Progress;
  vtkSMPTools::For(job.OutExt[2], job.OutExt[3] + 1, kernel);
  KernelReport report;
  for (const RowCache<Real>& c : kernel.Cache)
  {
    report.NonFinite = report.NonFinite || c.NonFinite;
    report.OutOfRange += c.OutOfRange;
  }
  return report;
}

template <typename InT>
KernelReport DispatchOutput(const InT* in, int stride, const Job& job)
{
  switch (job.OutputScalarType)
  {
    case VTK_FLOAT:
      return RunKernel<InT, float>(in, stride, job);
    case VTK_UNSIGNED_SHORT:
      return RunKernel<InT, unsigned short>(in, stride, job);
    default:
      return RunKernel<InT, unsigned char>(in, stride, job);
  }
}

// Floating-point heights: the kernel notes non-finite heights as it reads them. Only then
// (rarely) are they counted, repaired in a copy (the input stays untouched) and the map
// computed again; heights clamped into the relief's [0,1] are reported.
template <typename Real>
void RunFloating(
  vtkHeightMapToNormalMap* self, const Real* in, int stride, const Job& job, bool relief)
{
  KernelReport report = DispatchOutput(in, stride, job);
  if (report.NonFinite)
  {
    const vtkIdType n = static_cast<vtkIdType>(job.W) * job.H;
    std::vector<Real> repaired(static_cast<size_t>(n));
    vtkIdType nonFinite = 0;
    for (vtkIdType k = 0; k < n; ++k)
    {
      repaired[k] = in[k * stride];
      nonFinite += std::isfinite(repaired[k]) ? 0 : 1;
    }
    vtkWarningWithObjectMacro(
      self, << nonFinite << " height(s) are NaN or infinite; each is replaced by the mean of its "
            << "finite neighbours (continuing their slope where it can).");
    // The fill reads neighbours inside the image: the border is not a height to continue.
    RepairHeights(repaired, job.W, job.H,
      job.Wrap == vtkSurfaceDetail::ClampToBorder ? vtkSurfaceDetail::ClampToEdge : job.Wrap);
    report = DispatchOutput(repaired.data(), 1, job);
  }
  if (relief && report.OutOfRange > 0)
  {
    vtkWarningWithObjectMacro(self,
      << report.OutOfRange << " height(s) lie outside [0,1]; their relief depth 1 - h is "
      << "clamped to [0,1]. Rescale the heights (e.g. vtkImageShiftScale) and raise BumpScale "
      << "instead.");
  }
}

template <typename InT>
void Run(vtkHeightMapToNormalMap* self, const InT* in, int stride, const Job& job, bool relief)
{
  if constexpr (std::is_floating_point<InT>::value)
  {
    RunFloating(self, in, stride, job, relief);
  }
  else
  {
    DispatchOutput(in, stride, job);
  }
}

} // anonymous namespace

//------------------------------------------------------------------------------
vtkHeightMapToNormalMap::vtkHeightMapToNormalMap()
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
void vtkHeightMapToNormalMap::SetOutputScalarType(int type)
{
  if (type != VTK_UNSIGNED_CHAR && type != VTK_UNSIGNED_SHORT && type != VTK_FLOAT)
  {
    vtkErrorMacro("OutputScalarType " << type << " is not supported: use VTK_UNSIGNED_CHAR, "
                                      << "VTK_UNSIGNED_SHORT or VTK_FLOAT.");
    return;
  }
  if (this->OutputScalarType != type)
  {
    this->OutputScalarType = type;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
const char* vtkHeightMapToNormalMap::GetDifferenceSchemeAsString()
{
  switch (this->DifferenceScheme)
  {
    case Forward:
      return "Forward";
    case Sobel:
      return "Sobel";
    case Scharr:
      return "Scharr";
    default:
      return "Central";
  }
}

//------------------------------------------------------------------------------
const char* vtkHeightMapToNormalMap::GetWrapAsString()
{
  return vtkSurfaceDetail::WrapModeName(this->Wrap);
}

//------------------------------------------------------------------------------
int vtkHeightMapToNormalMap::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject::SetPointDataActiveScalarInfo(
    outInfo, this->OutputScalarType, this->OutputRelief ? 4 : 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkHeightMapToNormalMap::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every output texel may read across the wrapped borders: ask for the whole input.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  int whole[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), whole, 6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkHeightMapToNormalMap::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  // The previous map's memory is reused when nobody else holds it (as
  // vtkImageData::AllocateScalars does): a fresh 4096^2 array costs page faults every run.
  vtkSmartPointer<vtkDataArray> previous = output->GetPointData()->GetScalars();
  output->Initialize();
  if (!input)
  {
    vtkErrorMacro("No input image: connect a vtkImageData height map to port 0.");
    return 0;
  }

  int ext[6];
  input->GetExtent(ext);
  const int w = ext[1] - ext[0] + 1, h = ext[3] - ext[2] + 1, d = ext[5] - ext[4] + 1;
  if (w <= 0 || h <= 0 || d <= 0)
  {
    vtkErrorMacro("The height map is empty (extent "
      << ext[0] << " " << ext[1] << " " << ext[2] << " " << ext[3] << " " << ext[4] << " " << ext[5]
      << "): give it at least one texel.");
    return 0;
  }
  if (d != 1)
  {
    vtkErrorMacro("The height map is a 3-D image (" << w << "x" << h << "x" << d
                                                    << "): extract one XY slice first "
                                                       "(e.g. vtkExtractVOI).");
    return 0;
  }
  vtkDataArray* heights = this->GetInputArrayToProcess(0, inputVector);
  if (!heights)
  {
    vtkErrorMacro("The height map has no point scalars: set the heights as the image's "
                  "active point scalars (or choose an array with SetInputArrayToProcess).");
    return 0;
  }
  if (heights->GetNumberOfTuples() != static_cast<vtkIdType>(w) * h ||
    heights->GetNumberOfComponents() < 1)
  {
    vtkErrorMacro("The height array \""
      << (heights->GetName() ? heights->GetName() : "") << "\" has " << heights->GetNumberOfTuples()
      << " tuples for " << w << "x" << h << " texels: give one height per point.");
    return 0;
  }
  if (this->HeightComponent >= heights->GetNumberOfComponents())
  {
    vtkErrorMacro("HeightComponent " << this->HeightComponent << " was asked for but the height "
                                     << "array has " << heights->GetNumberOfComponents()
                                     << " component(s).");
    return 0;
  }
  double typeScale;
  if (!vtkSurfaceDetail::HeightMapScale(heights->GetDataType(), typeScale))
  {
    vtkErrorMacro("The height map's scalars are "
      << heights->GetDataTypeAsString() << ": " << vtkSurfaceDetail::HeightMapTypeAdvice() << ".");
    return 0;
  }
  if (!std::isfinite(this->BumpScale) || !std::isfinite(this->BorderHeight))
  {
    vtkErrorMacro("BumpScale is " << this->BumpScale << " and BorderHeight " << this->BorderHeight
                                  << ": set finite values.");
    return 0;
  }
  // The kernels read the array's memory directly; other layouts are copied once.
  vtkSmartPointer<vtkDataArray> contiguous = heights;
  if (!heights->HasStandardMemoryLayout())
  {
    contiguous.TakeReference(vtkDataArray::CreateDataArray(heights->GetDataType()));
    contiguous->DeepCopy(heights);
  }

  int outExt[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), outExt);
  for (int a = 0; a < 3; ++a)
  {
    outExt[2 * a] = std::max(outExt[2 * a], ext[2 * a]);
    outExt[2 * a + 1] = std::min(outExt[2 * a + 1], ext[2 * a + 1]);
  }
  output->SetExtent(outExt);
  const int comps = this->OutputRelief ? 4 : 3;
  const bool reuse = previous && previous->GetReferenceCount() == 1 &&
    previous->GetDataType() == this->OutputScalarType && previous->HasStandardMemoryLayout();
  vtkSmartPointer<vtkDataArray> map = reuse ? previous.Get() : nullptr;
  previous = nullptr;
  if (!map)
  {
    map.TakeReference(vtkDataArray::CreateDataArray(this->OutputScalarType));
  }
  map->SetName(this->OutputRelief ? "ReliefMap" : "NormalMap");
  map->SetNumberOfComponents(comps);
  map->SetNumberOfTuples(output->GetNumberOfPoints());
  output->GetPointData()->SetScalars(map);
  if (map->GetNumberOfTuples() == 0)
  {
    return 1;
  }

  Job job;
  job.W = w;
  job.H = h;
  job.OutExt[0] = outExt[0] - ext[0];
  job.OutExt[1] = outExt[1] - ext[0];
  job.OutExt[2] = outExt[2] - ext[2];
  job.OutExt[3] = outExt[3] - ext[2];
  job.Scheme = this->DifferenceScheme;
  job.Wrap = this->Wrap;
  job.OutputScalarType = this->OutputScalarType;
  job.OutComps = comps;
  job.GreenUp = this->GreenUp;
  job.BumpScale = this->BumpScale;
  job.BorderHeight = this->BorderHeight;
  job.Out = map->GetVoidPointer(0);
  // Floating-point maps with NaN are done twice (RunFloating): the progress may pass 1 there.
  vtkSurfaceDetail::Progress progress(this, 0.0, 1.0, outExt[3] - outExt[2] + 1);
  job.Progress = &progress;

  const int stride = contiguous->GetNumberOfComponents();
  // The kernels read every stride-th value from the height's own component on.
  const int comp = this->HeightComponent;
  const void* in = contiguous->GetVoidPointer(0);
  switch (contiguous->GetDataType())
  {
    case VTK_UNSIGNED_CHAR:
      Run(this, static_cast<const unsigned char*>(in) + comp, stride, job, this->OutputRelief);
      break;
    case VTK_UNSIGNED_SHORT:
      Run(this, static_cast<const unsigned short*>(in) + comp, stride, job, this->OutputRelief);
      break;
    case VTK_FLOAT:
      Run(this, static_cast<const float*>(in) + comp, stride, job, this->OutputRelief);
      break;
    default:
      Run(this, static_cast<const double*>(in) + comp, stride, job, this->OutputRelief);
  }
  if (progress.Aborted())
  {
    // Stopped by the user (AbortExecute): no error, and no half-made map.
    output->Initialize();
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkHeightMapToNormalMap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DifferenceScheme: " << this->GetDifferenceSchemeAsString() << "\n";
  os << indent << "BumpScale: " << this->BumpScale << "\n";
  os << indent << "Wrap: " << this->GetWrapAsString() << "\n";
  os << indent << "BorderHeight: " << this->BorderHeight << "\n";
  os << indent << "GreenUp: " << (this->GreenUp ? "On" : "Off") << "\n";
  os << indent << "HeightComponent: " << this->HeightComponent << "\n";
  os << indent << "OutputScalarType: " << vtkImageScalarTypeNameMacro(this->OutputScalarType)
     << "\n";
  os << indent << "OutputRelief: " << (this->OutputRelief ? "On" : "Off") << "\n";
}
