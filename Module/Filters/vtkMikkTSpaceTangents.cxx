#include "vtkMikkTSpaceTangents.h"

#include "vtkSurfaceDetailCells.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailGhosts.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolygon.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStaticCellLinksTemplate.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkMikkTSpaceTangents);

namespace
{
// Points, triangles and face corners are numbered with 32 bits: the records stay compact,
// and an input with more (CheckInput refuses it) can be processed in pieces.
using Index = vtkTypeInt32;

// Triangle flags, with the meanings of the reference implementation's, and where its own
// texture area was positive (OrientPreserving may be forced to its quad's).
constexpr int OrientPreserving = 1;
constexpr int GroupWithAny = 2;      // no usable texture derivatives: joins any group
constexpr int Degenerate = 4;        // two corners at the same position
constexpr int QuadOneDegenerate = 8; // a quad whose other triangle is degenerate
constexpr int PositiveArea = 16;
constexpr int CornerShift = 5; // bits 5-10: its corners' offsets in their face, 2 bits each

// Groups of more than this many triangles at one vertex (poles of hundreds of triangles)
// are not split into sub-groups: the pairwise test is quadratic.
constexpr size_t MaxSubGroupTest = 1024;

using Frame = std::array<float, 4>;
using CornerFrames = std::vector<std::pair<Index, Frame>>; // (face corner, frame)

// Sorts a list of corner frames by corner, for lookups.
void SortByCorner(CornerFrames& frames)
{
  std::sort(frames.begin(), frames.end(),
    [](const std::pair<Index, Frame>& x, const std::pair<Index, Frame>& y)
    { return x.first < y.first; });
}

// The reference's NotZero: single-precision values up to FLT_MIN count as zero.
inline bool NotZeroF(float x)
{
  return std::abs(x) > FLT_MIN;
}

// Normalises @a v if it has a length; a zero (or non-finite) vector stays as it is, as the
// reference leaves vectors that fail its VNotZero test.
inline void NormalizeIfNotZero(double v[3])
{
  const double len = std::sqrt(vtkSurfaceDetail::Dot(v, v));
  if (len > 0.0 && std::isfinite(len))
  {
    const double inv = 1.0 / len;
    v[0] *= inv;
    v[1] *= inv;
    v[2] *= inv;
  }
}

// @a v minus its part along unit @a n, normalised if not zero.
inline void ProjectNormalize(const double v[3], const double n[3], double out[3])
{
  const double d = vtkSurfaceDetail::Dot(n, v);
  out[0] = v[0] - d * n[0];
  out[1] = v[1] - d * n[1];
  out[2] = v[2] - d * n[2];
  NormalizeIfNotZero(out);
}

// The output frame of a corner from its tangent space: the direction made exactly
// orthogonal to the unit normal @a n, w from the orientation. A direction that leaves
// nothing across the normal (no usable texture derivatives, the reference's (1, 0, 0)
// placeholder along the normal, non-finite input) becomes any unit vector orthogonal to it.
Frame FinalFrame(const double n[3], const double os[3], bool orient)
{
  const double up[3] = { 0.0, 0.0, 1.0 };
  const double* nn = std::abs(vtkSurfaceDetail::Dot(n, n) - 1.0) < 1e-6 ? n : up;
  const double d = vtkSurfaceDetail::Dot(nn, os);
  double t[4] = { os[0] - d * nn[0], os[1] - d * nn[1], os[2] - d * nn[2], 0.0 };
  const double len = vtkSurfaceDetail::Normalize(t);
  if (!(len > 1e-6 && std::isfinite(len)))
  {
    const double zero[3] = { 0.0, 0.0, 0.0 };
    vtkSurfaceDetail::MakeTangentFrame(nn, zero, zero, t);
  }
  return { static_cast<float>(t[0]), static_cast<float>(t[1]), static_cast<float>(t[2]),
    orient ? 1.0f : -1.0f };
}

// The angle between two vectors whose cross product has length s and whose dot product is
// c: atan2(s, c) to within 1.2e-8 radians, from a polynomial for atan on [0, 1] (a
// Chebyshev fit of atan(q)/q in q^2), without the library call's cost per corner.
inline double CornerAngle(double s, double c)
{
  const double ac = std::abs(c);
  const bool steep = s > ac;
  const double q = (steep ? ac : s) / (steep ? s : ac);
  const double u = q * q, u2 = u * u, u4 = u2 * u2;
  const double p01 = 0.9999999842426364 - 0.3333306678069164 * u;
  const double p23 = 0.1999248357850966 - 0.1420257051178519 * u;
  const double p45 = 0.1063675409849997 - 0.07495445444194075 * u;
  const double p67 = 0.04258760747628684 - 0.016005030510568757 * u;
  const double p = (p01 + p23 * u2) + (p45 + p67 * u2) * u4 + 0.002834064300823229 * (u4 * u4);
  const double r = steep ? 0.5 * vtkMath::Pi() - q * p : q * p;
  return c < 0.0 ? vtkMath::Pi() - r : r;
}

/// One input array read in place, a value at a time: float and double arrays as they are
/// (a float widens to double exactly), an array of any other kind converted to double once.
class Values
{
public:
  explicit Values(vtkDataArray* array)
    : Stride(array->GetNumberOfComponents())
  {
    if (auto* f = vtkAOSDataArrayTemplate<float>::FastDownCast(array))
    {
      this->F = f->GetPointer(0);
    }
    else if (auto* d = vtkAOSDataArrayTemplate<double>::FastDownCast(array))
    {
      this->D = d->GetPointer(0);
    }
    else
    {
      auto copy = vtkSmartPointer<vtkDoubleArray>::New();
      copy->DeepCopy(array);
      this->D = copy->GetPointer(0);
      this->Copy = copy;
    }
  }
  double operator()(Index i, int k) const
  {
    const size_t at = static_cast<size_t>(this->Stride) * static_cast<size_t>(i) + k;
    return this->F ? this->F[at] : this->D[at];
  }

private:
  const float* F = nullptr;
  const double* D = nullptr;
  const int Stride;
  vtkSmartPointer<vtkDataArray> Copy;
};

/// The offsets or the connectivity of a vtkCellArray, 32- or 64-bit, read in place.
class Ids
{
public:
  Ids() = default;
  Ids(vtkCellArray* cells, bool offsets)
  {
    if (cells->IsStorage64Bit())
    {
      this->Wide =
        (offsets ? cells->GetOffsetsArray64() : cells->GetConnectivityArray64())->GetPointer(0);
    }
    else
    {
      this->Narrow =
        (offsets ? cells->GetOffsetsArray32() : cells->GetConnectivityArray32())->GetPointer(0);
    }
  }
  vtkIdType operator[](vtkIdType i) const { return this->Wide ? this->Wide[i] : this->Narrow[i]; }

private:
  const vtkTypeInt64* Wide = nullptr;
  const vtkTypeInt32* Narrow = nullptr;
};

/// The good triangles around one vertex and how they connect there.
struct Fan
{
  std::vector<Index> Tri, Degenerate; // increasing
  std::vector<int> Corner;            // the vertex's corner in each good triangle
  std::vector<Index> Next, Prev;      // the vertices after and before it there
  std::vector<int> Out, In;           // neighbour across (v, next) and (prev, v), or -1
  // Edge matching: an open-addressing table on the other vertex, chains in fan order.
  std::vector<Index> SlotKey;
  std::vector<int> SlotHead, SlotTail, Chain;
  // Per good triangle while evaluating:
  std::vector<int> Group, Members, Stack, Subset;
  std::vector<std::array<double, 3>> Os, Ot, Result;
  std::vector<double> Angle;
};

// Visits the triangles linked to fan entry @a s, depth first: enter(a) says whether a
// joins (and records it); only those that join spread further.
template <typename Enter>
void Flood(const Fan& fan, int s, std::vector<int>& stack, Enter&& enter)
{
  stack.assign(1, s);
  while (!stack.empty())
  {
    const int a = stack.back();
    stack.pop_back();
    if (enter(a))
    {
      for (int b : { fan.Out[a], fan.In[a] })
      {
        if (b >= 0)
        {
          stack.push_back(b);
        }
      }
    }
  }
}

// Triangles are neighbours across an edge they use in opposite directions. Where more than
// two share an edge, the reference pairs them greedily in triangle order: each unpaired one
// with the first later unpaired one running the other way. That pairs the r-th triangle
// leaving v towards x with the r-th one arriving from x, which a table of the arrivals by x
// (chained in fan order) finds in time linear in the fan. Every triangle on an edge at v is
// around v, so v's triangles alone decide its links, and the same way as at the other end.
void MatchEdges(Fan& fan)
{
  const int k = static_cast<int>(fan.Tri.size());
  size_t size = 8;
  while (size < 2 * static_cast<size_t>(k))
  {
    size *= 2;
  }
  const size_t mask = size - 1;
  fan.SlotKey.assign(size, -1);
  fan.SlotHead.assign(size, -1);
  fan.SlotTail.resize(size);
  fan.Chain.assign(k, -1);
  fan.Out.assign(k, -1);
  fan.In.assign(k, -1);
  auto slotOf = [&](Index x)
  {
    size_t s = (static_cast<std::uint32_t>(x) * 2654435761u) & mask;
    while (fan.SlotKey[s] >= 0 && fan.SlotKey[s] != x)
    {
      s = (s + 1) & mask;
    }
    return s;
  };
  for (int b = 0; b < k; ++b)
  {
    const size_t s = slotOf(fan.Prev[b]);
    if (fan.SlotKey[s] < 0)
    {
      fan.SlotKey[s] = fan.Prev[b];
      fan.SlotHead[s] = b;
    }
    else
    {
      fan.Chain[fan.SlotTail[s]] = b;
    }
    fan.SlotTail[s] = b;
  }
  for (int a = 0; a < k; ++a)
  {
    const size_t s = slotOf(fan.Next[a]);
    const int b = fan.SlotKey[s] >= 0 ? fan.SlotHead[s] : -1;
    if (b >= 0)
    {
      fan.SlotHead[s] = fan.Chain[b];
      fan.Out[a] = b;
      fan.In[b] = a;
    }
  }
}

/// The algorithm, stage by stage, on one input.
class MikkTSpace
{
public:
  MikkTSpace(vtkPolyData* input, vtkDataArray* normals, vtkDataArray* tcoords, double threshold)
    : Input(input)
    , NumberOfPoints(static_cast<Index>(input->GetNumberOfPoints()))
    , P(input->GetPoints()->GetData())
    , N(normals)
    , T(tcoords)
    , ThresholdCos(std::cos(vtkMath::RadiansFromDegrees(threshold)))
  {
  }

