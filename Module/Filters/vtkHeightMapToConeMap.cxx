// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHeightMapToConeMap.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkHeightMapToConeMap);

namespace
{
// A float no greater than @a v: a higher apex and a narrower cone are still empty.
float RoundDown(double v)
{
  const float f = static_cast<float>(v);
  return f > v ? std::nextafter(f, -1.0f) : f;
}

// A float no less than @a v.
float RoundUp(double v)
{
  const float f = static_cast<float>(v);
  return f < v ? std::nextafter(f, 2.0f) : f;
}

// The relief's depth 1 - h at the texel centres, read past the edges as the wrap mode says.
struct DepthField
{
  int W = 0, H = 0;
  bool Repeat = true;
  std::vector<double> Depth;

  double At(int i, int j) const
  {
    if (this->Repeat)
    {
      // Most reads are within a map of it: a subtraction is cheaper than a division.
      i = i < 0 ? i + this->W : (i >= this->W ? i - this->W : i);
      j = j < 0 ? j + this->H : (j >= this->H ? j - this->H : j);
      i = i >= 0 && i < this->W ? i : ((i % this->W) + this->W) % this->W;
      j = j >= 0 && j < this->H ? j : ((j % this->H) + this->H) % this->H;
    }
    else
    {
      i = std::min(std::max(i, 0), this->W - 1);
      j = std::min(std::max(j, 0), this->H - 1);
    }
    return this->Depth[static_cast<size_t>(j) * this->W + i];
  }

  // The depth of the highest point of the bilinear surface over texel (i, j)'s footprint: it
  // is bilinear on each quarter of the footprint, so its extremes lie at the quarters' corners.
  double ApexDepth(int i, int j) const
  {
    const double c = this->At(i, j);
    double apex = c;
    for (int dj = -1; dj <= 1; dj += 2)
    {
      for (int di = -1; di <= 1; di += 2)
      {
        const double x = this->At(i + di, j), y = this->At(i, j + dj),
                     xy = this->At(i + di, j + dj);
        apex = std::min({ apex, 0.5 * (c + x), 0.5 * (c + y), 0.25 * (c + x + y + xy) });
      }
    }
    return apex;
  }

  // The depth of the highest point of the bilinear surface over the rectangle @a within =
  // {s0, s1, t0, t1} of cell (k, l) (fractions of the cell): it lies at a corner.
  double HighestInCell(int k, int l, const double within[4]) const
  {
    const double d00 = this->At(k, l), d10 = this->At(k + 1, l), d01 = this->At(k, l + 1),
                 d11 = this->At(k + 1, l + 1);
    double top = 1e300;
    for (double s : { within[0], within[1] })
    {
      for (double t : { within[2], within[3] })
      {
        top = std::min(top, (1 - s) * ((1 - t) * d00 + t * d01) + s * ((1 - t) * d10 + t * d11));
      }
    }
    return top;
  }

  // The range of the depth's derivatives, per texel index, along s and t over cell (k, l)
  // (between texel centres k and k + 1, l and l + 1): on a bilinear cell each is linear in the
  // other coordinate, so it lies between its values on the two edges.
  std::array<double, 4> Derivatives(int k, int l) const
  {
    const double d00 = this->At(k, l), d10 = this->At(k + 1, l), d01 = this->At(k, l + 1),
                 d11 = this->At(k + 1, l + 1);
    return { std::min(d10 - d00, d11 - d01), std::max(d10 - d00, d11 - d01),
      std::min(d01 - d00, d11 - d10), std::max(d01 - d00, d11 - d10) };
  }
};

// The cells (the squares between four texel centres, [k, k+1] x [l, l+1] in texel indices):
// each one's highest corner and steepest slope (texture units), and a pyramid of each block's
// highest corner, each level halving both counts.
struct Cells
{
  int NX = 0, NY = 0;
  bool LineX = false, LineY = false; // one texel wide without repeat: the cells are lines
  std::vector<double> Slope;
  double SteepestSlope = 0.0;
  struct Level
  {
    int NX, NY;
    std::vector<double> Top; // the depth of the highest corner
  };
  std::vector<Level> Levels;

