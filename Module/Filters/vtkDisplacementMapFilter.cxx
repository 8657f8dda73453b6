#include "vtkDisplacementMapFilter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkSurfaceDetailCells.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailMemory.h"
#include "vtkSurfaceDetailVectorize.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkDisplacementMapFilter);

namespace
{
using namespace vtkSurfaceDetail;

// Raw, typed access to a float or double array with the standard memory layout
// (RequestData converts anything else first): no virtual call and no type test per value.
template <typename R>
struct ArrayReader
{
  const R* P;
  int NC;

  explicit ArrayReader(vtkDataArray* a)
    : P(static_cast<const R*>(a->GetVoidPointer(0)))
    , NC(a->GetNumberOfComponents())
  {
  }

  double Get(vtkIdType i, int c) const { return this->P[i * this->NC + c]; }

  void Get3(vtkIdType i, double v[3]) const
  {
    const R* x = this->P + i * this->NC;
    v[0] = x[0];
    v[1] = x[1];
    v[2] = x[2];
  }
};

template <typename R>
struct ArrayWriter
{
  R* P;
  int NC;

  explicit ArrayWriter(vtkDataArray* a)
    : P(static_cast<R*>(a->GetVoidPointer(0)))
    , NC(a->GetNumberOfComponents())
  {
  }

  // For unit vectors: no range to check.
  void Set(vtkIdType i, int c, double v) const { this->P[i * this->NC + c] = static_cast<R>(v); }

  // For positions: beyond float's range, the largest float rather than infinity.
  void SetClamped(vtkIdType i, int c, double v) const
  {
    if (std::is_same<R, float>::value)
    {
      constexpr double big = std::numeric_limits<float>::max();
      v = std::min(std::max(v, -big), big);
    }
    this->P[i * this->NC + c] = static_cast<R>(v);
  }
};

template <typename R>
vtkSmartPointer<vtkDataArray> NewRealArray(const char* name, int nc, vtkIdType n)
{
  vtkSmartPointer<vtkDataArray> a;
  if (std::is_same<R, float>::value)
  {
    a = vtkSmartPointer<vtkFloatArray>::New();
  }
  else
  {
    a = vtkSmartPointer<vtkDoubleArray>::New();
  }
  a->SetNumberOfComponents(nc);
  a->SetNumberOfTuples(n);
  a->SetName(name);
  return a;
}

// An output array of n tuples whose values the passes write: from vtkSurfaceDetailMemory, which
// hands back the huge pages of an earlier execution's freed output instead of faulting in
// fresh ones, and not initialised.
template <typename R>
vtkSmartPointer<vtkDataArray> NewOutputArray(const char* name, int nc, vtkIdType n)
{
  using Array = std::conditional_t<std::is_same<R, float>::value, vtkFloatArray, vtkDoubleArray>;
  auto a = vtkSmartPointer<Array>::New();
  a->SetNumberOfComponents(nc);
  a->SetName(name);
  if (!vtkSurfaceDetailMemory::AllocateTuples(a.Get(), n))
  {
    a->SetNumberOfTuples(n);
  }
  return a;
}

// @a a itself when it is already a plain array of R, else a copy converted to R.
template <typename R>
vtkSmartPointer<vtkDataArray> AsReal(vtkDataArray* a)
{
  const int type = std::is_same<R, float>::value ? VTK_FLOAT : VTK_DOUBLE;
  if (!a || (a->GetDataType() == type && a->HasStandardMemoryLayout()))
  {
    return a;
  }
  auto copy = NewRealArray<R>(a->GetName(), a->GetNumberOfComponents(), 0);
  copy->DeepCopy(a);
  return copy;
}

// The height map as a texture: texel values of one component, normalised, non-finite
// values replaced by the midlevel.
template <typename T>
struct Texels
{
  const T* Data;
  int W, H, NC, Comp;
  double Norm, Mid;
  bool Clean; // no non-finite texel: values need no test

  // The height at a raw texel, non-finite values replaced (integer maps have none).
  double Value(T raw) const
  {
    const double v = this->Norm * raw;
    if (std::is_integral<T>::value)
    {
      return v;
    }
    return std::isfinite(v) ? v : this->Mid;
  }

  double At(int i, int j) const
  {
    const double v =
      this->Norm * this->Data[(static_cast<vtkIdType>(j) * this->W + i) * this->NC + this->Comp];
    if (std::is_integral<T>::value)
    {
      return v;
    }
    return std::isfinite(v) ? v : this->Mid;
  }
};

// WrapIndex, with the common case (inside the texture) spared its integer division.
inline int Wrapped(int i, int n, int mode)
{
  return static_cast<unsigned>(i) < static_cast<unsigned>(n) ? i : WrapIndex(i, n, mode);
}

// Normalize with one division: the passes normalise a few vectors per point.
inline double FastNormalize(double v[3])
{
  const double len = std::sqrt(Dot(v, v));
  if (len > 0.0 && std::isfinite(len))
  {
    const double inv = 1.0 / len;
    v[0] *= inv;
    v[1] *= inv;
    v[2] *= inv;
  }
  return len;
}

// Keeps huge coordinates from overflowing the texel index; 2 is a period of every wrap.
inline double TameCoordinate(double s, int wrap)
{
  if (std::abs(s) < 1e6)
  {
    return s;
  }
  return wrap == ClampToEdge ? std::min(std::max(s, -1.0), 2.0) : std::fmod(s, 2.0);
}

// Catmull-Rom weights and their derivatives for the fraction f in [0,1).
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

// Height h(s,t) of the interpolant and its derivatives with respect to s and t. The
// interpolation is a template parameter, so the per-point loop has no test of the kind; forced
// inline, so that pass 1's AVX2 copy also samples with AVX2 (floor is one instruction there).
template <int Interp, typename T>
VTK_ALWAYS_INLINE void SampleHeight(
  const Texels<T>& tex, int wrap, double s, double t, double& h, double& hs, double& ht)
{
  s = TameCoordinate(s, wrap);
  t = TameCoordinate(t, wrap);
  const int W = tex.W, H = tex.H;
  if constexpr (Interp == vtkDisplacementMapFilter::Nearest)
  {
    const double x = std::floor(s * W), y = std::floor(t * H);
    const int i = std::isfinite(x) ? static_cast<int>(x) : 0;
    const int j = std::isfinite(y) ? static_cast<int>(y) : 0;
    h = tex.At(Wrapped(i, W, wrap), Wrapped(j, H, wrap));
    hs = 0.0;
    ht = 0.0;
    return;
  }
  int i0, j0;
  double fx, fy;
  LinearTexels(s, W, i0, fx);
  LinearTexels(t, H, j0, fy);
  const vtkIdType rowStride = static_cast<vtkIdType>(W) * tex.NC;
  if constexpr (Interp == vtkDisplacementMapFilter::Linear)
  {
    double h00, h10, h01, h11;
    if (tex.Clean && i0 >= 0 && i0 + 1 < W && j0 >= 0 && j0 + 1 < H)
    {
      // The common case, away from the borders of a map without NaN: no wrap, no test.
      const T* p = tex.Data + j0 * rowStride + i0 * tex.NC + tex.Comp;
      h00 = tex.Norm * p[0];
      h10 = tex.Norm * p[tex.NC];
      h01 = tex.Norm * p[rowStride];
      h11 = tex.Norm * p[rowStride + tex.NC];
    }
    else
    {
      const int ia = Wrapped(i0, W, wrap), ib = Wrapped(i0 + 1, W, wrap);
      const int ja = Wrapped(j0, H, wrap), jb = Wrapped(j0 + 1, H, wrap);
      h00 = tex.At(ia, ja);
      h10 = tex.At(ib, ja);
      h01 = tex.At(ia, jb);
      h11 = tex.At(ib, jb);
    }
    const double b0 = (1.0 - fx) * h00 + fx * h10;
    const double b1 = (1.0 - fx) * h01 + fx * h11;
    h = (1.0 - fy) * b0 + fy * b1;
    hs = W * ((1.0 - fy) * (h10 - h00) + fy * (h11 - h01));
    ht = H * (b1 - b0);
    return;
  }
  double wx[4], dwx[4], wy[4], dwy[4];
  CatmullRom(fx, wx, dwx);
  CatmullRom(fy, wy, dwy);
  if (tex.Clean && i0 >= 1 && i0 + 2 < W && j0 >= 1 && j0 + 2 < H)
  {
    // The common case, away from the borders of a map without NaN: no wrap, no test.
    const T* first = tex.Data + (j0 - 1) * rowStride + (i0 - 1) * tex.NC + tex.Comp;
    const int nc = tex.NC;
    h = hs = ht = 0.0;
    for (int l = 0; l < 4; ++l)
    {
      const T* rowData = first + l * rowStride;
      double row = 0.0, drow = 0.0;
      for (int k = 0; k < 4; ++k)
      {
        const double v = tex.Norm * rowData[k * nc];
        row += wx[k] * v;
        drow += dwx[k] * v;
      }
      h += wy[l] * row;
      hs += wy[l] * drow;
      ht += dwy[l] * row;
    }
    hs *= W;
    ht *= H;
    return;
  }
  // Offsets of the 4 columns and a pointer per row: 16 reads, no index arithmetic each.
  vtkIdType column[4];
  for (int k = 0; k < 4; ++k)
  {
    column[k] = static_cast<vtkIdType>(Wrapped(i0 - 1 + k, W, wrap)) * tex.NC + tex.Comp;
  }
  h = hs = ht = 0.0;
  for (int l = 0; l < 4; ++l)
  {
    const T* rowData = tex.Data + Wrapped(j0 - 1 + l, H, wrap) * rowStride;
    double row = 0.0, drow = 0.0;
    for (int k = 0; k < 4; ++k)
    {
      const double v = tex.Value(rowData[column[k]]);
      row += wx[k] * v;
      drow += dwx[k] * v;
    }
    h += wy[l] * row;
    hs += wy[l] * drow;
    ht += dwy[l] * row;
  }
  hs *= W;
  ht *= H;
}

// A big scratch array in huge pages (vtkSurfaceDetailMemory), its values left uninitialised:
// std::vector would zero it first, and each of its 4 kB pages would fault on first touch.
template <typename V>
class Buffer
{
public:
  Buffer() = default;
  explicit Buffer(size_t n) { this->Resize(n); }
  ~Buffer() { vtkSurfaceDetailMemory::Release(this->P); }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  // Keeps the block when its size is already @a n (a cache rebuilt for the same mesh).
  void Resize(size_t n)
  {
    if (this->P && this->N == n)
    {
      return;
    }
    vtkSurfaceDetailMemory::Release(this->P);
    this->N = 0;
    this->P = static_cast<V*>(vtkSurfaceDetailMemory::Allocate(n * sizeof(V)));
    if (!this->P)
    {
      throw std::bad_alloc();
    }
    this->N = n;
  }
  void Free()
  {
    vtkSurfaceDetailMemory::Release(this->P);
    this->P = nullptr;
    this->N = 0;
  }
  V* data() const { return this->P; }
  size_t size() const { return this->N; }
  V& operator[](size_t i) const { return this->P[i]; }

private:
  V* P = nullptr;
  size_t N = 0;
};

std::vector<vtkIdType> Widen(vtkDataArray* a)
{
  std::vector<vtkIdType> out(a->GetNumberOfValues());
  if (a->GetDataType() == VTK_TYPE_INT32)
  {
    const auto* p = static_cast<const vtkTypeInt32*>(a->GetVoidPointer(0));
    std::copy(p, p + out.size(), out.begin());
  }
  else
  {
    const auto* p = static_cast<const vtkTypeInt64*>(a->GetVoidPointer(0));
    std::copy(p, p + out.size(), out.begin());
  }
  return out;
}

// The point-to-polygon links in CSR form (each point's polygons in increasing id order, so
// that every sum over them has one order).
struct LinkTable
{
  Buffer<vtkIdType> Offsets, Links;
};

// Polygons as offsets + connectivity, and their links (owned by a LinkTable).
struct PolyLinks
{
  std::vector<vtkIdType> OffsetsCopy, ConnCopy;
  const vtkIdType* Offsets = nullptr;
  const vtkIdType* Conn = nullptr;
  vtkIdType NumCells = 0;
  const vtkIdType* LinkOffsets = nullptr;
  const vtkIdType* Links = nullptr;

  void Build(vtkCellArray* polys)
  {
    this->NumCells = polys->GetNumberOfCells();
    static_assert(sizeof(vtkIdType) == 8 || sizeof(vtkIdType) == 4, "id size");
    if (polys->IsStorage64Bit() && sizeof(vtkIdType) == 8)
    {
      this->Offsets = reinterpret_cast<const vtkIdType*>(polys->GetOffsetsArray64()->GetPointer(0));
      this->Conn =
        reinterpret_cast<const vtkIdType*>(polys->GetConnectivityArray64()->GetPointer(0));
    }
    else
    {
      // 32-bit storage: widened once, with typed loops rather than virtual calls.
      this->OffsetsCopy =
        Widen(polys->IsStorage64Bit() ? static_cast<vtkDataArray*>(polys->GetOffsetsArray64())
                                      : static_cast<vtkDataArray*>(polys->GetOffsetsArray32()));
      this->ConnCopy = Widen(polys->IsStorage64Bit()
          ? static_cast<vtkDataArray*>(polys->GetConnectivityArray64())
          : static_cast<vtkDataArray*>(polys->GetConnectivityArray32()));
      this->Offsets = this->OffsetsCopy.data();
      this->Conn = this->ConnCopy.data();
    }
  }

  void UseLinks(const LinkTable& table)
  {
    this->LinkOffsets = table.Offsets.data();
    this->Links = table.Links.data();
  }

  // False if a polygon names a point outside [0, numPts) (the table is then unusable): the count
  // pass checks every id as it reads it, so that no separate check reads the connectivity.
  bool BuildLinks(vtkIdType numPts, LinkTable& table) const
  {
    // Counts, then their running sums (the end of each point's list), then the polygons
    // placed from the last one down: each list ends up in increasing order and the ends
    // become the starts, with no cursor array.
    table.Offsets.Resize(numPts + 1);
    vtkIdType* offsets = table.Offsets.data();
    std::fill_n(offsets, numPts + 1, 0);
    const vtkIdType nConn = this->Offsets[this->NumCells];
    const std::uint64_t limit = static_cast<std::uint64_t>(numPts);
    bool bad = false;
    for (vtkIdType k = 0; k < nConn; ++k)
    {
      // An id outside is counted in the last entry, which only a good table needs at 0.
      const vtkIdType id = this->Conn[k];
      const bool outside = static_cast<std::uint64_t>(id) >= limit;
      bad |= outside;
      ++offsets[outside ? numPts : id];
    }
    if (bad)
    {
      return false;
    }
    for (vtkIdType i = 0; i < numPts; ++i)
    {
      offsets[i + 1] += offsets[i];
    }
    table.Links.Resize(nConn);
    // Restricted locals (no store into the links makes the loop reload the polygons' offsets), and
    // triangles, the usual polygons, unrolled.
    vtkIdType* __restrict ends = offsets;
    vtkIdType* __restrict links = table.Links.data();
    const vtkIdType* __restrict cellOffsets = this->Offsets;
    const vtkIdType* __restrict conn = this->Conn;
    for (vtkIdType c = this->NumCells - 1; c >= 0; --c)
    {
      const vtkIdType b = cellOffsets[c], e = cellOffsets[c + 1];
      if (e - b == 3)
      {
        links[--ends[conn[b]]] = c;
        links[--ends[conn[b + 1]]] = c;
        links[--ends[conn[b + 2]]] = c;
        continue;
      }
      for (vtkIdType k = b; k < e; ++k)
      {
        links[--ends[conn[k]]] = c;
      }
    }
    return true;
  }
};

// Which polygons touch a range of points, without links: the polygons in chunks of Chunk
// consecutive ids, each chunk with the least and the largest point id of its corners. A usual
// mesh numbers its polygons along its points (a grid's rows), so a chunk spans a few rows of
// points and a range of points meets few chunks; scattered point ids (a renumbered mesh) make
// every chunk span nearly all points (see Work).
struct CellSpans
{
  static constexpr vtkIdType Chunk = 512;
  // Above this Work (polygons read per polygon), the links' gather is cheaper than the spans.
  static constexpr double MaxWork = 1.5;
  // Per chunk: the least and the largest id of its corners (Lo > Hi: no corners); MaxHi is the
  // running maximum of Hi, MinLo the running minimum of Lo from the last chunk down: both never
  // decrease, so the chunks that may meet a range are found by two binary searches.
  std::vector<vtkIdType> Lo, Hi, MaxHi, MinLo;
  // Per chunk: 1 if its polygons are all triangles (a walk then finds each one's corners without
  // reading the offsets).
  std::vector<unsigned char> Triangles;

  size_t Bytes() const { return (sizeof(vtkIdType) * 4 + 1) * this->Lo.size(); }

  // The chunks that may meet [pb, pe): [first, last), each still to be asked Meets.
  void Candidates(vtkIdType pb, vtkIdType pe, vtkIdType& first, vtkIdType& last) const
  {
    first = static_cast<vtkIdType>(
      std::lower_bound(this->MaxHi.begin(), this->MaxHi.end(), pb) - this->MaxHi.begin());
    last = static_cast<vtkIdType>(
      std::lower_bound(this->MinLo.begin(), this->MinLo.end(), pe) - this->MinLo.begin());
  }

  // Whether chunk @a c may have a corner in [pb, pe); whether all its corners are there.
  bool Meets(vtkIdType c, vtkIdType pb, vtkIdType pe) const
  {
    return this->Lo[c] < pe && this->Hi[c] >= pb;
  }
  bool Within(vtkIdType c, vtkIdType pb, vtkIdType pe) const
  {
    return this->Lo[c] >= pb && this->Hi[c] < pe;
  }

  // The polygons that ForCellsTouching reads over the ranges [t S, (t + 1) S) that cover the
  // points, relative to the polygon count (1: each read once).
  double Work(const PolyLinks& mesh, vtkIdType S) const
  {
    double read = 0.0;
    for (size_t c = 0; c < this->Lo.size(); ++c)
    {
      if (this->Lo[c] <= this->Hi[c])
      {
        const vtkIdType b = static_cast<vtkIdType>(c) * Chunk;
        const vtkIdType cells = std::min(mesh.NumCells - b, Chunk);
        read +=
          static_cast<double>(cells) * static_cast<double>(this->Hi[c] / S - this->Lo[c] / S + 1);
      }
    }
    return mesh.NumCells > 0 ? read / static_cast<double>(mesh.NumCells) : 1.0;
  }

  // Build's pass over chunks [c0, c1), in AVX-512 or AVX2 where the processor has it (the least
  // and largest of 64-bit ids vectorise there; the baseline build compares them one by one, about
  // 2.5 times the cycles).
  struct Pass
  {
    const PolyLinks& Mesh;
    CellSpans& Spans;

    void operator()(vtkIdType c0, vtkIdType c1) const
    {
      vtkSurfaceDetailVectorize::RunWidest(*this, c0, c1);
    }

    VTK_ALWAYS_INLINE void Run(vtkIdType c0, vtkIdType c1) const
    {
      const vtkIdType* __restrict conn = this->Mesh.Conn;
      for (vtkIdType c = c0; c < c1; ++c)
      {
        const vtkIdType b = this->Mesh.Offsets[c * Chunk];
        const vtkIdType e = this->Mesh.Offsets[std::min(this->Mesh.NumCells, (c + 1) * Chunk)];
        vtkIdType lo = std::numeric_limits<vtkIdType>::max();
        vtkIdType hi = std::numeric_limits<vtkIdType>::min();
        for (vtkIdType k = b; k < e; ++k)
        {
          lo = std::min(lo, conn[k]);
          hi = std::max(hi, conn[k]);
        }
        this->Spans.Lo[c] = lo;
        this->Spans.Hi[c] = hi;
        const vtkIdType cb = c * Chunk, ce = std::min(this->Mesh.NumCells, cb + Chunk);
        bool triangles = e - b == 3 * (ce - cb);
        if (triangles)
        {
          // An integer OR as the reduction, so that the loop vectorises.
          int other = 0;
          for (vtkIdType cell = cb; cell < ce; ++cell)
          {
            other |= static_cast<int>(this->Mesh.Offsets[cell + 1] - this->Mesh.Offsets[cell] != 3);
          }
          triangles = other == 0;
        }
        this->Spans.Triangles[c] = triangles ? 1 : 0;
      }
    }
  };