  void Weld();
  void BuildFaces();
  void BuildTriangles();
  void BuildLinks();
  void ResolveGroupWithAnyOrientation();
  void EvaluateVertices();
  void FixQuadsWithOneDegenerateTriangle();
  void SplitPoints();
  void Assemble(vtkPointData* inPD, vtkPolyData* output) const;
  vtkIdType NonFinitePoints = 0; // points with a non-finite coordinate

private:
  bool SameValues(Index a, Index b) const;
  std::uint32_t Hash(Index i) const;
  void Normal(Index pt, double n[3]) const;
  float MakeTriangle(Index t, vtkIdType base, const int offsets[3]);
  void TriangleDirections(Index t, double p[3][3], double os[3], double ot[3]) const;
  void BuildFan(Index v, Fan& fan);
  void EvaluateVertex(Index v, Fan& fan, CornerFrames& differing);
  void EvaluateCorners(const double n[3], Fan& fan) const;
  void EvaluateGroup(Fan& fan) const;
  void SetCornerFrame(Index v, Index c, const Frame& frame, CornerFrames& differing);
  Frame FrameOf(Index c, Index v) const;
  void DistinctFrames(const std::vector<Index>& corners, Index v, std::vector<int>& rank,
    std::vector<Index>& firsts) const;
  Index Vertex(Index t, int k) const { return this->TriVertex[3 * t + k]; }
  Index Corner(Index t, int k) const
  {
    return this->TriBase[t] + ((this->TriFlag[t] >> (CornerShift + 2 * k)) & 3);
  }
  bool Orient(Index t) const { return (this->TriFlag[t] & OrientPreserving) != 0; }

  vtkPolyData* Input;
  const Index NumberOfPoints;
  const Values P, N, T;
  const double ThresholdCos;
  std::unique_ptr<Index[]> WeldOf; // point -> vertex: the smallest point id with its values

  // Output polygons ("faces"): the input's triangles and quads (its own cell array when it
  // has nothing else), larger polygons and strips triangulated. FaceCell: the input cell
  // each came from, when they are not the input's polygons.
  vtkSmartPointer<vtkCellArray> Faces;
  Ids Offsets, Connectivity;
  std::vector<vtkIdType> FaceCell;
  bool FacesAreInputPolys = true;
  vtkSmartPointer<vtkDataArray> Renumbered; // the faces' connectivity after splits

  // Triangles of the faces with 3 or 4 corners, in face order (MikkTSpace's triangles): their
  // welded vertices, their face's first corner and their flags.
  Index NumberOfTriangles = 0;
  vtkNew<vtkTypeInt32Array> TriVertexArray;
  Index* TriVertex = nullptr;
  std::unique_ptr<Index[]> TriBase;
  std::unique_ptr<std::uint16_t[]> TriFlag;
  vtkStaticCellLinksTemplate<Index> Links; // vertex -> triangles, decreasing

  // Corner frames: most corners have their vertex's frame (the first one set, kept in the
  // output array at the vertex's point); the others are listed in Differing, sorted by
  // corner. Per vertex: NoFrame, OneFrame (for all its corners) or Mixed.
  CornerFrames Differing;
  enum VertexState : char
  {
    NoFrame,
    OneFrame,
    Mixed
  };
  std::unique_ptr<VertexState[]> State;
  vtkNew<vtkFloatArray> Tangents;
  Frame* VertexFrame = nullptr;
  std::vector<Index> ExtraSource; // the input point of each split point
};

bool MikkTSpace::SameValues(Index a, Index b) const
{
  return this->P(a, 0) == this->P(b, 0) && this->P(a, 1) == this->P(b, 1) &&
    this->P(a, 2) == this->P(b, 2) && this->N(a, 0) == this->N(b, 0) &&
    this->N(a, 1) == this->N(b, 1) && this->N(a, 2) == this->N(b, 2) &&
    this->T(a, 0) == this->T(b, 0) && this->T(a, 1) == this->T(b, 1);
}

// A hash of a point's values, the same for equal values (-0 and 0 included). A point with
// a NaN equals nothing, not even itself, and hashes its id, so that many such points do
// not make one long run to compare.
std::uint32_t MikkTSpace::Hash(Index i) const
{
  const double values[8] = { this->P(i, 0), this->P(i, 1), this->P(i, 2), this->N(i, 0),
    this->N(i, 1), this->N(i, 2), this->T(i, 0), this->T(i, 1) };
  std::uint64_t h = 1469598103934665603ULL;
  bool nan = false;
  for (double x : values)
  {
    nan |= x != x;
    x = x == 0.0 ? 0.0 : x;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof(bits));
    h = (h ^ bits) * 0x100000001b3ULL;
    h ^= h >> 29;
  }
  h = nan ? static_cast<std::uint64_t>(i) : h;
  h = (h ^ (h >> 33)) * 0xff51afd7ed558ccdULL;
  return static_cast<std::uint32_t>(h >> 32);
}