  explicit Cells(const DepthField& f)
  {
    this->NX = f.Repeat ? f.W : std::max(f.W - 1, 1);
    this->NY = f.Repeat ? f.H : std::max(f.H - 1, 1);
    this->LineX = !f.Repeat && f.W == 1;
    this->LineY = !f.Repeat && f.H == 1;
    Level base{ this->NX, this->NY, std::vector<double>(static_cast<size_t>(this->NX) * this->NY) };
    this->Slope.resize(base.Top.size());
    for (int l = 0; l < this->NY; ++l)
    {
      for (int k = 0; k < this->NX; ++k)
      {
        const double d00 = f.At(k, l), d10 = f.At(k + 1, l), d01 = f.At(k, l + 1),
                     d11 = f.At(k + 1, l + 1);
        const size_t c = static_cast<size_t>(l) * this->NX + k;
        base.Top[c] = std::min({ d00, d10, d01, d11 });
        // On a bilinear cell each partial derivative is largest on an edge.
        const double gx = std::max(std::abs(d10 - d00), std::abs(d11 - d01)) * f.W;
        const double gy = std::max(std::abs(d01 - d00), std::abs(d11 - d10)) * f.H;
        this->Slope[c] = std::hypot(gx, gy);
        this->SteepestSlope = std::max(this->SteepestSlope, this->Slope[c]);
      }
    }
    this->Levels.push_back(std::move(base));
    while (this->Levels.back().NX > 1 || this->Levels.back().NY > 1)
    {
      const Level& below = this->Levels.back();
      Level up{ (below.NX + 1) / 2, (below.NY + 1) / 2, {} };
      up.Top.assign(static_cast<size_t>(up.NX) * up.NY, 1e300);
      for (int l = 0; l < below.NY; ++l)
      {
        for (int k = 0; k < below.NX; ++k)
        {
          double& top = up.Top[static_cast<size_t>(l / 2) * up.NX + k / 2];
          top = std::min(top, below.Top[static_cast<size_t>(l) * below.NX + k]);
        }
      }
      this->Levels.push_back(std::move(up));
    }
  }

  // For relaxed cones: each block's range of the depth's derivatives (DepthField::Derivatives)
  // over its cells, rounded outward, for the levels above the cells (those are read from the
  // field).
  std::vector<std::vector<std::array<float, 4>>> Derivatives;

  void AddDerivatives(const DepthField& f)
  {
    this->Derivatives.resize(this->Levels.size());
    for (size_t level = 1; level < this->Levels.size(); ++level)
    {
      const Level& at = this->Levels[level];
      auto& ranges = this->Derivatives[level];
      ranges.assign(static_cast<size_t>(at.NX) * at.NY, { 1e30f, -1e30f, 1e30f, -1e30f });
      const Level& below = this->Levels[level - 1];
      for (int l = 0; l < below.NY; ++l)
      {
        for (int k = 0; k < below.NX; ++k)
        {
          const std::array<float, 4> child = this->DerivativesOf(f, level - 1, k, l);
          std::array<float, 4>& range = ranges[static_cast<size_t>(l / 2) * at.NX + k / 2];
          range = { std::min(range[0], child[0]), std::max(range[1], child[1]),
            std::min(range[2], child[2]), std::max(range[3], child[3]) };
        }
      }
    }
  }

  std::array<float, 4> DerivativesOf(const DepthField& f, int level, int k, int l) const
  {
    if (level > 0)
    {
      return this->Derivatives[level][static_cast<size_t>(l) * this->Levels[level].NX + k];
    }
    const std::array<double, 4> d = f.Derivatives(k, l);
    return { RoundDown(d[0]), RoundUp(d[1]), RoundDown(d[2]), RoundUp(d[3]) };
  }
};

// The gap between index intervals [a, b] and [c, d] (0 where they meet).
double Gap(double a, double b, double c, double d)
{
  return std::max({ 0.0, c - b, a - d });
}

// The widest cone of every texel, by branch and bound over the pyramid.
class ConeSearch
{
public:
  ConeSearch(const DepthField& field, const Cells& cells, double maxRatio)
    : Field(field)
    , Grid(cells)
    , MaxRatio(maxRatio)
  {
  }