  // Builds the spans of @a mesh (one threaded pass over the connectivity). False if a polygon names
  // a point outside [0, numPts) (the spans are then unusable): each chunk's least and largest id
  // tell.
  bool Build(const PolyLinks& mesh, vtkIdType numPts)
  {
    const vtkIdType chunks = (mesh.NumCells + Chunk - 1) / Chunk;
    this->Lo.resize(chunks);
    this->Hi.resize(chunks);
    this->MaxHi.resize(chunks);
    this->MinLo.resize(chunks);
    this->Triangles.resize(chunks);
    vtkSMPTools::For(0, chunks, 64, Pass{ mesh, *this });
    bool inRange = true;
    vtkIdType maxHi = std::numeric_limits<vtkIdType>::min();
    for (vtkIdType c = 0; c < chunks; ++c)
    {
      inRange &= this->Lo[c] > this->Hi[c] || (this->Lo[c] >= 0 && this->Hi[c] < numPts);
      maxHi = std::max(maxHi, this->Hi[c]);
      this->MaxHi[c] = maxHi;
    }
    vtkIdType minLo = std::numeric_limits<vtkIdType>::max();
    for (vtkIdType c = chunks - 1; c >= 0; --c)
    {
      minLo = std::min(minLo, this->Lo[c]);
      this->MinLo[c] = minLo;
    }
    return inRange;
  }
};

// Whether @a id lies in [pb, pb + width).
VTK_ALWAYS_INLINE bool InRange(vtkIdType id, vtkIdType pb, std::uint64_t width)
{
  return static_cast<std::uint64_t>(id - pb) < width;
}

// Whether any of @a ids lies in [pb, pb + width): an OR of the tests, free of branches.
template <typename... Id>
VTK_ALWAYS_INLINE bool AnyInRange(vtkIdType pb, std::uint64_t width, Id... ids)
{
  return (static_cast<int>(InRange(ids, pb, width)) | ...) != 0;
}

// Calls body(cell, end) for every polygon of @a mesh with a corner in [pb, pe), in increasing id
// order (a polygon with several corners there, once). The body returns how many polygons it did
// (more than one: it did the next ones, before @a end, too, whether they touch the range or not).
// A chunk of triangles only goes to body.Triangles(ids, cell, end, within) instead (its corners
// @a ids from polygon @a cell to @a end; @a within: all of them in the range), which does the same
// for that chunk.
template <typename Body>
VTK_ALWAYS_INLINE void ForCellsTouching(
  const PolyLinks& mesh, const CellSpans& spans, vtkIdType pb, vtkIdType pe, Body&& body)
{
  vtkIdType first, last;
  spans.Candidates(pb, pe, first, last);
  const vtkIdType* __restrict offsets = mesh.Offsets;
  const vtkIdType* __restrict conn = mesh.Conn;
  const std::uint64_t width = static_cast<std::uint64_t>(pe - pb);
  for (vtkIdType c = first; c < last; ++c)
  {
    if (!spans.Meets(c, pb, pe))
    {
      continue;
    }
    const vtkIdType cb = c * CellSpans::Chunk;
    const vtkIdType ce = std::min(mesh.NumCells, cb + CellSpans::Chunk);
    if (spans.Triangles[c])
    {
      body.Triangles(conn + offsets[cb], cb, ce, spans.Within(c, pb, pe));
      continue;
    }
    if (spans.Within(c, pb, pe))
    {
      // Every corner inside: every polygon with a corner.
      for (vtkIdType cell = cb; cell < ce;)
      {
        cell += offsets[cell + 1] > offsets[cell] ? body(cell, ce) : 1;
      }
      continue;
    }
    for (vtkIdType cell = cb; cell < ce;)
    {
      const vtkIdType b = offsets[cell], e = offsets[cell + 1];
      bool touches;
      if (e - b == 3)
      {
        touches = InRange(conn[b], pb, width) | InRange(conn[b + 1], pb, width) |
          InRange(conn[b + 2], pb, width);
      }
      else
      {
        touches = false;
        for (vtkIdType k = b; k < e; ++k)
        {
          touches |= InRange(conn[k], pb, width);
        }
      }
      cell += touches ? body(cell, ce) : 1;
    }
  }
}

// NaN becomes 0 and infinity the largest double.
inline double Finite(double x)
{
  if (std::isnan(x))
  {
    return 0.0;
  }
  return std::min(
    std::max(x, -std::numeric_limits<double>::max()), std::numeric_limits<double>::max());
}

// Finite for float lanes: NaN becomes 0 and infinity the largest float.
inline float Finite(float x)
{
  if (std::isnan(x))
  {
    return 0.0f;
  }
  return std::min(
    std::max(x, -std::numeric_limits<float>::max()), std::numeric_limits<float>::max());
}

inline void RemoveNormalPart(const double n[3], double v[3])
{
  const double d = Dot(n, v);
  v[0] -= d * n[0];
  v[1] -= d * n[1];
  v[2] -= d * n[2];
}

// Everything RequestData hands to the threaded passes.
template <typename R>
struct Context
{
  ArrayReader<R>* Points = nullptr;
  ArrayReader<R>* Normals = nullptr;
  ArrayReader<R>* TCoords = nullptr;
  ArrayReader<R>* DPdu = nullptr;
  ArrayReader<R>* DPdv = nullptr;
  ArrayReader<R>* Tangents = nullptr;
  const PolyLinks* Polys = nullptr;
  int Wrap = Repeat;
  int Interpolation = vtkDisplacementMapFilter::Linear;
  int NormalMode = vtkDisplacementMapFilter::Exact;
  double Scale = 1.0;
  double Midlevel = 0.0;
  double DerivativeScale[2] = { 1.0, 1.0 }; // dP/ds = dPdu * [0], dP/dt = dPdv * [1]
  ArrayWriter<R>* OutPoints = nullptr;
  ArrayWriter<R>* OutNormals = nullptr;  // null in None mode
  ArrayWriter<R>* OutTangents = nullptr; // null without input tangents or in None mode
  // Exact mode: per point the unit input normal and the texture coordinate s, four doubles that
  // the fits read as one vector (each point is a neighbour in a dozen fits).
  const double* FitNormals = nullptr;
  // The fitted derivatives, which depend on the input alone: per point FitStride values, P_s and
  // P_t when fitted (no dPdu/dPdv), then n_s and n_t (Exact). Written by pass 1, or (FitsKnown)
  // read instead of fitting again. Kept in R: float arrays' fits go to float lanes (and, rounded
  // the same way, to the double lanes of the points redone), so float halves what re-executions
  // read and changes nothing else; a point whose fits float cannot hold keeps NaN and is fitted
  // again, in double, whenever it is needed (FitDouble).
  R* Fits = nullptr;
  int FitStride = 0;
  bool FitsKnown = false;
  // Where set, the fits' sums are made per range of points through these spans (RangeFitSums), in
  // per-thread records (FitScratch); else they are gathered point by point through the links.
  const CellSpans* Spans = nullptr;
  vtkSMPThreadLocal<std::vector<double>>* FitScratch = nullptr;
};

// The unit input normal, or zero when it has no direction.
template <typename R>
VTK_ALWAYS_INLINE void InputNormal(const Context<R>& c, vtkIdType i, double n[3])
{
  c.Normals->Get3(i, n);
  if (FastNormalize(n) == 0.0 || !std::isfinite(n[0] + n[1] + n[2]))
  {
    n[0] = n[1] = n[2] = 0.0;
  }
}

template <typename R>
inline void WritePoint(const Context<R>& c, vtkIdType i, const double offset[3])
{
  double p[3];
  c.Points->Get3(i, p);
  for (int k = 0; k < 3; ++k)
  {
    // Adding +0 would turn -0 into +0: no displacement leaves the bits alone.
    c.OutPoints->SetClamped(i, k, offset[k] == 0.0 ? p[k] : Finite(p[k] + offset[k]));
  }
}

// Normalises @a m and writes it (the input normal where @a m has no direction).
template <typename R>
VTK_ALWAYS_INLINE void WriteNormal(const Context<R>& c, vtkIdType i, double m[3])
{
  if (FastNormalize(m) == 0.0 || !std::isfinite(m[0] + m[1] + m[2]))
  {
    InputNormal(c, i, m);
    if (m[0] == 0.0 && m[1] == 0.0 && m[2] == 0.0)
    {
      m[2] = 1.0;
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    c.OutNormals->Set(i, k, m[k]);
  }
}

// The tangent re-orthogonalised to the unit normal @a m, its handedness kept.
template <typename R>
VTK_ALWAYS_INLINE void WriteTangent(const Context<R>& c, vtkIdType i, const double m[3])
{
  const int tnc = c.OutTangents->NC;
  double tg[4] = { 0.0, 0.0, 0.0, 1.0 };
  for (int k = 0; k < tnc; ++k)
  {
    tg[k] = c.Tangents->Get(i, k);
  }
  RemoveNormalPart(m, tg);
  if (FastNormalize(tg) == 0.0 || !std::isfinite(tg[0] + tg[1] + tg[2]))
  {
    const double zero[3] = { 0.0, 0.0, 0.0 };
    const double w = tg[3];
    MakeTangentFrame(m, zero, zero, tg);
    tg[3] = w;
  }
  for (int k = 0; k < tnc; ++k)
  {
    c.OutTangents->Set(i, k, tg[k]);
  }
}

template <typename R>
VTK_ALWAYS_INLINE void WriteNormalAndTangent(const Context<R>& c, vtkIdType i, double m[3])
{
  WriteNormal(c, i, m);
  if (c.OutTangents)
  {
    WriteTangent(c, i, m);
  }
}

#if defined(__GNUC__)
// Four doubles, one AVX register in the AVX2 build (two SSE2 ones in the baseline build). Each
// operation is four lane-wise IEEE ones, so the bits are those of the scalar operations.
using Double4 = double __attribute__((vector_size(4 * sizeof(double))));
#else
struct Double4
{
  double V[4];
  double operator[](int q) const { return this->V[q]; }
  Double4& operator+=(const Double4& a)
  {
    for (int q = 0; q < 4; ++q)
    {
      this->V[q] += a.V[q];
    }
    return *this;
  }
  Double4& operator-=(const Double4& a)
  {
    for (int q = 0; q < 4; ++q)
    {
      this->V[q] -= a.V[q];
    }
    return *this;
  }
};
inline Double4 operator*(double x, const Double4& a)
{
  return { { x * a.V[0], x * a.V[1], x * a.V[2], x * a.V[3] } };
}
#endif

// One neighbour's terms in the sums of a fit: @a g is (f_j, s_j) and @a own (f_i, s_i), so that
// @a f = (df, ds) and its four lanes add ds df and, last, ds^2 to @a bs, dt df and dt ds to @a bt.
VTK_ALWAYS_INLINE void AddNeighbour(
  const double g[4], const Double4& own, double dt, Double4& bs, Double4& bt, Double4& f)
{
  std::memcpy(&f, g, sizeof(f));
  f -= own;
  bs += f[3] * f;
  bt += dt * f;
}

// The sums of the least-squares fit of the derivatives of a vector field f in (s,t) at point @a i,
// which minimises sum |f_j - f_i - f_s ds - f_t dt|^2 over the point's neighbours j in its
// polygons: per field (@a p for P when WantP, @a n for the unit normal when WantN) sum ds df,
// sum ds^2, sum dt df, sum dt ds (AddNeighbour's lanes), and @a dt2 = sum dt^2. A neighbour counts
// once per polygon it shares with the point (every occurrence is added as it comes: no sorting or
// merging). @a near and @a far are the least and largest squared distances to a neighbour (WantP).
template <bool WantP, bool WantN, typename R>
VTK_ALWAYS_INLINE void FitSums(const Context<R>& c, vtkIdType i, double p[8], double n[8],
  double& dt2, double& near, double& far)
{
  const PolyLinks& mesh = *c.Polys;
  const R* tc = c.TCoords->P;
  const vtkIdType tnc = c.TCoords->NC;
  const R* points = c.Points->P;
  const double* normals = c.FitNormals;
  const double t = tc[tnc * i + 1];
  Double4 ownP = {}, ownN = {};
  if (WantP)
  {
    const double own[4] = { static_cast<double>(points[3 * i]),
      static_cast<double>(points[3 * i + 1]), static_cast<double>(points[3 * i + 2]),
      static_cast<double>(tc[tnc * i]) };
    std::memcpy(&ownP, own, sizeof(ownP));
  }
  if (WantN)
  {
    std::memcpy(&ownN, normals + 4 * i, sizeof(ownN));
  }
  Double4 bsP = {}, btP = {}, bsN = {}, btN = {};
  double sumDt2 = 0.0;
  double minD2 = std::numeric_limits<double>::max(), maxD2 = 0.0;
  for (vtkIdType l = mesh.LinkOffsets[i]; l < mesh.LinkOffsets[i + 1]; ++l)
  {
    const vtkIdType cell = mesh.Links[l];
    for (vtkIdType corner = mesh.Offsets[cell]; corner < mesh.Offsets[cell + 1]; ++corner)
    {
      const vtkIdType j = mesh.Conn[corner];
      if (j == i)
      {
        continue;
      }
      const double dt = tc[tnc * j + 1] - t;
      sumDt2 += dt * dt;
      Double4 f;
      if (WantP)
      {
        const double g[4] = { static_cast<double>(points[3 * j]),
          static_cast<double>(points[3 * j + 1]), static_cast<double>(points[3 * j + 2]),
          static_cast<double>(tc[tnc * j]) };
        AddNeighbour(g, ownP, dt, bsP, btP, f);
        const double d2 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
        minD2 = std::min(minD2, d2);
        maxD2 = std::max(maxD2, d2);
      }
      if (WantN)
      {
        AddNeighbour(normals + 4 * j, ownN, dt, bsN, btN, f);
      }
    }
  }
  std::memcpy(p, &bsP, sizeof(bsP));
  std::memcpy(p + 4, &btP, sizeof(btP));
  std::memcpy(n, &bsN, sizeof(bsN));
  std::memcpy(n + 4, &btN, sizeof(btN));
  dt2 = sumDt2;
  near = minD2;
  far = maxD2;
}

// FitSums's sums for a range of points at once, without links. FitSums adds, for point i, the
// terms of every (polygon, neighbour j) occurrence in increasing polygon order and, within a
// polygon, corner order. The terms of (i, j) and of (j, i) are the same bits (the differences and
// dt only change sign, and each term is a product of two of them), so a polygon's pair terms are
// made once and added to both corners. Visiting the polygons that touch the range in increasing
// id order (ForCellsTouching) and adding each corner's terms in corner order gives every point of
// the range FitSums's additions in FitSums's order: the same bits, and half its products.
//
// The sums of a point make one record of Size doubles: (WantP) P's bs[4], bt[4] and the least and
// largest squared distance; (WantN) the normal's bs[4], bt[4]; last the sum of dt^2.
template <bool WantP, bool WantN>
struct FitRecord
{
  static constexpr int P = 0;
  static constexpr int Near = 8;
  static constexpr int Far = 9;
  static constexpr int N = WantP ? 10 : 0;
  static constexpr int Dt2 = N + (WantN ? 8 : 0);
  static constexpr int Size = Dt2 + 1;
};

// Doubles per FitRecord.
inline int FitRecordSize(bool wantP, bool wantN)
{
  return (wantP ? 10 : 0) + (wantN ? 8 : 0) + 1;
}

// ForCellsTouching's body: adds each polygon's terms to the records of its corners in
// [First, First + Width) (@a Sums holds First's record, then the next points').
template <bool WantP, bool WantN, typename R>
struct AddFitTerms
{
  using Rec = FitRecord<WantP, WantN>;
  const vtkIdType* Offsets;
  const vtkIdType* Conn;
  const R* Points;
  const R* TC;
  vtkIdType TNC;
  const double* Normals;
  double* Sums;
  vtkIdType First;
  std::uint64_t Width;

  // Neighbour j's terms in point i's sums, FitSums's operations.
  struct Terms
  {
    Double4 BsP, BtP, BsN, BtN;
    double Dt2, D2;
  };

  VTK_ALWAYS_INLINE void Make(vtkIdType i, vtkIdType j, Terms& u) const
  {
    const R* tc = this->TC;
    const vtkIdType tnc = this->TNC;
    const double dt = static_cast<double>(tc[tnc * j + 1]) - static_cast<double>(tc[tnc * i + 1]);
    u.Dt2 = dt * dt;
    if (WantP)
    {
      const R* points = this->Points;
      const double gi[4] = { static_cast<double>(points[3 * i]),
        static_cast<double>(points[3 * i + 1]), static_cast<double>(points[3 * i + 2]),
        static_cast<double>(tc[tnc * i]) };
      const double gj[4] = { static_cast<double>(points[3 * j]),
        static_cast<double>(points[3 * j + 1]), static_cast<double>(points[3 * j + 2]),
        static_cast<double>(tc[tnc * j]) };
      Double4 f, own;
      std::memcpy(&f, gj, sizeof(f));
      std::memcpy(&own, gi, sizeof(own));
      f -= own;
      u.BsP = f[3] * f;
      u.BtP = dt * f;
      u.D2 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
    }
    if (WantN)
    {
      Double4 f, own;
      std::memcpy(&f, this->Normals + 4 * j, sizeof(f));
      std::memcpy(&own, this->Normals + 4 * i, sizeof(own));
      f -= own;
      u.BsN = f[3] * f;
      u.BtN = dt * f;
    }
  }

  // Each of @a terms added to record @a r in turn, the record read and written once.
  template <typename... T>
  static VTK_ALWAYS_INLINE void AddAll(double* r, const T&... terms)
  {
    auto add = [](double* sum, const auto&... v)
    {
      Double4 x;
      std::memcpy(&x, sum, sizeof(x));
      ((x += v), ...);
      std::memcpy(sum, &x, sizeof(x));
    };
    if (WantP)
    {
      add(r + Rec::P, terms.BsP...);
      add(r + Rec::P + 4, terms.BtP...);
      double near = r[Rec::Near], far = r[Rec::Far];
      ((near = std::min(near, terms.D2)), ...);
      ((far = std::max(far, terms.D2)), ...);
      r[Rec::Near] = near;
      r[Rec::Far] = far;
    }
    if (WantN)
    {
      add(r + Rec::N, terms.BsN...);
      add(r + Rec::N + 4, terms.BtN...);
    }
    double dt2 = r[Rec::Dt2];
    ((dt2 += terms.Dt2), ...);
    r[Rec::Dt2] = dt2;
  }

  // What Make fills of @a from, copied to @a to.
  static VTK_ALWAYS_INLINE void Keep(const Terms& from, Terms& to)
  {
    to.Dt2 = from.Dt2;
    if (WantP)
    {
      to.BsP = from.BsP;
      to.BtP = from.BtP;
      to.D2 = from.D2;
    }
    if (WantN)
    {
      to.BsN = from.BsN;
      to.BtN = from.BtN;
    }
  }

  // The fan pair (i0, i1, i2), (i0, i2, i3) of four distinct points, given its pairs' terms but
  // (i2, i3)'s: each record of a shared corner read and written once.
  VTK_ALWAYS_INLINE void AddPair(vtkIdType i0, vtkIdType i1, vtkIdType i2, vtkIdType i3,
    const Terms& u01, const Terms& u02, const Terms& u12, const Terms& u03) const
  {
    const std::uint64_t k0 = static_cast<std::uint64_t>(i0 - this->First);
    const std::uint64_t k1 = static_cast<std::uint64_t>(i1 - this->First);
    const std::uint64_t k2 = static_cast<std::uint64_t>(i2 - this->First);
    const std::uint64_t k3 = static_cast<std::uint64_t>(i3 - this->First);
    Terms u23;
    this->Make(i2, i3, u23);
    if (k0 < this->Width)
    {
      AddAll(this->Sums + Rec::Size * k0, u01, u02, u02, u03);
    }
    if (k1 < this->Width)
    {
      AddAll(this->Sums + Rec::Size * k1, u01, u12);
    }
    if (k2 < this->Width)
    {
      AddAll(this->Sums + Rec::Size * k2, u02, u12, u02, u23);
    }
    if (k3 < this->Width)
    {
      AddAll(this->Sums + Rec::Size * k3, u03, u23);
    }
  }

  // ForCellsTouching's walk over a chunk of triangles only: as operator() for each triangle that
  // touches the range, without reading the offsets, and a fan pair of distinct points at once
  // wherever one of its four corners does (a point's additions do not depend on how the polygons
  // are grouped). Where one pair (a, b, d), (a, d, c) follows another along a row, (b, b', d'),
  // (b, d', d), the first's (b, d) terms are the second's (a, c) ones: made once.
  VTK_ALWAYS_INLINE void Triangles(
    const vtkIdType* ids, vtkIdType cell, vtkIdType end, bool within) const
  {
    Terms carried{};
    vtkIdType carriedI = -1, carriedJ = -1;
    while (cell < end)
    {
      const vtkIdType i0 = ids[0], i1 = ids[1], i2 = ids[2];
      const bool touches = within || AnyInRange(this->First, this->Width, i0, i1, i2);
      if (cell + 1 < end && ((ids[3] == i0) & (ids[4] == i2)))
      {
        const vtkIdType i3 = ids[5];
        if (!touches && !InRange(i3, this->First, this->Width))
        {
          cell += 2;
          ids += 6;
          continue;
        }
        if ((i0 != i1) & (i0 != i2) & (i1 != i2) & (i3 != i0) & (i3 != i1) & (i3 != i2))
        {
          Terms u01, u02, u12, u03;
          this->Make(i0, i1, u01);
          this->Make(i0, i2, u02);
          this->Make(i1, i2, u12);
          if ((i0 == carriedI) & (i3 == carriedJ))
          {
            Keep(carried, u03);
          }
          else
          {
            this->Make(i0, i3, u03);
          }
          this->AddPair(i0, i1, i2, i3, u01, u02, u12, u03);
          Keep(u12, carried);
          carriedI = i1;
          carriedJ = i2;
          cell += 2;
          ids += 6;
          continue;
        }
      }
      const vtkIdType done = touches ? (*this)(cell, end) : 1;
      cell += done;
      ids += 3 * done;
    }
  }

  // Adds polygon @a cell's terms, or those of @a cell and the next one (before @a end) where they
  // are a fan's two triangles (a, b, d), (a, d, c), as quads split into triangles are: their
  // shared pair's terms made once, and each record of a shared corner read and written once (the
  // same additions in the same order). Returns the number of polygons done.
  VTK_ALWAYS_INLINE vtkIdType operator()(vtkIdType cell, vtkIdType end) const
  {
    const vtkIdType b = this->Offsets[cell], n = this->Offsets[cell + 1] - b;
    const vtkIdType* ids = this->Conn + b;
    if (n == 3)
    {
      // A triangle of three distinct points (the usual case): three pairs, each corner in the
      // range given its two.
      const vtkIdType i0 = ids[0], i1 = ids[1], i2 = ids[2];
      if ((i0 != i1) & (i0 != i2) & (i1 != i2))
      {
        const std::uint64_t k0 = static_cast<std::uint64_t>(i0 - this->First);
        const std::uint64_t k1 = static_cast<std::uint64_t>(i1 - this->First);
        const std::uint64_t k2 = static_cast<std::uint64_t>(i2 - this->First);
        Terms u01, u02, u12;
        this->Make(i0, i1, u01);
        this->Make(i0, i2, u02);
        this->Make(i1, i2, u12);
        if (cell + 1 < end && this->Offsets[cell + 2] - this->Offsets[cell + 1] == 3)
        {
          // The next triangle (i0, i2, i3): its pair (i0, i2) is this one's.
          const vtkIdType* next = this->Conn + this->Offsets[cell + 1];
          const vtkIdType i3 = next[2];
          if ((next[0] == i0) & (next[1] == i2) & (i3 != i0) & (i3 != i1) & (i3 != i2))
          {
            Terms u03;
            this->Make(i0, i3, u03);
            this->AddPair(i0, i1, i2, i3, u01, u02, u12, u03);
            return 2;
          }
        }
        if (k0 < this->Width)
        {
          AddAll(this->Sums + Rec::Size * k0, u01, u02);
        }
        if (k1 < this->Width)
        {
          AddAll(this->Sums + Rec::Size * k1, u01, u12);
        }
        if (k2 < this->Width)
        {
          AddAll(this->Sums + Rec::Size * k2, u02, u12);
        }
        return 1;
      }
    }
    // Any polygon: each corner in the range (a point named twice, twice, as its links list the
    // polygon twice), its neighbours in corner order.
    for (vtkIdType a = 0; a < n; ++a)
    {
      const vtkIdType i = ids[a];
      const std::uint64_t k = static_cast<std::uint64_t>(i - this->First);
      if (k >= this->Width)
      {
        continue;
      }
      double* r = this->Sums + Rec::Size * k;
      for (vtkIdType q = 0; q < n; ++q)
      {
        const vtkIdType j = ids[q];
        if (j != i)
        {
          Terms u;
          this->Make(i, j, u);
          AddAll(r, u);
        }
      }
    }
    return 1;
  }
};

// FitSums's sums for the points [pb, pe), into their records from @a sums on.
template <bool WantP, bool WantN, typename R>
VTK_ALWAYS_INLINE void RangeFitSums(const Context<R>& c, vtkIdType pb, vtkIdType pe, double* sums)
{
  using Rec = FitRecord<WantP, WantN>;
  for (vtkIdType k = 0; k < pe - pb; ++k)
  {
    double* r = sums + Rec::Size * k;
    std::fill_n(r, Rec::Size, 0.0);
    if (WantP)
    {
      r[Rec::Near] = std::numeric_limits<double>::max();
    }
  }
  const AddFitTerms<WantP, WantN, R> add{ c.Polys->Offsets, c.Polys->Conn, c.Points->P,
    c.TCoords->P, c.TCoords->NC, c.FitNormals, sums, pb, static_cast<std::uint64_t>(pe - pb) };
  ForCellsTouching(*c.Polys, *c.Spans, pb, pe, add);
}

// RangeFitSums for one point (a point whose kept fits float could not hold, fitted again), out of
// line: one copy, whichever build of pass 1 calls it (the bits are the same in each).
template <bool WantP, bool WantN, typename R>
void PointFitSumsThroughSpans(const Context<R>& c, vtkIdType i, double* record)
{
  RangeFitSums<WantP, WantN>(c, i, i + 1, record);
}

// The displacement d at point @a i, with the height h and its derivatives in (s,t); one
// function so that the seam pass sees the very values of pass 1.
template <int Interp, typename T, typename R>
VTK_ALWAYS_INLINE double Displacement(
  const Context<R>& c, const Texels<T>& tex, vtkIdType i, double& h, double& hs, double& ht)
{
  SampleHeight<Interp>(tex, c.Wrap, c.TCoords->Get(i, 0), c.TCoords->Get(i, 1), h, hs, ht);
  // An absurd Scale may overflow: keep every quantity finite so that no NaN comes out.
  return Finite(c.Scale * (h - c.Midlevel));
}

// |x| at most the largest double: false for infinities and NaN, as std::isfinite, but a plain
// compare that vectorises.
inline bool IsFinite(double x)
{
  return std::abs(x) <= std::numeric_limits<double>::max();
}

inline bool IsFinite(float x)
{
  return std::abs(x) <= std::numeric_limits<float>::max();
}

// FastNormalize and its check for one lane of a block, free of branches so that block loops
// vectorise (bitwise & rather than a short circuit, which GCC splits the loop on): x, y, z
// scaled to unit length where their length is positive and finite, else left as they are;
// true where the result is usable (a non-zero length and a finite sum), as FastNormalize's
// callers test.
VTK_ALWAYS_INLINE bool UnitLane(double& x, double& y, double& z)
{
  const double len = std::sqrt(x * x + y * y + z * z);
  const double inv = 1.0 / len;
  const bool scale = (len > 0.0) & IsFinite(len);
  x = scale ? x * inv : x;
  y = scale ? y * inv : y;
  z = scale ? z * inv : z;
  return (len != 0.0) & IsFinite(x + y + z);
}

// A double narrowed to R (an output value, or a float lane's input): for float, beyond float's
// range the largest float (converting an out-of-range double to float is undefined in C++;
// the float lanes flag such points and redo them in double).
template <typename R>
inline R ToReal(double v)
{
  if (std::is_same<R, float>::value)
  {
    constexpr double big = std::numeric_limits<float>::max();
    v = std::min(std::max(v, -big), big);
  }
  return static_cast<R>(v);
}

// Marks four values as changed by an empty asm statement: a loop that reads texels at computed
// positions stays scalar, which GCC would otherwise vectorise with one insert per value (slower
// than plain loads: emulated gathers).
VTK_ALWAYS_INLINE void KeepScalar([[maybe_unused]] double& a, [[maybe_unused]] double& b,
  [[maybe_unused]] double& c, [[maybe_unused]] double& d)
{
#if defined(__GNUC__) && defined(__SSE2__)
  asm("" : "+x"(a), "+x"(b), "+x"(c), "+x"(d));
#endif
}

// The block loops are also compiled for AVX2 and that copy runs where the processor has it
// (vtkSurfaceDetailVectorize::RunWidest: the same bits either way).

// Software prefetching: asks for the cache lines of [p, p + bytes) ahead of their use (Write:
// to be written, so also taken exclusive). The passes stream a dozen arrays at once, which the
// hardware prefetchers of the machine measured did not follow: asking for the next block's lines
// took about a third off pass 1's cycles (BENCHMARKS.md). A hint only: no fault, no effect on
// results.
template <bool Write>
VTK_ALWAYS_INLINE void PrefetchBytes([[maybe_unused]] const void* p, [[maybe_unused]] size_t bytes)
{
#if defined(__GNUC__)
  // From the line that holds p on, so that the last line is not left out.
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(p) + bytes;
  for (std::uintptr_t q = reinterpret_cast<std::uintptr_t>(p) & ~std::uintptr_t(63); q < end;
       q += 64)
  {
    __builtin_prefetch(reinterpret_cast<const void*>(q), Write ? 1 : 0, 3);
  }
#endif
}

// Squared lengths that float lanes take as they come: within them a float vector's length, its
// inverse and the unit vector keep float's relative precision (no overflow, no subnormals).
constexpr float FloatLength2Min = 0x1p-100f;
constexpr float FloatLength2Max = 0x1p100f;

// UnitLane for float lanes: scales x, y, z to unit length and tells whether the squared length
// was within [FloatLength2Min, FloatLength2Max] (false for NaN and infinities too).
VTK_ALWAYS_INLINE bool UnitLaneFloat(float& x, float& y, float& z)
{
  const float len2 = x * x + y * y + z * z;
  const float inv = 1.0f / std::sqrt(len2);
  x *= inv;
  y *= inv;
  z *= inv;
  return (len2 >= FloatLength2Min) & (len2 <= FloatLength2Max);
}

// The per-block steps that pass 1 and Mesh's point normals share: points in blocks of Block,
// held as structure of arrays in lanes of L.
//
// Double lanes (L = double, the only kind for double arrays) keep the operations of the per-point
// helpers above, so their results are those helpers' to the bit. Float lanes (L = float, for
// float arrays) hold twice as many values per vector: the inputs and outputs have float's
// precision anyway, and what needs more stays in double (texture coordinates and height samples,
// whose texel positions in a big map need more than float's 24 bits; the fits' sums, which
// cancel; Mesh's polygon normals). Float's range and precision are short for some points: the
// steps flag them (Flags: a value beyond 2^32, a length outside [2^-50, 2^50], derivatives within
// 0.6 degrees of parallel, a tangent or a new normal that mostly cancels), and the workers redo
// those points, one by one, with double lanes. Every flag depends on the point alone, so that
// the results never depend on the blocks (on the threads).
template <typename R, typename L = R>
struct BlockOps
{
  static constexpr int Block = 64;
  static constexpr bool Float = std::is_same<L, float>::value;
  using Lanes = L[Block];
  using Flags = int[Block];
  const Context<R>& C;

  // Interleaved values of R to lanes, and back (for R float from double lanes, clamped to
  // float's range; float lanes are finite).
  template <int NC>
  static VTK_ALWAYS_INLINE void Gather(const R* in, int count, Lanes* lanes)
  {
    for (int k = 0; k < count; ++k)
    {
      for (int j = 0; j < NC; ++j)
      {
        lanes[j][k] = static_cast<L>(in[NC * k + j]);
      }
    }
  }

  template <int NC>
  static VTK_ALWAYS_INLINE void Scatter(const Lanes* lanes, int count, R* out)
  {
    for (int k = 0; k < count; ++k)
    {
      for (int j = 0; j < NC; ++j)
      {
        if constexpr (Float)
        {
          out[NC * k + j] = lanes[j][k];
        }
        else
        {
          out[NC * k + j] = ToReal<R>(lanes[j][k]);
        }
      }
    }
  }

  // InputNormal for the block, and WriteNormal's fallback: that normal, or +z where it has none.
  // Float lanes: sets @a redo (the first step of a block).
  VTK_ALWAYS_INLINE void UnitNormals(
    vtkIdType first, int count, Lanes n[3], Lanes fallback[3], [[maybe_unused]] Flags redo) const
  {
    Gather<3>(this->C.Normals->P + 3 * first, count, n);
    for (int k = 0; k < count; ++k)
    {
      // No re-read of what the loop stored: GCC would re-read masked stores (a
      // store-forwarding stall per block).
      L sx = n[0][k], sy = n[1][k], sz = n[2][k];
      bool keep;
      if constexpr (Float)
      {
        keep = UnitLaneFloat(sx, sy, sz);
        redo[k] = !keep;
      }
      else
      {
        keep = UnitLane(sx, sy, sz);
      }
      const L ux = keep ? sx : L(0), uy = keep ? sy : L(0);
      n[0][k] = ux;
      n[1][k] = uy;
      n[2][k] = keep ? sz : L(0);
      fallback[0][k] = ux;
      fallback[1][k] = uy;
      fallback[2][k] = keep ? sz : L(1);
    }
  }

  // WriteNormal for the block: normalises m in place and writes it. Float lanes flag where the
  // length is out of range or, when it came from a sum of a unit vector and others, below
  // @a minLength2 (the sum mostly cancelled, and lost float's relative precision).
  VTK_ALWAYS_INLINE void Normals(vtkIdType first, int count, const Lanes fallback[3], Lanes m[3],
    [[maybe_unused]] Flags redo, [[maybe_unused]] float minLength2 = 0.0f) const
  {
    for (int k = 0; k < count; ++k)
    {
      L sx = m[0][k], sy = m[1][k], sz = m[2][k];
      bool keep;
      if constexpr (Float)
      {
        const float len2 = sx * sx + sy * sy + sz * sz;
        keep = UnitLaneFloat(sx, sy, sz);
        redo[k] |= !keep | (len2 < minLength2);
      }
      else
      {
        keep = UnitLane(sx, sy, sz);
      }
      m[0][k] = keep ? sx : fallback[0][k];
      m[1][k] = keep ? sy : fallback[1][k];
      m[2][k] = keep ? sz : fallback[2][k];
    }
    // Unit vectors: static_cast as WriteNormal, no range to clamp.
    R* out = this->C.OutNormals->P + 3 * first;
    for (int k = 0; k < count; ++k)
    {
      for (int j = 0; j < 3; ++j)
      {
        out[3 * k + j] = static_cast<R>(m[j][k]);
      }
    }
  }

  // The block's output tangents, if the output has them (3 or 4 components; @a t is scratch).
  VTK_ALWAYS_INLINE void OutputTangents(
    vtkIdType first, int count, const Lanes m[3], Lanes t[4], Flags redo) const
  {
    if (this->C.OutTangents && this->C.OutTangents->NC == 4)
    {
      this->template Tangents<4>(first, count, m, t, redo);
    }
    else if (this->C.OutTangents)
    {
      this->template Tangents<3>(first, count, m, t, redo);
    }
  }

  // WriteTangent for the block (@a t is scratch). Double lanes: a block with a tangent left
  // without direction is redone by WriteTangent itself (same results for the others). Float
  // lanes: flags a tangent that is out of range or lies within 0.6 degrees of the normal (its
  // part across the normal would keep too few bits).
  template <int NC>
  VTK_ALWAYS_INLINE void Tangents(
    vtkIdType first, int count, const Lanes m[3], Lanes t[4], [[maybe_unused]] Flags redo) const
  {
    const Context<R>& c = this->C;
    Gather<NC>(c.Tangents->P + NC * first, count, t);
    // An integer OR as the reduction (a max of doubles would keep the loop scalar).
    int bad = 0;
    for (int k = 0; k < count; ++k)
    {
      L x = t[0][k], y = t[1][k], z = t[2][k];
      const L along = m[0][k] * x + m[1][k] * y + m[2][k] * z;
      if constexpr (Float)
      {
        const float before2 = x * x + y * y + z * z;
        x -= along * m[0][k];
        y -= along * m[1][k];
        z -= along * m[2][k];
        const float len2 = x * x + y * y + z * z;
        const bool keep = UnitLaneFloat(x, y, z);
        redo[k] |= !keep | !(len2 > 1e-4f * before2);
        t[0][k] = x;
        t[1][k] = y;
        t[2][k] = z;
      }
      else
      {
        x -= along * m[0][k];
        y -= along * m[1][k];
        z -= along * m[2][k];
        const double len = std::sqrt(x * x + y * y + z * z);
        const double inv = 1.0 / len;
        const bool scale = (len > 0.0) & IsFinite(len);
        const double sx = scale ? x * inv : x, sy = scale ? y * inv : y, sz = scale ? z * inv : z;
        bad |= static_cast<int>((len == 0.0) | !IsFinite(sx + sy + sz));
        t[0][k] = sx;
        t[1][k] = sy;
        t[2][k] = sz;
      }
    }
    R* out = c.OutTangents->P + NC * first;
    for (int k = 0; k < count; ++k)
    {
      for (int j = 0; j < NC; ++j)
      {
        out[NC * k + j] = static_cast<R>(t[j][k]);
      }
    }
    if (!bad)
    {
      return;
    }
    for (int k = 0; k < count; ++k)
    {
      const double mk[3] = { m[0][k], m[1][k], m[2][k] };
      WriteTangent(c, first + k, mk);
    }
  }

  // PrefetchBytes for @a count tuples of an ArrayReader or ArrayWriter (none if null) from @a
  // first.
  template <bool Write, typename A>
  static VTK_ALWAYS_INLINE void PrefetchTuples(const A* a, vtkIdType first, int count)
  {
    if (a)
    {
      PrefetchBytes<Write>(a->P + first * a->NC, sizeof(R) * a->NC * count);
    }
  }

  // Whether any point of the block is flagged.
  static VTK_ALWAYS_INLINE bool Any(int count, const Flags redo)
  {
    int any = 0;
    for (int k = 0; k < count; ++k)
    {
      any |= redo[k];
    }
    return any != 0;
  }
};

// Pass 1: displacement, and the analytic normals (Approximate, Exact). The points go in blocks
// held as structure of arrays: the height samples and the fits (gathers) run point by point,
// everything else in short branch-free loops over the block that the compiler vectorises; the
// rare points that need a fallback (a tangent with no direction left) are redone afterwards
// with the general code. With double lanes each loop keeps the operations and their order of
// the per-point helpers above (InputNormal, WritePoint, WriteNormal, WriteTangent), so the
// results are theirs to the bit; with float lanes (float arrays) the points they flag are redone
// with double lanes (BlockOps).
template <int Interp, typename T, typename R, typename L = R>
struct DisplaceWorker : BlockOps<R, L>
{
  using Base = BlockOps<R, L>;
  using Base::Block;
  using Base::Float;
  using typename Base::Flags;
  using typename Base::Lanes;
  using DoubleLanes = double[Block];
  const Texels<T>& Tex;
  // A float lanes' point redone in double lanes (this worker's [begin, end)): the fit sums of the
  // points from SumsFirst on, made by the float lanes' task (null: none were made).
  const double* Sums = nullptr;
  vtkIdType SumsFirst = 0;

  // Points per range of RangeFitSums, at most: pass 1's tasks (Grain), so that a task's polygons
  // are read once but those around its ends (about two rows of a usual mesh, read by both tasks).
  // 8192 and 4096 were no faster (their records stay in cache, but more ends are read twice).
  static constexpr vtkIdType FitSlice = 16384;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    vtkSurfaceDetailVectorize::RunWidest(*this, begin, end);
  }

  // Everything it calls for the block is inlined into it, so that the AVX2 build compiles
  // it all.
  VTK_ALWAYS_INLINE void Run(vtkIdType begin, vtkIdType end) const
  {
    const Context<R>& c = this->C;
    const bool exact = c.NormalMode == vtkDisplacementMapFilter::Exact;
    const bool wantP = !c.DPdu;
    const bool fits = (exact || (wantP && c.NormalMode == vtkDisplacementMapFilter::Approximate));
    const int size = FitRecordSize(wantP, exact);
    // The fits' sums of each range, then its blocks, which read them (one call of Blocks, which
    // is inlined: each instruction set's build holds one copy).
    const bool ranges = !this->Sums && c.Spans && fits && !c.FitsKnown;
    const vtkIdType slice = ranges ? FitSlice : end - begin;
    std::vector<double>* sums = ranges ? &c.FitScratch->Local() : nullptr;
    if (sums)
    {
      sums->resize(static_cast<size_t>(size) * slice);
    }
    for (vtkIdType sb = begin; sb < end; sb += slice)
    {
      const vtkIdType se = std::min(end, sb + slice);
      const double* blockSums =
        this->Sums ? this->Sums + size * (begin - this->SumsFirst) : nullptr;
      if (ranges)
      {
        if (wantP && exact)
        {
          RangeFitSums<true, true>(c, sb, se, sums->data());
        }
        else if (wantP)
        {
          RangeFitSums<true, false>(c, sb, se, sums->data());
        }
        else
        {
          RangeFitSums<false, true>(c, sb, se, sums->data());
        }
        blockSums = sums->data();
      }
      this->Blocks(sb, se, blockSums);
    }
  }

  // Pass 1 over the points [begin, end) in blocks; @a sums holds the fits' sums from begin's
  // record on, or is null (then the fits gather them, or read kept fits).
  VTK_ALWAYS_INLINE void Blocks(vtkIdType begin, vtkIdType end, const double* sums) const
  {
    const Context<R>& c = this->C;
    const bool analytic = c.NormalMode == vtkDisplacementMapFilter::Approximate ||
      c.NormalMode == vtkDisplacementMapFilter::Exact;
    const bool exact = c.NormalMode == vtkDisplacementMapFilter::Exact;
    const int size = FitRecordSize(!c.DPdu, exact);
    alignas(64) Lanes n[3], fallback[3], d, ds, dt, ps[3], pt[3], ns[3], nt[3], m[3], x[4];
    alignas(64) Flags redo;
    for (vtkIdType first = begin; first < end; first += Block)
    {
      const int count = static_cast<int>(std::min<vtkIdType>(end - first, Block));
      if (first + Block < end)
      {
        this->PrefetchBlock(first + Block, end, analytic);
      }
      const double* blockSums = sums ? sums + size * (first - begin) : nullptr;
      if (sums && first + Block < end)
      {
        PrefetchBytes<false>(blockSums + size * Block,
          sizeof(double) * size * std::min<vtkIdType>(end - first - Block, Block));
      }
      this->UnitNormals(first, count, n, fallback, redo);
      this->Heights(first, count, d, ds, dt, redo);
      this->Points(first, count, n, d, x);
      if (analytic)
      {
        this->Derivatives(first, count, exact, ps, pt, ns, nt, redo, blockSums);
        if (exact)
        {
          this->template Directions<true>(count, n, d, ds, dt, ps, pt, ns, nt, m, redo);
        }
        else
        {
          this->template Directions<false>(count, n, d, ds, dt, ps, pt, ns, nt, m, redo);
        }
        // Exact's new normal is n plus a change: one much shorter than n cancelled it.
        this->Normals(first, count, fallback, m, redo, exact ? 1e-4f : 0.0f);
        this->OutputTangents(first, count, m, x, redo);
      }
      if constexpr (Float)
      {
        if (Base::Any(count, redo))
        {
          const DisplaceWorker<Interp, T, R, double> again{ { c }, this->Tex, blockSums, first };
          for (int k = 0; k < count; ++k)
          {
            if (redo[k])
            {
              again(first + k, first + k + 1);
            }
          }
        }
      }
    }
  }

  // The lines of the arrays that the block from @a next reads and writes (not the texels, nor
  // the neighbours that a fit reads).
  VTK_ALWAYS_INLINE void PrefetchBlock(vtkIdType next, vtkIdType end, bool analytic) const
  {
    const Context<R>& c = this->C;
    const int count = static_cast<int>(std::min<vtkIdType>(end - next, Block));
    Base::template PrefetchTuples<false>(c.Normals, next, count);
    Base::template PrefetchTuples<false>(c.TCoords, next, count);
    Base::template PrefetchTuples<false>(c.Points, next, count);
    Base::template PrefetchTuples<true>(c.OutPoints, next, count);
    if (!analytic)
    {
      return;
    }
    if (c.Fits)
    {
      const R* kept = c.Fits + static_cast<vtkIdType>(c.FitStride) * next;
      const size_t bytes = sizeof(R) * c.FitStride * count;
      if (c.FitsKnown)
      {
        PrefetchBytes<false>(kept, bytes);
      }
      else
      {
        PrefetchBytes<true>(kept, bytes);
      }
    }
    Base::template PrefetchTuples<false>(c.DPdu, next, count);
    Base::template PrefetchTuples<false>(c.DPdv, next, count);
    Base::template PrefetchTuples<false>(c.Tangents, next, count);
    Base::template PrefetchTuples<true>(c.OutNormals, next, count);
    Base::template PrefetchTuples<true>(c.OutTangents, next, count);
  }

  // The displacement and its derivatives in (s,t), sampled and scaled in double (float lanes:
  // then rounded to float, and flagged beyond 2^32, where products of them and the derivatives
  // could leave float's range).
  VTK_ALWAYS_INLINE void Heights(
    vtkIdType first, int count, Lanes d, Lanes ds, Lanes dt, [[maybe_unused]] Flags redo) const
  {
    const Context<R>& c = this->C;
    if constexpr (Float)
    {
      alignas(64) DoubleLanes h, hs, ht;
      this->Samples(first, count, h, hs, ht);
      // Finite and ToReal<float> with fewer operations: a point with a value beyond 2^32 is redone
      // (its lanes only need to stay finite); below, both leave the value as it is, and NaN
      // becomes 0.
      for (int k = 0; k < count; ++k)
      {
        const double dk = c.Scale * (h[k] - c.Midlevel);
        const double dsk = c.Scale * hs[k];
        const double dtk = c.Scale * ht[k];
        const bool big =
          (std::abs(dk) > 0x1p32) | (std::abs(dsk) > 0x1p32) | (std::abs(dtk) > 0x1p32);
        redo[k] |= big;
        d[k] = (!big & (dk == dk)) ? static_cast<float>(dk) : 0.0f;
        ds[k] = (!big & (dsk == dsk)) ? static_cast<float>(dsk) : 0.0f;
        dt[k] = (!big & (dtk == dtk)) ? static_cast<float>(dtk) : 0.0f;
      }
    }
    else
    {
      this->Samples(first, count, d, ds, dt);
      // Displacement's arithmetic, in a loop of its own that vectorises.
      for (int k = 0; k < count; ++k)
      {
        d[k] = Finite(c.Scale * (d[k] - c.Midlevel));
        ds[k] = Finite(c.Scale * ds[k]);
        dt[k] = Finite(c.Scale * dt[k]);
      }
    }
  }

  VTK_ALWAYS_INLINE void Samples(
    vtkIdType first, int count, DoubleLanes h, DoubleLanes hs, DoubleLanes ht) const
  {
    const Context<R>& c = this->C;
    if constexpr (Interp == vtkDisplacementMapFilter::Linear)
    {
      if (this->Tex.Clean && this->Tex.W > 1 && this->Tex.H > 1)
      {
        this->LinearSamples(first, count, h, hs, ht);
        return;
      }
    }
    for (int k = 0; k < count; ++k)
    {
      const vtkIdType i = first + k;
      SampleHeight<Interp>(
        this->Tex, c.Wrap, c.TCoords->Get(i, 0), c.TCoords->Get(i, 1), h[k], hs[k], ht[k]);
    }
  }

  // SampleHeight<Linear> for the block, on a map without NaN (and at least 2 x 2): texel
  // positions and the blend in loops that vectorise, the four texel reads in one of their own.
  // The points whose texels are not all inside the map (or whose coordinates TameCoordinate
  // would change) are sampled again by SampleHeight itself, which wraps. The inside points get
  // SampleHeight's operations in its order, so the same bits.
  VTK_ALWAYS_INLINE void LinearSamples(
    vtkIdType first, int count, DoubleLanes h, DoubleLanes hs, DoubleLanes ht) const
  {
    const Context<R>& c = this->C;
    const Texels<T>& tex = this->Tex;
    const int nc = c.TCoords->NC;
    const R* tc = c.TCoords->P + first * nc;
    const double W = tex.W, H = tex.H;
    alignas(64) DoubleLanes fx, fy;
    alignas(64) int i0[Block], j0[Block];
    alignas(64) Flags outside;
    for (int k = 0; k < count; ++k)
    {
      const double s = tc[nc * k], t = tc[nc * k + 1];
      const double x = s * W - 0.5, y = t * H - 0.5;
      const double i = std::floor(x), j = std::floor(y);
      const bool in = (std::abs(s) < 1e6) & (std::abs(t) < 1e6) & (i >= 0.0) & (i + 1.0 < W) &
        (j >= 0.0) & (j + 1.0 < H);
      outside[k] = !in;
      // Outside points read texel (0,0) here (in the map), and are sampled again below.
      i0[k] = static_cast<int>(in ? i : 0.0);
      j0[k] = static_cast<int>(in ? j : 0.0);
      fx[k] = x - i;
      fy[k] = y - j;
    }
    const vtkIdType rowStride = static_cast<vtkIdType>(tex.W) * tex.NC;
    const int tnc = tex.NC;
    // The texels are not prefetched: the hardware follows their two rows. Asking for the next
    // block's texels took about 4% off Approximate's re-execution on the Intel machine of the
    // ninth round but added about 9% on the AMD EPYC (BENCHMARKS.md).
    // The texels read in a scalar loop, the blend in one of its own that vectorises (in the same
    // loop the blend stayed scalar too).
    alignas(64) DoubleLanes h00, h10, h01, h11;
    for (int k = 0; k < count; ++k)
    {
      const T* p = tex.Data + j0[k] * rowStride + i0[k] * tnc + tex.Comp;
      double t00 = tex.Norm * p[0], t10 = tex.Norm * p[tnc];
      double t01 = tex.Norm * p[rowStride], t11 = tex.Norm * p[rowStride + tnc];
      KeepScalar(t00, t10, t01, t11);
      h00[k] = t00;
      h10[k] = t10;
      h01[k] = t01;
      h11[k] = t11;
    }
    for (int k = 0; k < count; ++k)
    {
      const double b0 = (1.0 - fx[k]) * h00[k] + fx[k] * h10[k];
      const double b1 = (1.0 - fx[k]) * h01[k] + fx[k] * h11[k];
      h[k] = (1.0 - fy[k]) * b0 + fy[k] * b1;
      hs[k] = W * ((1.0 - fy[k]) * (h10[k] - h00[k]) + fy[k] * (h11[k] - h01[k]));
      ht[k] = H * (b1 - b0);
    }
    if (Base::Any(count, outside))
    {
      for (int k = 0; k < count; ++k)
      {
        if (outside[k])
        {
          SampleHeight<Interp>(tex, c.Wrap, tc[nc * k], tc[nc * k + 1], h[k], hs[k], ht[k]);
        }
      }
    }
  }

  // WritePoint for the block (@a x is scratch).
  VTK_ALWAYS_INLINE void Points(
    vtkIdType first, int count, const Lanes n[3], const Lanes d, Lanes x[3]) const
  {
    this->template Gather<3>(this->C.Points->P + 3 * first, count, x);
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < count; ++k)
      {
        const L offset = d[k] * n[j][k];
        x[j][k] = offset == 0.0 ? x[j][k] : Finite(x[j][k] + offset);
      }
    }
    this->template Scatter<3>(x, count, this->C.OutPoints->P + 3 * first);
  }

  // P_s, P_t (dPdu/dPdv scaled, or fitted) and, for Exact, the fitted n_s, n_t. Float lanes
  // flag the points whose fits float cannot hold (see FitDouble).
  VTK_ALWAYS_INLINE void Derivatives(vtkIdType first, int count, bool exact, Lanes ps[3],
    Lanes pt[3], Lanes ns[3], Lanes nt[3], [[maybe_unused]] Flags redo, const double* sums) const
  {
    const Context<R>& c = this->C;
    if (c.DPdu)
    {
      this->template Gather<3>(c.DPdu->P + 3 * first, count, ps);
      this->template Gather<3>(c.DPdv->P + 3 * first, count, pt);
      const L scaleS = ToReal<L>(c.DerivativeScale[0]);
      const L scaleT = ToReal<L>(c.DerivativeScale[1]);
      for (int j = 0; j < 3; ++j)
      {
        for (int k = 0; k < count; ++k)
        {
          ps[j][k] *= scaleS;
          pt[j][k] *= scaleT;
        }
      }
    }
    if (c.DPdu && !exact)
    {
      return;
    }
    const bool wantP = !c.DPdu;
    const int stride = c.FitStride;
    const R* kept = c.Fits + static_cast<vtkIdType>(stride) * first;
    if (!c.FitsKnown)
    {
      if (wantP && exact)
      {
        this->template Fit<true, true>(first, count, ps, pt, ns, nt, redo, sums);
      }
      else if (wantP)
      {
        this->template Fit<true, false>(first, count, ps, pt, ns, nt, redo, sums);
      }
      else
      {
        this->template Fit<false, true>(first, count, ps, pt, ns, nt, redo, sums);
      }
      return;
    }
    if (wantP)
    {
      for (int k = 0; k < count; ++k)
      {
        for (int j = 0; j < 3; ++j)
        {
          ps[j][k] = static_cast<L>(kept[stride * k + j]);
          pt[j][k] = static_cast<L>(kept[stride * k + 3 + j]);
        }
      }
      kept += 6;
    }
    if (exact)
    {
      for (int k = 0; k < count; ++k)
      {
        for (int j = 0; j < 3; ++j)
        {
          ns[j][k] = static_cast<L>(kept[stride * k + j]);
          nt[j][k] = static_cast<L>(kept[stride * k + 3 + j]);
        }
      }
    }
    if constexpr (Float)
    {
      // A kept NaN: a point whose fits float cannot hold (Fit), redone in double lanes.
      const Lanes& firstRead = wantP ? ps[0] : ns[0];
      for (int k = 0; k < count; ++k)
      {
        redo[k] |= static_cast<int>(std::isnan(firstRead[k]));
      }
    }
    if constexpr (std::is_same<R, float>::value && !Float)
    {
      // Over the NaNs just read: the point fitted again, as its first execution did.
      for (int k = 0; k < count; ++k)
      {
        if (std::isnan(c.Fits[stride * (first + k)]))
        {
          this->RefitOne(first + k, wantP, exact, ps, pt, ns, nt, k);
        }
      }
    }
  }

  // Lane @a k of the derivatives: point @a i fitted again, not kept (a re-execution's point
  // whose fits float could not hold).
  void RefitOne(vtkIdType i, bool wantP, bool exact, Lanes ps[3], Lanes pt[3], Lanes ns[3],
    Lanes nt[3], int k) const
  {
    alignas(64) Lanes fps[3], fpt[3], fns[3], fnt[3];
    alignas(64) Flags unkept;
    if (wantP && exact)
    {
      this->template FitDouble<true, true>(i, 1, fps, fpt, fns, fnt, unkept, false, nullptr);
    }
    else if (wantP)
    {
      this->template FitDouble<true, false>(i, 1, fps, fpt, fns, fnt, unkept, false, nullptr);
    }
    else
    {
      this->template FitDouble<false, true>(i, 1, fps, fpt, fns, fnt, unkept, false, nullptr);
    }
    for (int j = 0; j < 3; ++j)
    {
      if (wantP)
      {
        ps[j][k] = fps[j][0];
        pt[j][k] = fpt[j][0];
      }
      if (exact)
      {
        ns[j][k] = fns[j][0];
        nt[j][k] = fnt[j][0];
      }
    }
  }

  // The fitted P_s, P_t (WantP) and n_s, n_t (WantN) of the block, also written to the kept
  // buffer: the sums point by point (gathers over the neighbours), the solutions in a loop over
  // the block that vectorises. Where the texture coordinates around a point do not span two
  // directions, or (P) a neighbour sits at the point with other texture coordinates (a pole:
  // p(s,t) is singular there), the derivatives are 0 and the normal falls back on the input's.
  template <bool WantP, bool WantN>
  VTK_ALWAYS_INLINE void Fit(vtkIdType first, int count, Lanes ps[3], Lanes pt[3], Lanes ns[3],
    Lanes nt[3], [[maybe_unused]] Flags redo, const double* sums) const
  {
    alignas(64) Flags unkept;
    if constexpr (Float)
    {
      // Solved in double, rounded to float and kept (re-executions read the kept values: the
      // same lanes); the points whose fits float cannot hold keep NaN and are redone.
      alignas(64) DoubleLanes fps[3], fpt[3], fns[3], fnt[3];
      this->template FitDouble<WantP, WantN>(first, count, fps, fpt, fns, fnt, unkept, false, sums);
      for (int q = 0; q < 3; ++q)
      {
        for (int k = 0; k < count; ++k)
        {
          if (WantP)
          {
            ps[q][k] = ToReal<float>(fps[q][k]);
            pt[q][k] = ToReal<float>(fpt[q][k]);
          }
          if (WantN)
          {
            ns[q][k] = ToReal<float>(fns[q][k]);
            nt[q][k] = ToReal<float>(fnt[q][k]);
          }
        }
      }
      FlagUnkept<WantP, WantN>(count, ps, pt, ns, nt, unkept);
      FlagVanished<WantP, WantN>(count, fps, fpt, fns, fnt, unkept);
      for (int k = 0; k < count; ++k)
      {
        redo[k] |= unkept[k];
      }
      const int stride = this->C.FitStride;
      R* kept = this->C.Fits + static_cast<vtkIdType>(stride) * first;
      auto keep = [&](const Lanes* vs, const Lanes* vt, R* to)
      {
        for (int k = 0; k < count; ++k)
        {
          for (int q = 0; q < 3; ++q)
          {
            to[stride * k + q] = unkept[k] ? std::numeric_limits<float>::quiet_NaN() : vs[q][k];
            to[stride * k + 3 + q] = unkept[k] ? std::numeric_limits<float>::quiet_NaN() : vt[q][k];
          }
        }
      };
      if (WantP)
      {
        keep(ps, pt, kept);
      }
      if (WantN)
      {
        keep(ns, nt, kept + (WantP ? 6 : 0));
      }
    }
    else
    {
      this->template FitDouble<WantP, WantN>(first, count, ps, pt, ns, nt, unkept, true, sums);
    }
  }

  // Whether float cannot hold a fitted value at its precision: @a r, the value rounded to float
  // (clamped), is infinite, NaN, the largest float (perhaps clamped) or subnormal. Integer
  // compares of the bits, which vectorise 8 to a register.
  static VTK_ALWAYS_INLINE int FloatFitUnkept(float r)
  {
    std::uint32_t u;
    std::memcpy(&u, &r, sizeof(u));
    u &= 0x7fffffffu;
    return static_cast<int>((u != 0) & (u - 0x00800000u >= 0x7f7fffffu - 0x00800000u));
  }

  static VTK_ALWAYS_INLINE int FloatFitUnkept(double v) { return FloatFitUnkept(ToReal<float>(v)); }

  // Calls @a f with the lanes of each field the fit makes: P_s and P_t (WantP), n_s and n_t
  // (WantN).
  template <bool WantP, bool WantN, typename V, typename F>
  static VTK_ALWAYS_INLINE void ForEachFit(V* ps, V* pt, V* ns, V* nt, F&& f)
  {
    if (WantP)
    {
      f(ps);
      f(pt);
    }
    if (WantN)
    {
      f(ns);
      f(nt);
    }
  }

  // Sets @a unkept for the points of the block with a fitted value that float cannot hold (float
  // or double lanes @a V), in loops that vectorise.
  template <bool WantP, bool WantN, typename V>
  static VTK_ALWAYS_INLINE void FlagUnkept(
    int count, const V* ps, const V* pt, const V* ns, const V* nt, Flags unkept)
  {
    std::fill_n(unkept, count, 0);
    ForEachFit<WantP, WantN>(ps, pt, ns, nt,
      [&](const V* f)
      {
        for (int q = 0; q < 3; ++q)
        {
          for (int k = 0; k < count; ++k)
          {
            unkept[k] |= FloatFitUnkept(f[q][k]);
          }
        }
      });
  }

  // Adds to @a unkept the points of the block with a fitted value (double lanes, before rounding)
  // that is not zero but below float's normal range: rounded to float it keeps few bits (a
  // subnormal, which FlagUnkept also flags) or none (zero, which FlagUnkept cannot tell from a
  // zero fit). Branch-free, so that the loops vectorise.
  template <bool WantP, bool WantN>
  static VTK_ALWAYS_INLINE void FlagVanished(int count, const DoubleLanes* ps,
    const DoubleLanes* pt, const DoubleLanes* ns, const DoubleLanes* nt, Flags unkept)
  {
    ForEachFit<WantP, WantN>(ps, pt, ns, nt,
      [&](const DoubleLanes* f)
      {
        for (int q = 0; q < 3; ++q)
        {
          for (int k = 0; k < count; ++k)
          {
            const double a = std::abs(f[q][k]);
            unkept[k] |= static_cast<int>(
              (a > 0.0) & (a < static_cast<double>(std::numeric_limits<float>::min())));
          }
        }
      });
  }

  // Point @a i's fit record, gathered through the links where they are set, else made through
  // the spans.
  template <bool WantP, bool WantN>
  VTK_ALWAYS_INLINE void PointFitSums(vtkIdType i, double* r) const
  {
    using Rec = FitRecord<WantP, WantN>;
    const Context<R>& c = this->C;
    if (!c.Polys->LinkOffsets)
    {
      PointFitSumsThroughSpans<WantP, WantN>(c, i, r);
      return;
    }
    double p[8], n[8], near, far;
    FitSums<WantP, WantN>(c, i, p, n, r[Rec::Dt2], near, far);
    if (WantP)
    {
      std::copy_n(p, 8, r + Rec::P);
      r[Rec::Near] = near;
      r[Rec::Far] = far;
    }
    if (WantN)
    {
      std::copy_n(n, 8, r + Rec::N);
    }
  }

  // With float arrays (double lanes: the redone points) the fits are kept rounded to float and
  // the lanes get the rounded values, which a re-execution reads back, except at points with a
  // fitted value that float cannot hold at its precision (FlagUnkept, FlagVanished; @a unkept):
  // these keep NaN, and their lanes the double values. Float lanes (Fit) round and keep alike.
  //
  // @a sums holds the block's fit sums (RangeFitSums's records); null: each point's are gathered.
  template <bool WantP, bool WantN>
  VTK_ALWAYS_INLINE void FitDouble(vtkIdType first, int count, DoubleLanes ps[3], DoubleLanes pt[3],
    DoubleLanes ns[3], DoubleLanes nt[3], Flags unkept, bool store, const double* sums) const
  {
    using Rec = FitRecord<WantP, WantN>;
    const Context<R>& c = this->C;
    alignas(64) DoubleLanes m[3], bp[6], bn[6], near, far;
    for (int k = 0; k < count; ++k)
    {
      double own[Rec::Size];
      const double* r = sums ? sums + Rec::Size * k : own;
      if (!sums)
      {
        this->template PointFitSums<WantP, WantN>(first + k, own);
      }
      constexpr int mk = WantN ? Rec::N : Rec::P;
      m[0][k] = r[mk + 3];
      m[1][k] = r[mk + 7];
      m[2][k] = r[Rec::Dt2];
      near[k] = WantP ? r[Rec::Near] : std::numeric_limits<double>::max();
      far[k] = WantP ? r[Rec::Far] : 0.0;
      for (int q = 0; q < 3; ++q)
      {
        bp[q][k] = WantP ? r[Rec::P + q] : 0.0;
        bp[3 + q][k] = WantP ? r[Rec::P + 4 + q] : 0.0;
        bn[q][k] = WantN ? r[Rec::N + q] : 0.0;
        bn[3 + q][k] = WantN ? r[Rec::N + 4 + q] : 0.0;
      }
    }
    for (int k = 0; k < count; ++k)
    {
      const double det = m[0][k] * m[2][k] - m[1][k] * m[1][k];
      const double tr = m[0][k] + m[2][k];
      const bool spans = det > 1e-12 * tr * tr;
      const double divisor = spans ? det : 1.0;
      const bool distinct = spans & !(near[k] <= 1e-16 * far[k]);
      for (int q = 0; q < 3; ++q)
      {
        if (WantP)
        {
          const double fs = (m[2][k] * bp[q][k] - m[1][k] * bp[3 + q][k]) / divisor;
          const double ft = (m[0][k] * bp[3 + q][k] - m[1][k] * bp[q][k]) / divisor;
          ps[q][k] = distinct ? fs : 0.0;
          pt[q][k] = distinct ? ft : 0.0;
        }
        if (WantN)
        {
          const double fs = (m[2][k] * bn[q][k] - m[1][k] * bn[3 + q][k]) / divisor;
          const double ft = (m[0][k] * bn[3 + q][k] - m[1][k] * bn[q][k]) / divisor;
          ns[q][k] = spans ? fs : 0.0;
          nt[q][k] = spans ? ft : 0.0;
        }
      }
    }
    std::fill_n(unkept, count, 0);
    if constexpr (std::is_same<R, float>::value && !Float)
    {
      // The double lanes of float arrays' points (redone points): Fit's flags and rounding.
      FlagUnkept<WantP, WantN>(count, ps, pt, ns, nt, unkept);
      FlagVanished<WantP, WantN>(count, ps, pt, ns, nt, unkept);
      ForEachFit<WantP, WantN>(ps, pt, ns, nt,
        [&](DoubleLanes* f)
        {
          for (int q = 0; q < 3; ++q)
          {
            for (int k = 0; k < count; ++k)
            {
              const double r = static_cast<double>(ToReal<float>(f[q][k]));
              f[q][k] = unkept[k] ? f[q][k] : r;
            }
          }
        });
    }
    if (!store)
    {
      return;
    }
    const int stride = c.FitStride;
    R* kept = c.Fits + static_cast<vtkIdType>(stride) * first;
    constexpr double unkeptValue = std::numeric_limits<double>::quiet_NaN();
    if (WantP)
    {
      for (int k = 0; k < count; ++k)
      {
        for (int q = 0; q < 3; ++q)
        {
          kept[stride * k + q] = static_cast<R>(unkept[k] ? unkeptValue : ps[q][k]);
          kept[stride * k + 3 + q] = static_cast<R>(unkept[k] ? unkeptValue : pt[q][k]);
        }
      }
      kept += 6;
    }
    if (WantN)
    {
      for (int k = 0; k < count; ++k)
      {
        for (int q = 0; q < 3; ++q)
        {
          kept[stride * k + q] = static_cast<R>(unkept[k] ? unkeptValue : ns[q][k]);
          kept[stride * k + 3 + q] = static_cast<R>(unkept[k] ? unkeptValue : nt[q][k]);
        }
      }
    }
  }

  // The new normal's direction: the seed's formula, or (Exact) the cross product of the
  // displaced surface's derivatives; the input normal where the surface is degenerate.
  template <bool Exact>
  VTK_ALWAYS_INLINE void Directions(int count, const Lanes n[3], const Lanes d, const Lanes ds,
    const Lanes dt, const Lanes ps[3], const Lanes pt[3], const Lanes ns[3], const Lanes nt[3],
    Lanes m[3], [[maybe_unused]] Flags redo) const
  {
    if constexpr (Float)
    {
      this->template DirectionsFloat<Exact>(count, n, d, ds, dt, ps, pt, ns, nt, m, redo);
    }
    else
    {
      this->template DirectionsDouble<Exact>(count, n, d, ds, dt, ps, pt, ns, nt, m);
    }
  }

  template <bool Exact>
  VTK_ALWAYS_INLINE void DirectionsDouble(int count, const Lanes n[3], const Lanes d,
    const Lanes ds, const Lanes dt, const Lanes ps[3], const Lanes pt[3], const Lanes ns[3],
    const Lanes nt[3], Lanes m[3]) const
  {
    for (int k = 0; k < count; ++k)
    {
      const double nk[3] = { n[0][k], n[1][k], n[2][k] };
      double Ps[3] = { ps[0][k], ps[1][k], ps[2][k] }, Pt[3] = { pt[0][k], pt[1][k], pt[2][k] };
      // Only the parts across n count: then P_s x P_t is along n and Scale 0 gives n.
      RemoveNormalPart(nk, Ps);
      RemoveNormalPart(nk, Pt);
      double base[3];
      Cross(Ps, Pt, base);
      const double area = Dot(nk, base);
      const double size = std::sqrt(Dot(Ps, Ps) * Dot(Pt, Pt));
      double mk[3];
      if (Exact)
      {
        double Ns[3] = { ns[0][k], ns[1][k], ns[2][k] }, Nt[3] = { nt[0][k], nt[1][k], nt[2][k] };
        RemoveNormalPart(nk, Ns);
        RemoveNormalPart(nk, Nt);
        double qs[3], qt[3];
        for (int j = 0; j < 3; ++j)
        {
          qs[j] = Finite(Ps[j] + ds[k] * nk[j] + d[k] * Ns[j]);
          qt[j] = Finite(Pt[j] + dt[k] * nk[j] + d[k] * Nt[j]);
        }
        // Only the direction matters: dividing each vector by its largest component first
        // keeps the cross product finite.
        const double ms = std::max(std::max(std::abs(qs[0]), std::abs(qs[1])), std::abs(qs[2]));
        const double mt = std::max(std::max(std::abs(qt[0]), std::abs(qt[1])), std::abs(qt[2]));
        const double invS = 1.0 / ms, invT = 1.0 / mt;
        for (int j = 0; j < 3; ++j)
        {
          qs[j] = ms > 0.0 ? qs[j] * invS : qs[j];
          qt[j] = mt > 0.0 ? qt[j] * invT : qt[j];
        }
        Cross(qs, qt, mk);
      }
      else
      {
        double nxPs[3], nxPt[3];
        Cross(nk, Ps, nxPs);
        Cross(nk, Pt, nxPt);
        const double largest =
          std::max(std::max(std::max(std::abs(area), std::abs(ds[k])), std::abs(dt[k])), 1e-300);
        const double inv = 1.0 / largest;
        const double a = area * inv, bs = ds[k] * inv, bt = dt[k] * inv;
        for (int j = 0; j < 3; ++j)
        {
          mk[j] = a * nk[j] + bs * nxPt[j] - bt * nxPs[j];
        }
      }
      const bool degenerate = !(std::abs(area) > 1e-10 * size) | !IsFinite(area);
      const double sign = area < 0.0 ? -1.0 : 1.0;
      for (int j = 0; j < 3; ++j)
      {
        // Negation, not a product with the sign: -0 stays what WriteNormal would get.
        const double flipped = sign < 0.0 ? -mk[j] : mk[j];
        m[j][k] = degenerate ? nk[j] : flipped;
      }
    }
  }

  // Directions in float lanes. Where P_s and P_t (across n) lie within 0.6 degrees of parallel,
  // or out of float's range, the point is flagged: its redo in double also decides, as the
  // per-point code does, whether the surface is degenerate there. Exact: the cross product of the
  // displaced surface's derivatives, (P_s + a_s) x (P_t + a_t) with a_s = d_s n + d n_s and
  // a_t = d_t n + d n_t, is P_s x P_t = area n plus D = a_s x P_t + P_s x a_t + a_s x a_t, taken
  // as n + D / area (oriented by the sign of area): no difference of two large cross products, so
  // that float keeps its relative precision in the change of the normal.
  template <bool Exact>
  VTK_ALWAYS_INLINE void DirectionsFloat(int count, const Lanes n[3], const Lanes d, const Lanes ds,
    const Lanes dt, const Lanes ps[3], const Lanes pt[3], const Lanes ns[3], const Lanes nt[3],
    Lanes m[3], Flags redo) const
  {
    auto cross = [](const float a[3], const float b[3], float c[3])
    {
      c[0] = a[1] * b[2] - a[2] * b[1];
      c[1] = a[2] * b[0] - a[0] * b[2];
      c[2] = a[0] * b[1] - a[1] * b[0];
    };
    auto across = [](const float nk[3], float v[3])
    {
      const float along = nk[0] * v[0] + nk[1] * v[1] + nk[2] * v[2];
      v[0] -= along * nk[0];
      v[1] -= along * nk[1];
      v[2] -= along * nk[2];
    };
    for (int k = 0; k < count; ++k)
    {
      const float nk[3] = { n[0][k], n[1][k], n[2][k] };
      float Ps[3] = { ps[0][k], ps[1][k], ps[2][k] }, Pt[3] = { pt[0][k], pt[1][k], pt[2][k] };
      across(nk, Ps);
      across(nk, Pt);
      float base[3];
      cross(Ps, Pt, base);
      const float area = nk[0] * base[0] + nk[1] * base[1] + nk[2] * base[2];
      const float size2 = (Ps[0] * Ps[0] + Ps[1] * Ps[1] + Ps[2] * Ps[2]) *
        (Pt[0] * Pt[0] + Pt[1] * Pt[1] + Pt[2] * Pt[2]);
      redo[k] |= !(area * area > 1e-4f * size2) | !IsFinite(size2);
      float mk[3];
      if (Exact)
      {
        float Ns[3] = { ns[0][k], ns[1][k], ns[2][k] }, Nt[3] = { nt[0][k], nt[1][k], nt[2][k] };
        across(nk, Ns);
        across(nk, Nt);
        float as[3], at[3];
        for (int j = 0; j < 3; ++j)
        {
          as[j] = ds[k] * nk[j] + d[k] * Ns[j];
          at[j] = dt[k] * nk[j] + d[k] * Nt[j];
        }
        // a_s x a_t as d (d_s n x n_t + n_s x a_t): its d_s d_t n x n part is zero, but taken
        // in float it leaves a residue of float's epsilon times d_s d_t, which swamps the normal's
        // change where the heights' slope is large and d small (error up to 1e-4 rad at Scale
        // 1e4 on a unit torus).
        float c1[3], c2[3], nxNt[3], c3[3];
        cross(as, Pt, c1);
        cross(Ps, at, c2);
        cross(nk, Nt, nxNt);
        cross(Ns, at, c3);
        const float inv = 1.0f / area;
        for (int j = 0; j < 3; ++j)
        {
          mk[j] = nk[j] + (c1[j] + c2[j] + d[k] * (ds[k] * nxNt[j] + c3[j])) * inv;
        }
      }
      else
      {
        float nxPs[3], nxPt[3];
        cross(nk, Ps, nxPs);
        cross(nk, Pt, nxPt);
        const float largest =
          std::max(std::max(std::max(std::abs(area), std::abs(ds[k])), std::abs(dt[k])),
            std::numeric_limits<float>::min());
        const float inv = 1.0f / largest;
        const float a = area * inv, bs = ds[k] * inv, bt = dt[k] * inv;
        const bool flip = area < 0.0f;
        for (int j = 0; j < 3; ++j)
        {
          const float v = a * nk[j] + bs * nxPt[j] - bt * nxPs[j];
          mk[j] = flip ? -v : v;
        }
      }
      for (int j = 0; j < 3; ++j)
      {
        m[j][k] = mk[j];
      }
    }
  }
};