// The point's normal, normalised (the reference assumes unit normals).
void MikkTSpace::Normal(Index pt, double n[3]) const
{
  n[0] = this->N(pt, 0);
  n[1] = this->N(pt, 1);
  n[2] = this->N(pt, 2);
  NormalizeIfNotZero(n);
}

// Sorts @a keys by their upper 32 bits, stably: a radix sort whose passes count digits per
// fixed block of keys, in parallel, so that nothing depends on the number of threads.
void SortByUpperHalf(std::vector<std::uint64_t>& keys)
{
  constexpr int Bits = 11;
  constexpr size_t Bins = size_t(1) << Bits, Block = size_t(1) << 16;
  const size_t n = keys.size(), nBlocks = (n + Block - 1) / Block;
  std::vector<std::uint64_t> sorted(n);
  std::vector<size_t> start(nBlocks * Bins);
  for (int shift = 32; shift < 64; shift += Bits)
  {
    auto digit = [shift](std::uint64_t key) { return (key >> shift) & (Bins - 1); };
    vtkSMPTools::For(0, static_cast<vtkIdType>(nBlocks),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (size_t b = begin; b < static_cast<size_t>(end); ++b)
        {
          size_t* count = &start[b * Bins];
          std::fill_n(count, Bins, 0);
          for (size_t i = b * Block; i < std::min(n, (b + 1) * Block); ++i)
          {
            ++count[digit(keys[i])];
          }
        }
      });
    size_t sum = 0;
    for (size_t d = 0; d < Bins; ++d)
    {
      for (size_t b = 0; b < nBlocks; ++b)
      {
        const size_t count = start[b * Bins + d];
        start[b * Bins + d] = sum;
        sum += count;
      }
    }
    vtkSMPTools::For(0, static_cast<vtkIdType>(nBlocks),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (size_t b = begin; b < static_cast<size_t>(end); ++b)
        {
          size_t* next = &start[b * Bins];
          for (size_t i = b * Block; i < std::min(n, (b + 1) * Block); ++i)
          {
            sorted[next[digit(keys[i])]++] = keys[i];
          }
        }
      });
    keys.swap(sorted);
  }
}

// MikkTSpace identifies corners by value: points with identical position, normal and
// texture coordinates are one vertex even if the cells do not share them. The points are
// sorted by a hash of their values (hashed in parallel, then radix sorted), so that equal
// points meet in runs of equal hashes, where they are compared value by value; each run is
// in point order, so a vertex is its smallest point id.
void MikkTSpace::Weld()
{
  const Index n = this->NumberOfPoints;
  std::vector<std::uint64_t> keys(n);
  vtkSMPThreadLocal<vtkIdType> nonFinite(0);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkIdType& count = nonFinite.Local();
      for (Index i = static_cast<Index>(begin); i < end; ++i)
      {
        keys[i] = (static_cast<std::uint64_t>(this->Hash(i)) << 32) | static_cast<std::uint32_t>(i);
        count += !(std::isfinite(this->P(i, 0)) && std::isfinite(this->P(i, 1)) &&
          std::isfinite(this->P(i, 2)));
      }
    });
  for (vtkIdType count : nonFinite)
  {
    this->NonFinitePoints += count;
  }
  SortByUpperHalf(keys);
  this->WeldOf.reset(new Index[n]);
  auto hashAt = [&keys](vtkIdType i) { return keys[i] >> 32; };
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      // Runs that began before this range belong to the range that has their start.
      while (begin > 0 && begin < end && hashAt(begin) == hashAt(begin - 1))
      {
        ++begin;
      }
      std::vector<Index> firsts; // the first point of each value met in the run
      for (vtkIdType r = begin; r < end;)
      {
        firsts.clear();
        const vtkIdType first = r;
        for (; r < n && hashAt(r) == hashAt(first); ++r)
        {
          const Index i = static_cast<Index>(keys[r]);
          const auto same = std::find_if(
            firsts.begin(), firsts.end(), [&](Index j) { return this->SameValues(i, j); });
          this->WeldOf[i] = same == firsts.end() ? i : *same;
          if (same == firsts.end())
          {
            firsts.push_back(i);
          }
        }
      }
    });
}

// Triangles and quads as they are (MikkTSpace takes both), larger polygons triangulated
// (ear cutting, a fan where that fails), polygons of fewer than 3 points kept, strips
// split into triangles (every other one turned round, those with a repeated point left
// out). Every triangle made here keeps the cell data of the cell it came from.
void MikkTSpace::BuildFaces()
{
  vtkPolyData* input = this->Input;
  vtkCellArray* inPolys = input->GetPolys();
  this->Faces = inPolys;
  if (input->GetNumberOfStrips() != 0 || inPolys->GetMaxCellSize() > 4)
  {
    this->FacesAreInputPolys = false;
    this->Faces = vtkSmartPointer<vtkCellArray>::New();
    if (!inPolys->IsStorage64Bit())
    {
      this->Faces->Use32BitStorage();
    }
    const vtkIdType nLead = input->GetNumberOfVerts() + input->GetNumberOfLines();
    this->FaceCell.reserve(input->GetNumberOfPolys());
    auto addFace = [&](vtkIdType npts, const vtkIdType* ids, vtkIdType cell)
    {
      this->Faces->InsertNextCell(npts, ids);
      this->FaceCell.push_back(cell);
    };
    vtkNew<vtkPolygon> polygon;
    vtkNew<vtkIdList> triIds;
    vtkIdType cell = nLead;
    auto polys = vtk::TakeSmartPointer(inPolys->NewIterator());
    for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cell)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      polys->GetCurrentCell(npts, pts);
      if (npts <= 4)
      {
        addFace(npts, pts, cell);
        continue;
      }
      polygon->Initialize(static_cast<int>(npts), pts, input->GetPoints());
      triIds->Reset();
      const bool ok =
        polygon->Triangulate(triIds) != 0 && triIds->GetNumberOfIds() == 3 * (npts - 2);
      for (vtkIdType t = 0; t < npts - 2; ++t)
      {
        vtkIdType tri[3];
        for (int k = 0; k < 3; ++k)
        {
          tri[k] = ok ? pts[triIds->GetId(3 * t + k)] : pts[k == 0 ? 0 : t + k];
        }
        addFace(3, tri, cell);
      }
    }
    auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
    for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cell)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      strips->GetCurrentCell(npts, pts);
      for (vtkIdType k = 0; k + 2 < npts; ++k)
      {
        const vtkIdType tri[3] = { pts[k + (k & 1)], pts[k + 1 - (k & 1)], pts[k + 2] };
        if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2])
        {
          addFace(3, tri, cell);
        }
      }
    }
  }
  this->Offsets = Ids(this->Faces, true);
  this->Connectivity = Ids(this->Faces, false);
}