  // A block of the pyramid and the least ratio any cell in it can give.
  struct Node
  {
    double Bound;
    int Level, K, L;
    bool operator<(const Node& other) const { return this->Bound > other.Bound; } // min-heap
  };

  // The ratio of texel (i, j), whose apex depth is @a apex: blocks visited nearest bound
  // first, so that the best ratio found soon prunes the rest.
  double Ratio(int i, int j, double apex, std::vector<Node>& heap) const
  {
    // Nothing rises faster than the steepest cell: no point of any block is nearer than that.
    const double floor = this->Grid.SteepestSlope > 0.0 ? 1.0 / this->Grid.SteepestSlope : 0.0;
    double best = this->MaxRatio;
    heap.clear();
    auto push = [&](int level, int k, int l)
    {
      const Cells::Level& at = this->Grid.Levels[level];
      const double top = at.Top[static_cast<size_t>(l) * at.NX + k];
      if (!(top < apex))
      {
        return; // nothing in the block is above the apex
      }
      const double bound = std::max(this->Distance(i, j, level, k, l) / (apex - top), floor);
      if (bound < best)
      {
        heap.push_back({ bound, level, k, l });
        std::push_heap(heap.begin(), heap.end());
      }
    };
    push(static_cast<int>(this->Grid.Levels.size()) - 1, 0, 0);
    while (!heap.empty())
    {
      std::pop_heap(heap.begin(), heap.end());
      const Node node = heap.back();
      heap.pop_back();
      if (!(node.Bound < best))
      {
        break; // every block left bounds no lower
      }
      if (node.Level == 0)
      {
        const Cells::Level& at = this->Grid.Levels[0];
        const double top = at.Top[static_cast<size_t>(node.L) * at.NX + node.K];
        const double far = this->Distance(i, j, 0, node.K, node.L) / (apex - top);
        best = std::min(best, std::max(far, 1.0 / this->SlopeOnTheWay(i, j, node.K, node.L)));
        continue;
      }
      const Cells::Level& below = this->Grid.Levels[node.Level - 1];
      for (int cl = 2 * node.L; cl < std::min(2 * node.L + 2, below.NY); ++cl)
      {
        for (int ck = 2 * node.K; ck < std::min(2 * node.K + 2, below.NX); ++ck)
        {
          push(node.Level - 1, ck, cl);
        }
      }
    }
    return best;
  }

  // A region in the repeat of the map (SX, SY) maps away: a block of the pyramid (Level > 0),
  // a cell (Level 0) or a part of one (Level < 0, 2^Level texels wide), and the least ratio
  // any of its points can give.
  struct RelaxedNode
  {
    double Bound;
    int Level, K, L, SX, SY;
    bool operator<(const RelaxedNode& other) const { return this->Bound > other.Bound; }
  };

  // Parts of cells are bounded down to this level (a sixteenth of a texel): the derivatives
  // and the highest point of a part are exact, so smaller parts give nearer bounds where a
  // crest and the slope falling from it share a cell.
  static constexpr int FinestPart = -4;

