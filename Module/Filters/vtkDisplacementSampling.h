// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkDisplacementSampling.h
 * @brief  Private: vtkDisplacementMapFilter's height map, sampled as a texture.
 *
 * The filter moves each point by the height at its texture coordinates and needs the
 * height's slope in s and t for the normals. This is that sampling, with the texel centres,
 * wrap modes and linear filtering of vtkSurfaceDetailConventions.h (what the GPU does with a
 * vtkTexture of the same map), and the analytic derivative of each interpolant. Heights are
 * sampled a block of points at a time through one virtual call, so that the passes that use
 * them are compiled once, not once per scalar type of the map.
 *
 * Part of SurfaceDetail::Filters; not installed.
 */
#ifndef vtkDisplacementSampling_h
#define vtkDisplacementSampling_h

#include "vtkDataArray.h"
#include "vtkDisplacementMapFilter.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSurfaceDetailConventions.h"

#include <atomic>
#include <cmath>
#include <memory>
#include <type_traits>

namespace vtkDisplacement
{
/// The number of points the passes handle at a time.
constexpr int Block = 64;

/// The height map as a texture: heights and their slopes at texture coordinates.
class HeightSampler
{
public:
  virtual ~HeightSampler() = default;

  /// The heights @a h and slopes @a hs = dh/ds, @a ht = dh/dt at the @a count points
  /// (@a s[k], @a t[k]). Thread-safe.
  virtual void Sample(
    int count, const double* s, const double* t, double* h, double* hs, double* ht) const = 0;

  /// Whether any sample so far read a NaN or infinite texel (which reads as the midlevel).
  bool SawNonFinite() const { return this->NonFinite.load(std::memory_order_relaxed); }

protected:
  mutable std::atomic<bool> NonFinite{ false };
};

/// Keeps huge coordinates from overflowing the texel index; 2 is a period of every wrap.
inline double TameCoordinate(double s, int wrap)
{
  if (std::abs(s) < 1e6)
  {
    return s;
  }
  const bool clamps =
    wrap == vtkSurfaceDetail::ClampToEdge || wrap == vtkSurfaceDetail::ClampToBorder;
  return clamps ? std::min(std::max(s, -1.0), 2.0) : std::fmod(s, 2.0);
}

/// Catmull-Rom weights @a w and their derivatives @a dw for the fraction @a f in [0,1).
inline void CatmullRom(double f, double w[4], double dw[4])
{
  const double f2 = f * f, f3 = f2 * f;
  w[0] = 0.5 * (-f3 + 2.0 * f2 - f);
  w[1] = 0.5 * (3.0 * f3 - 5.0 * f2 + 2.0);
  w[2] = 0.5 * (-3.0 * f3 + 4.0 * f2 + f);
  w[3] = 0.5 * (f3 - f2);
  dw[0] = 0.5 * (-3.0 * f2 + 4.0 * f - 1.0);
  dw[1] = 0.5 * (9.0 * f2 - 10.0 * f);
  dw[2] = 0.5 * (-9.0 * f2 + 8.0 * f + 1.0);
  dw[3] = 0.5 * (3.0 * f2 - 2.0 * f);
}

/**
 * A height map of scalar type T: component Comp of each texel, times Norm (integer maps
 * become fractions of their range), and Border outside it under ClampToBorder. Non-finite
 * texels read as the midlevel, so that they do not move the surface, and are remembered for
 * the filter's warning.
 */
template <typename T>
class HeightMap final : public HeightSampler
{
public:
  HeightMap(const T* data, int w, int h, int nc, int comp, int wrap, int interpolation, double norm,
    double mid, double border)
    : Data(data)
    , W(w)
    , H(h)
    , NC(nc)
    , Comp(comp)
    , Wrap(wrap)
    , Interpolation(interpolation)
    , Norm(norm)
    , Mid(mid)
    , Border(border)
  {
  }