// One triangle per triangle face, two per quad, split along the shorter texture diagonal
// (the shorter position diagonal on a tie), in parallel over blocks of faces whose first
// triangles come from a count per block. A quad's two triangles are forced to one
// orientation.
//
// The decisions (which diagonal, the sign of the texture area, whether the derivatives are
// usable) are the reference's own expressions in its single precision, on the values it
// would be given as floats, so that every tool that bakes with MikkTSpace takes the same
// ones: near zero, double precision would give another sign or call a float cancellation a
// direction.
void MikkTSpace::BuildTriangles()
{
  const Ids& off = this->Offsets;
  const Ids& conn = this->Connectivity;
  const vtkIdType nFaces = this->Faces->GetNumberOfCells();
  auto trianglesOf = [&](vtkIdType f)
  {
    const vtkIdType n = off[f + 1] - off[f];
    return n == 3 ? 1 : (n == 4 ? 2 : 0);
  };
  constexpr vtkIdType Block = 4096;
  const vtkIdType nBlocks = (nFaces + Block - 1) / Block;
  std::vector<Index> first(nBlocks + 1, 0);
  vtkSMPTools::For(0, nBlocks,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        for (vtkIdType f = b * Block; f < std::min(nFaces, (b + 1) * Block); ++f)
        {
          first[b + 1] += trianglesOf(f);
        }
      }
    });
  std::partial_sum(first.begin(), first.end(), first.begin());
  const Index nTris = this->NumberOfTriangles = first.back();
  this->TriVertexArray->SetNumberOfValues(3 * static_cast<vtkIdType>(nTris));
  this->TriVertex = this->TriVertexArray->GetPointer(0);
  this->TriBase.reset(new Index[nTris]);
  this->TriFlag.reset(new std::uint16_t[nTris]);
  // Squared distance between the points of face corners i and j, as floats, in texture
  // space or in space.
  auto dist2 = [&](const Values& x, int nc, vtkIdType i, vtkIdType j)
  {
    float d2 = 0.0f;
    for (int k = 0; k < nc; ++k)
    {
      const float d = static_cast<float>(x(static_cast<Index>(conn[j]), k)) -
        static_cast<float>(x(static_cast<Index>(conn[i]), k));
      d2 += d * d;
    }
    return d2;
  };
  vtkSMPTools::For(0, nBlocks,
    [&](vtkIdType begin, vtkIdType end)
    {
      const int split[2][6] = { { 0, 1, 3, 1, 2, 3 }, { 0, 1, 2, 0, 2, 3 } };
      for (vtkIdType blk = begin; blk < end; ++blk)
      {
        Index t = first[blk];
        for (vtkIdType f = blk * Block; f < std::min(nFaces, (blk + 1) * Block); ++f)
        {
          const int nt = trianglesOf(f);
          const vtkIdType b = off[f];
          const bool diag02 = nt != 2 ||
            dist2(this->T, 2, b, b + 2) < dist2(this->T, 2, b + 1, b + 3) ||
            (!(dist2(this->T, 2, b + 1, b + 3) < dist2(this->T, 2, b, b + 2)) &&
              !(dist2(this->P, 3, b + 1, b + 3) < dist2(this->P, 3, b, b + 2)));
          float area[2];
          for (int i = 0; i < nt; ++i)
          {
            area[i] = this->MakeTriangle(t + i, b, split[diag02] + 3 * i);
          }
          if (nt == 2)
          {
            std::uint16_t& fa = this->TriFlag[t];
            std::uint16_t& fb = this->TriFlag[t + 1];
            if (((fa ^ fb) & Degenerate) != 0)
            {
              fa |= QuadOneDegenerate;
              fb |= QuadOneDegenerate;
            }
            else if (!(fa & Degenerate) && ((fa ^ fb) & OrientPreserving) != 0)
            {
              // An inconsistently mapped quad: the larger texture area (or the triangle with
              // usable derivatives) decides its orientation.
              const bool keepFirst = (fb & GroupWithAny) || std::abs(area[0]) >= std::abs(area[1]);
              std::uint16_t& to = keepFirst ? fb : fa;
              to = (to & ~OrientPreserving) | ((keepFirst ? fa : fb) & OrientPreserving);
            }
          }
          t += nt;
        }
      }
    });
}

// Triangle t of the face whose first corner is @a base, with the face's corners base +
// offsets[k]: its welded vertices and its flags (the reference's expressions in single
// precision: eq. 18, 19 of its description, CalcTexArea). Returns the signed texture area
// as the reference computes it.
float MikkTSpace::MakeTriangle(Index t, vtkIdType base, const int offsets[3])
{
  Index pt[3];
  float p[3][3], tc[3][2];
  for (int k = 0; k < 3; ++k)
  {
    pt[k] = static_cast<Index>(this->Connectivity[base + offsets[k]]);
    this->TriVertex[3 * t + k] = this->WeldOf[pt[k]];
    for (int c = 0; c < 3; ++c)
    {
      p[k][c] = static_cast<float>(this->P(pt[k], c));
    }
    tc[k][0] = static_cast<float>(this->T(pt[k], 0));
    tc[k][1] = static_cast<float>(this->T(pt[k], 1));
  }
  const float t21x = tc[1][0] - tc[0][0], t21y = tc[1][1] - tc[0][1];
  const float t31x = tc[2][0] - tc[0][0], t31y = tc[2][1] - tc[0][1];
  const float area = t21x * t31y - t21y * t31x;
  float os2 = 0.0f, ot2 = 0.0f;
  for (int k = 0; k < 3; ++k)
  {
    const float d1 = p[1][k] - p[0][k], d2 = p[2][k] - p[0][k];
    const float os = t31y * d1 - t21y * d2, ot = -t31x * d1 + t21x * d2;
    os2 += os * os;
    ot2 += ot * ot;
  }
  const float absArea = std::abs(area);
  const bool usable =
    NotZeroF(area) && NotZeroF(std::sqrt(os2) / absArea) && NotZeroF(std::sqrt(ot2) / absArea);
  auto same = [this](Index a, Index b)
  {
    return this->P(a, 0) == this->P(b, 0) && this->P(a, 1) == this->P(b, 1) &&
      this->P(a, 2) == this->P(b, 2);
  };
  int flag = (area > 0.0f ? OrientPreserving | PositiveArea : 0) | (usable ? 0 : GroupWithAny) |
    (same(pt[0], pt[1]) || same(pt[0], pt[2]) || same(pt[1], pt[2]) ? Degenerate : 0);
  for (int k = 0; k < 3; ++k)
  {
    flag |= offsets[k] << (CornerShift + 2 * k);
  }
  this->TriBase[t] = static_cast<Index>(base);
  this->TriFlag[t] = static_cast<std::uint16_t>(flag);
  return area;
}

// The vertex -> triangles links, with VTK's static links over the triangles' welded
// vertices.
void MikkTSpace::BuildLinks()
{
  vtkNew<vtkCellArray> triangles;
  triangles->SetData(3, this->TriVertexArray);
  this->Links.SerialBuildLinks(this->NumberOfPoints, this->NumberOfTriangles, triangles);
}