  // The relaxed ratio of texel (i, j), no narrower than its conservative ratio @a conservative:
  // the widest cone in which no ray goes from under the surface back above it. Such a ray
  // leaves the surface where the surface falls away along it, past the highest point of its way
  // so far, which was above the ray: just past that crest lies a point q, almost as high, where
  // the depth rises along the way from the ray's start x. So a cone whose ratio is at most
  // |q - x| / (a - depth at q) for every such q is never left from below, and that bound is
  // the widest such cone: the conservative cone's bound, but only over the points that face
  // away from the footprint. It is found by the same best-first branch and bound, with the
  // blocks, cells and parts of cells where no point can face away from any point of the
  // footprint (by interval arithmetic on the depth's derivatives) left out.
  double RelaxedRatio(
    int i, int j, double apex, double conservative, std::vector<RelaxedNode>& heap) const
  {
    double best = this->MaxRatio;
    const int w = this->Field.W, h = this->Field.H;
    if (this->Field.Repeat)
    {
      // Repeats two or more maps away are at least a map less half a texel from the footprint.
      const double rise = apex - this->Grid.Levels.back().Top[0];
      best = rise > 0.0 ? std::min(best, std::min((w - 0.5) / w, (h - 0.5) / h) / rise) : best;
    }
    const double floor = this->Grid.SteepestSlope > 0.0 ? 1.0 / this->Grid.SteepestSlope : 0.0;
    const double footprint[4] = { i - 0.5, i + 0.5, j - 0.5, j + 0.5 };
    heap.clear();
    auto push = [&](int level, int k, int l, int sx, int sy)
    {
      double box[4];
      std::array<double, 4> slopes;
      const double top = this->Region(level, k, l, sx, sy, box, slopes);
      if (!(top < apex))
      {
        return; // nothing here is above the apex
      }
      const double u[2] = { box[0] - footprint[1], box[1] - footprint[0] };
      const double v[2] = { box[2] - footprint[3], box[3] - footprint[2] };
      if (!(ProductMax(slopes[0], slopes[1], u) + ProductMax(slopes[2], slopes[3], v) > 0.0))
      {
        return; // no point here faces away from any point of the footprint
      }
      const double gap = std::hypot(Gap(footprint[0], footprint[1], box[0], box[1]) / w,
        Gap(footprint[2], footprint[3], box[2], box[3]) / h);
      const double bound = std::max(gap / (apex - top), floor);
      if (bound < best)
      {
        heap.push_back({ bound, level, k, l, sx, sy });
        std::push_heap(heap.begin(), heap.end());
      }
    };
    const int root = static_cast<int>(this->Grid.Levels.size()) - 1;
    const int repeats = this->Field.Repeat ? 1 : 0;
    for (int sy = -repeats; sy <= repeats; ++sy)
    {
      for (int sx = -repeats; sx <= repeats; ++sx)
      {
        push(root, 0, 0, sx, sy);
      }
    }
    while (!heap.empty() && best > conservative)
    {
      std::pop_heap(heap.begin(), heap.end());
      const RelaxedNode node = heap.back();
      heap.pop_back();
      if (!(node.Bound < best))
      {
        break; // every region left bounds no lower
      }
      if (node.Level > 0 || (node.Level > FinestPart && !this->Unbounded(node)))
      {
        // The blocks below, or the quarters of a cell or of a part.
        const int nx = node.Level > 0 ? this->Grid.Levels[node.Level - 1].NX : 1 << 30;
        const int ny = node.Level > 0 ? this->Grid.Levels[node.Level - 1].NY : 1 << 30;
        for (int l = 2 * node.L; l < std::min(2 * node.L + 2, ny); ++l)
        {
          for (int k = 2 * node.K; k < std::min(2 * node.K + 2, nx); ++k)
          {
            push(node.Level - 1, k, l, node.SX, node.SY);
          }
        }
        continue;
      }
      best = std::min(best, std::max(node.Bound, 1.0 / this->SlopeToRepeat(i, j, node)));
    }
    return std::max(best, conservative);
  }

private:
  // max(x y) over x in [lo, hi] and y in @a range; a zero derivative contributes nothing
  // however far the range runs.
  static double ProductMax(double lo, double hi, const double range[2])
  {
    return std::max({ lo * range[0], lo * range[1], hi * range[0], hi * range[1] });
  }