// Mesh normals: area-weighted sum of the displaced polygons around each point, each
// polygon oriented as its points' input normals. The polygons' normals first, each once.
template <typename R>
struct MeshPolygonNormalWorker
{
  const Context<R>& C;
  const ArrayReader<R>& Moved;
  double* CellNormals;
  // Each polygon's orientation (-1 or 1), which depends on the input alone: found and stored in
  // Signs, or (Known) read from it, which spares reading the input points and normals again.
  signed char* Signs;
  bool Known;

  // Adds the cross products of the fan from the first of the @a n corners @a ids to @a sum; @a pts
  // has 3 components (points, moved points).
  static VTK_ALWAYS_INLINE void FanSum(
    const R* pts, const vtkIdType* ids, vtkIdType n, double sum[3])
  {
    const R* q0 = pts + 3 * ids[0];
    const double p0[3] = { q0[0], q0[1], q0[2] };
    for (vtkIdType k = 1; k + 1 < n; ++k)
    {
      const R* q1 = pts + 3 * ids[k];
      const R* q2 = pts + 3 * ids[k + 1];
      const double a1[3] = { q1[0] - p0[0], q1[1] - p0[1], q1[2] - p0[2] };
      const double a2[3] = { q2[0] - p0[0], q2[1] - p0[1], q2[2] - p0[2] };
      double x[3];
      Cross(a1, a2, x);
      sum[0] += x[0];
      sum[1] += x[1];
      sum[2] += x[2];
    }
  }