// Triangle t's positions @a p and the directions of dP/ds and dP/dt, normalised (eq. 18, 19
// of the reference's description, in double; zero when it has no usable derivatives).
void MikkTSpace::TriangleDirections(Index t, double p[3][3], double os[3], double ot[3]) const
{
  double tc[3][2];
  for (int k = 0; k < 3; ++k)
  {
    const Index pt = this->Vertex(t, k);
    p[k][0] = this->P(pt, 0);
    p[k][1] = this->P(pt, 1);
    p[k][2] = this->P(pt, 2);
    tc[k][0] = this->T(pt, 0);
    tc[k][1] = this->T(pt, 1);
  }
  const int flag = this->TriFlag[t];
  const bool usable = !(flag & GroupWithAny);
  const double sign = (flag & PositiveArea) ? 1.0 : -1.0;
  const double s21 = tc[1][1] - tc[0][1], s31 = tc[2][1] - tc[0][1];
  const double r21 = tc[1][0] - tc[0][0], r31 = tc[2][0] - tc[0][0];
  for (int k = 0; k < 3; ++k)
  {
    const double d1 = p[1][k] - p[0][k], d2 = p[2][k] - p[0][k];
    os[k] = usable ? sign * (s31 * d1 - s21 * d2) : 0.0;
    ot[k] = usable ? sign * (r21 * d2 - r31 * d1) : 0.0;
  }
  NormalizeIfNotZero(os);
  NormalizeIfNotZero(ot);
}

// The triangles around v from its links, and their neighbours there.
void MikkTSpace::BuildFan(Index v, Fan& fan)
{
  fan.Tri.clear();
  fan.Degenerate.clear();
  fan.Corner.clear();
  fan.Next.clear();
  fan.Prev.clear();
  const Index* links = this->Links.GetCells(v);
  for (vtkIdType l = this->Links.GetNcells(v) - 1; l >= 0; --l)
  {
    const Index t = links[l];
    if (this->TriFlag[t] & Degenerate)
    {
      if (fan.Degenerate.empty() || fan.Degenerate.back() != t)
      {
        fan.Degenerate.push_back(t);
      }
      continue;
    }
    const int i = this->Vertex(t, 0) == v ? 0 : (this->Vertex(t, 1) == v ? 1 : 2);
    fan.Tri.push_back(t);
    fan.Corner.push_back(i);
    fan.Next.push_back(this->Vertex(t, (i + 1) % 3));
    fan.Prev.push_back(this->Vertex(t, (i + 2) % 3));
  }
  MatchEdges(fan);
}

// A triangle without usable derivatives takes the orientation of the first group that
// reaches it, at any of its vertices: the reference's one order dependency. Its group
// building is replayed (seeds in triangle and corner order, each flooding across linked
// neighbours of its orientation) at the vertices that have such triangles; elsewhere it
// cannot matter. Afterwards every vertex's groups depend on its own triangles only.
void MikkTSpace::ResolveGroupWithAnyOrientation()
{
  const Index nTris = this->NumberOfTriangles;
  auto withAny = [this](Index t)
  { return (this->TriFlag[t] & (GroupWithAny | Degenerate)) == GroupWithAny; };
  vtkSMPThreadLocal<char> found(0);
  vtkSMPTools::For(0, nTris,
    [&](vtkIdType begin, vtkIdType end)
    {
      char& any = found.Local();
      for (Index t = static_cast<Index>(begin); t < end && !any; ++t)
      {
        any = withAny(t);
      }
    });
  if (std::none_of(found.begin(), found.end(), [](char any) { return any != 0; }))
  {
    return;
  }
  std::vector<char> anyVertex(this->NumberOfPoints, 0);
  for (Index t = 0; t < nTris; ++t)
  {
    for (int k = 0; k < 3 && withAny(t); ++k)
    {
      anyVertex[this->Vertex(t, k)] = 1;
    }
  }
  std::vector<char> assigned(3 * static_cast<size_t>(nTris), 0);
  std::unordered_map<Index, Fan> fans;
  std::vector<int> stack;
  for (Index t = 0; t < nTris; ++t)
  {
    for (int i = 0; i < 3; ++i)
    {
      const Index v = this->Vertex(t, i);
      if (!anyVertex[v] || (this->TriFlag[t] & (GroupWithAny | Degenerate)) ||
        assigned[3 * static_cast<size_t>(t) + i])
      {
        continue;
      }
      auto at = fans.find(v);
      if (at == fans.end())
      {
        at = fans.emplace(v, Fan()).first;
        this->BuildFan(v, at->second);
      }
      const Fan& fan = at->second;
      const bool orient = this->Orient(t);
      const int seed =
        static_cast<int>(std::lower_bound(fan.Tri.begin(), fan.Tri.end(), t) - fan.Tri.begin());
      Flood(fan, seed, stack,
        [&](int a)
        {
          const Index u = fan.Tri[a];
          char* done = &assigned[3 * static_cast<size_t>(u)];
          std::uint16_t& flag = this->TriFlag[u];
          if (done[fan.Corner[a]])
          {
            return false;
          }
          if ((flag & GroupWithAny) && !done[0] && !done[1] && !done[2])
          {
            flag = static_cast<std::uint16_t>(
              (flag & ~OrientPreserving) | (orient ? OrientPreserving : 0));
          }
          done[fan.Corner[a]] = this->Orient(u) == orient ? 1 : 0;
          return done[fan.Corner[a]] != 0;
        });
    }
  }
}

// Per vertex, in parallel: its groups (the linked triangles of one orientation, seeded by
// one with usable derivatives), each corner's tangent space (the angle-weighted average of
// its sub-group's projected dP/ds directions), a quad's two spaces at one corner averaged,
// and the corners of degenerate triangles at the vertex. A vertex's first frame goes to the
// output array at its point.
void MikkTSpace::EvaluateVertices()
{
  const Index nPts = this->NumberOfPoints;
  this->State.reset(new VertexState[nPts]);
  std::fill_n(this->State.get(), nPts, NoFrame);
  this->Tangents->SetName("Tangents");
  this->Tangents->SetNumberOfComponents(4);
  this->Tangents->SetNumberOfTuples(nPts);
  this->VertexFrame = reinterpret_cast<Frame*>(this->Tangents->GetPointer(0));
  vtkSMPThreadLocal<CornerFrames> differing;
  vtkSMPTools::For(0, nPts,
    [&](vtkIdType begin, vtkIdType end)
    {
      Fan fan;
      CornerFrames& local = differing.Local();
      for (Index v = static_cast<Index>(begin); v < end; ++v)
      {
        if (this->Links.GetNcells(v) > 0)
        {
          this->EvaluateVertex(v, fan, local);
        }
      }
    });
  for (const auto& local : differing)
  {
    this->Differing.insert(this->Differing.end(), local.begin(), local.end());
  }
  SortByCorner(this->Differing);
}