  // A node's extent in texel-index coordinates (texel centres at integers), box = {s0, s1, t0,
  // t1}, the range of the depth's derivatives over it, {s lo, s hi, t lo, t hi}, and the depth
  // of its highest point (returned). Without repeat, a block at the map's edge reaches on past
  // it, where the edge texels continue: the depth does not change across the edge there.
  double Region(int level, int k, int l, int sx, int sy, double box[4],
    std::array<double, 4>& slopes) const
  {
    const int block[2] = { k, l }, shift[2] = { sx, sy };
    const int count[2] = { this->Grid.NX, this->Grid.NY };
    if (level < 0)
    {
      // A part of cell (ck, cl): each derivative is linear along the other coordinate.
      const double part = std::ldexp(1.0, level);
      const int ck = k >> -level, cl = l >> -level;
      const double f0 = k * part - ck, g0 = l * part - cl;
      const double d00 = this->Field.At(ck, cl), d10 = this->Field.At(ck + 1, cl),
                   d01 = this->Field.At(ck, cl + 1), d11 = this->Field.At(ck + 1, cl + 1);
      const double twist = d11 - d01 - d10 + d00;
      const double ds0 = (d10 - d00) + g0 * twist, ds1 = ds0 + part * twist;
      const double dt0 = (d01 - d00) + f0 * twist, dt1 = dt0 + part * twist;
      slopes = { std::min(ds0, ds1), std::max(ds0, ds1), std::min(dt0, dt1), std::max(dt0, dt1) };
      for (int a = 0; a < 2; ++a)
      {
        box[2 * a] = block[a] * part + shift[a] * count[a];
        box[2 * a + 1] = box[2 * a] + part;
      }
      const double within[4] = { f0, f0 + part, g0, g0 + part };
      return this->Field.HighestInCell(ck, cl, within);
    }
    const std::array<float, 4> d = this->Grid.DerivativesOf(this->Field, level, k, l);
    slopes = { d[0], d[1], d[2], d[3] };
    const bool line[2] = { this->Grid.LineX, this->Grid.LineY };
    for (int a = 0; a < 2; ++a)
    {
      const int c0 = block[a] << level, c1 = std::min((block[a] + 1) << level, count[a]) - 1;
      box[2 * a] = c0 + shift[a] * count[a];
      box[2 * a + 1] = line[a] ? box[2 * a] : c1 + shift[a] * count[a] + 1.0;
      if (!this->Field.Repeat && (c0 == 0 || c1 == count[a] - 1))
      {
        box[2 * a] = c0 == 0 ? -1e30 : box[2 * a];
        box[2 * a + 1] = c1 == count[a] - 1 ? 1e30 : box[2 * a + 1];
        slopes[2 * a] = std::min(slopes[2 * a], 0.0);
        slopes[2 * a + 1] = std::max(slopes[2 * a + 1], 0.0);
      }
    }
    const Cells::Level& at = this->Grid.Levels[level];
    return at.Top[static_cast<size_t>(l) * at.NX + k];
  }

  // Whether the node's cell runs on past the map's edge (without repeat) or is a line: it is
  // not divided.
  bool Unbounded(const RelaxedNode& node) const
  {
    const int k = node.Level < 0 ? node.K >> -node.Level : node.K;
    const int l = node.Level < 0 ? node.L >> -node.Level : node.L;
    return !this->Field.Repeat &&
      (this->Grid.LineX || this->Grid.LineY || k == 0 || l == 0 || k == this->Grid.NX - 1 ||
        l == this->Grid.NY - 1);
  }

  // The steepest slope on every way from texel (i, j)'s footprint to the cell holding the node:
  // the cells around the way where the cell is the nearest repeat or one near it
  // (SlopeOnTheWay), else all.
  double SlopeToRepeat(int i, int j, const RelaxedNode& node) const
  {
    const int cell[2] = { node.Level < 0 ? node.K >> -node.Level : node.K,
      node.Level < 0 ? node.L >> -node.Level : node.L };
    const int texel[2] = { i, j }, shift[2] = { node.SX, node.SY };
    const int size[2] = { this->Field.W, this->Field.H };
    for (int a = 0; a < 2 && this->Field.Repeat; ++a)
    {
      const double f0 = texel[a] - 0.5, f1 = texel[a] + 0.5;
      double nearest = 1e300;
      for (int s : { -1, 0, 1 })
      {
        nearest = std::min(nearest, Gap(f0, f1, cell[a] + s * size[a], cell[a] + s * size[a] + 1));
      }
      const double c = cell[a] + shift[a] * size[a];
      if (Gap(f0, f1, c, c + 1) > nearest + 3.0)
      {
        return this->Grid.SteepestSlope;
      }
    }
    return this->SlopeOnTheWay(i, j, cell[0], cell[1]);
  }

