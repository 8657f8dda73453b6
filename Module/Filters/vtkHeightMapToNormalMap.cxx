#include "vtkHeightMapToNormalMap.h"

#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
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

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkHeightMapToNormalMap);

namespace
{

// Slopes beyond this are clamped so that their squares cannot overflow a float: the normal
// is then horizontal to within 1e-18, and never NaN.
constexpr double MaxSlope = 1e18;

// How heights of type InT become [0,1]: h = v*Scale + Offset.
template <typename InT>
void HeightNormalisation(double& scale, double& offset)
{
  if (std::is_floating_point<InT>::value)
  {
    scale = 1.0;
    offset = 0.0;
    return;
  }
  const double lo = static_cast<double>(std::numeric_limits<InT>::lowest());
  const double hi = static_cast<double>(std::numeric_limits<InT>::max());
  scale = 1.0 / (hi - lo);
  offset = -lo * scale;
}

// Output encoding: floats keep 0.5*n + 0.5, integers round it to nearest on their full range.
template <typename OutT, typename Real>
inline OutT Quantise(Real e)
{
  if (std::is_floating_point<OutT>::value)
  {
    return static_cast<OutT>(e);
  }
  const Real top = static_cast<Real>(std::numeric_limits<OutT>::max());
  const Real q = e * top + Real(0.5);
  return static_cast<OutT>(std::min(std::max(q, Real(0)), top));
}

template <typename Real>
struct RowCache
{
  std::array<std::vector<Real>, 3> Rows;
  std::array<int, 3> Tags{ { -1, -1, -1 } };
  std::vector<Real> Gx, Gy;
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
  Real HScale = 1, HOffset = 0;
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
  }

  // Row r of the height map as Real, padded with the wrapped texel on each side so that the
  // stencils below never test for borders: row[k + 1] is texel k, row[0] texel -1.
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
    const InT* src = this->In + static_cast<size_t>(r) * this->W * this->InStride;
    const int stride = this->InStride;
    for (int k = 0; k < this->W; ++k)
    {
      row[k + 1] = static_cast<Real>(src[static_cast<size_t>(k) * stride]);
    }
    row[0] = row[vtkSurfaceDetail::WrapIndex(-1, this->W, this->Wrap) + 1];
    row[this->W + 1] = row[vtkSurfaceDetail::WrapIndex(this->W, this->W, this->Wrap) + 1];
    c.Tags[b] = r;
    return row;
  }

  void operator()(vtkIdType rowBegin, vtkIdType rowEnd)
  {
    RowCache<Real>& c = this->Cache.Local();
    const int n = this->I1 - this->I0 + 1;
    Real* gx = c.Gx.data();
    Real* gy = c.Gy.data();
    for (vtkIdType jj = rowBegin; jj < rowEnd; ++jj)
    {
      const int j = static_cast<int>(jj);
      const int keep[3] = { vtkSurfaceDetail::WrapIndex(j - 1, this->H, this->Wrap), j,
        vtkSurfaceDetail::WrapIndex(j + 1, this->H, this->Wrap) };
      // Pointers offset so that m[i], c0[i], p[i] are texel i of rows j-1, j, j+1.
      const Real* c0 = this->Row(c, keep[1], keep) + 1 + this->I0;
      const Real* p = this->Row(c, keep[2], keep) + 1 + this->I0;
      const Real* m = this->Scheme == vtkHeightMapToNormalMap::Forward
        ? nullptr
        : this->Row(c, keep[0], keep) + 1 + this->I0;
      this->Slopes(m, c0, p, n, gx, gy);
      OutT* out = this->Out + static_cast<size_t>(j - this->J0) * n * this->OutComps;
      this->Encode(c0, gx, gy, n, out);
    }
  }

  void Reduce() {}

  void Slopes(const Real* m, const Real* c0, const Real* p, int n, Real* gx, Real* gy) const
  {
    const Real sx = this->Sx, sy = this->Sy;
    switch (this->Scheme)
    {
      case vtkHeightMapToNormalMap::Forward:
        for (int i = 0; i < n; ++i)
        {
          gx[i] = (c0[i + 1] - c0[i]) * sx;
          gy[i] = (p[i] - c0[i]) * sy;
        }
        break;
      case vtkHeightMapToNormalMap::Central:
      {
        const Real hx = sx * Real(0.5), hy = sy * Real(0.5);
        for (int i = 0; i < n; ++i)
        {
          gx[i] = (c0[i + 1] - c0[i - 1]) * hx;
          gy[i] = (p[i] - m[i]) * hy;
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
          gx[i] =
            (a * (m[i + 1] - m[i - 1]) + b * (c0[i + 1] - c0[i - 1]) + a * (p[i + 1] - p[i - 1])) *
            hx;
          gy[i] = (a * (p[i - 1] - m[i - 1]) + b * (p[i] - m[i]) + a * (p[i + 1] - m[i + 1])) * hy;
        }
        break;
      }
    }
  }

  void Encode(const Real* c0, const Real* gx, const Real* gy, int n, OutT* out) const
  {
    const Real lim = static_cast<Real>(MaxSlope);
    const Real half = Real(0.5);
    const Real ySign = this->GreenUp ? Real(-1) : Real(1);
    const int nc = this->OutComps;
    for (int i = 0; i < n; ++i)
    {
      const Real x = -std::min(std::max(gx[i], -lim), lim);
      const Real y = ySign * std::min(std::max(gy[i], -lim), lim);
      const Real len = std::sqrt(x * x + y * y + Real(1));
      out[static_cast<size_t>(i) * nc] = Quantise<OutT>(half * (x / len) + half);
      out[static_cast<size_t>(i) * nc + 1] = Quantise<OutT>(half * (y / len) + half);
      out[static_cast<size_t>(i) * nc + 2] = Quantise<OutT>(half * (Real(1) / len) + half);
    }
    if (nc == 4)
    {
      for (int i = 0; i < n; ++i)
      {
        const Real depth = Real(1) - (c0[i] * this->HScale + this->HOffset);
        out[static_cast<size_t>(i) * 4 + 3] =
          Quantise<OutT>(std::min(std::max(depth, Real(0)), Real(1)));
      }
    }
  }
};