// Each good triangle's directions projected onto the tangent plane of v's unit normal
// @a n, and its weight: the corner's angle between the edges projected onto that plane.
// From the cross and dot products it keeps the tiny angles of slivers (acos of a cosine
// rounded to 1 gives 0, and a group of slivers would have no direction at all); an edge
// along the normal leaves no direction, and the reference then takes the angle as a right
// angle.
void MikkTSpace::EvaluateCorners(const double n[3], Fan& fan) const
{
  const size_t k = fan.Tri.size();
  fan.Os.resize(k);
  fan.Ot.resize(k);
  fan.Angle.resize(k);
  fan.Result.resize(k);
  for (size_t a = 0; a < k; ++a)
  {
    const Index t = fan.Tri[a];
    double p[3][3], os[3], ot[3];
    this->TriangleDirections(t, p, os, ot);
    ProjectNormalize(os, n, fan.Os[a].data());
    ProjectNormalize(ot, n, fan.Ot[a].data());
    const int i = fan.Corner[a];
    const double* pv = p[i];
    const double* p0 = p[(i + 2) % 3];
    const double* p2 = p[(i + 1) % 3];
    const double d1[3] = { p0[0] - pv[0], p0[1] - pv[1], p0[2] - pv[2] };
    const double d2[3] = { p2[0] - pv[0], p2[1] - pv[1], p2[2] - pv[2] };
    const double n1 = vtkSurfaceDetail::Dot(n, d1), n2 = vtkSurfaceDetail::Dot(n, d2);
    const double e1[3] = { d1[0] - n1 * n[0], d1[1] - n1 * n[1], d1[2] - n1 * n[2] };
    const double e2[3] = { d2[0] - n2 * n[0], d2[1] - n2 * n[1], d2[2] - n2 * n[2] };
    double cross[3];
    vtkSurfaceDetail::Cross(e1, e2, cross);
    const bool zero = vtkSurfaceDetail::Dot(e1, e1) == 0.0 || vtkSurfaceDetail::Dot(e2, e2) == 0.0;
    const double angle = zero
      ? 0.5 * vtkMath::Pi()
      : CornerAngle(std::sqrt(vtkSurfaceDetail::Dot(cross, cross)), vtkSurfaceDetail::Dot(e1, e2));
    fan.Angle[a] = (this->TriFlag[t] & GroupWithAny) || !std::isfinite(angle) ? 0.0 : angle;
  }
}

void MikkTSpace::EvaluateVertex(Index v, Fan& fan, CornerFrames& differing)
{
  this->BuildFan(v, fan);
  const size_t k = fan.Tri.size();
  double n[3];
  this->Normal(v, n);
  this->EvaluateCorners(n, fan);
  // Groups, seeded in triangle order, each the linked triangles of its seed's orientation.
  fan.Group.assign(k, -1);
  for (size_t s = 0; s < k; ++s)
  {
    if (fan.Group[s] >= 0 || (this->TriFlag[fan.Tri[s]] & GroupWithAny))
    {
      continue;
    }
    const bool orient = this->Orient(fan.Tri[s]);
    fan.Members.clear();
    Flood(fan, static_cast<int>(s), fan.Stack,
      [&](int a)
      {
        if (fan.Group[a] >= 0 || this->Orient(fan.Tri[a]) != orient)
        {
          return false;
        }
        fan.Group[a] = static_cast<int>(s);
        fan.Members.push_back(a);
        return true;
      });
    std::sort(fan.Members.begin(), fan.Members.end());
    this->EvaluateGroup(fan);
  }
  // Per face corner: a quad's corner on its diagonal has a space from each triangle, which
  // the reference averages unless they are equal; the later group's orientation wins.
  // Most corners of a vertex share one space: its frame is made once.
  const double placeholder[3] = { 1.0, 0.0, 0.0 };
  double lastOs[3] = { 0.0, 0.0, 0.0 };
  int lastOrient = -1;
  Frame frame{};
  for (size_t a = 0; a < k; ++a)
  {
    const Index c = this->Corner(fan.Tri[a], fan.Corner[a]);
    const bool pair = a + 1 < k && this->Corner(fan.Tri[a + 1], fan.Corner[a + 1]) == c;
    const size_t b = pair ? a + 1 : a;
    const int ga = fan.Group[a], gb = fan.Group[b];
    double os[3];
    std::copy_n(
      ga >= 0 ? fan.Result[a].data() : (gb >= 0 ? fan.Result[b].data() : placeholder), 3, os);
    if (ga >= 0 && gb >= 0 && fan.Result[a] != fan.Result[b])
    {
      for (int i = 0; i < 3; ++i)
      {
        os[i] += fan.Result[b][i];
      }
      NormalizeIfNotZero(os);
    }
    const int g = std::max(ga, gb);
    const int orient = g >= 0 && this->Orient(fan.Tri[g]) ? 1 : 0;
    if (orient != lastOrient || !std::equal(os, os + 3, lastOs))
    {
      frame = FinalFrame(n, os, orient != 0);
      lastOrient = orient;
      std::copy_n(os, 3, lastOs);
    }
    this->SetCornerFrame(v, c, frame, differing);
    a = b;
  }
  // Degenerate triangles take the space of the vertex's first good triangle.
  for (Index d : fan.Degenerate)
  {
    if (this->TriFlag[d] & QuadOneDegenerate)
    {
      continue; // FixQuadsWithOneDegenerateTriangle
    }
    for (int j = 0; j < 3; ++j)
    {
      if (this->Vertex(d, j) == v)
      {
        // The first good triangle's frame is the vertex's (the first one set).
        this->SetCornerFrame(v, this->Corner(d, j),
          k > 0 ? this->VertexFrame[v] : FinalFrame(n, placeholder, false), differing);
      }
    }
  }
}

// The frame of corner c of vertex v: the vertex's own (its first) or, where it differs,
// listed; a vertex with several frames is Mixed, and only its points may need splitting.
void MikkTSpace::SetCornerFrame(Index v, Index c, const Frame& frame, CornerFrames& differing)
{
  if (this->State[v] == NoFrame)
  {
    this->State[v] = OneFrame;
    this->VertexFrame[v] = frame;
  }
  else if (std::memcmp(this->VertexFrame[v].data(), frame.data(), sizeof(Frame)) != 0)
  {
    this->State[v] = Mixed;
    differing.emplace_back(c, frame);
  }
}

Frame MikkTSpace::FrameOf(Index c, Index v) const
{
  const auto found = std::lower_bound(this->Differing.begin(), this->Differing.end(), c,
    [](const std::pair<Index, Frame>& x, Index y) { return x.first < y; });
  return found != this->Differing.end() && found->first == c ? found->second : this->VertexFrame[v];
}