  // Each polygon's normal, once (in AVX2 where the processor has it, as pass 1).
  void operator()(vtkIdType begin, vtkIdType end) const
  {
    vtkSurfaceDetailVectorize::RunWidest(*this, begin, end);
  }

  VTK_ALWAYS_INLINE void Run(vtkIdType begin, vtkIdType end) const
  {
    if (this->Known)
    {
      this->template Polygons<true>(begin, end);
    }
    else
    {
      this->template Polygons<false>(begin, end);
    }
  }

  // The arrays as raw pointers held in registers through the loop (the input points, normals and
  // moved points all have 3 components).
  template <bool SignKnown>
  VTK_ALWAYS_INLINE void Polygons(vtkIdType begin, vtkIdType end) const
  {
    const vtkIdType* offsets = this->C.Polys->Offsets;
    const vtkIdType* conn = this->C.Polys->Conn;
    const R* moved = this->Moved.P;
    const R* points = this->C.Points->P;
    const R* normals = this->C.Normals->P;
    signed char* signs = this->Signs;
    double* out = this->CellNormals + 3 * begin;
    for (vtkIdType cell = begin; cell < end; ++cell, out += 3)
    {
      const vtkIdType n = offsets[cell + 1] - offsets[cell];
      if (n == 0)
      {
        // No corner to read (the last polygon's would be past the connectivity's end): no
        // normal, the orientation OrientedNormal gives polygons of one or two points.
        out[0] = out[1] = out[2] = 0.0;
        if (!SignKnown)
        {
          signs[cell] = 1;
        }
        continue;
      }
      OrientedNormal<SignKnown>(moved, points, normals, conn + offsets[cell], n, signs[cell], out);
    }
  }