  // The distance, in texture coordinates, from texel (i, j)'s footprint to the cells of block
  // (k, l) of @a level, the nearest repeat of them where the pattern repeats.
  double Distance(int i, int j, int level, int k, int l) const
  {
    const int span = 1 << level;
    const int first[2] = { k * span, l * span };
    const int count[2] = { this->Grid.NX, this->Grid.NY };
    const bool line[2] = { this->Grid.LineX, this->Grid.LineY };
    const int texel[2] = { i, j };
    const int size[2] = { this->Field.W, this->Field.H };
    double gap[2];
    for (int a = 0; a < 2; ++a)
    {
      // The block covers the interval from its first cell's start to its last cell's end.
      const double lo = first[a];
      const double hi = line[a] ? lo : std::min(first[a] + span, count[a]);
      const double from = texel[a] - 0.5, to = texel[a] + 0.5;
      gap[a] = Gap(from, to, lo, hi);
      for (int shift : { -size[a], size[a] })
      {
        gap[a] = this->Field.Repeat ? std::min(gap[a], Gap(from, to, lo + shift, hi + shift))
                                    : gap[a];
      }
      gap[a] /= size[a];
    }
    return std::hypot(gap[0], gap[1]);
  }

  // The steepest slope of the cells in the box spanning the footprint and cell (k, l) in every
  // repeat of it near enough to hold the nearest way from the footprint to one of its points:
  // every straight way from the footprint to a point of the cell lies in that box. Past a few
  // cells the steepest slope of all serves (it is no smaller).
  double SlopeOnTheWay(int i, int j, int k, int l) const
  {
    int from[2], to[2];
    const int texel[2] = { i, j }, cell[2] = { k, l }, size[2] = { this->Field.W, this->Field.H };
    for (int a = 0; a < 2; ++a)
    {
      const double f0 = texel[a] - 0.5, f1 = texel[a] + 0.5;
      double nearest = Gap(f0, f1, cell[a], cell[a] + 1);
      for (int shift : { -size[a], size[a] })
      {
        nearest = this->Field.Repeat
          ? std::min(nearest, Gap(f0, f1, cell[a] + shift, cell[a] + shift + 1))
          : nearest;
      }
      from[a] = texel[a] - 1;
      to[a] = texel[a];
      for (int shift : { 0, -size[a], size[a] })
      {
        // A repeat more than a cell's and a footprint's diagonal farther than the nearest one
        // is never the nearest way to any of its points.
        if ((shift == 0 || this->Field.Repeat) &&
          Gap(f0, f1, cell[a] + shift, cell[a] + shift + 1) <= nearest + 3.0)
        {
          from[a] = std::min(from[a], cell[a] + shift);
          to[a] = std::max(to[a], cell[a] + shift);
        }
      }
    }
    if ((to[0] - from[0] + 1) * (to[1] - from[1] + 1) > 64)
    {
      return this->Grid.SteepestSlope;
    }
    double steepest = 0.0;
    for (int cl = from[1]; cl <= to[1]; ++cl)
    {
      for (int ck = from[0]; ck <= to[0]; ++ck)
      {
        // Where the edges continue, the surface past them is no steeper than the edge cells.
        const int x = this->Field.Repeat ? ((ck % this->Grid.NX) + this->Grid.NX) % this->Grid.NX
                                         : std::min(std::max(ck, 0), this->Grid.NX - 1);
        const int y = this->Field.Repeat ? ((cl % this->Grid.NY) + this->Grid.NY) % this->Grid.NY
                                         : std::min(std::max(cl, 0), this->Grid.NY - 1);
        steepest = std::max(steepest, this->Grid.Slope[static_cast<size_t>(y) * this->Grid.NX + x]);
      }
    }
    return steepest > 0.0 ? steepest : this->Grid.SteepestSlope;
  }

  const DepthField& Field;
  const Cells& Grid;
  double MaxRatio;
};
}

//------------------------------------------------------------------------------
vtkHeightMapToConeMap::vtkHeightMapToConeMap()
{
  // Heights: the input's point scalars unless an array is chosen.
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
int vtkHeightMapToConeMap::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkDataObject::SetPointDataActiveScalarInfo(outputVector->GetInformationObject(0), VTK_FLOAT, 2);
  return 1;
}