  void Sample(
    int count, const double* s, const double* t, double* h, double* hs, double* ht) const override
  {
    switch (this->Interpolation)
    {
      case vtkDisplacementMapFilter::Nearest:
        for (int k = 0; k < count; ++k)
        {
          this->SampleNearest(s[k], t[k], h[k], hs[k], ht[k]);
        }
        break;
      case vtkDisplacementMapFilter::Linear:
        for (int k = 0; k < count; ++k)
        {
          this->SampleLinear(s[k], t[k], h[k], hs[k], ht[k]);
        }
        break;
      default:
        for (int k = 0; k < count; ++k)
        {
          this->SampleCubic(s[k], t[k], h[k], hs[k], ht[k]);
        }
        break;
    }
  }

private:
  // Texel index i of a row (or column) n texels long, wrapped (-1: the border of
  // ClampToBorder); the wrap's integer division only outside the map.
  int Wrapped(int i, int n) const
  {
    return static_cast<unsigned>(i) < static_cast<unsigned>(n)
      ? i
      : vtkSurfaceDetail::WrapIndex(i, n, this->Wrap);
  }

  // The chosen component of the first texel of wrapped row @a j.
  const T* Row(int j) const
  {
    return this->Data + static_cast<vtkIdType>(j) * this->W * this->NC + this->Comp;
  }

  // A height read from the map: a non-finite one is the midlevel, and is remembered.
  double Checked(double v) const
  {
    if (std::is_integral<T>::value || std::isfinite(v))
    {
      return v;
    }
    this->NonFinite.store(true, std::memory_order_relaxed);
    return this->Mid;
  }

  // The texel at wrapped indices (i, j), or the border.
  double Texel(int i, int j) const
  {
    if (i < 0 || j < 0)
    {
      return this->Border;
    }
    return this->Checked(this->Norm * this->Row(j)[static_cast<vtkIdType>(i) * this->NC]);
  }

  // GL_NEAREST: the texel that contains (s,t); no slope.
  void SampleNearest(double s, double t, double& h, double& hs, double& ht) const
  {
    s = TameCoordinate(s, this->Wrap);
    t = TameCoordinate(t, this->Wrap);
    const double x = std::floor(s * this->W), y = std::floor(t * this->H);
    const int i = std::isfinite(x) ? static_cast<int>(x) : 0;
    const int j = std::isfinite(y) ? static_cast<int>(y) : 0;
    h = this->Texel(this->Wrapped(i, this->W), this->Wrapped(j, this->H));
    hs = ht = 0.0;
  }

  // GL_LINEAR: the bilinear blend of the four nearest texel centres, and its slope.
  void SampleLinear(double s, double t, double& h, double& hs, double& ht) const
  {
    s = TameCoordinate(s, this->Wrap);
    t = TameCoordinate(t, this->Wrap);
    int i0, j0;
    double fx, fy;
    vtkSurfaceDetail::LinearTexels(s, this->W, i0, fx);
    vtkSurfaceDetail::LinearTexels(t, this->H, j0, fy);
    const int ia = this->Wrapped(i0, this->W), ib = this->Wrapped(i0 + 1, this->W);
    const int ja = this->Wrapped(j0, this->H), jb = this->Wrapped(j0 + 1, this->H);
    double a, b, c, d;
    if (std::min({ ia, ib, ja, jb }) < 0)
    {
      // A tap on the border (ClampToBorder only).
      a = this->Texel(ia, ja);
      b = this->Texel(ib, ja);
      c = this->Texel(ia, jb);
      d = this->Texel(ib, jb);
    }
    else
    {
      const vtkIdType nc = this->NC;
      const T* rowA = this->Row(ja);
      const T* rowB = this->Row(jb);
      a = this->Norm * rowA[nc * ia];
      b = this->Norm * rowA[nc * ib];
      c = this->Norm * rowB[nc * ia];
      d = this->Norm * rowB[nc * ib];
      if (!std::is_integral<T>::value && !std::isfinite(a + b + c + d))
      {
        a = this->Checked(a);
        b = this->Checked(b);
        c = this->Checked(c);
        d = this->Checked(d);
      }
    }
    const double bottom = a + fx * (b - a), top = c + fx * (d - c);
    h = bottom + fy * (top - bottom);
    hs = this->W * ((b - a) + fy * ((d - c) - (b - a)));
    ht = this->H * (top - bottom);
  }