  // The displaced polygon of the @a n corners @a ids: its normal, area-weighted (a fan of cross
  // products from corner 0), oriented as its points' input normals: by @a sign (SignKnown), else
  // found from the input polygon (then stored in @a sign).
  template <bool SignKnown>
  static VTK_ALWAYS_INLINE void OrientedNormal(const R* moved, const R* points, const R* normals,
    const vtkIdType* ids, vtkIdType n, signed char& sign, double out[3])
  {
    double m[3] = { 0.0, 0.0, 0.0 };
    FanSum(moved, ids, n, m);
    double s;
    if (SignKnown)
    {
      s = sign < 0 ? -1.0 : 1.0;
    }
    else
    {
      // The orientation: the input polygon's normal against its points' input normals.
      double orig[3] = { 0.0, 0.0, 0.0 }, nsum[3] = { 0.0, 0.0, 0.0 };
      FanSum(points, ids, n, orig);
      for (vtkIdType k = 0; k < n; ++k)
      {
        const R* nk = normals + 3 * ids[k];
        nsum[0] += nk[0];
        nsum[1] += nk[1];
        nsum[2] += nk[2];
      }
      s = Dot(orig, nsum) < 0.0 ? -1.0 : 1.0;
      sign = s < 0.0 ? -1 : 1;
    }
    for (int k = 0; k < 3; ++k)
    {
      out[k] = s * m[k];
    }
  }
};

// Mesh normals' last step, shared by both ways of making the sums: each point's normal from the sum
// of its polygons' normals (in double), normalised and its tangent re-orthogonalised in blocks
// (BlockOps: with double lanes WriteNormalAndTangent's bits; with float lanes, flagged points
// redone by it).
template <typename R, typename L = R>
struct MeshNormalBlocks : BlockOps<R, L>
{
  using Base = BlockOps<R, L>;
  using Base::Block;
  using Base::Float;
  using typename Base::Flags;
  using typename Base::Lanes;

  // The points [first, first + count) (count <= Block), their sums in @a sums (4 doubles a point,
  // the last unused).
  VTK_ALWAYS_INLINE void FinishBlock(vtkIdType first, int count, const double* sums) const
  {
    alignas(64) Lanes n[3], fallback[3], m[3], x[4];
    alignas(64) Flags redo;
    for (int k = 0; k < count; ++k)
    {
      m[0][k] = ToReal<L>(sums[4 * k]);
      m[1][k] = ToReal<L>(sums[4 * k + 1]);
      m[2][k] = ToReal<L>(sums[4 * k + 2]);
    }
    this->UnitNormals(first, count, n, fallback, redo);
    this->Normals(first, count, fallback, m, redo);
    this->OutputTangents(first, count, m, x, redo);
    if constexpr (Float)
    {
      if (Base::Any(count, redo))
      {
        for (int k = 0; k < count; ++k)
        {
          if (redo[k])
          {
            double redone[3] = { sums[4 * k], sums[4 * k + 1], sums[4 * k + 2] };
            WriteNormalAndTangent(this->C, first + k, redone);
          }
        }
      }
    }
  }
};

// Each point's normal: the sum of its polygons' in increasing polygon order (in double), gathered
// through the links a block at a time, then MeshNormalBlocks's step.
template <typename R, typename L = R>
struct MeshPointNormalWorker : MeshNormalBlocks<R, L>
{
  using Base = MeshNormalBlocks<R, L>;
  using Base::Block;
  const double* CellNormals;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    vtkSurfaceDetailVectorize::RunWidest(*this, begin, end);
  }

  VTK_ALWAYS_INLINE void Run(vtkIdType begin, vtkIdType end) const
  {
    const PolyLinks& mesh = *this->C.Polys;
    alignas(64) double sums[4 * Block];
    for (vtkIdType first = begin; first < end; first += Block)
    {
      const int count = static_cast<int>(std::min<vtkIdType>(end - first, Block));
      for (int k = 0; k < count; ++k)
      {
        const vtkIdType i = first + k;
        double x = 0.0, y = 0.0, z = 0.0;
        for (vtkIdType l = mesh.LinkOffsets[i]; l < mesh.LinkOffsets[i + 1]; ++l)
        {
          const double* p = this->CellNormals + 3 * mesh.Links[l];
          x += p[0];
          y += p[1];
          z += p[2];
        }
        sums[4 * k] = x;
        sums[4 * k + 1] = y;
        sums[4 * k + 2] = z;
      }
      this->FinishBlock(first, count, sums);
    }
  }
};

// Mesh normals without links: a task of the points [pb, pe) (TaskSize of them) adds the oriented
// normals of the polygons with a corner among its points (ForCellsTouching: in increasing polygon
// order) to those corners' sums, held by the task (in cache), then writes its points' normals and
// tangents in blocks (MeshNormalBlocks). Each point's sum is made by one task in polygon order, as
// MeshPointNormalWorker's gather makes it: the same bits, at any thread count.
// Polygons with corners in two tasks are computed by both; an orientation found on a first
// execution is stored by the task that owns the polygon's first corner alone.
template <typename R, typename L = R>
struct MeshScatterNormalWorker : MeshNormalBlocks<R, L>
{
  using Base = MeshNormalBlocks<R, L>;
  using Base::Block;
  // The points of a task (a multiple of Block): the polygons around a task's two ends, about two
  // rows of a usual mesh, are computed by both tasks (1414-point rows, the 1M-point torus: about
  // 9% more polygons with 16384 points a task, 2% with 65536, which the cycles show), so large
  // tasks, but at least eight of them where the mesh allows. The results do not depend on it.
  static vtkIdType TaskSize(vtkIdType numPts)
  {
    vtkIdType size = 16384;
    while (size < 65536 && 16 * size <= numPts)
    {
      size *= 2;
    }
    return size;
  }
  const CellSpans& Spans;
  const ArrayReader<R>& Moved;
  signed char* Signs;
  bool Known;
  vtkSMPThreadLocal<std::vector<double>>& Sums;
  vtkIdType NumPoints;
  vtkIdType Size; // TaskSize(NumPoints)

  vtkIdType Tasks() const { return (this->NumPoints + this->Size - 1) / this->Size; }

  void operator()(vtkIdType t0, vtkIdType t1) const
  {
    vtkSurfaceDetailVectorize::RunWidest(*this, t0, t1);
  }

  VTK_ALWAYS_INLINE void Run(vtkIdType t0, vtkIdType t1) const
  {
    std::vector<double>& sums = this->Sums.Local();
    sums.resize(4 * this->Size);
    const vtkIdType numPts = this->NumPoints;
    for (vtkIdType t = t0; t < t1; ++t)
    {
      const vtkIdType pb = t * this->Size, pe = std::min(numPts, pb + this->Size);
      if (this->Known)
      {
        this->template Task<true>(pb, pe, sums.data());
      }
      else
      {
        this->template Task<false>(pb, pe, sums.data());
      }
    }
  }

  // Adds @a v to the sum of point @a j of the task (4 doubles a point: one vector add).
  static VTK_ALWAYS_INLINE void Add(double* sums, std::uint64_t j, const Double4& v)
  {
    Double4 sum;
    std::memcpy(&sum, sums + 4 * j, sizeof(sum));
    sum += v;
    std::memcpy(sums + 4 * j, &sum, sizeof(sum));
  }

  // Polygon @a cell's normal added to its corners' sums among the task's points [pb, pb + width)
  // (Within: all its corners are), its orientation stored if the task owns its first corner.
  // Triangles, the usual polygons, with their corner count known (loops unrolled).
  template <bool SignKnown, bool Within>
  VTK_ALWAYS_INLINE void AddPolygon(const vtkIdType* ids, vtkIdType n, vtkIdType cell, vtkIdType pb,
    std::uint64_t width, double* sums) const
  {
    if (n == 3)
    {
      this->template AddPolygonOf<SignKnown, Within>(ids, 3, cell, pb, width, sums);
    }
    else
    {
      this->template AddPolygonOf<SignKnown, Within>(ids, n, cell, pb, width, sums);
    }
  }