// The space of each member of a group: the angle-weighted average, in increasing triangle
// order, of the projected dP/ds directions of its sub-group, the members whose dP/ds and
// dP/dt are both within the angular threshold of its own (the whole group at 180
// degrees, unless two are exactly opposite). Triangles of one quad always join.
void MikkTSpace::EvaluateGroup(Fan& fan) const
{
  auto joins = [&](int f, int a)
  {
    if (vtkSurfaceDetail::Dot(fan.Os[f].data(), fan.Os[a].data()) > this->ThresholdCos &&
      vtkSurfaceDetail::Dot(fan.Ot[f].data(), fan.Ot[a].data()) > this->ThresholdCos)
    {
      return true;
    }
    const Index tf = fan.Tri[f], ta = fan.Tri[a];
    return this->TriBase[tf] == this->TriBase[ta] ||
      ((this->TriFlag[tf] | this->TriFlag[ta]) & GroupWithAny);
  };
  auto average = [&](const std::vector<int>& subset)
  {
    std::array<double, 3> sum{ 0.0, 0.0, 0.0 };
    for (int a : subset)
    {
      for (int c = 0; c < 3; ++c)
      {
        sum[c] += fan.Angle[a] * fan.Os[a][c];
      }
    }
    NormalizeIfNotZero(sum.data());
    return sum;
  };
  const std::vector<int>& members = fan.Members;
  bool allJoin = true;
  for (size_t x = 0; x < members.size() && members.size() <= MaxSubGroupTest && allJoin; ++x)
  {
    for (size_t y = x + 1; y < members.size() && allJoin; ++y)
    {
      allJoin = joins(members[x], members[y]);
    }
  }
  if (allJoin)
  {
    const std::array<double, 3> all = average(members);
    for (int a : members)
    {
      fan.Result[a] = all;
    }
    return;
  }
  for (int f : members)
  {
    fan.Subset.clear();
    std::copy_if(members.begin(), members.end(), std::back_inserter(fan.Subset),
      [&](int a) { return joins(f, a); });
    fan.Result[f] = average(fan.Subset);
  }
}

// A quad with one degenerate triangle: its corner that only the degenerate triangle has
// takes the space of the good triangle's corner at the same position (made orthogonal to
// its own normal), or the placeholder if there is none. Rare: one serial pass.
void MikkTSpace::FixQuadsWithOneDegenerateTriangle()
{
  const double placeholder[3] = { 1.0, 0.0, 0.0 };
  CornerFrames added;
  for (Index t = 0; t + 1 < this->NumberOfTriangles; ++t)
  {
    if (!(this->TriFlag[t] & QuadOneDegenerate) || this->TriBase[t + 1] != this->TriBase[t])
    {
      continue;
    }
    const Index good = (this->TriFlag[t] & Degenerate) ? t + 1 : t;
    const Index c[3] = { this->Corner(good, 0), this->Corner(good, 1), this->Corner(good, 2) };
    Index missing = this->TriBase[t];
    while (missing == c[0] || missing == c[1] || missing == c[2])
    {
      ++missing;
    }
    const Index target = static_cast<Index>(this->Connectivity[missing]);
    const Index* src = std::find_if(c, c + 3,
      [&](Index j)
      {
        const Index pt = static_cast<Index>(this->Connectivity[j]);
        return this->P(pt, 0) == this->P(target, 0) && this->P(pt, 1) == this->P(target, 1) &&
          this->P(pt, 2) == this->P(target, 2);
      });
    double n[3];
    this->Normal(target, n);
    const Frame from = src == c + 3 ? Frame{ 1.0f, 0.0f, 0.0f, -1.0f }
                                    : this->FrameOf(*src, this->WeldOf[this->Connectivity[*src]]);
    const double os[3] = { from[0], from[1], from[2] };
    this->SetCornerFrame(this->WeldOf[target], missing,
      FinalFrame(n, src == c + 3 ? placeholder : os, from[3] > 0.0f), added);
    ++t;
  }
  this->Differing.insert(this->Differing.end(), added.begin(), added.end());
  SortByCorner(this->Differing);
}

// Every point gets its vertex's first frame (a point of a vertex no triangle reaches, some
// unit vector orthogonal to its normal). Then a point of a vertex with several frames keeps
// the frame of its first corner, and every other distinct frame among its corners becomes
// a new point after the input's, numbered in point order and then in order of first
// appearance; its corners are renumbered. Only those points' corners are looked at, found
// through the links of their vertices.
void MikkTSpace::SplitPoints()
{
  const Index nPts = this->NumberOfPoints;
  Frame* pointFrame = this->VertexFrame;
  vtkSMPTools::For(0, nPts,
    [&](vtkIdType begin, vtkIdType end)
    {
      const double zero[3] = { 0.0, 0.0, 0.0 };
      for (Index p = static_cast<Index>(begin); p < end; ++p)
      {
        const Index v = this->WeldOf[p];
        if (this->State[v] == NoFrame)
        {
          double n[3];
          this->Normal(p, n);
          pointFrame[p] = FinalFrame(n, zero, true);
        }
        else if (v != p)
        {
          pointFrame[p] = pointFrame[v];
        }
      }
    });
  // (point, corner) of the points of mixed vertices, in point and corner order.
  std::vector<std::pair<Index, Index>> corners;
  for (Index v = 0; v < nPts; ++v)
  {
    if (this->State[v] != Mixed)
    {
      continue;
    }
    const Index* links = this->Links.GetCells(v);
    for (vtkIdType l = 0; l < this->Links.GetNcells(v); ++l)
    {
      for (int k = 0; k < 3; ++k)
      {
        if (this->Vertex(links[l], k) == v)
        {
          const Index c = this->Corner(links[l], k);
          corners.emplace_back(static_cast<Index>(this->Connectivity[c]), c);
        }
      }
    }
  }
  if (corners.empty())
  {
    return;
  }
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());

  // Rare, and in point order: serial. The first frames are written after all the lookups,
  // which read the vertices' own frames at their points.
  this->Renumbered.TakeReference(this->Faces->GetConnectivityArray()->NewInstance());
  this->Renumbered->DeepCopy(this->Faces->GetConnectivityArray());
  std::vector<std::pair<Index, Frame>> firstFrames;
  std::vector<Index> pointCorners, firsts;
  std::vector<int> rank;
  for (size_t i = 0; i < corners.size();)
  {
    const Index p = corners[i].first;
    pointCorners.clear();
    for (; i < corners.size() && corners[i].first == p; ++i)
    {
      pointCorners.push_back(corners[i].second);
    }
    const Index v = this->WeldOf[p];
    this->DistinctFrames(pointCorners, v, rank, firsts);
    for (size_t d = 0; d < firsts.size(); ++d)
    {
      const Frame frame = this->FrameOf(firsts[d], v);
      if (d == 0)
      {
        firstFrames.emplace_back(p, frame);
        continue;
      }
      firsts[d] = static_cast<Index>(this->Tangents->InsertNextTypedTuple(frame.data()));
      this->VertexFrame = reinterpret_cast<Frame*>(this->Tangents->GetPointer(0));
      this->ExtraSource.push_back(p);
    }
    for (size_t c = 0; c < rank.size(); ++c)
    {
      if (rank[c] > 0)
      {
        this->Renumbered->SetComponent(pointCorners[c], 0, firsts[rank[c]]);
      }
    }
  }
  for (const auto& first : firstFrames)
  {
    this->VertexFrame[first.first] = first.second;
  }
}

// The distinct frames of a point's corners in order of first appearance: firsts[d] is the
// first corner with frame d, rank[i] the frame number of corners[i]. Frames are told apart
// by their bits, as they are stored.
void MikkTSpace::DistinctFrames(const std::vector<Index>& corners, Index v, std::vector<int>& rank,
  std::vector<Index>& firsts) const
{
  auto less = [](const Frame& x, const Frame& y)
  { return std::memcmp(x.data(), y.data(), sizeof(Frame)) < 0; };
  std::map<Frame, int, decltype(less)> number(less);
  firsts.clear();
  rank.resize(corners.size());
  for (size_t i = 0; i < corners.size(); ++i)
  {
    const auto found =
      number.emplace(this->FrameOf(corners[i], v), static_cast<int>(firsts.size()));
    if (found.second)
    {
      firsts.push_back(corners[i]);
    }
    rank[i] = found.first->second;
  }
}