//------------------------------------------------------------------------------
int vtkHeightMapToConeMap::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every cone reads the whole map.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  int whole[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), whole, 6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkHeightMapToConeMap::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  if (!input)
  {
    vtkErrorMacro("No input image: connect a vtkImageData height map to port 0.");
    return 0;
  }
  int ext[6];
  input->GetExtent(ext);
  const int w = ext[1] - ext[0] + 1, h = ext[3] - ext[2] + 1, d = ext[5] - ext[4] + 1;
  vtkDataArray* heights = this->GetInputArrayToProcess(0, inputVector);
  double typeScale = 1.0;
  if (w <= 0 || h <= 0 || d != 1)
  {
    vtkErrorMacro("The height map must be a 2-D image of at least one texel; this one is "
      << std::max(w, 0) << "x" << std::max(h, 0) << "x" << std::max(d, 0) << ".");
    return 0;
  }
  if (!heights || heights->GetNumberOfTuples() != static_cast<vtkIdType>(w) * h ||
    this->HeightComponent >= heights->GetNumberOfComponents())
  {
    vtkErrorMacro("The height map needs one height per texel in component "
      << this->HeightComponent << " of its point scalars (or of the array chosen with "
      << "SetInputArrayToProcess).");
    return 0;
  }
  if (!vtkSurfaceDetail::HeightMapScale(heights->GetDataType(), typeScale))
  {
    vtkErrorMacro("The height map's scalars are "
      << heights->GetDataTypeAsString() << ": " << vtkSurfaceDetail::HeightMapTypeAdvice() << ".");
    return 0;
  }
  if (this->Wrap != vtkSurfaceDetail::Repeat && this->Wrap != vtkSurfaceDetail::ClampToEdge)
  {
    vtkErrorMacro("Wrap " << vtkSurfaceDetail::WrapModeName(this->Wrap)
                          << " is not supported: use Repeat or ClampToEdge.");
    return 0;
  }

  DepthField field;
  field.W = w;
  field.H = h;
  field.Repeat = this->Wrap == vtkSurfaceDetail::Repeat;
  field.Depth.resize(static_cast<size_t>(w) * h);
  for (vtkIdType t = 0; t < static_cast<vtkIdType>(w) * h; ++t)
  {
    const double height = typeScale * heights->GetComponent(t, this->HeightComponent);
    if (!std::isfinite(height))
    {
      vtkErrorMacro("The height map has a non-finite height at texel " << t
                                                                        << ": give finite heights.");
      return 0;
    }
    field.Depth[t] = 1.0 - std::min(std::max(height, 0.0), 1.0);
  }
  Cells cells(field);
  const bool relaxed = this->ConeType == Relaxed;
  if (relaxed)
  {
    cells.AddDerivatives(field);
  }
  const ConeSearch search(field, cells, this->MaxConeRatio);

  vtkNew<vtkFloatArray> cones;
  cones->SetName("ConeMap");
  cones->SetNumberOfComponents(2);
  cones->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  float* out = cones->GetPointer(0);
  vtkSMPTools::For(0, h,
    [&](int begin, int end)
    {
      std::vector<ConeSearch::Node> heap;
      std::vector<ConeSearch::RelaxedNode> relaxedHeap;
      for (int j = begin; j < end; ++j)
      {
        for (int i = 0; i < w; ++i)
        {
          const double apex = field.ApexDepth(i, j);
          double ratio = search.Ratio(i, j, apex, heap);
          ratio = relaxed ? search.RelaxedRatio(i, j, apex, ratio, relaxedHeap) : ratio;
          float* texel = out + 2 * (static_cast<size_t>(j) * w + i);
          texel[0] = RoundDown(apex);
          texel[1] = RoundDown(ratio);
        }
      }
    });
  output->SetExtent(ext);
  output->SetOrigin(input->GetOrigin());
  output->SetSpacing(input->GetSpacing());
  output->GetPointData()->SetScalars(cones);
  return 1;
}

//------------------------------------------------------------------------------
const char* vtkHeightMapToConeMap::GetConeTypeAsString()
{
  return this->ConeType == Relaxed ? "Relaxed" : "Conservative";
}

//------------------------------------------------------------------------------
void vtkHeightMapToConeMap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HeightComponent: " << this->HeightComponent << "\n";
  os << indent << "Wrap: " << vtkSurfaceDetail::WrapModeName(this->Wrap) << "\n";
  os << indent << "ConeType: " << this->GetConeTypeAsString() << "\n";
  os << indent << "MaxConeRatio: " << this->MaxConeRatio << "\n";
}