  template <bool SignKnown, bool Within>
  VTK_ALWAYS_INLINE void AddPolygonOf(const vtkIdType* ids, vtkIdType n, vtkIdType cell,
    vtkIdType pb, std::uint64_t width, double* sums) const
  {
    const Context<R>& c = this->C;
    signed char sign = SignKnown ? this->Signs[cell] : 0;
    double v[3];
    MeshPolygonNormalWorker<R>::template OrientedNormal<SignKnown>(
      this->Moved.P, c.Points->P, c.Normals->P, ids, n, sign, v);
    if (!SignKnown && (Within || InRange(ids[0], pb, width)))
    {
      this->Signs[cell] = sign;
    }
    const Double4 v4 = { v[0], v[1], v[2], 0.0 };
    for (vtkIdType k = 0; k < n; ++k)
    {
      // Tested even where the spans say every corner is the task's (Within): a connectivity changed
      // in place without Modified() must not make the task write outside its sums.
      const std::uint64_t j = static_cast<std::uint64_t>(ids[k] - pb);
      if (j < width)
      {
        Add(sums, j, v4);
      }
    }
  }

  // Whether the polygons @a cell and @a cell + 1 of the chunk ending at @a ce (@a cell a triangle
  // of the corners @a ids) are a fan pair (a, b, d), (a, d, c): a quad split along (a, d), as
  // parametric sources and vtkTriangleFilter make them.
  static VTK_ALWAYS_INLINE bool FanPair(
    const vtkIdType* offsets, const vtkIdType* ids, vtkIdType cell, vtkIdType ce)
  {
    return cell + 1 < ce && offsets[cell + 2] - offsets[cell + 1] == 3 && ids[3] == ids[0] &&
      ids[4] == ids[2];
  }

  // Whether the triangle of the @a points @a q0, @a q1, @a q2 (e1 = q1 - q0, e2 = q2 - q0) faces
  // against the sum of its corners' input @a normals: OrientedNormal's test. Its fan sum and normal
  // sum start from +0 there; from the first terms here, which changes at most the sign of a zero
  // in the dot product, and so not the test.
  static VTK_ALWAYS_INLINE bool Faces(
    const double e1[3], const double e2[3], const R* n0, const R* n1, const R* n2)
  {
    double orig[3];
    Cross(e1, e2, orig);
    const double nsum[3] = { double(n0[0]) + n1[0] + n2[0], double(n0[1]) + n1[1] + n2[1],
      double(n0[2]) + n1[2] + n2[2] };
    return Dot(orig, nsum) < 0.0;
  }

  // The edges from corner @a a of a fan pair to @a b, @a d and @a c (points of @a pts, 3
  // components), in double as FanSum makes them.
  static VTK_ALWAYS_INLINE void Edges(const R* pts, vtkIdType a, vtkIdType b, vtkIdType d,
    vtkIdType c, double eb[3], double ed[3], double ec[3])
  {
    const R* qa = pts + 3 * a;
    const R* qb = pts + 3 * b;
    const R* qd = pts + 3 * d;
    const R* qc = pts + 3 * c;
    const double p0[3] = { qa[0], qa[1], qa[2] };
    for (int k = 0; k < 3; ++k)
    {
      eb[k] = qb[k] - p0[k];
      ed[k] = qd[k] - p0[k];
      ec[k] = qc[k] - p0[k];
    }
  }

  // A fan pair's two triangles: each one's oriented normal with OrientedNormal's operations (the
  // edge d - a made once for both; no +0 start to the fan sum, which changes at most the sign of a
  // zero term, which adds nothing to a sum that starts from +0 (and so never is -0), so the sums
  // get the same bits), added to its corners in polygon order (a, b, d, then a, d, c). One range
  // test for the four corners where the task holds them all.
  template <bool SignKnown>
  VTK_ALWAYS_INLINE void AddFan(const vtkIdType* ids, vtkIdType cell, vtkIdType pb,
    std::uint64_t width, double* sums, const R* moved, const R* points, const R* normals,
    signed char* signs) const
  {
    const vtkIdType a = ids[0], b = ids[1], d = ids[2], c = ids[5];
    double eb[3], ed[3], ec[3];
    Edges(moved, a, b, d, c, eb, ed, ec);
    double x1[3], x2[3];
    Cross(eb, ed, x1);
    Cross(ed, ec, x2);
    const std::uint64_t ja = static_cast<std::uint64_t>(a - pb);
    const std::uint64_t jb = static_cast<std::uint64_t>(b - pb);
    const std::uint64_t jd = static_cast<std::uint64_t>(d - pb);
    const std::uint64_t jc = static_cast<std::uint64_t>(c - pb);
    bool flip1, flip2;
    if (SignKnown)
    {
      flip1 = signs[cell] < 0;
      flip2 = signs[cell + 1] < 0;
    }
    else
    {
      double fb[3], fd[3], fc[3];
      Edges(points, a, b, d, c, fb, fd, fc);
      const R* na = normals + 3 * a;
      const R* nd = normals + 3 * d;
      flip1 = Faces(fb, fd, na, normals + 3 * b, nd);
      flip2 = Faces(fd, fc, na, nd, normals + 3 * c);
      if (ja < width)
      {
        signs[cell] = flip1 ? -1 : 1;
        signs[cell + 1] = flip2 ? -1 : 1;
      }
    }
    const Double4 v1 = { flip1 ? -x1[0] : x1[0], flip1 ? -x1[1] : x1[1], flip1 ? -x1[2] : x1[2],
      0.0 };
    const Double4 v2 = { flip2 ? -x2[0] : x2[0], flip2 ? -x2[1] : x2[1], flip2 ? -x2[2] : x2[2],
      0.0 };
    if (((ja | jb | jd | jc) < width) & (a != d))
    {
      // a's and d's two additions in registers, b's before and c's after them: each point still
      // gets the first triangle's normal before the second's, however b and c coincide with a, d
      // or each other (a and d distinct), so the same bits, without a store to forward from each
      // first addition to the second.
      Add(sums, jb, v1);
      Double4 sa, sd;
      std::memcpy(&sa, sums + 4 * ja, sizeof(sa));
      sa += v1;
      sa += v2;
      std::memcpy(sums + 4 * ja, &sa, sizeof(sa));
      std::memcpy(&sd, sums + 4 * jd, sizeof(sd));
      sd += v1;
      sd += v2;
      std::memcpy(sums + 4 * jd, &sd, sizeof(sd));
      Add(sums, jc, v2);
      return;
    }
    const std::uint64_t j[6] = { ja, jb, jd, ja, jd, jc };
    for (int k = 0; k < 6; ++k)
    {
      if (j[k] < width)
      {
        Add(sums, j[k], k < 3 ? v1 : v2);
      }
    }
  }

  // The polygons' part of a task: ForCellsTouching's walk, with chunks whose corners are all the
  // task's added without a test per polygon, fan pairs two triangles at a time.
  template <bool SignKnown>
  VTK_ALWAYS_INLINE void AddPolygons(vtkIdType pb, vtkIdType pe, double* sums) const
  {
    const Context<R>& c = this->C;
    const PolyLinks& mesh = *c.Polys;
    const vtkIdType* __restrict offsets = mesh.Offsets;
    const vtkIdType* __restrict conn = mesh.Conn;
    // Held in registers: the sums' stores could alias members read through this.
    const R* moved = this->Moved.P;
    const R* points = c.Points->P;
    const R* normals = c.Normals->P;
    signed char* signs = this->Signs;
    const std::uint64_t width = static_cast<std::uint64_t>(pe - pb);
    vtkIdType first, last;
    this->Spans.Candidates(pb, pe, first, last);
    for (vtkIdType chunk = first; chunk < last; ++chunk)
    {
      if (!this->Spans.Meets(chunk, pb, pe))
      {
        continue;
      }
      const vtkIdType cb = chunk * CellSpans::Chunk;
      const vtkIdType ce = std::min(mesh.NumCells, cb + CellSpans::Chunk);
      const bool within = this->Spans.Within(chunk, pb, pe);
      if (this->Spans.Triangles[chunk])
      {
        // Triangles only: the corners follow one another in threes.
        const vtkIdType* ids = conn + offsets[cb];
        vtkIdType cell = cb;
        for (; cell + 1 < ce;)
        {
          const bool touches = within || AnyInRange(pb, width, ids[0], ids[1], ids[2], ids[5]);
          if ((ids[3] == ids[0]) & (ids[4] == ids[2]))
          {
            if (touches)
            {
              this->template AddFan<SignKnown>(
                ids, cell, pb, width, sums, moved, points, normals, signs);
            }
            cell += 2;
            ids += 6;
            continue;
          }
          if (within || AnyInRange(pb, width, ids[0], ids[1], ids[2]))
          {
            this->template AddPolygonOf<SignKnown, false>(ids, 3, cell, pb, width, sums);
          }
          ++cell;
          ids += 3;
        }
        if (cell < ce && (within || AnyInRange(pb, width, ids[0], ids[1], ids[2])))
        {
          this->template AddPolygonOf<SignKnown, false>(ids, 3, cell, pb, width, sums);
        }
        continue;
      }
      if (within)
      {
        for (vtkIdType cell = cb; cell < ce;)
        {
          const vtkIdType b = offsets[cell], n = offsets[cell + 1] - b;
          const vtkIdType* ids = conn + b;
          if (n == 3 && FanPair(offsets, ids, cell, ce))
          {
            this->template AddFan<SignKnown>(
              ids, cell, pb, width, sums, moved, points, normals, signs);
            cell += 2;
            continue;
          }
          if (n > 0)
          {
            this->template AddPolygon<SignKnown, true>(ids, n, cell, pb, width, sums);
          }
          ++cell;
        }
        continue;
      }
      for (vtkIdType cell = cb; cell < ce;)
      {
        const vtkIdType b = offsets[cell], n = offsets[cell + 1] - b;
        const vtkIdType* ids = conn + b;
        if (n == 3 && FanPair(offsets, ids, cell, ce))
        {
          // A pair of which one triangle does not touch the range adds nothing for it (and stores
          // no orientation: its first corner is not the task's).
          if (AnyInRange(pb, width, ids[0], ids[1], ids[2], ids[5]))
          {
            this->template AddFan<SignKnown>(
              ids, cell, pb, width, sums, moved, points, normals, signs);
          }
          cell += 2;
          continue;
        }
        bool touches = false;
        for (vtkIdType k = 0; k < n; ++k)
        {
          touches |= InRange(ids[k], pb, width);
        }
        if (touches)
        {
          this->template AddPolygon<SignKnown, false>(ids, n, cell, pb, width, sums);
        }
        ++cell;
      }
    }
  }

  template <bool SignKnown>
  VTK_ALWAYS_INLINE void Task(vtkIdType pb, vtkIdType pe, double* sums) const
  {
    const Context<R>& c = this->C;
    // The sums are zero here: the thread's buffer starts so, and each task's blocks clear theirs
    // once read (while in cache, rather than a pass over the buffer before the walk).
    this->template AddPolygons<SignKnown>(pb, pe, sums);
    for (vtkIdType first = pb; first < pe; first += Block)
    {
      const int count = static_cast<int>(std::min<vtkIdType>(pe - first, Block));
      // The next block's input and output lines, as pass 1 asks for them: the hardware
      // prefetchers do not follow these four streams.
      const vtkIdType next = first + Block;
      if (next < pe)
      {
        const int nextCount = static_cast<int>(std::min<vtkIdType>(pe - next, Block));
        Base::template PrefetchTuples<false>(c.Normals, next, nextCount);
        Base::template PrefetchTuples<false>(c.Tangents, next, nextCount);
        Base::template PrefetchTuples<true>(c.OutNormals, next, nextCount);
        Base::template PrefetchTuples<true>(c.OutTangents, next, nextCount);
      }
      double* blockSums = sums + 4 * (first - pb);
      this->FinishBlock(first, count, blockSums);
      std::fill_n(blockSums, 4 * count, 0.0);
    }
  }
};

// Seam candidates: a texture seam cuts the mesh, so its duplicated points lie on the
// mesh's boundary. One flat sweep over the polygons' directed edges, no links and no
// per-point sort: each edge a->b adds a hash of b to a's sum and subtracts a hash of a from
// b's (so each corner adds the hash of its next point minus that of its previous one). Where every
// edge around a point is shared by two consistently oriented polygons (an interior point), the sums
// cancel exactly; a boundary edge leaves a non-zero sum. The hash is a bijection, so the sum of a
// point on one boundary fan (a seam's usual point), the hash of the fan's last neighbour minus that
// of its first, is never zero; where several boundary fans meet (a bowtie), sums cancel only by a
// 63-bit chance, if the hash mixes well.
// Inconsistent orientation or non-manifold edges only add candidates, which the position test then
// discards. Points without polygons are candidates too. Serial, and integer sums commute: the flags
// never depend on threads.
// The sweep also checks every polygon's ids as it reads them (one pass over the connectivity
// instead of two): @a idsInRange is false if a polygon names a point outside [0, numPts) (its
// corners are then left out, and the candidates mean nothing).
std::vector<vtkIdType> BoundaryPoints(const PolyLinks& mesh, vtkIdType numPts, bool& idsInRange)
{
  // splitmix64's finaliser on 63 bits (each step, an addition, a multiplication by an odd number
  // or an xor with a right shift, modulo 2^63, is a bijection of [0, 2^63)), shifted up one bit:
  // every hash is even, distinct for distinct ids (vtkIdType is below 2^63), and so is every sum,
  // whose lowest bit is then free to mark the points that some polygon uses (it is set after each
  // addition, which keeps the even part exact). Sums of a few hashes of structured ids behave as
  // random 63-bit values. A multiply and one xor-shift cost a third less of this sweep but stay
  // nearly additive (for a + b = c + d, h(a) + h(b) - h(c) - h(d) spans about 37 bits): a bowtie
  // point of a 1M-point grid then goes unfound about 4 times in 10^9 (test BowtieSeamPointMerges has
  // such ids).
  auto hash = [](vtkIdType id)
  {
    constexpr std::uint64_t Low63 = ~std::uint64_t(0) >> 1;
    std::uint64_t z = (static_cast<std::uint64_t>(id) + 0x9E3779B97F4A7C15ULL) & Low63;
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL) & Low63;
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EBULL) & Low63;
    return (z ^ (z >> 31)) << 1;
  };
  // Each point's hash made once and read per corner (on usual meshes from nearby entries, which
  // the cache holds): fewer instructions than hashing every corner's next point. A point's hash
  // and sum side by side: a corner's update and its neighbours' hashes touch half the cache lines.
  struct HashSum
  {
    std::uint64_t Hash, Sum;
  };
  Buffer<HashSum> table(numPts);
  HashSum* __restrict point = table.data();
  for (vtkIdType i = 0; i < numPts; ++i)
  {
    point[i].Hash = hash(i);
    point[i].Sum = 0;
  }
  // Adds @a d to point i's sum and marks the point used.
  auto add = [point](vtkIdType i, std::uint64_t d) { point[i].Sum = (point[i].Sum + d) | 1; };
  const vtkIdType* __restrict offsets = mesh.Offsets;
  const vtkIdType* __restrict conn = mesh.Conn;
  const vtkIdType numCells = mesh.NumCells;
  const std::uint64_t limit = static_cast<std::uint64_t>(numPts);
  auto outside = [limit](vtkIdType id) { return static_cast<std::uint64_t>(id) >= limit; };
  bool inRange = true;
  for (vtkIdType cell = 0; cell < numCells; ++cell)
  {
    const vtkIdType* corner = conn + offsets[cell];
    const vtkIdType n = offsets[cell + 1] - offsets[cell];
    // Triangles (the usual polygons) unrolled: each corner adds the hash of its next point minus
    // that of its previous one.
    if (n == 3)
    {
      const vtkIdType p = corner[0], q = corner[1], r = corner[2];
      // A quad split along (p, r) into the fan pair (p, q, r), (p, r, c) in one step: r's and p's
      // terms from the two triangles partly cancel (p: hq - hr + hr - hc), so four hashes and four
      // sums instead of six and six. The sums are wrapping integer additions, the same whatever
      // their grouping or order.
      if (cell + 1 < numCells && offsets[cell + 2] - offsets[cell + 1] == 3 && corner[3] == p &&
        corner[4] == r)
      {
        const vtkIdType c = corner[5];
        ++cell;
        if (outside(p) | outside(q) | outside(r) | outside(c))
        {
          inRange = false;
          continue;
        }
        const std::uint64_t hp = point[p].Hash, hq = point[q].Hash, hr = point[r].Hash,
                            hc = point[c].Hash;
        add(p, hq - hc);
        add(q, hr - hp);
        add(r, hc - hq);
        add(c, hp - hr);
        continue;
      }
      if (outside(p) | outside(q) | outside(r))
      {
        inRange = false;
        continue;
      }
      const std::uint64_t hp = point[p].Hash, hq = point[q].Hash, hr = point[r].Hash;
      add(p, hq - hr);
      add(q, hr - hp);
      add(r, hp - hq);
      continue;
    }
    bool bad = false;
    for (vtkIdType k = 0; k < n; ++k)
    {
      bad |= outside(corner[k]);
    }
    if (bad)
    {
      inRange = false;
      continue;
    }
    if (n < 2)
    {
      continue;
    }
    // The two edges at a corner (prev->k and k->next) at once: one update per corner.
    std::uint64_t prevHash = point[corner[n - 1]].Hash, hereHash = point[corner[0]].Hash;
    for (vtkIdType k = 0; k < n; ++k)
    {
      const std::uint64_t nextHash = point[corner[k + 1 < n ? k + 1 : 0]].Hash;
      add(corner[k], nextHash - prevHash);
      prevHash = hereHash;
      hereHash = nextHash;
    }
  }
  idsInRange = inRange;
  // Interior points: sum 0, marked used. Candidates: a non-zero sum, or no polygon at all.
  std::vector<vtkIdType> candidates;
  for (vtkIdType i = 0; i < numPts; ++i)
  {
    if (point[i].Sum != 1)
    {
      candidates.push_back(i);
    }
  }
  return candidates;
}

// Groups the points @a ids that lie within @a tol of one another (transitively): returns,
// per entry of @a ids, the index of its group's first entry. Serial and in id order, so
// the groups never depend on the thread count; candidates are few (boundary points only).
// Each candidate looks for earlier ones in the 27 cells of size @a tol around its own, in a
// flat hash table of cells (open addressing) whose entries head lists through the candidates.
template <typename R>
std::vector<vtkIdType> CoincidentGroups(
  const ArrayReader<R>& points, const std::vector<vtkIdType>& ids, double tol)
{
  using Key = std::array<double, 3>;
  // The bits of the three (whole-number) keys, mixed by multiplication. Adding +0 makes -0 and
  // +0, which compare equal, hash alike. (The hash only places cells: the groups found do not
  // depend on it.)
  auto hash = [](const Key& k)
  {
    std::uint64_t h = 0;
    for (double x : k)
    {
      x += 0.0;
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof(bits));
      h = (h ^ bits) * 0x9E3779B97F4A7C15ULL;
      h ^= h >> 29;
    }
    return h;
  };
  const size_t n = ids.size();
  size_t slots = 16;
  while (slots < 2 * n)
  {
    slots *= 2;
  }
  // Per slot its cell and the last candidate put there (-1: empty); per candidate the one put
  // in its cell before it.
  std::vector<Key> cellKey(slots);
  std::vector<vtkIdType> head(slots, -1), below(n, -1);
  auto slotOf = [&](const Key& k)
  {
    size_t s = hash(k) & (slots - 1);
    while (head[s] >= 0 && cellKey[s] != k)
    {
      s = (s + 1) & (slots - 1);
    }
    return s;
  };
  const double cell = tol > 0.0 ? tol : 1.0;
  std::vector<vtkIdType> parent(n);
  auto find = [&](vtkIdType k)
  {
    while (parent[k] != k)
    {
      k = parent[k] = parent[parent[k]];
    }
    return k;
  };
  for (size_t k = 0; k < n; ++k)
  {
    parent[k] = static_cast<vtkIdType>(k);
    double p[3];
    points.Get3(ids[k], p);
    const Key key = { std::floor(p[0] / cell), std::floor(p[1] / cell), std::floor(p[2] / cell) };
    for (int dx = -1; dx <= 1; ++dx)
    {
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dz = -1; dz <= 1; ++dz)
        {
          for (vtkIdType j = head[slotOf({ key[0] + dx, key[1] + dy, key[2] + dz })]; j >= 0;
               j = below[j])
          {
            double q[3];
            points.Get3(ids[j], q);
            const double d[3] = { p[0] - q[0], p[1] - q[1], p[2] - q[2] };
            if (Dot(d, d) <= tol * tol)
            {
              const vtkIdType a = find(static_cast<vtkIdType>(k)), b = find(j);
              parent[std::max(a, b)] = std::min(a, b);
            }
          }
        }
      }
    }
    const size_t s = slotOf(key);
    cellKey[s] = key;
    below[k] = head[s];
    head[s] = static_cast<vtkIdType>(k);
  }
  std::vector<vtkIdType> rep(n);
  for (size_t k = 0; k < n; ++k)
  {
    rep[k] = find(static_cast<vtkIdType>(k));
  }
  return rep;
}