// Counts the non-finite heights and the finite ones outside [0,1].
template <typename Real>
struct HeightCensus
{
  const Real* In;
  int Stride;
  vtkSMPThreadLocal<vtkIdType> NonFinite, OutOfRange;

  void Initialize()
  {
    this->NonFinite.Local() = 0;
    this->OutOfRange.Local() = 0;
  }
  void operator()(vtkIdType begin, vtkIdType end)
  {
    vtkIdType bad = 0, outside = 0;
    for (vtkIdType k = begin; k < end; ++k)
    {
      const Real v = this->In[k * this->Stride];
      bad += std::isfinite(v) ? 0 : 1;
      outside += (v < Real(0) || v > Real(1)) ? 1 : 0;
    }
    this->NonFinite.Local() += bad;
    this->OutOfRange.Local() += outside;
  }
  void Reduce() {}
};

// Replaces each non-finite height by the mean of the finite ones among the eight texels its
// stencil reads (wrapped as the filter wraps), sweeping until none is left; an image with no
// finite height at all becomes flat 0.
template <typename Real>
void RepairHeights(std::vector<Real>& h, int w, int hgt, int wrap)
{
  std::vector<Real> next(h);
  bool left = true;
  while (left)
  {
    left = false;
    bool progress = false;
    for (int j = 0; j < hgt; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        const size_t k = static_cast<size_t>(j) * w + i;
        if (std::isfinite(h[k]))
        {
          continue;
        }
        double sum = 0.0;
        int count = 0;
        for (int dj = -1; dj <= 1; ++dj)
        {
          const int jj = vtkSurfaceDetail::WrapIndex(j + dj, hgt, wrap);
          for (int di = -1; di <= 1; ++di)
          {
            const int ii = vtkSurfaceDetail::WrapIndex(i + di, w, wrap);
            const Real v = h[static_cast<size_t>(jj) * w + ii];
            if ((di != 0 || dj != 0) && std::isfinite(v))
            {
              sum += v;
              ++count;
            }
          }
        }
        if (count > 0)
        {
          next[k] = static_cast<Real>(sum / count);
          progress = true;
        }
        else
        {
          left = true;
        }
      }
    }
    if (left && !progress)
    {
      std::fill(next.begin(), next.end(), Real(0));
      left = false;
    }
    h = next;
  }
}

struct Job
{
  int W, H;
  int OutExt[4]; // i0, i1, j0, j1 in input indices
  int Scheme, Wrap, OutputScalarType, OutComps;
  bool GreenUp;
  double Strength;
  void* Out;
};

