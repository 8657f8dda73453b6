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
      i = ((i % this->W) + this->W) % this->W;
      j = ((j % this->H) + this->H) % this->H;
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

private:
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
  const Cells cells(field);
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
      for (int j = begin; j < end; ++j)
      {
        for (int i = 0; i < w; ++i)
        {
          const double apex = field.ApexDepth(i, j);
          float* texel = out + 2 * (static_cast<size_t>(j) * w + i);
          texel[0] = RoundDown(apex);
          texel[1] = RoundDown(search.Ratio(i, j, apex, heap));
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
void vtkHeightMapToConeMap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HeightComponent: " << this->HeightComponent << "\n";
  os << indent << "Wrap: " << vtkSurfaceDetail::WrapModeName(this->Wrap) << "\n";
  os << indent << "MaxConeRatio: " << this->MaxConeRatio << "\n";
}