// The diagonal of the input's bounding box as vtkDataSet::GetLength() gives it (in VTK 9.1 the
// bounds of all of a vtkPolyData's points), in one pass that the compiler vectorises: 24 lanes
// (8 points) per step, each lane always the same coordinate. The extremes of the same values are
// the same, so the length is GetLength()'s to the bit; non-finite coordinates (x - x is then NaN,
// else 0) are left to it.
template <typename R>
double DiagonalLength(const ArrayReader<R>& points, vtkIdType numPts, vtkDataSet* input)
{
  constexpr int Lanes = 24;
  const R* v = points.P;
  R lo[Lanes], hi[Lanes], nonFinite[Lanes];
  for (int j = 0; j < Lanes; ++j)
  {
    lo[j] = hi[j] = v[j % 3];
    nonFinite[j] = 0;
  }
  const vtkIdType n = 3 * numPts;
  vtkIdType i = 0;
  for (; i + Lanes <= n; i += Lanes)
  {
    for (int j = 0; j < Lanes; ++j)
    {
      const R x = v[i + j];
      lo[j] = std::min(lo[j], x);
      hi[j] = std::max(hi[j], x);
      nonFinite[j] += x - x;
    }
  }
  for (int j = 0; i < n; ++i, ++j)
  {
    const R x = v[i];
    lo[j] = std::min(lo[j], x);
    hi[j] = std::max(hi[j], x);
    nonFinite[j] += x - x;
  }
  double l = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    R a = lo[c], b = hi[c];
    for (int j = c; j < Lanes; j += 3)
    {
      if (nonFinite[j] != 0)
      {
        return input->GetLength();
      }
      a = std::min(a, lo[j]);
      b = std::max(b, hi[j]);
    }
    const double diff = static_cast<double>(b) - static_cast<double>(a);
    l += diff * diff;
  }
  return std::sqrt(l);
}

// dPdu and dPdv may be derivatives with respect to parameters (u,v) of which the texture
// coordinates are an axis-aligned affine function, s = o_s + r_s u, t = o_t + r_t v
// (vtkParametricSurfaceSource's TextureRepeat and TextureOffset). Estimates r_s and r_t by
// least squares over up to 4096 edges spread over the polygons: each edge's (du, dv) solves
// dP ~ dPdu du + dPdv dv, against its (ds, dt). Returns 1/r (so dP/ds = dPdu / r_s); exactly
// 1 when the fit is within its own error of it (0.1%, or twice the O(h^2) chord bias estimated
// from how far the derivatives turn along the edges: float positions and that bias would
// otherwise perturb the untransformed case) or cannot be made. Edges with an id outside the
// @a numPts points, or with texture coordinates that are not finite, are left out (the ids' check
// may come later, beside pass 1).
template <typename R>
void EstimateDerivativeScale(
  const Context<R>& c, const PolyLinks& mesh, vtkIdType numPts, double scale[2])
{
  scale[0] = scale[1] = 1.0;
  double su = 0.0, uu = 0.0, tv = 0.0, vv = 0.0, biasU = 0.0, biasV = 0.0;
  const vtkIdType stride = std::max<vtkIdType>(1, mesh.NumCells / 4096);
  for (vtkIdType cell = 0; cell < mesh.NumCells; cell += stride)
  {
    if (mesh.Offsets[cell + 1] - mesh.Offsets[cell] < 2)
    {
      continue;
    }
    const vtkIdType i = mesh.Conn[mesh.Offsets[cell]], j = mesh.Conn[mesh.Offsets[cell] + 1];
    if (i < 0 || i >= numPts || j < 0 || j >= numPts)
    {
      continue;
    }
    // The mean of the two ends' derivatives: exact for quadratic p, so the fit has no
    // first-order bias from the surface's curvature.
    double pi[3], pj[3], a[3], b[3], aj[3], bj[3], ta[3], tb[3];
    c.Points->Get3(i, pi);
    c.Points->Get3(j, pj);
    c.DPdu->Get3(i, a);
    c.DPdv->Get3(i, b);
    c.DPdu->Get3(j, aj);
    c.DPdv->Get3(j, bj);
    for (int k = 0; k < 3; ++k)
    {
      ta[k] = aj[k] - a[k];
      tb[k] = bj[k] - b[k];
      a[k] = 0.5 * (a[k] + aj[k]);
      b[k] = 0.5 * (b[k] + bj[k]);
    }
    const double dp[3] = { pj[0] - pi[0], pj[1] - pi[1], pj[2] - pi[2] };
    const double aa = Dot(a, a), ab = Dot(a, b), bb = Dot(b, b);
    const double det = aa * bb - ab * ab;
    if (!(det > 1e-12 * (aa + bb) * (aa + bb)))
    {
      continue;
    }
    double du = (bb * Dot(a, dp) - ab * Dot(b, dp)) / det;
    double dv = (aa * Dot(b, dp) - ab * Dot(a, dp)) / det;
    // The chord of an arc that turns its tangent by phi is tan(phi/2) / (phi/2) = 1 + phi^2/12
    // times the mean tangent's step, so (du, dv) comes out that much long: a bias of order h^2
    // (0.6% on a 24-segment circle), which the correction leaves at order h^4 (exact to that
    // order for constant-speed curves such as the parametric circles of a sphere or torus).
    double turn[3], step[3];
    for (int k = 0; k < 3; ++k)
    {
      turn[k] = ta[k] * du + tb[k] * dv;
      step[k] = a[k] * du + b[k] * dv;
    }
    const double step2 = Dot(step, step);
    double bias = 0.0;
    if (step2 > 0.0)
    {
      bias = Dot(turn, turn) / (12.0 * step2);
      const double shrink = 1.0 / (1.0 + bias);
      du *= shrink;
      dv *= shrink;
    }
    const double ds = c.TCoords->Get(j, 0) - c.TCoords->Get(i, 0);
    const double dt = c.TCoords->Get(j, 1) - c.TCoords->Get(i, 1);
    // A sample with texture coordinates (or derivatives) that are not finite says nothing.
    if (!std::isfinite(ds * du + dt * dv + du * du + dv * dv))
    {
      continue;
    }
    su += ds * du;
    uu += du * du;
    tv += dt * dv;
    vv += dv * dv;
    biasU += bias * du * du;
    biasV += bias * dv * dv;
  }
  const double r[2] = { uu > 0.0 ? su / uu : 1.0, vv > 0.0 ? tv / vv : 1.0 };
  // Within the estimate's own error of 1 (the correction above is exact for circles only, and
  // other curves, such as a torus's diagonals, keep part of the phi^2/12), r is 1: the common
  // case of texture coordinates that are the parameters, whose dPdu/dPdv are then used as given.
  const double tolerance[2] = { std::max(1e-3, uu > 0.0 ? 2.0 * biasU / uu : 0.0),
    std::max(1e-3, vv > 0.0 ? 2.0 * biasV / vv : 0.0) };
  for (int k = 0; k < 2; ++k)
  {
    if (std::isfinite(r[k]) && std::abs(r[k]) > 1e-12 && std::abs(r[k] - 1.0) > tolerance[k])
    {
      scale[k] = 1.0 / r[k];
    }
  }
}

// Points per task: small inputs run in the calling thread (no hand-over to a busy worker),
// large ones in chunks big enough to amortise the scheduling.
constexpr vtkIdType Grain = 16384;

// Exact's Context::FitNormals: each point's input normal made unit with FastNormalize's operations
// (a zero, infinite or NaN length leaves it as it is), and its s. Branch-free, so that the loop
// vectorises: square roots and divisions are exact per lane, the bits are FastNormalize's.
template <typename R>
struct FitNormalsWorker
{
  const ArrayReader<R>& Normals;
  const ArrayReader<R>& TCoords;
  double* Out;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    vtkSurfaceDetailVectorize::RunWidest(*this, begin, end);
  }

  VTK_ALWAYS_INLINE void Run(vtkIdType begin, vtkIdType end) const
  {
    const R* __restrict n = this->Normals.P;
    const R* __restrict tc = this->TCoords.P;
    const vtkIdType tnc = this->TCoords.NC;
    double* __restrict out = this->Out;
    for (vtkIdType i = begin; i < end; ++i)
    {
      const double v[3] = { n[3 * i], n[3 * i + 1], n[3 * i + 2] };
      const double len = std::sqrt(Dot(v, v));
      const bool scale = (len > 0.0) & (len < std::numeric_limits<double>::infinity());
      const double inv = 1.0 / len;
      out[4 * i] = scale ? v[0] * inv : v[0];
      out[4 * i + 1] = scale ? v[1] * inv : v[1];
      out[4 * i + 2] = scale ? v[2] * inv : v[2];
      out[4 * i + 3] = tc[tnc * i];
    }
  }
};

template <typename T>
vtkIdType CountNonFinite(const Texels<T>& tex)
{
  std::atomic<vtkIdType> count(0);
  vtkSMPTools::For(0, tex.H,
    [&](vtkIdType j0, vtkIdType j1)
    {
      vtkIdType local = 0;
      for (vtkIdType j = j0; j < j1; ++j)
      {
        for (int i = 0; i < tex.W; ++i)
        {
          const double v = static_cast<double>(
            tex.Data[(j * tex.W + i) * static_cast<vtkIdType>(tex.NC) + tex.Comp]);
          local += std::isfinite(v) ? 0 : 1;
        }
      }
      count += local;
    });
  return count;
}
} // namespace

//------------------------------------------------------------------------------
// Each part is valid while the objects it was built from are the same ones (compared, never
// dereferenced) and none of them, nor the polydata or its point data that hold them, was
// modified after its build time. A new object at a freed one's address is no risk: its
// construction (vtkObject::Modified) comes after the build time.
struct vtkDisplacementMapFilter::MeshCache
{
  struct Key
  {
    // polys, offsets, connectivity, points, their data, normals, texture coordinates, and one
    // more for a part built from other arrays (the derivative scale: dPdu and dPdv in place of
    // the normals)
    std::array<const void*, 8> Objects = {};
    vtkIdType NumPoints = -1;
  };

  // Links: from the polygons and the point count.
  Key LinksKey;
  vtkTimeStamp LinksTime;
  LinkTable Links;
  bool HaveLinks = false;

  // Seam groups (representative, member): from the polygons and the points.
  Key GroupsKey;
  vtkTimeStamp GroupsTime;
  double GroupsTolerance = -1.0;
  std::vector<std::pair<vtkIdType, vtkIdType>> Groups;
  bool HaveGroups = false;

  // Exact's unit input normals, each with its texture coordinate s (Context::FitNormals): from
  // the normals and the texture coordinates.
  Key NormalsKey;
  vtkTimeStamp NormalsTime;
  Buffer<double> FitNormals;
  bool HaveFitNormals = false;

  // The cell spans (the fits' and Mesh normals' ranges of points find their polygons through
  // them), and whether the point ids are too scattered for them (both then go through the links):
  // from the polygons and the point count.
  Key SpansKey;
  vtkTimeStamp SpansTime;
  CellSpans Spans;
  bool SpansScattered = false;
  bool HaveSpans = false;

  // Mesh's polygon orientations: from the polygons, the points and the normals.
  Key SignsKey;
  vtkTimeStamp SignsTime;
  Buffer<signed char> Signs;
  bool HaveSigns = false;

  // The fitted derivatives (Context::Fits): from the polygons, points, normals and texture
  // coordinates; Layout says which were fitted (1: P_s and P_t, 2: n_s and n_t) and in which
  // type (4: float, in FitsFloat).
  Key FitsKey;
  vtkTimeStamp FitsTime;
  int FitsLayout = 0;
  Buffer<double> Fits;
  Buffer<float> FitsFloat;
  bool HaveFits = false;

  // The derivative scale (Context::DerivativeScale; EstimateDerivativeScale's samples are scattered
  // over the mesh, so its few thousand cache misses are a serial delay before pass 1 of every
  // execution): from the polygons, the points, dPdu, dPdv and the texture coordinates.
  Key ScaleKey;
  vtkTimeStamp ScaleTime;
  double DerivativeScale[2] = { 1.0, 1.0 };
  bool HaveScale = false;

  // The polygons' and strips' point ids were found in range: from them and the point count.
  Key IdsKey;
  vtkTimeStamp IdsTime;
  bool IdsInRange = false;

  // The memory held, in bytes.
  size_t Bytes() const
  {
    return sizeof(vtkIdType) * (this->Links.Offsets.size() + this->Links.Links.size()) +
      sizeof(this->Groups[0]) * this->Groups.capacity() +
      sizeof(double) * (this->FitNormals.size() + this->Fits.size()) +
      sizeof(float) * this->FitsFloat.size() + this->Signs.size() + this->Spans.Bytes();
  }

  static bool Fresh(const Key& built, const Key& now, vtkMTimeType changed, const vtkTimeStamp& t)
  {
    return built.Objects == now.Objects && built.NumPoints == now.NumPoints &&
      changed <= t.GetMTime();
  }
};

//------------------------------------------------------------------------------
vtkDisplacementMapFilter::vtkDisplacementMapFilter()
  : Cache(new MeshCache)
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkDisplacementMapFilter::~vtkDisplacementMapFilter() = default;