// The output: the input's points and point data (copied to the split points), the
// "Tangents" array, vertices and lines as they are, the faces with their cell data.
void MikkTSpace::Assemble(vtkPointData* inPD, vtkPolyData* output) const
{
  vtkPolyData* input = this->Input;
  const vtkIdType nPts = this->NumberOfPoints;
  const vtkIdType nOut = this->Tangents->GetNumberOfTuples();
  auto identity = [](vtkIdType n)
  {
    vtkNew<vtkIdList> ids;
    ids->SetNumberOfIds(n);
    std::iota(ids->begin(), ids->end(), 0);
    return ids;
  };
  if (nOut == nPts)
  {
    output->SetPoints(input->GetPoints());
    output->GetPointData()->PassData(inPD);
  }
  else
  {
    vtkNew<vtkIdList> src = identity(nOut);
    std::copy(this->ExtraSource.begin(), this->ExtraSource.end(), src->begin() + nPts);
    vtkNew<vtkPoints> points;
    points->SetDataType(input->GetPoints()->GetDataType());
    points->SetNumberOfPoints(nOut);
    input->GetPoints()->GetData()->GetTuples(src, points->GetData());
    output->SetPoints(points);
    output->GetPointData()->CopyAllocate(inPD, nOut);
    output->GetPointData()->CopyData(inPD, src, identity(nOut));
  }
  // VTK 9.1 takes only 3-component tangent attributes, so the frame is the named array of
  // DESIGN.md; an input array of that name must not survive next to it.
  output->GetPointData()->RemoveArray("Tangents");
  output->GetPointData()->AddArray(this->Tangents);

  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());
  if (!this->Renumbered)
  {
    output->SetPolys(this->Faces);
  }
  else
  {
    vtkNew<vtkCellArray> polys;
    polys->SetData(this->Faces->GetOffsetsArray(), this->Renumbered);
    output->SetPolys(polys);
  }
  if (this->FacesAreInputPolys)
  {
    output->GetCellData()->PassData(input->GetCellData());
  }
  else
  {
    const vtkIdType nLead = input->GetNumberOfVerts() + input->GetNumberOfLines();
    const vtkIdType nCells = nLead + static_cast<vtkIdType>(this->FaceCell.size());
    vtkNew<vtkIdList> src = identity(nCells);
    std::copy(this->FaceCell.begin(), this->FaceCell.end(), src->begin() + nLead);
    output->GetCellData()->CopyAllocate(input->GetCellData(), nCells);
    output->GetCellData()->CopyData(input->GetCellData(), src, identity(nCells));
  }
  output->GetFieldData()->PassData(input->GetFieldData());
}

} // anonymous namespace

//------------------------------------------------------------------------------
void vtkMikkTSpaceTangents::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AngularThreshold: " << this->AngularThreshold << "\n";
}

//------------------------------------------------------------------------------
int vtkMikkTSpaceTangents::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkSurfaceDetailGhosts::RequestOneMoreLevel(
    inputVector[0]->GetInformationObject(0), outputVector->GetInformationObject(0));
  return 1;
}

//------------------------------------------------------------------------------
int vtkMikkTSpaceTangents::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  vtkNew<vtkPointData> inPD; // the input's point data, with normals if we make them
  if (!this->CheckInput(input, output) || !this->PrepareNormals(input, inPD))
  {
    return 0;
  }
  vtkDataArray* tcoords = inPD->GetTCoords();
  MikkTSpace mikk(input, inPD->GetNormals(), tcoords, this->AngularThreshold);
  mikk.Weld();
  mikk.BuildFaces();
  mikk.BuildTriangles();
  mikk.BuildLinks();
  this->UpdateProgress(0.3);
  mikk.ResolveGroupWithAnyOrientation();
  mikk.EvaluateVertices();
  mikk.FixQuadsWithOneDegenerateTriangle();
  this->UpdateProgress(0.7);
  mikk.SplitPoints();
  mikk.Assemble(inPD, output);
  vtkSurfaceDetailGhosts::RemoveUnrequested(outputVector->GetInformationObject(0), output);
  if (mikk.NonFinitePoints > 0)
  {
    vtkWarningMacro(<< mikk.NonFinitePoints
                    << " points have non-finite coordinates; the tangents around "
                       "them are arbitrary unit vectors orthogonal to the normal.");
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkMikkTSpaceTangents::CheckInput(vtkPolyData* input, vtkPolyData* output)
{
  if (!input || !output)
  {
    vtkErrorMacro("The input must be a vtkPolyData.");
    return false;
  }
  const vtkIdType nPts = input->GetNumberOfPoints();
  if (nPts == 0 || !input->GetPoints())
  {
    vtkErrorMacro("The input has no points; give it a surface with points, normals and "
                  "texture coordinates.");
    return false;
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("The input has no polygons or triangle strips; tangents need a surface.");
    return false;
  }
  // Triangulated polygons and strips have at most 3 corners per point id they hold.
  const vtkIdType corners = 3 *
    (input->GetPolys()->GetNumberOfConnectivityIds() +
      input->GetStrips()->GetNumberOfConnectivityIds());
  if (nPts >= VTK_TYPE_INT32_MAX || corners >= VTK_TYPE_INT32_MAX)
  {
    vtkErrorMacro("The input has " << nPts << " points and " << corners
                                   << " polygon corners; the filter takes fewer than 2^31 of "
                                      "each: process it in pieces.");
    return false;
  }
  if (!vtkSurfaceDetailCells::PointIdsInRange(input->GetPolys(), nPts) ||
    !vtkSurfaceDetailCells::PointIdsInRange(input->GetStrips(), nPts))
  {
    vtkErrorMacro("A polygon or triangle strip of the input names a point id outside [0, "
      << nPts << "); fix the connectivity (e.g. with vtkCleanPolyData) first.");
    return false;
  }
  vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
  if (!tcoords || tcoords->GetNumberOfComponents() < 2 || tcoords->GetNumberOfTuples() != nPts)
  {
    vtkErrorMacro("The input has no 2-component point texture coordinates; set them as the "
                  "point data's TCoords (e.g. with vtkTextureMapToPlane or a parametric "
                  "source) before computing tangents.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkMikkTSpaceTangents::PrepareNormals(vtkPolyData* input, vtkPointData* inPD)
{
  inPD->ShallowCopy(input->GetPointData());
  vtkDataArray* normals = inPD->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() == input->GetNumberOfPoints())
  {
    return true;
  }
  vtkWarningMacro("The input has no 3-component point normals; computing them with "
                  "vtkPolyDataNormals (no splitting, no reordering).");
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(input->GetPolys());
  surface->SetStrips(input->GetStrips());
  vtkNew<vtkPolyDataNormals> pdn;
  pdn->SetInputData(surface);
  pdn->SplittingOff();
  pdn->ConsistencyOff();
  pdn->AutoOrientNormalsOff();
  pdn->ComputeCellNormalsOff();
  pdn->ComputePointNormalsOn();
  pdn->Update();
  vtkDataArray* computed = pdn->GetOutput()->GetPointData()->GetNormals();
  if (!computed || computed->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkErrorMacro("The input has no point normals and vtkPolyDataNormals could not make "
                  "them; set the point data's Normals.");
    return false;
  }
  inPD->SetNormals(computed);
  return true;
}