  // Catmull-Rom over the 4x4 nearest texel centres (the texel split of Linear), each index
  // wrapped, and its slope.
  void SampleCubic(double s, double t, double& h, double& hs, double& ht) const
  {
    s = TameCoordinate(s, this->Wrap);
    t = TameCoordinate(t, this->Wrap);
    int i0, j0;
    double fx, fy;
    vtkSurfaceDetail::LinearTexels(s, this->W, i0, fx);
    vtkSurfaceDetail::LinearTexels(t, this->H, j0, fy);
    double wx[4], dwx[4], wy[4], dwy[4];
    CatmullRom(fx, wx, dwx);
    CatmullRom(fy, wy, dwy);
    int columns[4];
    for (int k = 0; k < 4; ++k)
    {
      columns[k] = this->Wrapped(i0 - 1 + k, this->W);
    }
    h = hs = ht = 0.0;
    for (int l = 0; l < 4; ++l)
    {
      const int row = this->Wrapped(j0 - 1 + l, this->H);
      double value = 0.0, slope = 0.0;
      for (int k = 0; k < 4; ++k)
      {
        const double v = this->Texel(columns[k], row);
        value += wx[k] * v;
        slope += dwx[k] * v;
      }
      h += wy[l] * value;
      hs += wy[l] * slope;
      ht += dwy[l] * value;
    }
    hs *= this->W;
    ht *= this->H;
  }

  const T* Data;
  int W, H, NC, Comp, Wrap, Interpolation;
  double Norm, Mid, Border;
};

/// Calls @a body with the height map's scalars as a pointer to their type, among the types
/// vtkSurfaceDetail::HeightMapScale accepts (checked before).
template <typename F>
void WithTexelType(vtkDataArray* scalars, F&& body)
{
  void* raw = scalars->GetVoidPointer(0);
  switch (scalars->GetDataType())
  {
    case VTK_UNSIGNED_CHAR:
      body(static_cast<const unsigned char*>(raw));
      break;
    case VTK_UNSIGNED_SHORT:
      body(static_cast<const unsigned short*>(raw));
      break;
    case VTK_FLOAT:
      body(static_cast<const float*>(raw));
      break;
    default:
      body(static_cast<const double*>(raw));
      break;
  }
}

/// The sampler of component @a comp of the point array @a scalars of @a image (checked to be
/// a height map).
inline std::unique_ptr<HeightSampler> MakeHeightSampler(vtkImageData* image, vtkDataArray* scalars,
  int comp, int wrap, int interpolation, double mid, double border)
{
  int dims[3];
  image->GetDimensions(dims);
  double norm = 1.0;
  vtkSurfaceDetail::HeightMapScale(scalars->GetDataType(), norm);
  std::unique_ptr<HeightSampler> sampler;
  WithTexelType(scalars,
    [&](auto* data)
    {
      using T = std::remove_const_t<std::remove_pointer_t<decltype(data)>>;
      sampler.reset(new HeightMap<T>(data, dims[0], dims[1], scalars->GetNumberOfComponents(), comp,
        wrap, interpolation, norm, mid, border));
    });
  return sampler;
}

/// The number of NaN or infinite values in component @a comp of @a scalars.
inline vtkIdType CountNonFinite(vtkDataArray* scalars, int comp)
{
  const vtkIdType n = scalars->GetNumberOfTuples();
  const int nc = scalars->GetNumberOfComponents();
  std::atomic<vtkIdType> total(0);
  WithTexelType(scalars,
    [&](auto* data)
    {
      vtkSMPTools::For(0, n,
        [&](vtkIdType begin, vtkIdType end)
        {
          vtkIdType count = 0;
          for (vtkIdType k = begin; k < end; ++k)
          {
            count += !std::isfinite(static_cast<double>(data[k * nc + comp]));
          }
          total += count;
        });
    });
  return total;
}
} // namespace vtkDisplacement

#endif
// VTK-HeaderTest-Exclude: vtkDisplacementSampling.h