//------------------------------------------------------------------------------
int vtkDisplacementMapFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkDisplacementMapFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The surface streams piece by piece; every piece needs the whole height map.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(),
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()));
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(),
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(),
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()));
  vtkInformation* mapInfo = inputVector[1]->GetInformationObject(0);
  if (mapInfo && mapInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    mapInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    mapInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    mapInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    mapInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
      mapInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkDisplacementMapFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkImageData* image = vtkImageData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  // The caller wants memory back after each update (this filter's flag, or every data
  // object's): nothing is kept for the next one.
  const bool keepNothing =
    this->GetReleaseDataFlag() || vtkDataObject::GetGlobalReleaseDataFlag() != 0;
  if (keepNothing)
  {
    // Also when this execution returns early (Scale 0, empty or bad input): the flag was set
    // after an execution that kept data.
    this->Cache.reset(new MeshCache);
  }
  if (!input || !output)
  {
    vtkErrorMacro("Input port 0 needs a vtkPolyData.");
    return 0;
  }
  if (!image)
  {
    vtkErrorMacro("Input port 1 needs the height map as a vtkImageData "
                  "(SetInputConnection(1, ...)).");
    return 0;
  }
  const vtkIdType numPts = input->GetNumberOfPoints();
  if (numPts == 0)
  {
    output->ShallowCopy(input);
    return 1;
  }
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The input has no 3-component point normals; displacement moves points "
                  "along them. Compute them with vtkPolyDataNormals (SplittingOff) or "
                  "generate the surface with vtkParametricSurfaceSource.");
    return 0;
  }
  if (!tcoords || tcoords->GetNumberOfComponents() < 2)
  {
    vtkErrorMacro("The input has no point texture coordinates (2 or more components); "
                  "they locate each point in the height map. Generate them, e.g. with "
                  "vtkParametricSurfaceSource or vtkTextureMapToSphere.");
    return 0;
  }
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1 || image->GetNumberOfPoints() == 0 || !scalars ||
    scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    vtkErrorMacro("The height map on input port 1 is empty or has no point scalars; give "
                  "it at least 1x1 texels with scalars.");
    return 0;
  }
  if (dims[2] != 1)
  {
    vtkErrorMacro("The height map is a " << dims[0] << "x" << dims[1] << "x" << dims[2]
                                         << " volume; it must be a 2-D image "
                                            "(extract a slice with vtkExtractVOI).");
    return 0;
  }
  if (dims[0] == 1 && dims[1] == 1)
  {
    // Valid (a 1x1 texture samples to its only texel), but seldom meant: say what it does.
    vtkWarningMacro("The height map is a single texel: a constant, so every point moves by the "
                    "same distance and the map gives the normals no slope.");
  }
  if (this->Component >= scalars->GetNumberOfComponents())
  {
    vtkErrorMacro("Component " << this->Component << " was asked for but the height map has "
                               << scalars->GetNumberOfComponents() << " component(s).");
    return 0;
  }
  const int type = scalars->GetDataType();
  double norm = 1.0;
  if (!vtkSurfaceDetail::HeightMapScale(type, norm))
  {
    vtkErrorMacro("The height map's scalars are " << scalars->GetDataTypeAsString()
                                                  << "; use unsigned char, unsigned short, "
                                                     "float or double (vtkImageCast).");
    return 0;
  }
  vtkDataArray* dPdu = input->GetPointData()->GetArray("dPdu");
  vtkDataArray* dPdv = input->GetPointData()->GetArray("dPdv");
  const bool haveDerivs =
    dPdu && dPdv && dPdu->GetNumberOfComponents() == 3 && dPdv->GetNumberOfComponents() == 3;
  // The fits and Mesh normals read each point's polygons through the cell spans or (point ids too
  // scattered for them) the links.
  const bool fitsNeedCells =
    this->NormalMode == Exact || (this->NormalMode == Approximate && !haveDerivs);
  const bool needCells = fitsNeedCells || this->NormalMode == Mesh;
  if (needCells && input->GetNumberOfStrips() > 0)
  {
    vtkErrorMacro("The input has triangle strips; normal mode " << this->GetNormalModeAsString()
                                                                << " needs polygons. Run "
                                                                   "vtkTriangleFilter first.");
    return 0;
  }

  // Every pass reads points through the cells: an id outside the points must stop the filter
  // before a pass reads it. Checked once per change of the cells or of the point count: here
  // where nothing moves (Scale 0), else beside pass 1 by the passes that read the polygons first
  // anyway, as they read them: the link build (which pass 1 waits for where it reads the cells)
  // and the seam sweep (the derivative-scale estimate, the other reader there, skips ids outside
  // the points); by a separate pass where neither runs.
  vtkCellArray* polys = input->GetPolys();
  vtkCellArray* strips = input->GetStrips();
  MeshCache::Key idsKey;
  idsKey.Objects = { polys, polys->GetConnectivityArray(), strips, strips->GetConnectivityArray() };
  idsKey.NumPoints = numPts;
  auto idsChecked = [&]()
  {
    MeshCache& cache = *this->Cache;
    cache.IdsKey = idsKey;
    cache.IdsTime.Modified();
    cache.IdsInRange = true;
  };
  auto idsInRange = [&]()
  {
    if (!vtkSurfaceDetailCells::PointIdsInRange(polys, numPts) ||
      !vtkSurfaceDetailCells::PointIdsInRange(strips, numPts))
    {
      return false;
    }
    idsChecked();
    return true;
  };
  auto idsError = [&]()
  {
    vtkErrorMacro("A polygon or triangle strip of the input names a point id outside [0, "
      << numPts << "); fix the connectivity (e.g. with vtkCleanPolyData) first.");
  };
  bool checkIdsBeside = false;
  {
    MeshCache& cache = *this->Cache;
    const vtkMTimeType idsChanged = std::max(
      { input->vtkObject::GetMTime(), polys->GetMTime(), polys->GetConnectivityArray()->GetMTime(),
        strips->GetMTime(), strips->GetConnectivityArray()->GetMTime() });
    if (!cache.IdsInRange || !MeshCache::Fresh(cache.IdsKey, idsKey, idsChanged, cache.IdsTime))
    {
      cache.IdsInRange = false;
      checkIdsBeside = this->Scale != 0.0;
      if (!checkIdsBeside && !idsInRange())
      {
        idsError();
        return 0;
      }
    }
  }

  if (this->Scale == 0.0 && this->NormalMode != Mesh)
  {
    // Nothing moves, so nothing changes: the input itself, bit for bit.
    output->ShallowCopy(input);
    return 1;
  }

  const int W = dims[0], H = dims[1];
  const int nc = scalars->GetNumberOfComponents();
  void* raw = scalars->GetVoidPointer(0);

  // VTK 9.1's tangents attribute takes 3 components only, so DESIGN.md's 4-component
  // frame is found by its name "Tangents".
  vtkDataArray* inTangents = input->GetPointData()->GetTangents();
  if (!inTangents)
  {
    inTangents = input->GetPointData()->GetArray("Tangents");
  }
  const bool tangents = this->NormalMode != None && inTangents &&
    (inTangents->GetNumberOfComponents() == 3 || inTangents->GetNumberOfComponents() == 4);

  // One precision for all: float when every array used is float (what VTK's sources
  // make), else double; the outputs have it too. Arrays of another type or layout are
  // converted first, so that the passes read raw memory.
  vtkPoints* inPoints = input->GetPoints();
  std::vector<vtkDataArray*> used = { inPoints->GetData(), normals, tcoords };
  if (haveDerivs && (this->NormalMode == Approximate || this->NormalMode == Exact))
  {
    used.push_back(dPdu);
    used.push_back(dPdv);
  }
  if (tangents)
  {
    used.push_back(inTangents);
  }
  for (vtkDataArray* a : used)
  {
    if (a->GetNumberOfTuples() < numPts)
    {
      vtkErrorMacro("The point array " << (a->GetName() ? a->GetName() : "(unnamed)") << " has "
                                       << a->GetNumberOfTuples() << " tuples for " << numPts
                                       << " points; give it one tuple per point.");
      return 0;
    }
  }
  const bool allFloat = std::all_of(used.begin(), used.end(),
    [](vtkDataArray* a) { return a->GetDataType() == VTK_FLOAT && a->HasStandardMemoryLayout(); });
  auto execute = [&](auto precision) -> int
  {
    using R = decltype(precision);
    auto points = AsReal<R>(inPoints->GetData());
    auto normalsR = AsReal<R>(normals), tcoordsR = AsReal<R>(tcoords);
    const bool useDerivs =
      haveDerivs && (this->NormalMode == Approximate || this->NormalMode == Exact);
    auto dPduR = AsReal<R>(useDerivs ? dPdu : nullptr);
    auto dPdvR = AsReal<R>(useDerivs ? dPdv : nullptr);
    auto tangentsR = AsReal<R>(tangents ? inTangents : nullptr);

    // Outputs: nothing is allocated that is not asked for.
    vtkNew<vtkPoints> outPoints;
    outPoints->SetData(NewOutputArray<R>("Points", 3, numPts));
    vtkSmartPointer<vtkDataArray> outNormals, outTangents;
    if (this->NormalMode != None)
    {
      outNormals = NewOutputArray<R>(normals->GetName(), 3, numPts);
    }
    if (tangents)
    {
      outTangents =
        NewOutputArray<R>(inTangents->GetName(), inTangents->GetNumberOfComponents(), numPts);
    }

    ArrayReader<R> pts(points), nrm(normalsR), tc(tcoordsR);
    std::unique_ptr<ArrayReader<R>> du, dv, tan;
    ArrayWriter<R> wPoints(outPoints->GetData());
    std::unique_ptr<ArrayWriter<R>> wNormals, wTangents;
    Context<R> ctx;
    ctx.Points = &pts;
    ctx.Normals = &nrm;
    ctx.TCoords = &tc;
    ctx.Wrap = this->Wrap;
    ctx.Interpolation = this->Interpolation;
    ctx.NormalMode = this->NormalMode;
    ctx.Scale = this->Scale;
    ctx.Midlevel = this->Midlevel;
    ctx.OutPoints = &wPoints;
    if (useDerivs)
    {
      du.reset(new ArrayReader<R>(dPduR));
      dv.reset(new ArrayReader<R>(dPdvR));
      ctx.DPdu = du.get();
      ctx.DPdv = dv.get();
    }
    if (outNormals)
    {
      wNormals.reset(new ArrayWriter<R>(outNormals));
      ctx.OutNormals = wNormals.get();
    }
    if (tangents)
    {
      tan.reset(new ArrayReader<R>(tangentsR));
      wTangents.reset(new ArrayWriter<R>(outTangents));
      ctx.Tangents = tan.get();
      ctx.OutTangents = wTangents.get();
    }
    vtkSMPThreadLocal<std::vector<double>> fitScratch;
    ctx.FitScratch = &fitScratch;
    PolyLinks mesh;
    MeshCache& cache = *this->Cache;
    MeshCache::Key linksKey;
    linksKey.Objects = { polys, polys->GetOffsetsArray(), polys->GetConnectivityArray(), nullptr,
      nullptr };
    linksKey.NumPoints = numPts;
    // Data changed in place may be announced by the polydata's or the point data's Modified()
    // alone (the pipeline sees it): their own MTimes count too, not only the arrays'.
    const vtkMTimeType polyDataChanged = input->vtkObject::GetMTime();
    const vtkMTimeType pointDataChanged =
      std::max(polyDataChanged, input->GetPointData()->vtkObject::GetMTime());
    const vtkMTimeType linksChanged = std::max({ polyDataChanged, polys->GetMTime(),
      polys->GetOffsetsArray()->GetMTime(), polys->GetConnectivityArray()->GetMTime() });
    MeshCache::Key groupsKey = linksKey;
    groupsKey.Objects[3] = inPoints;
    groupsKey.Objects[4] = inPoints->GetData();
    const vtkMTimeType groupsChanged =
      std::max({ linksChanged, inPoints->GetMTime(), inPoints->GetData()->GetMTime() });
    const bool haveLinks =
      cache.HaveLinks && MeshCache::Fresh(cache.LinksKey, linksKey, linksChanged, cache.LinksTime);
    const bool haveGroups = cache.HaveGroups && cache.GroupsTolerance == this->SeamTolerance &&
      MeshCache::Fresh(cache.GroupsKey, groupsKey, groupsChanged, cache.GroupsTime);
    // Beside the seam sweep: the fits of pass 1 need the cell spans (and, where the ids are too
    // scattered for them, the links) as soon as it starts (built by the thread that then runs it,
    // while another thread sweeps the seams); Mesh normals need the spans only after pass 1 (built
    // beside it), the links only where the ids are scattered (built after pass 1, when the spans
    // have told).
    const bool haveSpans = needCells && cache.HaveSpans &&
      MeshCache::Fresh(cache.SpansKey, linksKey, linksChanged, cache.SpansTime);
    const bool spansFirst = fitsNeedCells && !haveSpans;
    const bool spansBeside = this->NormalMode == Mesh && !haveSpans;
    // False if a polygon names a point outside the input's.
    auto buildLinks = [&]()
    {
      cache.HaveLinks = false;
      if (!mesh.BuildLinks(numPts, cache.Links))
      {
        return false;
      }
      cache.LinksKey = linksKey;
      cache.LinksTime.Modified();
      cache.HaveLinks = true;
      return true;
    };
    auto buildSpans = [&]()
    {
      cache.HaveSpans = false;
      if (!cache.Spans.Build(mesh, numPts))
      {
        return false;
      }
      // Scattered point ids: each range of points (pass 1's at most Grain points, Mesh's tasks
      // multiples of it) would read most polygons; the links' gather is then cheaper.
      cache.SpansScattered = cache.Spans.Work(mesh, Grain) > CellSpans::MaxWork;
      cache.SpansKey = linksKey;
      cache.SpansTime.Modified();
      cache.HaveSpans = true;
      return true;
    };
    // Where links or spans are needed, building them checks the polygons' ids (the strips are none
    // then); kept ones (the polygons unchanged since a good build) check nothing, so the ids are
    // checked here, before anything reads them.
    if (checkIdsBeside && needCells && !spansFirst && !spansBeside)
    {
      if (!idsInRange())
      {
        idsError();
        return 0;
      }
      checkIdsBeside = false;
    }
    if (needCells || this->MergeSeams || useDerivs)
    {
      mesh.Build(polys);
      ctx.Polys = &mesh;
    }
    if (this->NormalMode == Exact)
    {
      Buffer<double>& fitNormals = cache.FitNormals;
      MeshCache::Key normalsKey;
      normalsKey.Objects[0] = normals;
      normalsKey.Objects[1] = tcoords;
      normalsKey.NumPoints = numPts;
      if (!cache.HaveFitNormals ||
        !MeshCache::Fresh(cache.NormalsKey, normalsKey,
          std::max({ pointDataChanged, normals->GetMTime(), tcoords->GetMTime() }),
          cache.NormalsTime))
      {
        cache.HaveFitNormals = false;
        fitNormals.Resize(4 * static_cast<size_t>(numPts));
        vtkSMPTools::For(0, numPts, Grain, FitNormalsWorker<R>{ nrm, tc, fitNormals.data() });
        cache.NormalsKey = normalsKey;
        cache.NormalsTime.Modified();
        cache.HaveFitNormals = true;
      }
      ctx.FitNormals = fitNormals.data();
    }
    const int fitsLayout = (this->NormalMode == Approximate && !useDerivs ? 1 : 0) |
      (this->NormalMode == Exact ? (useDerivs ? 2 : 3) : 0);
    const int floatFits = std::is_same<R, float>::value ? 4 : 0;
    MeshCache::Key fitsKey = groupsKey;
    fitsKey.Objects[5] = normals;
    fitsKey.Objects[6] = tcoords;
    bool keepFits = false;
    if (fitsLayout != 0)
    {
      const vtkMTimeType fitsChanged =
        std::max({ groupsChanged, pointDataChanged, normals->GetMTime(), tcoords->GetMTime() });
      ctx.FitsKnown = cache.HaveFits && cache.FitsLayout == (fitsLayout | floatFits) &&
        MeshCache::Fresh(cache.FitsKey, fitsKey, fitsChanged, cache.FitsTime);
      ctx.FitStride = ((fitsLayout & 1) ? 6 : 0) + ((fitsLayout & 2) ? 6 : 0);
      auto& fits = [&]() -> Buffer<R>&
      {
        if constexpr (std::is_same<R, float>::value)
        {
          return cache.FitsFloat;
        }
        else
        {
          return cache.Fits;
        }
      }();
      if (!ctx.FitsKnown)
      {
        cache.HaveFits = false;
        // Only one of the two types is kept.
        if constexpr (std::is_same<R, float>::value)
        {
          cache.Fits.Free();
        }
        else
        {
          cache.FitsFloat.Free();
        }
        fits.Resize(static_cast<size_t>(ctx.FitStride) * numPts);
        keepFits = true;
      }
      ctx.Fits = fits.data();
    }
    MeshCache::Key scaleKey = groupsKey;
    vtkMTimeType scaleChanged = 0;
    bool haveScale = false;
    if (useDerivs)
    {
      scaleKey.Objects[5] = dPdu;
      scaleKey.Objects[6] = dPdv;
      scaleKey.Objects[7] = tcoords;
      scaleChanged = std::max({ groupsChanged, pointDataChanged, dPdu->GetMTime(), dPdv->GetMTime(),
        tcoords->GetMTime() });
      haveScale = cache.HaveScale &&
        MeshCache::Fresh(cache.ScaleKey, scaleKey, scaleChanged, cache.ScaleTime);
      cache.HaveScale = cache.HaveScale && haveScale;
    }
    // Coincident points (seams, poles; from the input points alone) as groups of (representative,
    // member) in increasing order, so that every sum over a group has one order whatever the thread
    // count.
    static const std::vector<std::pair<vtkIdType, vtkIdType>> noGroups;
    std::vector<std::pair<vtkIdType, vtkIdType>>& groups = cache.Groups;
    const bool findsGroups = this->MergeSeams && !haveGroups;
    // False if a polygon names a point outside the input's (the seam sweep checks them).
    auto findGroups = [&]()
    {
      if (!findsGroups)
      {
        return true;
      }
      cache.HaveGroups = false;
      groups.clear();
      bool polygonIdsInRange = true;
      const std::vector<vtkIdType> candidates = BoundaryPoints(mesh, numPts, polygonIdsInRange);
      if (!polygonIdsInRange)
      {
        return false;
      }
      if (candidates.size() > 1)
      {
        // The input's bounds here, beside pass 1, which reads no bounds.
        const double seamTolerance = this->SeamTolerance * DiagonalLength(pts, numPts, input);
        const std::vector<vtkIdType> rep = CoincidentGroups(pts, candidates, seamTolerance);
        std::vector<unsigned char> isRep(candidates.size(), 0);
        for (size_t k = 0; k < candidates.size(); ++k)
        {
          if (rep[k] != static_cast<vtkIdType>(k))
          {
            groups.emplace_back(candidates[rep[k]], candidates[k]);
            isRep[rep[k]] = 1;
          }
        }
        for (size_t k = 0; k < candidates.size(); ++k)
        {
          if (isRep[k])
          {
            groups.emplace_back(candidates[k], candidates[k]);
          }
        }
        std::sort(groups.begin(), groups.end());
      }
      cache.GroupsKey = groupsKey;
      cache.GroupsTolerance = this->SeamTolerance;
      cache.GroupsTime.Modified();
      cache.HaveGroups = true;
      return true;
    };
    auto forEachGroup = [&](auto&& body)
    {
      const auto& g = this->MergeSeams ? groups : noGroups;
      for (size_t b = 0; b < g.size();)
      {
        size_t e = b;
        while (e < g.size() && g[e].first == g[b].first)
        {
          ++e;
        }
        body(b, e);
        b = e;
      }
    };
    // Pass 1: points, and the normals of the analytic modes.
    vtkIdType nonFinite = 0;
    bool idsOk = true;
    auto run = [&](auto* data)
    {
      using T = std::remove_const_t<std::remove_pointer_t<decltype(data)>>;
      Texels<T> tex{ data, W, H, nc, this->Component, norm, this->Midlevel, true };
      if (type == VTK_FLOAT || type == VTK_DOUBLE)
      {
        const vtkMTimeType changed = std::max(image->GetMTime(), scalars->GetMTime());
        if (this->NonFiniteScanArray != scalars || this->NonFiniteScanTime != changed ||
          this->NonFiniteScanComponent != this->Component)
        {
          this->NonFiniteCount = CountNonFinite(tex);
          this->NonFiniteScanArray = scalars;
          this->NonFiniteScanTime = changed;
          this->NonFiniteScanComponent = this->Component;
        }
        nonFinite = this->NonFiniteCount;
        tex.Clean = nonFinite == 0;
      }
      auto displace = [&](auto kind)
      {
        constexpr int interp = decltype(kind)::value;
        DisplaceWorker<interp, T, R> worker{ { ctx }, tex };
        // Pass 1 (threaded), the seam groups (serial) and the cell spans (or links) read only the
        // input and write apart: they run side by side on whichever threads pass 1 leaves. The
        // spans (and links) that the fits of pass 1 need first are built by the thread that then
        // starts pass 1, while another thread sweeps the seams; spans wanted only after pass 1
        // (Mesh) come first in the task list instead, so that they and the seam sweep start at
        // once on two threads and pass 1 fills the time they leave. The derivative-scale estimate
        // (serial, for pass 1 only) is made by the thread that then starts pass 1 too.
        bool linksOk = true;
        vtkSMPTools::For(0, 3, 1,
          [&](vtkIdType task0, vtkIdType task1)
          {
            for (vtkIdType task = task0; task < task1; ++task)
            {
              if (task == 0 && spansBeside)
              {
                linksOk = buildSpans();
              }
              else if (task == 0)
              {
                if (spansFirst)
                {
                  linksOk = buildSpans();
                }
                if (linksOk && fitsNeedCells && cache.SpansScattered)
                {
                  if (!haveLinks)
                  {
                    linksOk = buildLinks();
                  }
                  mesh.UseLinks(cache.Links);
                }
                else if (linksOk && fitsNeedCells)
                {
                  ctx.Spans = &cache.Spans;
                }
                if (useDerivs && haveScale)
                {
                  std::copy_n(cache.DerivativeScale, 2, ctx.DerivativeScale);
                }
                else if (useDerivs)
                {
                  EstimateDerivativeScale(ctx, mesh, numPts, ctx.DerivativeScale);
                }
                if (linksOk)
                {
                  vtkSMPTools::For(0, numPts, Grain, worker);
                }
              }
              else if (task == 1 && needCells)
              {
                idsOk = findGroups();
              }
              else if (task == 1 && checkIdsBeside && findsGroups)
              {
                // The seam sweep checks the polygons' ids as it reads them: the strips' are
                // left.
                idsOk = vtkSurfaceDetailCells::PointIdsInRange(strips, numPts) && findGroups();
                if (idsOk)
                {
                  idsChecked();
                }
              }
              else if (task == 1)
              {
                idsOk = (!checkIdsBeside || idsInRange()) && findGroups();
              }
              else if (spansBeside)
              {
                vtkSMPTools::For(0, numPts, Grain, worker);
              }
            }
          });
        idsOk = idsOk && linksOk;
        if (!idsOk)
        {
          return;
        }
        if (checkIdsBeside && needCells)
        {
          idsChecked();
        }
        // One displacement per group: the mean of the members' own.
        forEachGroup(
          [&](size_t b, size_t e)
          {
            double mean[3] = { 0.0, 0.0, 0.0 };
            for (size_t g = b; g < e; ++g)
            {
              double n[3], h, hs, ht;
              InputNormal(ctx, groups[g].second, n);
              const double d = Displacement<interp>(ctx, tex, groups[g].second, h, hs, ht);
              for (int k = 0; k < 3; ++k)
              {
                mean[k] += d * n[k];
              }
            }
            for (int k = 0; k < 3; ++k)
            {
              mean[k] /= static_cast<double>(e - b);
            }
            for (size_t g = b; g < e; ++g)
            {
              WritePoint(ctx, groups[g].second, mean);
            }
          });
      };
      switch (this->Interpolation)
      {
        case Nearest:
          displace(std::integral_constant<int, Nearest>());
          break;
        case Linear:
          displace(std::integral_constant<int, Linear>());
          break;
        default:
          displace(std::integral_constant<int, Cubic>());
          break;
      }
    };
    switch (type)
    {
      case VTK_UNSIGNED_CHAR:
        run(static_cast<const unsigned char*>(raw));
        break;
      case VTK_UNSIGNED_SHORT:
        run(static_cast<const unsigned short*>(raw));
        break;
      case VTK_FLOAT:
        run(static_cast<const float*>(raw));
        break;
      default:
        run(static_cast<const double*>(raw));
        break;
    }
    if (!idsOk)
    {
      idsError();
      return 0;
    }
    if (useDerivs && !haveScale)
    {
      std::copy_n(ctx.DerivativeScale, 2, cache.DerivativeScale);
      cache.ScaleKey = scaleKey;
      cache.ScaleTime.Modified();
      cache.HaveScale = true;
    }
    if (keepFits)
    {
      cache.FitsKey = fitsKey;
      cache.FitsLayout = fitsLayout | floatFits;
      cache.FitsTime.Modified();
      cache.HaveFits = true;
    }
    if (nonFinite > 0)
    {
      vtkWarningMacro(<< nonFinite << " height value(s) in component " << this->Component
                      << " of the height map are NaN or infinite; they are treated as Midlevel ("
                      << this->Midlevel << ").");
    }

    if (this->NormalMode == Mesh)
    {
      ArrayReader<R> moved(outPoints->GetData());
      MeshCache::Key signsKey = groupsKey;
      signsKey.Objects[5] = normals;
      const vtkMTimeType signsChanged =
        std::max({ groupsChanged, pointDataChanged, normals->GetMTime() });
      const bool haveSigns = cache.HaveSigns &&
        MeshCache::Fresh(cache.SignsKey, signsKey, signsChanged, cache.SignsTime);
      if (!haveSigns)
      {
        cache.HaveSigns = false;
        cache.Signs.Resize(std::max<vtkIdType>(mesh.NumCells, 1));
      }
      if (!cache.SpansScattered)
      {
        vtkSMPThreadLocal<std::vector<double>> sums;
        MeshScatterNormalWorker<R> worker{ { ctx }, cache.Spans, moved, cache.Signs.data(),
          haveSigns, sums, numPts, MeshScatterNormalWorker<R>::TaskSize(numPts) };
        vtkSMPTools::For(0, worker.Tasks(), 1, worker);
      }
      else
      {
        // Scattered point ids: each polygon's normal once, then gathered through the links.
        if (!haveLinks)
        {
          buildLinks();
        }
        mesh.UseLinks(cache.Links);
        Buffer<double> cellNormals(3 * static_cast<size_t>(mesh.NumCells));
        MeshPolygonNormalWorker<R> polygons{ ctx, moved, cellNormals.data(), cache.Signs.data(),
          haveSigns };
        vtkSMPTools::For(0, mesh.NumCells, Grain, polygons);
        MeshPointNormalWorker<R> worker{ { ctx }, cellNormals.data() };
        vtkSMPTools::For(0, numPts, Grain, worker);
      }
      if (!haveSigns)
      {
        cache.SignsKey = signsKey;
        cache.SignsTime.Modified();
        cache.HaveSigns = true;
      }
    }

    // One normal per group member: the sum of the members' that share its input normal.
    if (this->NormalMode != None)
    {
      ArrayReader<R> computed(outNormals);
      forEachGroup(
        [&](size_t b, size_t e)
        {
          std::vector<double> sums(3 * (e - b), 0.0);
          for (size_t g = b; g < e; ++g)
          {
            double ng[3];
            InputNormal(ctx, groups[g].second, ng);
            for (size_t h = b; h < e; ++h)
            {
              double nh[3], x[3];
              InputNormal(ctx, groups[h].second, nh);
              if (Dot(ng, nh) > 1.0 - 1e-9)
              {
                computed.Get3(groups[h].second, x);
                for (int k = 0; k < 3; ++k)
                {
                  sums[3 * (g - b) + k] += x[k];
                }
              }
            }
          }
          for (size_t g = b; g < e; ++g)
          {
            WriteNormalAndTangent(ctx, groups[g].second, &sums[3 * (g - b)]);
          }
        });
    }

    output->CopyStructure(input);
    output->SetPoints(outPoints);
    output->GetPointData()->PassData(input->GetPointData());
    output->GetCellData()->PassData(input->GetCellData());
    if (outNormals)
    {
      output->GetPointData()->SetNormals(outNormals);
    }
    if (outTangents && outTangents->GetNumberOfComponents() == 3)
    {
      output->GetPointData()->SetTangents(outTangents);
    }
    else if (outTangents)
    {
      output->GetPointData()->AddArray(outTangents);
    }
    return 1;
  };
  const int ok = allFloat ? execute(float()) : execute(double());
  if (keepNothing)
  {
    this->Cache.reset(new MeshCache);
  }
  return ok;
}

//------------------------------------------------------------------------------
const char* vtkDisplacementMapFilter::GetWrapAsString()
{
  return vtkSurfaceDetail::WrapModeName(this->Wrap);
}

//------------------------------------------------------------------------------
const char* vtkDisplacementMapFilter::GetInterpolationAsString()
{
  switch (this->Interpolation)
  {
    case Nearest:
      return "Nearest";
    case Cubic:
      return "Cubic";
    default:
      return "Linear";
  }
}

//------------------------------------------------------------------------------
const char* vtkDisplacementMapFilter::GetNormalModeAsString()
{
  switch (this->NormalMode)
  {
    case None:
      return "None";
    case Approximate:
      return "Approximate";
    case Mesh:
      return "Mesh";
    default:
      return "Exact";
  }
}

//------------------------------------------------------------------------------
void vtkDisplacementMapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scale: " << this->Scale << "\n";
  os << indent << "Midlevel: " << this->Midlevel << "\n";
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "Wrap: " << this->GetWrapAsString() << "\n";
  os << indent << "Interpolation: " << this->GetInterpolationAsString() << "\n";
  os << indent << "NormalMode: " << this->GetNormalModeAsString() << "\n";
  os << indent << "MergeSeams: " << (this->MergeSeams ? "On" : "Off") << "\n";
  os << indent << "SeamTolerance: " << this->SeamTolerance << "\n";
  os << indent << "NonFiniteCount (last scan of the height map): " << this->NonFiniteCount << "\n";
  os << indent << "Mesh data kept between executions: " << this->Cache->Bytes() << " bytes\n";
  os << indent << "Point ids too scattered for cell spans (point links used instead): "
     << (this->Cache->HaveSpans && this->Cache->SpansScattered ? "yes" : "no") << "\n";
}