template <typename InT, typename OutT>
void RunKernel(const InT* in, int stride, const Job& job)
{
  using Real = typename std::conditional<std::is_same<InT, double>::value, double, float>::type;
  double scale, offset;
  HeightNormalisation<InT>(scale, offset);
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
  kernel.Sx = static_cast<Real>(std::min(std::max(job.Strength * job.W * scale, -top), top));
  kernel.Sy = static_cast<Real>(std::min(std::max(job.Strength * job.H * scale, -top), top));
  kernel.HScale = static_cast<Real>(scale);
  kernel.HOffset = static_cast<Real>(offset);
  vtkSMPTools::For(job.OutExt[2], job.OutExt[3] + 1, kernel);
}

template <typename InT>
void DispatchOutput(const InT* in, int stride, const Job& job)
{
  switch (job.OutputScalarType)
  {
    case VTK_FLOAT:
      RunKernel<InT, float>(in, stride, job);
      break;
    case VTK_UNSIGNED_SHORT:
      RunKernel<InT, unsigned short>(in, stride, job);
      break;
    default:
      RunKernel<InT, unsigned char>(in, stride, job);
      break;
  }
}

// Floating-point heights are checked first: non-finite ones are repaired in a copy (the
// input stays untouched), and out-of-range ones are reported when they would be clamped.
template <typename Real>
void RunFloating(
  vtkHeightMapToNormalMap* self, const Real* in, int stride, const Job& job, bool relief)
{
  HeightCensus<Real> census;
  census.In = in;
  census.Stride = stride;
  const vtkIdType n = static_cast<vtkIdType>(job.W) * job.H;
  vtkSMPTools::For(0, n, census);
  vtkIdType nonFinite = 0, outside = 0;
  for (vtkIdType v : census.NonFinite)
  {
    nonFinite += v;
  }
  for (vtkIdType v : census.OutOfRange)
  {
    outside += v;
  }
  if (relief && outside > 0)
  {
    vtkWarningWithObjectMacro(
      self, << outside << " height(s) lie outside [0,1]; their relief depth 1 - h is clamped to "
            << "[0,1]. Rescale the heights (e.g. vtkImageShiftScale) and raise Strength instead.");
  }
  if (nonFinite == 0)
  {
    DispatchOutput(in, stride, job);
    return;
  }
  vtkWarningWithObjectMacro(
    self, << nonFinite << " height(s) are NaN or infinite; each is replaced by the mean of its "
          << "finite neighbours.");
  std::vector<Real> repaired(static_cast<size_t>(n));
  for (vtkIdType k = 0; k < n; ++k)
  {
    repaired[k] = in[k * stride];
  }
  RepairHeights(repaired, job.W, job.H, job.Wrap);
  DispatchOutput(repaired.data(), 1, job);
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
const char* vtkHeightMapToNormalMap::GetSchemeAsString()
{
  switch (this->Scheme)
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
  switch (this->Wrap)
  {
    case ClampToEdge:
      return "ClampToEdge";
    case MirroredRepeat:
      return "MirroredRepeat";
    default:
      return "Repeat";
  }
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
  if (!std::isfinite(this->Strength))
  {
    vtkErrorMacro("Strength is " << this->Strength << ": set a finite value.");
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
  vtkSmartPointer<vtkDataArray> map =
    vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(this->OutputScalarType));
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
  job.Scheme = this->Scheme;
  job.Wrap = this->Wrap;
  job.OutputScalarType = this->OutputScalarType;
  job.OutComps = comps;
  job.GreenUp = this->GreenUp;
  job.Strength = this->Strength;
  job.Out = map->GetVoidPointer(0);

  const int stride = contiguous->GetNumberOfComponents();
  switch (contiguous->GetDataType())
  {
    vtkTemplateMacro(Run(this, static_cast<const VTK_TT*>(contiguous->GetVoidPointer(0)), stride,
      job, this->OutputRelief));
    default:
      vtkErrorMacro("Heights of type " << contiguous->GetDataTypeAsString()
                                       << " are not supported: convert them to a numeric type "
                                          "(e.g. vtkImageCast).");
      output->Initialize();
      return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkHeightMapToNormalMap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: " << this->GetSchemeAsString() << "\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "Wrap: " << this->GetWrapAsString() << "\n";
  os << indent << "GreenUp: " << (this->GreenUp ? "On" : "Off") << "\n";
  os << indent << "OutputScalarType: " << vtkImageScalarTypeNameMacro(this->OutputScalarType)
     << "\n";
  os << indent << "OutputRelief: " << (this->OutputRelief ? "On" : "Off") << "\n";
}
