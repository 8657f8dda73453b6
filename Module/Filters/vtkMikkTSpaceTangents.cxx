#include "vtkMikkTSpaceTangents.h"

#include "vtkSurfaceDetailCells.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailMemory.h"
#include "vtkSurfaceDetailVectorize.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArrayRange.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
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
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <numeric>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#if defined(__SSE__) || defined(__x86_64__) || defined(_M_X64)
#include <xmmintrin.h>
#endif

// The AVX-512 and AVX2 builds write their permutations and masked loads with GCC vector
// extensions and <immintrin.h> intrinsics when GCC compiles them. Elsewhere (clang's builds
// included, which scripts/test-clang.sh tests), or with SURFACEDETAIL_MIKK_PORTABLE defined, plain
// loops that give the same bits.
#if !defined(SURFACEDETAIL_MIKK_PORTABLE) && defined(__GNUC__) && !defined(__clang__) &&           \
  (defined(__x86_64__) || defined(__i386__))
#define SURFACEDETAIL_MIKK_INTRINSICS 1
#include <immintrin.h>
#else
#define SURFACEDETAIL_MIKK_INTRINSICS 0
#endif

vtkStandardNewMacro(vtkMikkTSpaceTangents);

namespace
{
using V3 = std::array<double, 3>;

// Triangle flags, with the meaning of the reference implementation's.
constexpr int OrientPreserving = 1;  // signed texture area > 0
constexpr int GroupWithAny = 2;      // no usable texture derivatives: joins any group
constexpr int MarkDegenerate = 4;    // two corners at the same position
constexpr int QuadOneDegenerate = 8; // a quad whose other triangle is degenerate

// MikkTSpace works in float and calls a value zero when it is below FLT_MIN; the same test
// in double keeps the same triangles "good". NaN is zero here, which keeps it out.
inline bool NotZero(double x)
{
  return std::abs(x) > FLT_MIN;
}

// A few units of single-precision rounding, relative.
constexpr double CancellationEps = 4.0 * FLT_EPSILON;

// Fans up to this many triangles use quadratic scans (faster when small); larger ones sort.
constexpr size_t SmallFan = 32;
// Groups larger than this are not split into sub-groups (see EvaluateVertices).
constexpr size_t MaxSubGroupTest = 256;

inline V3 Sub(const V3& a, const V3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

inline V3 Scale(double s, const V3& a)
{
  return { s * a[0], s * a[1], s * a[2] };
}

inline double Dot(const V3& a, const V3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline V3 NormalizeSafe(const V3& v)
{
  if (!(NotZero(v[0]) || NotZero(v[1]) || NotZero(v[2])))
  {
    return v;
  }
  return Scale(1.0 / std::sqrt(Dot(v, v)), v);
}

inline V3 ProjectNormalize(const V3& v, const V3& n)
{
  return NormalizeSafe(Sub(v, Scale(Dot(n, v), n)));
}

// Exact equality of values, as the reference's veq: NaN equals nothing.
inline bool Equal(const V3& a, const V3& b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

inline std::uint64_t HashDouble(std::uint64_t h, double v)
{
  // 0 and -0 compare equal, so they must hash equal.
  if (v == 0.0)
  {
    v = 0.0;
  }
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof(bits));
  h ^= bits + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  return h;
}

// An allocator whose resize() leaves new elements default-initialised: the big per-point
// and per-triangle arrays are written entirely by a parallel pass right after, and
// zero-filling them first is a serial pass over up to ~100 MB.
template <typename T>
struct NoInitAllocator : std::allocator<T>
{
  template <typename U>
  struct rebind
  {
    using other = NoInitAllocator<U>;
  };
  NoInitAllocator() = default;
  template <typename U>
  NoInitAllocator(const NoInitAllocator<U>&) noexcept
  {
  }
  // Big arrays in transparent huge pages where the system has them: first touch then
  // faults once per 2 MB instead of once per 4 kB.
  T* allocate(std::size_t n)
  {
    void* p = vtkSurfaceDetailMemory::Allocate(n * sizeof(T));
    if (!p)
    {
      throw std::bad_alloc();
    }
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) { vtkSurfaceDetailMemory::Release(p); }
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
template <typename T>
using RawVector = std::vector<T, NoInitAllocator<T>>;

/// Everything the algorithm needs, indexed by input point, face corner or triangle.
struct MikkMesh
{
  vtkIdType NumberOfPoints = 0;
  RawVector<V3> P;
  RawVector<V3> N; // normalised
  RawVector<std::array<double, 2>> T;
  std::vector<vtkIdType> Weld; // the vertex a point is (same P, N and T: same vertex)

  // Output polygons ("faces"), in output order. When they are the input's polygons as
  // they are (the usual case) Offsets and Points view the input's cell array, nothing is
  // copied and FaceCell stays empty (face f is cell f after the vertices and lines);
  // otherwise they view the Own* arrays built here, with the input cell each came from.
  const vtkIdType* Offsets = nullptr;
  const vtkIdType* Points = nullptr;
  vtkIdType NumberOfFaces = 0;
  vtkIdType NumberOfCorners = 0;
  bool InputFaces = false;
  std::vector<vtkIdType> OwnOffsets{ 0 };
  std::vector<vtkIdType> OwnPoints;
  std::vector<vtkIdType> FaceCell;

  // Triangles of the faces with 3 or 4 corners, in face order.
  std::vector<vtkIdType> FaceFirstTri; // per face, size faces+1
  std::vector<vtkIdType> TriFace;
  std::vector<std::array<unsigned char, 3>> TriVert; // corner numbers within the face
  std::vector<int> TriFlag;

  vtkIdType CornerPoint(vtkIdType tri, int k) const
  {
    return this->Points[this->Offsets[this->TriFace[tri]] + this->TriVert[tri][k]];
  }
  vtkIdType CornerVertex(vtkIdType tri, int k) const
  {
    return this->Weld[this->CornerPoint(tri, k)];
  }
  vtkIdType FaceCorner(vtkIdType tri, int k) const
  {
    return this->Offsets[this->TriFace[tri]] + this->TriVert[tri][k];
  }
};

/// The part of a tangent space the output needs.
struct TSpace
{
  V3 Os{ { 1.0, 0.0, 0.0 } }; // the reference's default for corners no group reaches
  bool Orient = false;
  vtkIdType Group = -1;
};

// Normals are read as they are (the weld compares them so) and normalised after welding.
// The first NC components of every tuple, as doubles; typed access for the usual value
// types (a virtual call per value costs as much as the rest of the reading).
struct CopyComponents
{
  template <typename ArrayT, std::size_t NC>
  void operator()(ArrayT* array, RawVector<std::array<double, NC>>& out) const
  {
    const auto tuples = vtk::DataArrayTupleRange(array);
    vtkSMPTools::For(0, static_cast<vtkIdType>(out.size()),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const auto tuple = tuples[i];
          for (std::size_t c = 0; c < NC; ++c)
          {
            out[i][c] = static_cast<double>(tuple[c]);
          }
        }
      });
  }
};

template <std::size_t NC>
void ReadComponents(vtkDataArray* array, RawVector<std::array<double, NC>>& out)
{
  CopyComponents worker;
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(array, worker, out))
  {
    worker(array, out);
  }
}

void ReadAttributes(vtkPoints* points, vtkDataArray* normals, vtkDataArray* tcoords, MikkMesh& mesh)
{
  const vtkIdType n = mesh.NumberOfPoints;
  mesh.P.resize(n);
  mesh.N.resize(n);
  mesh.T.resize(n);
  ReadComponents(points->GetData(), mesh.P);
  ReadComponents(normals, mesh.N);
  ReadComponents(tcoords, mesh.T);
}

void NormalizeNormals(MikkMesh& mesh)
{
  vtkSMPTools::For(0, mesh.NumberOfPoints,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const double len = std::sqrt(Dot(mesh.N[i], mesh.N[i]));
        if (len > 0.0 && std::isfinite(len))
        {
          mesh.N[i] = Scale(1.0 / len, mesh.N[i]);
        }
      }
    });
}

// MikkTSpace welds corners whose position, normal and texture coordinates are identical,
// so two input points with the same values are one vertex even if the cells do not share
// them. Hashes are computed in parallel; the insertion into a flat open-addressing table
// is serial and in point order, so each vertex is represented by its smallest point id.
void Weld(MikkMesh& mesh)
{
  const vtkIdType n = mesh.NumberOfPoints;
  RawVector<std::uint64_t> hashes(n);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        std::uint64_t h = 1469598103934665603ULL;
        for (int c = 0; c < 3; ++c)
        {
          h = HashDouble(h, mesh.P[i][c]);
          h = HashDouble(h, mesh.N[i][c]);
        }
        h = HashDouble(h, mesh.T[i][0]);
        h = HashDouble(h, mesh.T[i][1]);
        // Round values leave the low bits of the combination regular; the table masks them.
        h ^= h >> 31;
        h *= 0x7fb5d329728ea185ULL;
        h ^= h >> 27;
        hashes[i] = h;
      }
    });

  std::uint64_t capacity = 16;
  while (capacity < 2 * static_cast<std::uint64_t>(n))
  {
    capacity *= 2;
  }
  const std::uint64_t mask = capacity - 1;
  std::vector<vtkIdType> table(capacity, -1);
  mesh.Weld.resize(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    mesh.Weld[i] = i;
    // NaN equals nothing, and all-NaN points would share a hash: never compared.
    if (!(Equal(mesh.P[i], mesh.P[i]) && Equal(mesh.N[i], mesh.N[i]) &&
          mesh.T[i][0] == mesh.T[i][0] && mesh.T[i][1] == mesh.T[i][1]))
    {
      continue;
    }
    for (std::uint64_t s = hashes[i] & mask;; s = (s + 1) & mask)
    {
      const vtkIdType o = table[s];
      if (o < 0)
      {
        table[s] = i;
        break;
      }
      if (hashes[o] == hashes[i] && Equal(mesh.P[i], mesh.P[o]) && Equal(mesh.N[i], mesh.N[o]) &&
        mesh.T[i][0] == mesh.T[o][0] && mesh.T[i][1] == mesh.T[o][1])
      {
        mesh.Weld[i] = o;
        break;
      }
    }
  }
}

// Output polygons: triangles and quads as they are, larger polygons triangulated (ear
// cutting, fan if that fails), polygons with fewer than 3 points kept, strips split.
void BuildFaces(vtkPolyData* input, MikkMesh& mesh)
{
  vtkCellArray* inPolys = input->GetPolys();
  if (input->GetNumberOfStrips() == 0 && inPolys->IsStorage64Bit())
  {
    const vtkIdType nPolys = inPolys->GetNumberOfCells();
    const vtkIdType* offsets = inPolys->GetOffsetsArray64()->GetPointer(0);
    bool small = true;
    for (vtkIdType f = 0; f < nPolys && small; ++f)
    {
      small = offsets[f + 1] - offsets[f] <= 4;
    }
    if (small)
    {
      mesh.Offsets = offsets;
      mesh.Points = inPolys->GetConnectivityArray64()->GetPointer(0);
      mesh.NumberOfFaces = nPolys;
      mesh.NumberOfCorners = offsets[nPolys];
      mesh.InputFaces = true;
      return;
    }
  }

  const vtkIdType polyCellBase = input->GetNumberOfVerts() + input->GetNumberOfLines();
  mesh.OwnPoints.reserve(inPolys->GetNumberOfConnectivityIds());
  mesh.OwnOffsets.reserve(input->GetNumberOfPolys() + 1);
  mesh.FaceCell.reserve(input->GetNumberOfPolys());
  auto addFace = [&mesh](const vtkIdType* ids, vtkIdType npts, vtkIdType cell)
  {
    mesh.OwnPoints.insert(mesh.OwnPoints.end(), ids, ids + npts);
    mesh.OwnOffsets.push_back(static_cast<vtkIdType>(mesh.OwnPoints.size()));
    mesh.FaceCell.push_back(cell);
  };

  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> triIds;
  vtkIdType cell = polyCellBase;
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cell)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    polys->GetCurrentCell(npts, pts);
    if (npts <= 4)
    {
      addFace(pts, npts, cell);
      continue;
    }
    polygon->Initialize(static_cast<int>(npts), pts, input->GetPoints());
    triIds->Reset();
    const bool ok = polygon->Triangulate(triIds) != 0 && triIds->GetNumberOfIds() == 3 * (npts - 2);
    for (vtkIdType t = 0; t < npts - 2; ++t)
    {
      vtkIdType tri[3];
      for (int k = 0; k < 3; ++k)
      {
        tri[k] = ok ? pts[triIds->GetId(3 * t + k)] : pts[k == 0 ? 0 : t + k];
      }
      addFace(tri, 3, cell);
    }
  }

  cell = polyCellBase + input->GetNumberOfPolys();
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cell)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    strips->GetCurrentCell(npts, pts);
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      // Every other triangle of a strip is wound the other way round.
      const vtkIdType tri[3] = { pts[k + (k & 1)], pts[k + 1 - (k & 1)], pts[k + 2] };
      if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2])
      {
        addFace(tri, 3, cell);
      }
    }
  }
  mesh.Offsets = mesh.OwnOffsets.data();
  mesh.Points = mesh.OwnPoints.data();
  mesh.NumberOfFaces = static_cast<vtkIdType>(mesh.FaceCell.size());
  mesh.NumberOfCorners = static_cast<vtkIdType>(mesh.OwnPoints.size());
}

// One triangle per triangle face, two per quad, split along the shorter diagonal in
// texture space (in position space on a tie) as MikkTSpace does.
void BuildTriangles(MikkMesh& mesh)
{
  const vtkIdType nFaces = mesh.NumberOfFaces;
  mesh.FaceFirstTri.resize(nFaces + 1);
  mesh.FaceFirstTri[0] = 0;
  for (vtkIdType f = 0; f < nFaces; ++f)
  {
    const vtkIdType n = mesh.Offsets[f + 1] - mesh.Offsets[f];
    mesh.FaceFirstTri[f + 1] = mesh.FaceFirstTri[f] + (n == 3 ? 1 : (n == 4 ? 2 : 0));
  }
  const vtkIdType nTris = mesh.FaceFirstTri[nFaces];
  mesh.TriFace.resize(nTris);
  mesh.TriVert.resize(nTris);
  mesh.TriFlag.assign(nTris, 0);
  vtkSMPTools::For(0, nFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        const vtkIdType t = mesh.FaceFirstTri[f];
        const vtkIdType nt = mesh.FaceFirstTri[f + 1] - t;
        if (nt == 0)
        {
          continue;
        }
        mesh.TriFace[t] = f;
        if (nt == 1)
        {
          mesh.TriVert[t] = { 0, 1, 2 };
          continue;
        }
        mesh.TriFace[t + 1] = f;
        const vtkIdType* c = mesh.Points + mesh.Offsets[f];
        auto dist2T = [&](int a, int b)
        {
          const double ds = mesh.T[c[a]][0] - mesh.T[c[b]][0];
          const double dt = mesh.T[c[a]][1] - mesh.T[c[b]][1];
          return ds * ds + dt * dt;
        };
        auto dist2P = [&](int a, int b)
        {
          const V3 d = Sub(mesh.P[c[a]], mesh.P[c[b]]);
          return Dot(d, d);
        };
        const double t02 = dist2T(0, 2), t13 = dist2T(1, 3);
        const bool diag02 = t02 < t13 || (!(t13 < t02) && !(dist2P(1, 3) < dist2P(0, 2)));
        if (diag02)
        {
          mesh.TriVert[t] = { 0, 1, 2 };
          mesh.TriVert[t + 1] = { 0, 2, 3 };
        }
        else
        {
          mesh.TriVert[t] = { 0, 1, 3 };
          mesh.TriVert[t + 1] = { 1, 2, 3 };
        }
      }
    });
}

double TexArea2(const MikkMesh& mesh, vtkIdType tri)
{
  const auto& t1 = mesh.T[mesh.CornerPoint(tri, 0)];
  const auto& t2 = mesh.T[mesh.CornerPoint(tri, 1)];
  const auto& t3 = mesh.T[mesh.CornerPoint(tri, 2)];
  return (t2[0] - t1[0]) * (t3[1] - t1[1]) - (t2[1] - t1[1]) * (t3[0] - t1[0]);
}

// The final frame of a corner: the tangent made exactly orthogonal to the unit normal; if
// that leaves nothing (degenerate input), any unit vector orthogonal to the normal.
void FinalTangent(const V3& n, const TSpace& ts, float out[4])
{
  double t[4] = { ts.Os[0], ts.Os[1], ts.Os[2], 0.0 };
  const double nDotT = Dot(n, ts.Os);
  double tp[3] = { t[0] - nDotT * n[0], t[1] - nDotT * n[1], t[2] - nDotT * n[2] };
  const double len = vtkSurfaceDetail::Normalize(tp);
  if (!(len > 1e-6 && std::isfinite(len)))
  {
    const double zero[3] = { 0.0, 0.0, 0.0 };
    double nn[3] = { n[0], n[1], n[2] };
    if (!(std::isfinite(Dot(n, n)) && Dot(n, n) > 0.5))
    {
      nn[0] = 0.0;
      nn[1] = 0.0;
      nn[2] = 1.0;
    }
    vtkSurfaceDetail::MakeTangentFrame(nn, zero, zero, t);
    tp[0] = t[0];
    tp[1] = t[1];
    tp[2] = t[2];
  }
  out[0] = static_cast<float>(tp[0]);
  out[1] = static_cast<float>(tp[1]);
  out[2] = static_cast<float>(tp[2]);
  out[3] = ts.Orient ? 1.0f : -1.0f;
}

/// The algorithm proper, on the triangles of a MikkMesh; fills per face corner tangents.
class MikkTSpace
{
public:
  MikkTSpace(MikkMesh& mesh, double angularThreshold)
    : Mesh(mesh)
    , ThresholdCos(std::cos(vtkMath::RadiansFromDegrees(angularThreshold)))
  {
  }

  /// Fills @a tangents for the face corners it can and sets @a set for those.
  /// @a tangents has a slot per face corner, left uninitialised (a corner's slot is only
  /// read once @a set says it was written, or after the caller writes it).
  void Run(std::array<float, 4>* tangents, std::vector<char>& set)
  {
    const size_t nCorners = static_cast<size_t>(this->Mesh.NumberOfCorners);
    set.assign(nCorners, 0);
    this->Tangents = tangents;
    this->Set = set.data();
    this->MarkDegenerates();
    this->InitTriangles();
    this->ForceQuadOrientation();
    this->BuildVertexTriangles();
    this->ResolveGroupWithAnyOrientation();
    this->EvaluateVertices();
    this->FixDegenerates();
  }

private:
  MikkMesh& Mesh;
  const double ThresholdCos;

  std::vector<vtkIdType> Good; // good triangles in input order, then the degenerate
  vtkIdType NumberOfGood = 0;
  // Per good triangle, everything the per-vertex pass reads, together in memory.
  struct GoodTriangle
  {
    V3 Os, Ot; // directions of dP/ds and dP/dt
    vtkIdType Face;
    int Flag;
    std::array<unsigned char, 3> Vert; // corner numbers within the face
  };

  vtkIdType FaceCorner(const GoodTriangle& tri, int k) const
  {
    return this->Mesh.Offsets[tri.Face] + tri.Vert[k];
  }
  RawVector<GoodTriangle> Tris;
  // Welded vertex of each corner of each good triangle; apart from Tris because the
  // adjacency passes read only these.
  RawVector<std::array<vtkIdType, 3>> W;
  std::vector<vtkIdType> VertexTriOffsets; // vertex -> good triangles
  RawVector<vtkIdType> VertexTris;
  std::array<float, 4>* Tangents = nullptr; // per face corner
  char* Set = nullptr;                      // per face corner: Tangents[c] is set

  void MarkDegenerates()
  {
    MikkMesh& m = this->Mesh;
    const vtkIdType nTris = static_cast<vtkIdType>(m.TriFace.size());
    vtkSMPTools::For(0, nTris,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType t = begin; t < end; ++t)
        {
          const V3& p0 = m.P[m.CornerVertex(t, 0)];
          const V3& p1 = m.P[m.CornerVertex(t, 1)];
          const V3& p2 = m.P[m.CornerVertex(t, 2)];
          if (Equal(p0, p1) || Equal(p0, p2) || Equal(p1, p2))
          {
            m.TriFlag[t] |= MarkDegenerate;
          }
        }
      });
    // A quad with exactly one good triangle gets special treatment at the end.
    for (vtkIdType t = 0; t + 1 < nTris; ++t)
    {
      if (m.TriFace[t] == m.TriFace[t + 1])
      {
        if (((m.TriFlag[t] ^ m.TriFlag[t + 1]) & MarkDegenerate) != 0)
        {
          m.TriFlag[t] |= QuadOneDegenerate;
          m.TriFlag[t + 1] |= QuadOneDegenerate;
        }
        ++t;
      }
    }
    this->Good.reserve(nTris);
    for (vtkIdType t = 0; t < nTris; ++t)
    {
      if (!(m.TriFlag[t] & MarkDegenerate))
      {
        this->Good.push_back(t);
      }
    }
    this->NumberOfGood = static_cast<vtkIdType>(this->Good.size());
    for (vtkIdType t = 0; t < nTris; ++t)
    {
      if (m.TriFlag[t] & MarkDegenerate)
      {
        this->Good.push_back(t);
      }
    }
  }

  // Per triangle: the normalised directions of dP/ds and dP/dt (eq. 18, 19 of the
  // reference's description), the texture orientation, and whether the texture mapping
  // is usable at all (if not, the triangle joins any group and adds nothing).
  void InitTriangles()
  {
    const MikkMesh& m = this->Mesh;
    const vtkIdType n = this->NumberOfGood;
    this->Tris.resize(n);
    this->W.resize(n);
    vtkSMPTools::For(0, n,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType g = begin; g < end; ++g)
        {
          const vtkIdType t = this->Good[g];
          GoodTriangle& tri = this->Tris[g];
          tri.Face = m.TriFace[t];
          for (int k = 0; k < 3; ++k)
          {
            this->W[g][k] = m.CornerVertex(t, k);
            tri.Vert[k] = m.TriVert[t][k];
          }
          tri.Os = V3{ 0.0, 0.0, 0.0 };
          tri.Ot = V3{ 0.0, 0.0, 0.0 };
          const V3& v1 = m.P[this->W[g][0]];
          const V3& v2 = m.P[this->W[g][1]];
          const V3& v3 = m.P[this->W[g][2]];
          const auto& t1 = m.T[this->W[g][0]];
          const auto& t2 = m.T[this->W[g][1]];
          const auto& t3 = m.T[this->W[g][2]];
          const double t21x = t2[0] - t1[0], t21y = t2[1] - t1[1];
          const double t31x = t3[0] - t1[0], t31y = t3[1] - t1[1];
          const V3 d1 = Sub(v2, v1), d2 = Sub(v3, v1);
          const double area2 = t21x * t31y - t21y * t31x;
          const V3 os = Sub(Scale(t31y, d1), Scale(t21y, d2));
          const V3 ot = Sub(Scale(t21x, d2), Scale(t31x, d1));
          int flag = (m.TriFlag[t] & ~MarkDegenerate) | GroupWithAny;
          if (area2 > 0.0)
          {
            flag |= OrientPreserving;
          }
          if (NotZero(area2))
          {
            const double absArea = std::abs(area2);
            // dP/ds and dP/dt are differences of terms as large as the edges; what is left
            // below single-precision rounding of those terms is cancellation noise (a sliver
            // whose texture edge runs along a vanishing position edge), not a direction. The
            // reference, in float, finds zero there; in double we must say so explicitly.
            const double l1 = std::sqrt(Dot(d1, d1)), l2 = std::sqrt(Dot(d2, d2));
            double lenOs = std::sqrt(Dot(os, os));
            double lenOt = std::sqrt(Dot(ot, ot));
            if (lenOs <= CancellationEps * (std::abs(t31y) * l1 + std::abs(t21y) * l2))
            {
              lenOs = 0.0;
            }
            if (lenOt <= CancellationEps * (std::abs(t31x) * l1 + std::abs(t21x) * l2))
            {
              lenOt = 0.0;
            }
            const double sign = area2 > 0.0 ? 1.0 : -1.0;
            if (NotZero(lenOs))
            {
              this->Tris[g].Os = Scale(sign / lenOs, os);
            }
            if (NotZero(lenOt))
            {
              this->Tris[g].Ot = Scale(sign / lenOt, ot);
            }
            if (NotZero(lenOs / absArea) && NotZero(lenOt / absArea))
            {
              flag &= ~GroupWithAny;
            }
          }
          this->Tris[g].Flag = flag;
        }
      });
  }

  // The two triangles of a quad must have one orientation; the larger texture area (or
  // the one with usable derivatives) decides.
  void ForceQuadOrientation()
  {
    const MikkMesh& m = this->Mesh;
    vtkSMPTools::For(0, std::max<vtkIdType>(this->NumberOfGood - 1, 0),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType g = begin; g < end; ++g)
        {
          const vtkIdType a = this->Good[g], b = this->Good[g + 1];
          if (m.TriFace[a] != m.TriFace[b] ||
            ((this->Tris[g].Flag ^ this->Tris[g + 1].Flag) & OrientPreserving) == 0)
          {
            continue;
          }
          const bool first = (this->Tris[g + 1].Flag & GroupWithAny) != 0 ||
            std::abs(TexArea2(m, a)) >= std::abs(TexArea2(m, b));
          const vtkIdType from = first ? g : g + 1, to = first ? g + 1 : g;
          this->Tris[to].Flag =
            (this->Tris[to].Flag & ~OrientPreserving) | (this->Tris[from].Flag & OrientPreserving);
        }
      });
  }

  // Vertex -> good triangles, each list in increasing triangle order.
  void BuildVertexTriangles()
  {
    // Counts shifted by two places: after the prefix sum, entry v+1 is where v's list
    // starts, and filling advances it to where v's list ends, which is the offset of v+1.
    // No separate fill cursors.
    const vtkIdType nv = this->Mesh.NumberOfPoints;
    auto& offsets = this->VertexTriOffsets;
    offsets.assign(nv + 2, 0);
    for (const auto& w : this->W)
    {
      for (vtkIdType v : w)
      {
        ++offsets[v + 2];
      }
    }
    for (vtkIdType v = 0; v < nv; ++v)
    {
      offsets[v + 2] += offsets[v + 1];
    }
    this->VertexTris.resize(offsets[nv + 1]);
    for (vtkIdType g = 0; g < this->NumberOfGood; ++g)
    {
      for (vtkIdType v : this->W[g])
      {
        this->VertexTris[offsets[v + 1]++] = g;
      }
    }
    offsets.pop_back();
  }

  static int CornerOf(const std::array<vtkIdType, 3>& w, vtkIdType v)
  {
    return w[0] == v ? 0 : (w[1] == v ? 1 : (w[2] == v ? 2 : -1));
  }

  /// The triangles around one vertex and how they connect there.
  struct Fan
  {
    std::vector<vtkIdType> Tri;                  // good triangles, increasing
    std::vector<int> Corner;                     // the vertex's corner in each
    std::vector<vtkIdType> Next, Prev;           // the other two vertices, in winding order
    std::vector<int> Out, In;                    // neighbour across (v, next) and (prev, v), or -1
    std::vector<std::array<vtkIdType, 3>> Slots; // large fans: (other vertex, entry, direction)
  };

  // Triangles are neighbours across an edge they use in opposite directions. Where more
  // than two triangles share an edge, the reference pairs them greedily in triangle order:
  // each unpaired one with the first later unpaired one running the other way. All the
  // triangles on an edge at v are around v, so v's fan alone decides its links.
  void BuildFan(vtkIdType v, Fan& fan) const
  {
    const vtkIdType begin = this->VertexTriOffsets[v], end = this->VertexTriOffsets[v + 1];
    const size_t k = static_cast<size_t>(end - begin);
    fan.Tri.assign(this->VertexTris.begin() + begin, this->VertexTris.begin() + end);
    fan.Corner.resize(k);
    fan.Next.resize(k);
    fan.Prev.resize(k);
    fan.Out.assign(k, -1);
    fan.In.assign(k, -1);
    for (size_t a = 0; a < k; ++a)
    {
      const auto& w = this->W[fan.Tri[a]];
      const int i = CornerOf(w, v);
      fan.Corner[a] = i;
      fan.Next[a] = w[i < 2 ? i + 1 : 0];
      fan.Prev[a] = w[i > 0 ? i - 1 : 2];
    }
    if (k <= SmallFan)
    {
      for (size_t a = 0; a < k; ++a)
      {
        for (size_t b = a + 1; b < k && fan.Out[a] < 0; ++b)
        {
          if (fan.In[b] < 0 && fan.Prev[b] == fan.Next[a])
          {
            fan.Out[a] = static_cast<int>(b);
            fan.In[b] = static_cast<int>(a);
          }
        }
        for (size_t b = a + 1; b < k && fan.In[a] < 0; ++b)
        {
          if (fan.Out[b] < 0 && fan.Next[b] == fan.Prev[a])
          {
            fan.In[a] = static_cast<int>(b);
            fan.Out[b] = static_cast<int>(a);
          }
        }
      }
      return;
    }
    // Large fans: the same greedy pairing, per edge in triangle order, is a first-in
    // first-out match of the two directions (the earliest unpaired triangle running the
    // other way takes the current one).
    fan.Slots.clear();
    for (size_t a = 0; a < k; ++a)
    {
      fan.Slots.push_back({ fan.Next[a], static_cast<vtkIdType>(a), 0 });
      fan.Slots.push_back({ fan.Prev[a], static_cast<vtkIdType>(a), 1 });
    }
    std::sort(fan.Slots.begin(), fan.Slots.end());
    std::vector<int> pending[2];
    size_t head[2];
    for (size_t g = 0; g < fan.Slots.size();)
    {
      size_t e = g;
      pending[0].clear();
      pending[1].clear();
      head[0] = head[1] = 0;
      for (; e < fan.Slots.size() && fan.Slots[e][0] == fan.Slots[g][0]; ++e)
      {
        const int a = static_cast<int>(fan.Slots[e][1]);
        const int d = static_cast<int>(fan.Slots[e][2]);
        if (head[1 - d] < pending[1 - d].size())
        {
          const int b = pending[1 - d][head[1 - d]++];
          (d == 0 ? fan.Out[a] : fan.In[a]) = b;
          (d == 0 ? fan.In[b] : fan.Out[b]) = a;
        }
        else
        {
          pending[d].push_back(a);
        }
      }
      g = e;
    }
  }

  bool Orient(vtkIdType t) const { return (this->Tris[t].Flag & OrientPreserving) != 0; }

  // A triangle without usable texture derivatives takes the orientation of the first group
  // that reaches it, at any of its vertices: the reference's one order dependency. Replay
  // its group building (seeds in triangle/corner order, floods across linked neighbours of
  // the same orientation) at the vertices that have such triangles; elsewhere it cannot
  // matter, and every other vertex is then independent of the rest.
  void ResolveGroupWithAnyOrientation()
  {
    const vtkIdType n = this->NumberOfGood;
    const vtkIdType nv = this->Mesh.NumberOfPoints;
    std::vector<char> anyVertex(nv, 0);
    bool any = false;
    for (vtkIdType g = 0; g < n; ++g)
    {
      if (this->Tris[g].Flag & GroupWithAny)
      {
        any = true;
        for (vtkIdType v : this->W[g])
        {
          anyVertex[v] = 1;
        }
      }
    }
    if (!any)
    {
      return;
    }
    std::vector<char> assigned(3 * n, 0);
    // A vertex seeds many groups; large fans are built once and kept.
    Fan small;
    std::unordered_map<vtkIdType, Fan> large;
    std::vector<int> stack;
    for (vtkIdType g = 0; g < n; ++g)
    {
      for (int i = 0; i < 3; ++i)
      {
        const vtkIdType v = this->W[g][i];
        if (!anyVertex[v] || (this->Tris[g].Flag & GroupWithAny) || assigned[3 * g + i])
        {
          continue;
        }
        const bool big = this->VertexTriOffsets[v + 1] - this->VertexTriOffsets[v] >
          static_cast<vtkIdType>(SmallFan);
        Fan& fan = big ? large[v] : small;
        if (!big || fan.Tri.empty())
        {
          this->BuildFan(v, fan);
        }
        const bool orient = this->Orient(g);
        stack.assign(1,
          static_cast<int>(std::lower_bound(fan.Tri.begin(), fan.Tri.end(), g) - fan.Tri.begin()));
        while (!stack.empty())
        {
          const int a = stack.back();
          stack.pop_back();
          const vtkIdType t = fan.Tri[a];
          char& done = assigned[3 * t + fan.Corner[a]];
          if (done)
          {
            continue;
          }
          if ((this->Tris[t].Flag & GroupWithAny) && !assigned[3 * t] && !assigned[3 * t + 1] &&
            !assigned[3 * t + 2])
          {
            this->Tris[t].Flag =
              (this->Tris[t].Flag & ~OrientPreserving) | (orient ? OrientPreserving : 0);
          }
          if (this->Orient(t) != orient)
          {
            continue;
          }
          done = 1;
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
  }

  // Angle-weighted average of the members' dP/ds directions projected onto the tangent
  // plane of the vertex normal, summed in increasing triangle order as the reference does.
  static V3 Average(const std::vector<int>& members, const std::vector<V3>& os,
    const std::vector<double>& angle, const std::vector<char>& contributes)
  {
    V3 sum{ 0.0, 0.0, 0.0 };
    for (int a : members)
    {
      if (contributes[a])
      {
        for (int c = 0; c < 3; ++c)
        {
          sum[c] += angle[a] * os[a][c];
        }
      }
    }
    return NormalizeSafe(sum);
  }

  // A quad's diagonal corner gets a space from each of its triangles: the reference
  // averages them unless equal, and the later group's orientation wins.
  static void Merge(TSpace& out, const TSpace& in)
  {
    if (!Equal(out.Os, in.Os))
    {
      out.Os =
        NormalizeSafe(V3{ out.Os[0] + in.Os[0], out.Os[1] + in.Os[1], out.Os[2] + in.Os[2] });
    }
    if (in.Group > out.Group)
    {
      out.Orient = in.Orient;
      out.Group = in.Group;
    }
  }

  // Per vertex: groups are the linked triangles of one orientation that contain a
  // triangle with usable derivatives (the group's seed: its first triangle); each member's
  // frame is the average over its sub-group (the members whose projected directions are
  // within the angular threshold of its own; all of them at 180 degrees).
  void EvaluateVertices()
  {
    const MikkMesh& m = this->Mesh;
    vtkSMPTools::For(0, m.NumberOfPoints,
      [&](vtkIdType begin, vtkIdType end)
      {
        Fan fan;
        std::vector<int> comp, members, subset, byComponent;
        std::vector<size_t> bucket;
        std::vector<V3> os, ot, edgeNext;
        std::vector<double> angle;
        std::vector<char> contributes;
        std::vector<vtkIdType> face;
        std::vector<std::pair<vtkIdType, TSpace>> written; // face corner, its space
        for (vtkIdType v = begin; v < end; ++v)
        {
          if (this->VertexTriOffsets[v] == this->VertexTriOffsets[v + 1])
          {
            continue;
          }
          this->BuildFan(v, fan);
          written.clear();
          const size_t k = fan.Tri.size();
          const V3& n = m.N[v];
          const V3& pv = m.P[v];
          os.resize(k);
          ot.resize(k);
          edgeNext.resize(k);
          angle.resize(k);
          contributes.resize(k);
          face.resize(k);
          for (size_t a = 0; a < k; ++a)
          {
            const vtkIdType t = fan.Tri[a];
            face[a] = this->Tris[t].Face;
            os[a] = ProjectNormalize(this->Tris[t].Os, n);
            ot[a] = ProjectNormalize(this->Tris[t].Ot, n);
            contributes[a] = (this->Tris[t].Flag & GroupWithAny) == 0;
            if (contributes[a])
            {
              edgeNext[a] = ProjectNormalize(Sub(m.P[fan.Next[a]], pv), n);
            }
          }
          // Linked neighbours share an edge at v (Prev[a] is Next[In[a]]): each projected
          // edge is computed once.
          for (size_t a = 0; a < k; ++a)
          {
            if (contributes[a])
            {
              const int b = fan.In[a];
              const V3 e1 = b >= 0 && contributes[b]
                ? edgeNext[b]
                : ProjectNormalize(Sub(m.P[fan.Prev[a]], pv), n);
              const double c = std::acos(std::min(1.0, std::max(-1.0, Dot(e1, edgeNext[a]))));
              angle[a] = std::isfinite(c) ? c : 0.0;
            }
          }
          // Components of the link graph between triangles of one orientation. The usual
          // vertex is one fan of one orientation: a walk along its links from the first
          // triangle reaches all of them. Links are one-to-one (Out and In are inverse), so
          // a walk visits distinct triangles until it ends or comes back to its start.
          auto linked = [&](int a, int b)
          { return b >= 0 && this->Orient(fan.Tri[a]) == this->Orient(fan.Tri[b]); };
          size_t reached = 1;
          for (int a = 0; reached < k && linked(a, fan.Out[a]) && fan.Out[a] != 0; ++reached)
          {
            a = fan.Out[a];
          }
          for (int a = 0; reached < k && linked(a, fan.In[a]) && fan.In[a] != 0; ++reached)
          {
            a = fan.In[a];
          }
          comp.resize(k);
          for (size_t a = 0; a < k; ++a)
          {
            comp[a] = reached == k ? 0 : static_cast<int>(a);
          }
          auto root = [&comp](int a)
          {
            while (comp[a] != a)
            {
              a = comp[a] = comp[comp[a]];
            }
            return a;
          };
          for (size_t a = 0; a < k && reached < k; ++a)
          {
            const int b = fan.Out[a];
            if (linked(static_cast<int>(a), b))
            {
              const int ra = root(static_cast<int>(a)), rb = root(b);
              comp[std::max(ra, rb)] = std::min(ra, rb);
            }
          }
          for (size_t a = 0; a < k; ++a)
          {
            comp[a] = root(static_cast<int>(a));
          }
          // The group of the corners in members: its seed is its first triangle with usable
          // derivatives, if any.
          auto seedOf = [&]()
          {
            for (int a : members)
            {
              if (contributes[a])
              {
                return a;
              }
            }
            return -1;
          };
          auto joins = [&](int f, int a)
          {
            return !contributes[f] || !contributes[a] || face[f] == face[a] ||
              (Dot(os[f], os[a]) > this->ThresholdCos && Dot(ot[f], ot[a]) > this->ThresholdCos);
          };
          // The pairwise test is quadratic; above MaxSubGroupTest members (a pole shared
          // by hundreds of triangles) the group is taken whole. At the default 180 degrees
          // it only separates exactly opposite directions, which at such a pole are
          // opposite up to rounding, and the reference's choice there is rounding noise.
          auto allJoinOf = [&]()
          {
            bool allJoin = true;
            for (size_t x = 0; x < members.size() && members.size() <= MaxSubGroupTest && allJoin;
                 ++x)
            {
              for (size_t y = x + 1; y < members.size() && allJoin; ++y)
              {
                allJoin = joins(members[x], members[y]);
              }
            }
            return allJoin;
          };
          // The usual vertex: one group, all of whose members join. Every corner then gets
          // the same space (a quad's shared corner merges two equal ones, which keeps it),
          // so the final tangent is computed once and the merging is skipped. A NaN in the
          // average would not merge as equal: that goes the general way.
          if (std::all_of(comp.begin(), comp.end(), [](int r) { return r == 0; }))
          {
            members.resize(k);
            std::iota(members.begin(), members.end(), 0);
            const int seed = seedOf();
            if (seed < 0)
            {
              continue;
            }
            const V3 all = Average(members, os, angle, contributes);
            if (Equal(all, all) && allJoinOf())
            {
              std::array<float, 4> out;
              FinalTangent(n,
                TSpace{ all, this->Orient(fan.Tri[seed]), 3 * fan.Tri[seed] + fan.Corner[seed] },
                out.data());
              for (size_t a = 0; a < k; ++a)
              {
                const vtkIdType c = this->FaceCorner(this->Tris[fan.Tri[a]], fan.Corner[a]);
                this->Tangents[c] = out;
                this->Set[c] = 1;
              }
              continue;
            }
          }
          // Members of each component in triangle order (a counting sort by root, which
          // is the component's first entry).
          bucket.assign(k + 1, 0);
          for (size_t a = 0; a < k; ++a)
          {
            ++bucket[comp[a] + 1];
          }
          for (size_t a = 0; a < k; ++a)
          {
            bucket[a + 1] += bucket[a];
          }
          byComponent.resize(k);
          for (size_t a = 0; a < k; ++a)
          {
            byComponent[bucket[comp[a]]++] = static_cast<int>(a);
          }
          for (size_t r = 0, first = 0; r < k; ++r)
          {
            if (comp[r] != static_cast<int>(r))
            {
              continue;
            }
            // bucket[r] is now the end of r's members; they start where the last root ended
            members.assign(byComponent.begin() + first, byComponent.begin() + bucket[r]);
            first = bucket[r];
            const int seed = seedOf();
            if (seed < 0)
            {
              continue; // no triangle to seed a group: the reference leaves these corners
            }
            const vtkIdType key = 3 * fan.Tri[seed] + fan.Corner[seed];
            const bool orient = this->Orient(fan.Tri[seed]);
            const bool allJoin = allJoinOf();
            const V3 all = Average(members, os, angle, contributes);
            for (int f : members)
            {
              V3 result = all;
              if (!allJoin)
              {
                subset.clear();
                for (int a : members)
                {
                  if (a == f || joins(f, a))
                  {
                    subset.push_back(a);
                  }
                }
                result = Average(subset, os, angle, contributes);
              }
              const vtkIdType c = this->FaceCorner(this->Tris[fan.Tri[f]], fan.Corner[f]);
              auto same = written.end();
              if (k <= SmallFan)
              {
                same = std::find_if(written.begin(), written.end(),
                  [c](const std::pair<vtkIdType, TSpace>& e) { return e.first == c; });
              }
              if (same == written.end())
              {
                written.push_back({ c, TSpace{ result, orient, key } });
                continue;
              }
              Merge(same->second, TSpace{ result, orient, key });
            }
          }
          if (k > SmallFan)
          {
            // Large fans: merge the quads' pairs by sorting rather than searching.
            std::sort(written.begin(), written.end(),
              [](const std::pair<vtkIdType, TSpace>& x, const std::pair<vtkIdType, TSpace>& y)
              { return x.first < y.first; });
            size_t kept = 0;
            for (size_t e = 0; e < written.size(); ++e)
            {
              if (kept > 0 && written[kept - 1].first == written[e].first)
              {
                Merge(written[kept - 1].second, written[e].second);
              }
              else
              {
                written[kept++] = written[e];
              }
            }
            written.resize(kept);
          }
          for (const auto& e : written)
          {
            FinalTangent(n, e.second, this->Tangents[e.first].data());
            this->Set[e.first] = 1;
          }
        }
      });
  }

  // Degenerate triangles take the space of the first good corner at the same vertex; a
  // quad with one good triangle gives its missing corner the space of the corner at the
  // same position (made orthogonal to its own normal).
  void FixDegenerates()
  {
    const MikkMesh& m = this->Mesh;
    for (size_t d = static_cast<size_t>(this->NumberOfGood); d < this->Good.size(); ++d)
    {
      const vtkIdType t = this->Good[d];
      if (m.TriFlag[t] & QuadOneDegenerate)
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType v = m.CornerVertex(t, k);
        if (this->VertexTriOffsets[v] == this->VertexTriOffsets[v + 1])
        {
          continue;
        }
        const vtkIdType g = this->VertexTris[this->VertexTriOffsets[v]];
        const vtkIdType src = this->FaceCorner(this->Tris[g], CornerOf(this->W[g], v));
        const vtkIdType dst = m.FaceCorner(t, k);
        if (this->Set[src])
        {
          this->Tangents[dst] = this->Tangents[src];
          this->Set[dst] = 1;
        }
      }
    }
    for (vtkIdType g = 0; g < this->NumberOfGood; ++g)
    {
      const vtkIdType t = this->Good[g];
      if (!(m.TriFlag[t] & QuadOneDegenerate))
      {
        continue;
      }
      const auto& vn = m.TriVert[t];
      const int used = (1 << vn[0]) | (1 << vn[1]) | (1 << vn[2]);
      const int missing = !(used & 2) ? 1 : (!(used & 4) ? 2 : (!(used & 8) ? 3 : 0));
      const vtkIdType base = m.Offsets[m.TriFace[t]];
      const V3& target = m.P[m.Points[base + missing]];
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType src = base + vn[k];
        if (Equal(m.P[m.Points[src]], target))
        {
          if (!this->Set[src])
          {
            break; // the corner keeps the default space, as its source does
          }
          const auto& f = this->Tangents[src];
          FinalTangent(m.N[m.Points[base + missing]],
            TSpace{ V3{ f[0], f[1], f[2] }, f[3] > 0.0f, 0 },
            this->Tangents[base + missing].data());
          this->Set[base + missing] = this->Set[src];
          break;
        }
      }
    }
  }
};

// ---------------------------------------------------------------------------------------
// The fast path, for the usual input: triangles only, point coordinates, normals and
// texture coordinates in float or double arrays, the default angular threshold, no
// degenerate or non-finite input, and every vertex a simple fan (one connected run of
// triangles of one texture orientation, all of which MikkTSpace joins). There every
// corner of a vertex gets the same frame, so the frames are computed per point, in one
// parallel pass over a vertex -> corner list, with no per-corner arrays and no point
// splitting. Anything else makes the fast path give up (Run returns false) and the
// general algorithm above does the whole job; the checks are conservative, with margins
// far above the rounding of the quantities they test, so the two paths take the same
// decisions wherever the fast one finishes.

// The angle between two plane vectors whose dot product is c and the absolute value of
// whose cross product is s, as atan2(s, c) with an absolute error below 1.2e-8 rad in
// double (in float, a few units of its last place more): atan on [0, 1] is q times a
// degree-8 polynomial in q^2 (a Chebyshev fit of atan(q)/q). Unlike acos of normalised
// vectors it needs no square root, and it stays accurate near 0 and pi; as a corner weight
// its relative error is far below what the reference's single precision leaves. Inlined
// and free of branches, so that loops over it vectorise.
template <typename Real>
[[gnu::always_inline]] inline Real FastAngle(Real s, Real c)
{
  const Real ac = std::abs(c);
  const bool steep = s > ac;
  const Real q = (steep ? ac : s) / (steep ? s : ac);
  const Real u = q * q, u2 = u * u, u4 = u2 * u2;
  const Real p01 = Real(0.9999999842426364) - Real(0.3333306678069164) * u;
  const Real p23 = Real(0.1999248357850966) - Real(0.1420257051178519) * u;
  const Real p45 = Real(0.1063675409849997) - Real(0.07495445444194075) * u;
  const Real p67 = Real(0.04258760747628684) - Real(0.016005030510568757) * u;
  const Real p = (p01 + p23 * u2) + (p45 + p67 * u2) * u4 + Real(0.002834064300823229) * (u4 * u4);
  Real r = q * p;
  r = steep ? Real(0.5 * vtkMath::Pi()) - r : r;
  return c < Real(0) ? Real(vtkMath::Pi()) - r : r;
}

// While it lives, this thread's floating-point arithmetic flushes subnormal results and
// operands to zero (x86: MXCSR's FTZ and DAZ bits; elsewhere nothing). In float, squares
// and products of tiny components (a direction's 1e-20 part) are subnormal, and each such
// operation takes a slow microcode path (10% of the filter's cycles on the 1M torus); the
// values flushed are below 1.2e-38, far under the rounding of the sums they enter. Every
// instruction set build runs under the same mode, so they keep giving the same bits.
class FlushSubnormals
{
public:
  explicit FlushSubnormals(bool enable)
  {
#if defined(__SSE__) || defined(__x86_64__) || defined(_M_X64)
    this->Saved = _mm_getcsr();
    if (enable)
    {
      _mm_setcsr(this->Saved | 0x8040u); // FTZ | DAZ
    }
#else
    (void)enable;
#endif
  }
  ~FlushSubnormals()
  {
#if defined(__SSE__) || defined(__x86_64__) || defined(_M_X64)
    _mm_setcsr(this->Saved);
#endif
  }
  FlushSubnormals(const FlushSubnormals&) = delete;
  FlushSubnormals& operator=(const FlushSubnormals&) = delete;

private:
  unsigned int Saved = 0;
};

// Memory from vtkSurfaceDetailMemory (huge pages for big blocks), not initialised. Blocks
// of half a huge page or more take a whole one, so that they too come from the cache of
// freed huge pages at the next execution: from malloc, a block of 1-2 MB (the per-point
// arrays of a 500k-point mesh) is new memory every time, one page fault and one page
// zeroed by the kernel per 4 kB.
template <typename T>
class Block
{
public:
  explicit Block(std::size_t n)
    : Data(static_cast<T*>(vtkSurfaceDetailMemory::Allocate(Bytes(n))))
  {
    if (!this->Data)
    {
      throw std::bad_alloc();
    }
  }
  ~Block() { vtkSurfaceDetailMemory::Release(this->Data); }
  Block(const Block&) = delete;
  Block& operator=(const Block&) = delete;
  T* Get() const { return this->Data; }
  T& operator[](std::size_t i) const { return this->Data[i]; }

private:
  static std::size_t Bytes(std::size_t n)
  {
    constexpr std::size_t page = vtkSurfaceDetailMemory::HugePageBytes;
    const std::size_t bytes = n * sizeof(T);
    return bytes >= page / 2 && bytes < page ? page : bytes;
  }

  T* Data;
};

// Fans larger than this (poles) go the general way.
constexpr int MaxFastFan = 32;

// Meshes with more triangles go the general way: the fans' corner loops index the
// triangles' directions (6 floats each) with 32-bit offsets, 6 * triangle + 5.
constexpr vtkIdType MaxFastTriangles = std::numeric_limits<std::int32_t>::max() / 6;

// Whether the triangles prev[a] -> v -> next[a] (a < k) at a vertex v form one run (one
// chain or one closed fan) in which each edge at v joins exactly two triangles or bounds the
// run: the prev values are distinct, so are the next values, and the links a -> b where
// next[a] == prev[b] chain all k triangles. IsOneRun takes the links (-1: none) and which
// triangles have a link to them; the functions below find them.
VTK_ALWAYS_INLINE bool IsOneRun(const std::int32_t* link, std::uint32_t hasIn, int k)
{
  const std::uint32_t noIn = ~hasIn & (k == 32 ? ~0u : (1u << k) - 1u);
  if ((noIn & (noIn - 1u)) != 0)
  {
    return false; // more than one run
  }
  int start = 0;
  while (noIn != 0 && !((noIn >> start) & 1u))
  {
    ++start;
  }
  // With distinct prev and next values the links are one-to-one, so k - 1 steps from the
  // start that neither end nor come back visit every triangle.
  for (int c = 1, cur = start; c < k; ++c)
  {
    cur = link[cur];
    if (cur < 0 || cur == start)
    {
      return false;
    }
  }
  return true;
}

// Larger fans: the triangle b whose prev[b] is next[a] is found through a small hash table
// of prev values (a quadratic scan mispredicts).
VTK_ALWAYS_INLINE bool LargeFanIsOneRun(const std::int32_t* next, const std::int32_t* prev, int k)
{
  constexpr int TableBits = 6;
  static_assert(MaxFastFan <= (1 << TableBits) / 2, "table at most half full");
  unsigned char table[1 << TableBits];
  std::memset(table, 0xff, sizeof(table));
  auto slot = [](std::int32_t x)
  { return (static_cast<std::uint32_t>(x) * 0x9e3779b1u) >> (32 - TableBits); };
  for (int b = 0; b < k; ++b)
  {
    std::uint32_t h = slot(prev[b]);
    for (; table[h] != 0xff; h = (h + 1) & ((1u << TableBits) - 1u))
    {
      if (prev[table[h]] == prev[b])
      {
        return false; // two triangles run the same way along an edge
      }
    }
    table[h] = static_cast<unsigned char>(b);
  }
  std::int32_t link[MaxFastFan];
  std::uint32_t hasIn = 0;
  for (int a = 0; a < k; ++a)
  {
    int l = -1;
    for (std::uint32_t h = slot(next[a]); table[h] != 0xff; h = (h + 1) & ((1u << TableBits) - 1u))
    {
      if (prev[table[h]] == next[a])
      {
        l = table[h];
        break;
      }
    }
    if (l >= 0 && ((hasIn >> l) & 1u))
    {
      return false;
    }
    link[a] = l;
    hasIn |= l >= 0 ? 1u << l : 0u;
  }
  return IsOneRun(link, hasIn, k);
}

// Fans up to 8 triangles, in the AVX2 build: the prev and next values in 8 lanes, compared
// with every rotation of each other (no hash table, no branch per pair). Lanes past k hold
// distinct negative values, which equal no point id and no other padding.
#if (defined(__x86_64__) || defined(__i386__)) &&                                                  \
  (defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 12))
#define SURFACEDETAIL_MIKK_LANES 1
using Lanes8 = std::int32_t __attribute__((vector_size(32)));
// Vectors go by reference only: by value, their calling convention would differ between
// the baseline and the AVX2 build (and GCC warns about it).

// r = x rotated: r[a] = x[a + Rotation] (lanes mod 8).
template <int Rotation>
VTK_ALWAYS_INLINE void Rotate(const Lanes8& x, Lanes8& r)
{
  r = __builtin_shufflevector(x, x, Rotation & 7, (Rotation + 1) & 7, (Rotation + 2) & 7,
    (Rotation + 3) & 7, (Rotation + 4) & 7, (Rotation + 5) & 7, (Rotation + 6) & 7,
    (Rotation + 7) & 7);
}

#if !defined(__clang__) // the walk in lanes below, which needs GCC's __builtin_shuffle
// s = the sum of all eight lanes of x, in every lane.
VTK_ALWAYS_INLINE void SumOfLanes(const Lanes8& x, Lanes8& s)
{
  Lanes8 r;
  Rotate<4>(x, r);
  s = x + r;
  Rotate<2>(s, r);
  s += r;
  Rotate<1>(s, r);
  s += r;
}
#endif

// Lanes of x equal to some other lane of x, or of y to some other lane of y (rotations by
// 1 to 4 meet every pair).
template <int Rotation>
VTK_ALWAYS_INLINE void Duplicates(const Lanes8& x, const Lanes8& y, Lanes8& dup)
{
  Lanes8 rx, ry;
  Rotate<Rotation>(x, rx);
  Rotate<Rotation>(y, ry);
  dup |= (x == rx) | (y == ry);
}

// Where next[a] == prev[a + Rotation]: a links to a + Rotation, which has a link to it.
template <int Rotation>
VTK_ALWAYS_INLINE void Links(const Lanes8& nx, const Lanes8& pv, Lanes8& link, Lanes8& in)
{
  static constexpr Lanes8 Lane = { 0, 1, 2, 3, 4, 5, 6, 7 };
  Lanes8 r, back;
  Rotate<Rotation>(pv, r);
  const Lanes8 eq = nx == r;
  const Lanes8 to = (Lane + Rotation) & 7;
  link = (link & ~eq) | (to & eq);
  Rotate<8 - Rotation>(eq, back);
  in |= back;
}

// The next and prev values are loaded eight at a time (their arrays have eight more
// entries: see Finish), and lanes past k are replaced.
VTK_ALWAYS_INLINE bool SmallFanIsOneRun(const std::int32_t* next, const std::int32_t* prev, int k)
{
  static constexpr Lanes8 Lane = { 0, 1, 2, 3, 4, 5, 6, 7 };
  Lanes8 nx, pv;
  std::memcpy(&nx, next, sizeof(nx));
  std::memcpy(&pv, prev, sizeof(pv));
  const Lanes8 pad = Lane >= k;
  nx = (nx & ~pad) | (pad & (-1 - Lane));
  pv = (pv & ~pad) | (pad & (-9 - Lane));
  Lanes8 dup = Lanes8{};
  Duplicates<1>(nx, pv, dup);
  Duplicates<2>(nx, pv, dup);
  Duplicates<3>(nx, pv, dup);
  Duplicates<4>(nx, pv, dup);
  std::uint64_t any[4];
  std::memcpy(any, &dup, sizeof(any));
  if (((any[0] | any[1]) | (any[2] | any[3])) != 0)
  {
    return false; // two triangles run the same way along an edge
  }
  Lanes8 link = Lanes8{} - 1, in = Lanes8{};
  Links<0>(nx, pv, link, in);
  Links<1>(nx, pv, link, in);
  Links<2>(nx, pv, link, in);
  Links<3>(nx, pv, link, in);
  Links<4>(nx, pv, link, in);
  Links<5>(nx, pv, link, in);
  Links<6>(nx, pv, link, in);
  Links<7>(nx, pv, link, in);
#if defined(__clang__)
  std::int32_t links[8], ins[8];
  std::memcpy(links, &link, sizeof(links));
  std::memcpy(ins, &in, sizeof(ins));
  std::uint32_t hasIn = 0;
  for (int a = 0; a < 8; ++a)
  {
    hasIn |= static_cast<std::uint32_t>(ins[a] & 1) << a;
  }
  return IsOneRun(links, hasIn, k);
#else
  // The walk of IsOneRun in the lanes (a walk through memory waits on each step, and on
  // the vector's store): a chain's end is linked back to its start (the one triangle with
  // no link to it), padding lanes to themselves; then the links are one permutation, and
  // the run is one if the start comes back only after k steps. Lane j gets link^j(start)
  // by composing link with itself (variable shuffles: vpermd).
  const Lanes8 real = Lane < k;
  const Lanes8 noIn = (in == 0) & real;
  Lanes8 starts, start;
  SumOfLanes(noIn & 1, starts);
  SumOfLanes(noIn & Lane, start);
  const Lanes8 end = (link < 0) & real;
  link = (link & ~end) | (start & end);
  link = (link & real) | (Lane & ~real);
  const Lanes8 link2 = __builtin_shuffle(link, link), link4 = __builtin_shuffle(link2, link2);
  Lanes8 orbit = start;
  const Lanes8 b0 = (Lane & 1) != 0, b1 = (Lane & 2) != 0, b2 = (Lane & 4) != 0;
  orbit = (orbit & ~b0) | (__builtin_shuffle(link, orbit) & b0);
  orbit = (orbit & ~b1) | (__builtin_shuffle(link2, orbit) & b1);
  orbit = (orbit & ~b2) | (__builtin_shuffle(link4, orbit) & b2);
  const Lanes8 early = (orbit == start) & (Lane > 0) & real;
  std::uint64_t bad[4];
  std::memcpy(bad, &early, sizeof(bad));
  std::int32_t count;
  std::memcpy(&count, &starts, sizeof(count));
  return count <= 1 && ((bad[0] | bad[1]) | (bad[2] | bad[3])) == 0;
#endif
}
#else
#define SURFACEDETAIL_MIKK_LANES 0
#endif

// Whether a fan, given by the next and prev values of its corners, is one run; Wide: in the
// AVX2 and AVX-512 builds (the lanes' code built for the baseline costs more than the hash).
template <bool Wide>
VTK_ALWAYS_INLINE bool FanIsOneRun(const std::int32_t* next, const std::int32_t* prev, int k)
{
#if SURFACEDETAIL_MIKK_LANES
  if constexpr (Wide)
  {
    if (k <= 8)
    {
      return SmallFanIsOneRun(next, prev, k);
    }
  }
#endif
  return LargeFanIsOneRun(next, prev, k);
}

// A range [0, n) cut into a fixed number of chunks that depends on n alone (at most 64, at
// least 16384 items each, or one): passes whose results depend on the order of the items
// (counting sorts, running sums) run per chunk in parallel and stay the same whatever the
// number of threads. For(f) calls f(chunk, begin, end) for every chunk.
struct FixedChunks
{
  explicit FixedChunks(vtkIdType n)
    : N(n)
    , Count(std::max<vtkIdType>(1, std::min<vtkIdType>(64, n / 16384)))
    , Size((n + this->Count - 1) / this->Count)
  {
  }

  template <typename F>
  void For(F&& f) const
  {
    vtkSMPTools::For(0, this->Count, 1,
      [&](vtkIdType cb, vtkIdType ce)
      {
        for (vtkIdType c = cb; c < ce; ++c)
        {
          const vtkIdType b = c * this->Size;
          f(c, b, std::min<vtkIdType>(this->N, b + this->Size));
        }
      });
  }

  const vtkIdType N;
  const vtkIdType Count;
  const vtkIdType Size;
};

// Margins of the fast path's checks: squared sine of ~0.06 degrees for projections onto
// the tangent plane, cosine of 89.94 degrees for directions within a quarter turn.
constexpr double FastProjection2 = 1e-6;
constexpr double FastCos = 1e-3;

// A closed fan is taken as one run without matching its edges (FanIsOneRun) when its
// corners show it is one: every corner's angle turning the same way about the normal (all
// one way or all the other), between FastTurn and pi - FastTurn radians, the sum of the
// angles within 1 radian of a full turn, and the point ids after the corners the same
// multiset as the ids before them. Then the edges from each corner's next point to its
// previous one make closed walks (each point entered as often as left) whose angles, all in
// (0, pi) one way, add up to a whole number of turns each, at least one; a full turn in all
// leaves one walk, visiting no point twice (that would split it into two walks of a turn or
// more): every edge at the vertex joins exactly two triangles, which chain into one closed
// run, as FanIsOneRun would have found. The margins: the corner loop's angles are within
// ~3e-5 radians of those between the projected edges when each edge's projection keeps a
// tenth of its squared length (FastEdgeProjection: the rounding of n.(e1 x e2) and
// e1.e2 - (e1.n)(e2.n), ~1e-6 of |e1||e2| for a unit normal rounded to float or checked to
// 1e-6, over |proj e1||proj e2| >= 0.1 |e1||e2|), 30 times less than FastTurn; 32 corners'
// errors are 1e-3 radians, far inside the 1 radian that separates one turn from two.
constexpr double FastTurn = 1e-3;
constexpr double FastEdgeProjection = 0.1;
// One sum per fan shows both the angles' total and which way its corners turn: a corner
// turning the other way adds TurnBack to its angle, one outside the margins is TurnOff. The
// fan's sum is a full turn (within 1) if all turn one way, TurnBack k more if all turn the
// other; TurnBack exceeds 32 corners' angles (32 pi) and TurnOff 32 TurnBacks, so mixed
// fans and fans with any corner off give neither. Float sums of 32 values below 2^14 are
// within 2^-6 of exact, far inside the 1 radian.
constexpr double TurnBack = 256.0;
constexpr double TurnOff = 65536.0;

// The multiset check compares sums of a 64-bit mix of the ids (splitmix64's finaliser)
// modulo 2^64: different multisets of up to 32 ids give equal sums with probability about
// 2^-64 for ids a mesh did not choose to collide (the displacement filter's
// BowtieSeamPointMerges accepts the same bound); a mesh built to collide could make the
// fast path take two runs for one. Exact matching costs as much as FanIsOneRun itself.
VTK_ALWAYS_INLINE std::uint64_t IdMix(std::int32_t id)
{
  std::uint64_t h = static_cast<std::uint32_t>(id) + 0x9e3779b97f4a7c15ull;
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

// The fans of a run of vertices are done in blocks, in three phases: checking each fan and
// listing its corners, weighing all the block's corners in one loop of plain arithmetic
// (which the compiler vectorises), and summing each fan. Real: the corner loop's precision.
template <typename Real>
struct FanBlock
{
  static constexpr int MaxVertices = 128;
  static constexpr int MaxCorners = 512;
  // The corner loop runs to a multiple of this, on copies of the last corner: a remainder
  // would run in narrower vectors and scalar code, which cost as much as many full vectors.
  static constexpr int Lanes = 16;
  static_assert(MaxCorners >= MaxFastFan, "a fan fits in a block");
  int NumberOfVertices = 0;
  int NumberOfCorners = 0;
  std::int32_t Vertex[MaxVertices];
  float Handedness[MaxVertices];
  int First[MaxVertices + 1];
  // Per vertex: its unit normal, the offset of its first triangle's directions, the
  // projections of those (unit vectors, see References), whether checks passed, the sum of
  // weighted dP/ds, the tangent.
  alignas(32) double NV[3][MaxVertices];
  alignas(32) std::int32_t First6[MaxVertices];
  alignas(32) double R[6][MaxVertices];
  alignas(32) double Good[MaxVertices];
  alignas(32) double S[3][MaxVertices];
  // Per vertex, its corners' sums of Turn and Cycle, and the closed-fan test's answer.
  alignas(64) Real Turns[MaxVertices];
  alignas(64) std::uint64_t Cycles[MaxVertices];
  alignas(64) std::int32_t Closed[MaxVertices];
  alignas(32) float Tangent[3][MaxVertices];
  // Per corner: its triangle, the point ids of the corner and of its next and previous
  // corners (times 3: offsets of their coordinates), its vertex's unit normal, its weighted
  // dP/ds.
  alignas(64) std::int32_t Triangle[MaxCorners + Lanes];
  alignas(64) std::int32_t Self[MaxCorners + Lanes];
  alignas(64) std::int32_t Next[MaxCorners + Lanes];
  alignas(64) std::int32_t Prev[MaxCorners + Lanes];
  alignas(64) Real N[3][MaxCorners + Lanes];
  alignas(64) Real WeightedOs[3][MaxCorners + Lanes];
  // Per corner, for the closed-fan test (see FastTurn): its angle if it is within the
  // margins, plus TurnBack if it turns the other way about the normal (else TurnOff), and
  // the mix of its next point's id minus that of its previous one.
  alignas(64) Real Turn[MaxCorners + Lanes];
  alignas(64) std::uint64_t Cycle[MaxCorners + Lanes];
};

// The same in the AVX-512 build, slot-major: the block's vertices go in groups of Lanes, one
// vertex to a lane, and corner s of a group's lane i is at [Lanes * s + i] of the group's
// slots, so the corner loop takes corner s of every lane at once. A vertex's own values
// (position, normal, references) are then one vector per group instead of copies per
// corner, and its sums (which FanBlock's SumFans adds in a scalar loop per fan) are vertical
// adds in the order of its corners; a lane with fewer corners than the group's largest fan
// is padded with its last corner, masked off: its sums keep their values, bit for bit
// (adding +0 would not, where flush-to-zero made one -0). Each corner's next and previous
// ids and directions are copied into its slot, 8 scalar stores. On the 1M torus (Zen 5):
// 6% fewer cycles than FanBlock in the AVX-512 build, but 2.3% more in the AVX2 build and
// 4.6% more in the baseline, which keep FanBlock for the global vertex lists (the task-local
// slots below, in the AVX-512 and AVX2 builds, use SlotBlock).
template <typename Real>
struct SlotBlock
{
  static constexpr int MaxVertices = 128;
  static constexpr int MaxSlots = 1024;
  // Sixteen lanes: one AVX-512 vector of floats.
  static constexpr int Lanes = 16;
  static constexpr int MaxGroups = MaxVertices / Lanes;
  static_assert(MaxSlots >= Lanes * MaxFastFan, "a fan fits in a block");
  int NumberOfVertices = 0;
  // Per group: its first slot and the size of its largest fan (its slots per lane).
  int GroupFirst[MaxGroups];
  int GroupSlots[MaxGroups];
  // Per lane (a group's lanes past the block's vertices repeat its first vertex, with no
  // corners; a task's slots also give a vertex no triangle uses a lane with none): its vertex,
  // number of corners and handedness; its unit normal (in double and in Real), position, the offset
  // of its first triangle's directions, the projections of those (unit vectors, see References),
  // whether checks passed; the corners' sums of weighted dP/ds, of turns and of id mixes (see
  // FanBlock), the closed-fan test's answer, the tangent.
  std::int32_t Vertex[MaxVertices];
  float Handedness[MaxVertices];
  alignas(64) std::int32_t K[MaxVertices];
  alignas(64) double NV[3][MaxVertices];
  alignas(64) Real NR[3][MaxVertices];
  alignas(64) Real Position[3][MaxVertices];
  alignas(64) std::int32_t First6[MaxVertices];
  alignas(64) Real R[6][MaxVertices];
  alignas(64) double Good[MaxVertices];
  alignas(64) Real S[3][MaxVertices];
  alignas(64) Real Turns[MaxVertices];
  alignas(64) std::uint64_t Cycles[MaxVertices];
  alignas(64) std::int32_t Closed[MaxVertices];
  alignas(64) float Tangent[3][MaxVertices];
  // Per slot, in SlotStorage or in a task's slots (see FastMikk::TaskSlots), 64-byte
  // aligned: the ids of its corner's next and previous points times 3 (the offsets of their
  // coordinates), and its triangle's dP/ds and dP/dt.
  std::int32_t* Next;
  std::int32_t* Prev;
  float* Dir[6];
  // From one corner of a lane to the next in each of the arrays above: Lanes in SlotStorage,
  // 8 Lanes in a task's slots, where a row of corners is Lanes records of eight values.
  int RowStride = Lanes;
  // From one lane's slot to the next: 1, or 8 in a task's slots, where each slot is a record
  // of its eight values (see FastMikk::TaskSlots).
  int LaneStride = 1;

  int GroupStart(int g) const { return g > 0 ? GroupFirst[g - 1] + Lanes * GroupSlots[g - 1] : 0; }
  // The block's slots with one more fan, of k corners.
  int SlotsWith(int k) const
  {
    const int g = NumberOfVertices / Lanes;
    return NumberOfVertices % Lanes == 0 ? GroupStart(g) + Lanes * k
                                         : GroupFirst[g] + Lanes * std::max(k, GroupSlots[g]);
  }
};

// The slots of one SlotBlock.
struct SlotStorage
{
  static constexpr int MaxSlots = 1024;
  alignas(64) std::int32_t Next[MaxSlots];
  alignas(64) std::int32_t Prev[MaxSlots];
  alignas(64) float Dir[6][MaxSlots];
  template <typename Real>
  void Attach(SlotBlock<Real>& fb)
  {
    static_assert(MaxSlots == SlotBlock<Real>::MaxSlots, "storage for a whole block");
    fb.Next = this->Next;
    fb.Prev = this->Prev;
    for (int x = 0; x < 6; ++x)
    {
      fb.Dir[x] = this->Dir[x];
    }
  }
};

template <typename PT, typename NT, typename TT>
class FastMikk
{
  // The corners are weighed in the precision of the points: in single precision for float
  // points (sixteen lanes to an AVX-512 vector, no conversions), as the reference does.
  using Real = std::conditional_t<std::is_same<PT, float>::value, float, double>;

public:
  FastMikk(const PT* p, const NT* n, const TT* t, int tcStride, vtkIdType nPts)
    : P(p)
    , N(n)
    , T(t)
    , TcStride(tcStride)
    , NumberOfPoints(static_cast<std::int32_t>(nPts))
  {
  }

  /// Tangents of all points into @a out (4 floats each), or false if the input needs the
  /// general algorithm (then @a out holds garbage, and @a weldOut the weld if it was
  /// computed: the general algorithm's own, which it need not repeat).
  template <typename IdT>
  bool Run(const IdT* offsets, const IdT* conn, vtkIdType nTris, float* out,
    std::vector<vtkIdType>& weldOut)
  {
    Block<std::int32_t> weld(this->NumberOfPoints);
    if (!this->Weld(weld))
    {
      return false;
    }
    if (this->Finish(offsets, conn, nTris, weld, out))
    {
      return true;
    }
    weldOut.resize(static_cast<std::size_t>(this->NumberOfPoints));
    vtkSMPTools::For(0, vtkIdType(this->NumberOfPoints),
      [&](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType i = b; i < e; ++i)
        {
          weldOut[i] = this->Welded ? weld[i] : i;
        }
      });
    return false;
  }

private:
  template <typename IdT>
  bool Finish(const IdT* offsets, const IdT* conn, vtkIdType nTris, const Block<std::int32_t>& weld,
    float* out)
  {
    const std::size_t nt = static_cast<std::size_t>(nTris);
    std::unique_ptr<Block<std::atomic<unsigned char>>> referenced;
    if (this->Welded)
    {
      referenced.reset(new Block<std::atomic<unsigned char>>(this->NumberOfPoints));
      auto* r = referenced->Get();
      vtkSMPTools::For(0, vtkIdType(this->NumberOfPoints),
        [r](vtkIdType b, vtkIdType e)
        {
          for (vtkIdType i = b; i < e; ++i)
          {
            // Constructed here: Block's memory is raw.
            new (&r[i]) std::atomic<unsigned char>(0);
          }
        });
    }
    // One more value and direction: the task-local slots read a triangle's ids and
    // directions as whole vectors (see LocalSlots).
    Block<std::int32_t> w(3 * nt + 1);
    Block<std::array<float, 6>> dir(nt + 1);
    w[3 * nt] = 0;
    dir[nt] = {};
    Block<unsigned char> orient(nt);
    // The spans of the triangle chunks, for the task-local slots (AVX-512 and AVX2 builds).
    const bool local =
      vtkSurfaceDetailVectorize::HaveAVX512() || vtkSurfaceDetailVectorize::HaveAVX2();
    std::vector<std::int32_t> spanLo(local ? (nt + SpanTriangles - 1) / SpanTriangles : 0),
      spanHi(spanLo.size());
    if (!this->Triangles(offsets, conn, nTris, weld.Get(), referenced ? referenced->Get() : nullptr,
          w.Get(), dir.Get(), orient.Get(), local ? spanLo.data() : nullptr,
          local ? spanHi.data() : nullptr))
    {
      return false;
    }
    std::vector<std::int32_t> taskFirst, taskChunks;
    // The task-local slots make their lanes' unit normals themselves (LaneVertices): the
    // 12 bytes per point that a pass of its own wrote, read back, cost more than the square
    // roots.
    std::unique_ptr<Block<double>> unitNormals;
    if (local && this->TaskChunks(spanLo, spanHi, taskFirst, taskChunks))
    {
      if (!this->LocalVertices(
            w.Get(), nTris, taskFirst, taskChunks, dir.Get(), orient.Get(), weld.Get(), out))
      {
        return false;
      }
    }
    else
    {
      unitNormals.reset(new Block<double>(3 * static_cast<std::size_t>(this->NumberOfPoints)));
      this->ComputeUnitNormals(unitNormals->Get());
      Block<std::int32_t> first(static_cast<std::size_t>(this->NumberOfPoints) + 1);
      Block<std::int32_t> corners(3 * nt);
      // Eight more: a fan's next and prev values are read eight at a time.
      Block<std::int32_t> nextIds(3 * nt + 8), prevIds(3 * nt + 8);
      std::fill_n(nextIds.Get() + 3 * nt, 8, 0);
      std::fill_n(prevIds.Get() + 3 * nt, 8, 0);
      // A pole (a fan too large for the fast path) is found while the vertex lists are
      // sized, rather than in the per-vertex pass, which may have done most of its work by
      // then.
      if (!this->VertexCorners(
            w.Get(), nTris, first.Get(), corners.Get(), nextIds.Get(), prevIds.Get()) ||
        !this->Vertices(nextIds.Get(), prevIds.Get(), dir.Get(), orient.Get(), first.Get(),
          corners.Get(), weld.Get(), out))
      {
        return false;
      }
    }
    if (this->Welded)
    {
      this->CopyWelded(weld.Get(), referenced->Get(), out);
    }
    return true;
  }

  const PT* P;
  const NT* N;
  const TT* T;
  const int TcStride;
  const std::int32_t NumberOfPoints;
  bool Welded = false;
  const double* UnitNormals = nullptr; // UnitNormal of every point, for FanBlock and SlotFans

  // UnitNormal of every point into un (and UnitNormals), in a loop that vectorises: the fans
  // then do not wait on a square root and a division per vertex.
  void ComputeUnitNormals(double* un)
  {
    vtkSMPTools::For(0, vtkIdType(this->NumberOfPoints),
      [&](vtkIdType b, vtkIdType e)
      {
        if (vtkSurfaceDetailVectorize::HaveAVX512())
        {
          UnitNormalsAVX512(*this, b, e, un);
        }
        else if (vtkSurfaceDetailVectorize::HaveAVX2())
        {
          UnitNormalsAVX2(*this, b, e, un);
        }
        else
        {
          this->UnitNormalRange(b, e, un);
        }
      });
    this->UnitNormals = un;
  }

  SURFACEDETAIL_TARGET_AVX2 static void UnitNormalsAVX2(
    const FastMikk& self, vtkIdType b, vtkIdType e, double* un)
  {
    self.UnitNormalRange(b, e, un);
  }

  SURFACEDETAIL_TARGET_AVX512 static void UnitNormalsAVX512(
    const FastMikk& self, vtkIdType b, vtkIdType e, double* un)
  {
    self.UnitNormalRange(b, e, un);
  }

  // UnitNormal without branches.
  VTK_ALWAYS_INLINE void UnitNormalRange(vtkIdType b, vtkIdType e, double* __restrict un) const
  {
    for (vtkIdType i = b; i < e; ++i)
    {
      UnitNormalOf(this->N + 3 * i, un + 3 * i);
    }
  }

  // UnitNormal of the normal n into u.
  VTK_ALWAYS_INLINE static void UnitNormalOf(const NT* __restrict n, double* __restrict u)
  {
    const double x = double(n[0]), y = double(n[1]), z = double(n[2]);
    const double len = std::sqrt(x * x + y * y + z * z);
    const double inv = 1.0 / len;
    const bool scale = len > 0.0 && len <= DBL_MAX;
    u[0] = scale ? inv * x : x;
    u[1] = scale ? inv * y : y;
    u[2] = scale ? inv * z : z;
  }

  V3 Position(std::int32_t i) const
  {
    return { double(this->P[3 * std::size_t(i)]), double(this->P[3 * std::size_t(i) + 1]),
      double(this->P[3 * std::size_t(i) + 2]) };
  }
  std::array<double, 2> TCoord(std::int32_t i) const
  {
    const TT* t = this->T + std::size_t(this->TcStride) * i;
    return { double(t[0]), double(t[1]) };
  }
  // A value's bits for the hash, 0 and -0 alike (they compare equal), and whether it is not
  // finite (all exponent bits set). Integer code only, with no conversion to double and no
  // branch, so that the hash loop vectorises: single precision values are hashed as 32-bit
  // words, whose products with 32-bit constants are one vector instruction.
  template <typename X>
  VTK_ALWAYS_INLINE static std::uint64_t HashBits(X v, std::uint64_t& nonFinite)
  {
    if constexpr (sizeof(X) == sizeof(std::uint32_t))
    {
      std::uint32_t bits;
      std::memcpy(&bits, &v, sizeof(bits));
      nonFinite |= (bits & 0x7f800000u) == 0x7f800000u ? 1u : 0u;
      return (bits & 0x7fffffffu) == 0 ? 0 : bits;
    }
    else
    {
      std::uint64_t bits;
      std::memcpy(&bits, &v, sizeof(bits));
      constexpr std::uint64_t exponent = 0x7ff0000000000000ULL;
      nonFinite |= (bits & exponent) == exponent ? 1u : 0u;
      return (bits & ~(std::uint64_t(1) << 63)) == 0 ? 0 : bits;
    }
  }

  // Hashes of points [b, e) of their values; false if any value is not finite. Independent
  // products rather than a chain of dependent steps.
  VTK_ALWAYS_INLINE bool HashRange(vtkIdType b, vtkIdType e, std::uint64_t* __restrict hashes) const
  {
    const PT* __restrict p = this->P;
    const NT* __restrict n = this->N;
    const TT* __restrict t = this->T;
    const std::size_t ts = static_cast<std::size_t>(this->TcStride);
    static constexpr std::uint64_t K[8] = { 0x7f4a7c15u, 0x27d4eb4fu, 0x9e3779f9u, 0x6659fd93u,
      0x78bd642fu, 0xa0b428dbu, 0x9c88c6e3u, 0x75374cc3u };
    std::uint64_t nonFinite = 0;
    for (vtkIdType i = b; i < e; ++i)
    {
      const std::size_t i3 = 3 * static_cast<std::size_t>(i), it = ts * static_cast<std::size_t>(i);
      std::uint64_t h = HashBits(p[i3], nonFinite) * K[0] + HashBits(p[i3 + 1], nonFinite) * K[1];
      h += HashBits(p[i3 + 2], nonFinite) * K[2] + HashBits(n[i3], nonFinite) * K[3];
      h += HashBits(n[i3 + 1], nonFinite) * K[4] + HashBits(n[i3 + 2], nonFinite) * K[5];
      h += HashBits(t[it], nonFinite) * K[6] + HashBits(t[it + 1], nonFinite) * K[7];
      h ^= h >> 31;
      h *= 0x7fb5d329728ea185ULL;
      h ^= h >> 27;
      h *= 0x81dadef4bc2dd44dULL;
      h ^= h >> 33;
      hashes[i] = h;
    }
    return nonFinite == 0;
  }

  SURFACEDETAIL_TARGET_AVX2 static bool HashRangeAVX2(
    const FastMikk& self, vtkIdType b, vtkIdType e, std::uint64_t* hashes)
  {
    return self.HashRange(b, e, hashes);
  }

  // AVX-512 has 64-bit vector products (the mixing steps).
  SURFACEDETAIL_TARGET_AVX512 static bool HashRangeAVX512(
    const FastMikk& self, vtkIdType b, vtkIdType e, std::uint64_t* hashes)
  {
    return self.HashRange(b, e, hashes);
  }

  bool SameValues(std::int32_t i, std::int32_t o) const
  {
    for (int c = 0; c < 3; ++c)
    {
      if (this->P[3 * std::size_t(i) + c] != this->P[3 * std::size_t(o) + c] ||
        this->N[3 * std::size_t(i) + c] != this->N[3 * std::size_t(o) + c])
      {
        return false;
      }
    }
    const TT* ti = this->T + std::size_t(this->TcStride) * i;
    const TT* to = this->T + std::size_t(this->TcStride) * o;
    return ti[0] == to[0] && ti[1] == to[1];
  }

  // The weld of the general path, in parallel. Points are hashed in parallel and sorted
  // by the hash's low bits into buckets (a counting sort, which keeps increasing ids within
  // each bucket); buckets are welded independently, each in a table small enough to stay
  // in the first-level cache, so every vertex is represented by its smallest point id, as
  // in the general path, with no atomics and no cache misses on a big table. Non-finite
  // values anywhere send the input to the general path (which warns about them).
  bool Weld(const Block<std::int32_t>& weld)
  {
    const std::int32_t n = this->NumberOfPoints;
    int bucketBits = 0;
    while (bucketBits < 16 && (std::int64_t(1024) << bucketBits) < n)
    {
      ++bucketBits;
    }
    const std::uint64_t buckets = std::uint64_t(1) << bucketBits;
    const std::uint64_t bucketMask = buckets - 1;
    // The counting sort runs on fixed chunks of points, not on the threads' ranges: chunk c's
    // points of bucket k go after those of chunks before c, so each bucket lists its points
    // in increasing order whatever the number of threads.
    const FixedChunks chunks(n);
    Block<std::uint64_t> hashes(n);
    // Per (chunk, bucket): the chunk's count of the bucket's points, then where they go.
    std::vector<std::int32_t> cursor(static_cast<std::size_t>(chunks.Count) * buckets, 0);
    std::atomic<bool> fail(false);
    chunks.For(
      [&](vtkIdType c, vtkIdType b, vtkIdType e)
      {
        const bool finite = vtkSurfaceDetailVectorize::HaveAVX512()
          ? HashRangeAVX512(*this, b, e, hashes.Get())
          : vtkSurfaceDetailVectorize::HaveAVX2() ? HashRangeAVX2(*this, b, e, hashes.Get())
                                                  : this->HashRange(b, e, hashes.Get());
        if (!finite)
        {
          fail.store(true, std::memory_order_relaxed);
        }
        std::int32_t* count = cursor.data() + c * buckets;
        for (vtkIdType i = b; i < e; ++i)
        {
          ++count[hashes[i] & bucketMask];
        }
      });
    if (fail)
    {
      return false;
    }
    std::vector<std::int32_t> bucketFirst(buckets + 1, 0);
    vtkSMPTools::For(0, vtkIdType(buckets),
      [&](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType k = b; k < e; ++k)
        {
          std::int32_t sum = 0;
          for (vtkIdType c = 0; c < chunks.Count; ++c)
          {
            const std::int32_t count = cursor[c * buckets + k];
            cursor[c * buckets + k] = sum;
            sum += count;
          }
          bucketFirst[k + 1] = sum;
        }
      });
    for (std::uint64_t k = 0; k < buckets; ++k)
    {
      bucketFirst[k + 1] += bucketFirst[k];
    }
    // The points in bucket order, each with its hash: the buckets' tables then read the
    // hashes in order rather than from all over the hash array.
    struct Entry
    {
      std::uint64_t Hash;
      std::int32_t Id;
    };
    Block<Entry> order(n);
    chunks.For(
      [&](vtkIdType c, vtkIdType b, vtkIdType e)
      {
        std::int32_t* at = cursor.data() + c * buckets;
        for (vtkIdType i = b; i < e; ++i)
        {
          const std::uint64_t k = hashes[i] & bucketMask;
          order[bucketFirst[k] + at[k]++] = Entry{ hashes[i], static_cast<std::int32_t>(i) };
        }
      });
    std::atomic<bool> welded(false);
    vtkSMPTools::For(0, vtkIdType(buckets),
      [&](vtkIdType b, vtkIdType e)
      {
        std::vector<std::int32_t> table;
        bool any = false;
        for (vtkIdType k = b; k < e; ++k)
        {
          const std::int32_t begin = bucketFirst[k], end = bucketFirst[k + 1];
          // At most a quarter full: a point's first slot is then rarely taken, and that
          // branch, which no predictor can learn, mispredicts less (at half full the
          // table's loop took 1.75 times the cycles on the 1M torus).
          std::uint64_t capacity = 16;
          while (capacity < 4 * static_cast<std::uint64_t>(end - begin))
          {
            capacity *= 2;
          }
          const std::uint64_t mask = capacity - 1;
          table.assign(capacity, -1);
          for (std::int32_t j = begin; j < end; ++j)
          {
            const Entry entry = order[j];
            const std::int32_t i = entry.Id;
            for (std::uint64_t s = (entry.Hash >> bucketBits) & mask;; s = (s + 1) & mask)
            {
              const std::int32_t o = table[s]; // an index into order
              if (o < 0)
              {
                table[s] = j;
                weld[i] = i;
                break;
              }
              if (order[o].Hash == entry.Hash && this->SameValues(i, order[o].Id))
              {
                weld[i] = order[o].Id;
                any = true;
                break;
              }
            }
          }
        }
        if (any)
        {
          welded.store(true, std::memory_order_relaxed);
        }
      });
    this->Welded = welded;
    return true;
  }

  // Per triangle: welded corners, the directions of dP/ds and dP/dt as the general path's
  // InitTriangles computes them (then stored in single precision: every use below has a
  // margin far above that rounding), and the orientation. Quads, larger polygons,
  // degenerate triangles and triangles without usable derivatives need the general path.
  template <typename IdT>
  bool Triangles(const IdT* offsets, const IdT* conn, vtkIdType nTris, const std::int32_t* weld,
    std::atomic<unsigned char>* referenced, std::int32_t* w, std::array<float, 6>* dir,
    unsigned char* orient, std::int32_t* spanLo, std::int32_t* spanHi) const
  {
    if (offsets[nTris] != 3 * nTris)
    {
      return false;
    }
    std::atomic<bool> fail(false);
    // For the spans, whole chunks of SpanTriangles, each a block of TriangleRange.
    const vtkIdType unit = spanLo ? SpanTriangles : 1;
    vtkSMPTools::For(0, (nTris + unit - 1) / unit,
      [&](vtkIdType cb, vtkIdType ce)
      {
        if (fail.load(std::memory_order_relaxed))
        {
          return;
        }
        const vtkIdType b = cb * unit, e = std::min(nTris, ce * unit);
        const bool done = vtkSurfaceDetailVectorize::HaveAVX512()
          ? TrianglesAVX512(
              *this, b, e, offsets, conn, weld, referenced, w, dir, orient, spanLo, spanHi)
          : vtkSurfaceDetailVectorize::HaveAVX2() ? TrianglesAVX2(*this, b, e, offsets, conn, weld,
                                                      referenced, w, dir, orient, spanLo, spanHi)
                                                  : this->TriangleRange(b, e, offsets, conn, weld,
                                                      referenced, w, dir, orient, spanLo, spanHi);
        if (!done)
        {
          fail.store(true, std::memory_order_relaxed);
        }
      });
    return !fail;
  }

  template <typename IdT>
  SURFACEDETAIL_TARGET_AVX2 static bool TrianglesAVX2(const FastMikk& self, vtkIdType b,
    vtkIdType e, const IdT* offsets, const IdT* conn, const std::int32_t* weld,
    std::atomic<unsigned char>* referenced, std::int32_t* w, std::array<float, 6>* dir,
    unsigned char* orient, std::int32_t* spanLo, std::int32_t* spanHi)
  {
    return self.TriangleRange(
      b, e, offsets, conn, weld, referenced, w, dir, orient, spanLo, spanHi);
  }

  template <typename IdT>
  SURFACEDETAIL_TARGET_AVX512 static bool TrianglesAVX512(const FastMikk& self, vtkIdType b,
    vtkIdType e, const IdT* offsets, const IdT* conn, const std::int32_t* weld,
    std::atomic<unsigned char>* referenced, std::int32_t* w, std::array<float, 6>* dir,
    unsigned char* orient, std::int32_t* spanLo, std::int32_t* spanHi)
  {
    return self.TriangleRange<true>(
      b, e, offsets, conn, weld, referenced, w, dir, orient, spanLo, spanHi);
  }

  // As the fans: blocks of triangles, each checked and listed, then one loop of plain
  // arithmetic that the compiler vectorises (checks fold into a 0/1 flag). The checks of a
  // block fold into flags too, tested once per block: loops with an early exit do not
  // vectorise. With spanLo and spanHi, also each block's least and largest welded id (see
  // TaskChunks); b is then a multiple of SpanTriangles.
  // Stream: the AVX-512 build, whose welded corners and directions go out by streaming stores
  // (StreamIds, StreamDirections: 2% and 1% fewer cycles on the 1M torus).
  template <bool Stream = false, typename IdT>
  VTK_ALWAYS_INLINE bool TriangleRange(vtkIdType b, vtkIdType e, const IdT* offsets,
    const IdT* conn, const std::int32_t* weld, std::atomic<unsigned char>* referenced,
    std::int32_t* w, std::array<float, 6>* dir, unsigned char* orient, std::int32_t* spanLo,
    std::int32_t* spanHi) const
  {
    constexpr int Size = static_cast<int>(SpanTriangles);
    struct Columns
    {
      alignas(32) std::int32_t X[3][Size]; // offsets of the corners' coordinates
      alignas(32) std::int32_t U[3][Size]; // offsets of the corners' texture coordinates
      alignas(32) double Good[Size];
      alignas(32) double Sign[Size];
      alignas(32) float D[6][Size];
      alignas(64) std::int32_t W[3 * Size]; // the welded corners, to stream
    };
    std::unique_ptr<Columns> columns(new Columns);
    Columns& cb = *columns;
    using UIdT = std::make_unsigned_t<IdT>;
    const UIdT nPts = static_cast<UIdT>(this->NumberOfPoints);
    const std::int32_t tcStride = this->TcStride;
    for (vtkIdType t0 = b; t0 < e; t0 += Size)
    {
      const int m = static_cast<int>(std::min<vtkIdType>(Size, e - t0));
      const IdT* __restrict o = offsets + t0;
      const IdT* __restrict ids = conn + 3 * t0;
      std::int32_t* __restrict wb = Stream ? cb.W : w + 3 * t0;
      // RequestData leaves the ids' range to this pass, which reads them anyway.
      UIdT bad = 0;
      for (int j = 0; j < m; ++j)
      {
        bad |= static_cast<UIdT>(o[j]) ^ static_cast<UIdT>(3 * (t0 + j));
      }
      if (this->Welded)
      {
        for (int j = 0; j < m && bad == 0; ++j)
        {
          for (int k = 0; k < 3; ++k)
          {
            const IdT id = ids[3 * j + k];
            if (static_cast<UIdT>(id) >= nPts)
            {
              return false;
            }
            const std::int32_t p = static_cast<std::int32_t>(id);
            wb[3 * j + k] = weld[p];
            referenced[p].store(1, std::memory_order_relaxed);
            cb.X[k][j] = 3 * p;
            cb.U[k][j] = tcStride * p;
          }
        }
      }
      else
      {
        for (int j = 0; j < m; ++j)
        {
          for (int k = 0; k < 3; ++k)
          {
            const IdT id = ids[3 * j + k];
            bad |= static_cast<UIdT>(id) >= nPts ? 1 : 0;
            const std::int32_t p = static_cast<std::int32_t>(id);
            wb[3 * j + k] = p;
            cb.X[k][j] = 3 * p;
            cb.U[k][j] = tcStride * p;
          }
        }
      }
      if (bad != 0)
      {
        return false;
      }
      if (spanLo)
      {
        std::int32_t lo = std::numeric_limits<std::int32_t>::max(), hi = 0;
        for (int j = 0; j < 3 * m; ++j)
        {
          lo = std::min(lo, wb[j]);
          hi = std::max(hi, wb[j]);
        }
        spanLo[t0 / Size] = lo;
        spanHi[t0 / Size] = hi;
      }
      this->TriangleColumns(cb.X, cb.U, m, cb.Good, cb.Sign, cb.D);
      int good = 1;
      unsigned char* __restrict ob = orient + t0;
      for (int j = 0; j < m; ++j)
      {
        good &= cb.Good[j] != 0.0 ? 1 : 0;
        ob[j] = cb.Sign[j] > 0.0 ? 1 : 0;
      }
      int streamed = 0;
      if constexpr (Stream)
      {
        const int done = StreamIds(cb.W, 3 * m, w + 3 * t0);
        std::copy(cb.W + done, cb.W + 3 * m, w + 3 * t0 + done);
        streamed = StreamDirections(cb.D, m, dir[t0].data());
      }
      for (int j = streamed; j < m; ++j)
      {
        for (int i = 0; i < 6; ++i)
        {
          dir[t0 + j][i] = cb.D[i][j];
        }
      }
      if (!good)
      {
        return false;
      }
    }
#if SURFACEDETAIL_MIKK_INTRINSICS
    if constexpr (Stream)
    {
      _mm_sfence(); // the streaming stores, before other threads read them
    }
#endif
    return true;
  }

  // Where the directions of 16 triangles go in their records of six floats: output vector o
  // takes its element e from pair p of the six input arrays (d[2 p], d[2 p + 1]) at Index[o][p]
  // if bit e of Mask[o][p] is set.
  struct DirectionRecords
  {
    std::int32_t Index[6][3][16];
    std::uint16_t Mask[6][3];
    constexpr DirectionRecords()
      : Index()
      , Mask()
    {
      for (int f = 0; f < 96; ++f)
      {
        const int o = f / 16, e = f % 16, t = f / 6, c = f % 6;
        this->Index[o][c / 2][e] = t + 16 * (c % 2);
        this->Mask[o][c / 2] = static_cast<std::uint16_t>(this->Mask[o][c / 2] | (1u << e));
      }
    }
  };

  // The directions d of triangles [0, m) of a block into their records at `to` (six floats
  // each), 16 triangles at a time, by permutations and streaming stores: the triangle pass
  // writes 24 bytes per triangle that the fans read only after the whole pass, and ordinary
  // stores first read each line from memory. Returns how many triangles it stored (none if
  // `to` is not 64-byte aligned, or in builds without it); the caller stores the rest.
  template <int Size>
  SURFACEDETAIL_TARGET_AVX512 static int StreamDirections(
    const float (&d)[6][Size], int m, float* to)
  {
    int j0 = 0;
#if SURFACEDETAIL_MIKK_INTRINSICS
    static constexpr DirectionRecords records{};
    if (reinterpret_cast<std::uintptr_t>(to) % 64 != 0)
    {
      return 0;
    }
    for (; j0 + 16 <= m; j0 += 16)
    {
      __m512 in[6];
      for (int c = 0; c < 6; ++c)
      {
        in[c] = _mm512_loadu_ps(d[c] + j0);
      }
      for (int o = 0; o < 6; ++o)
      {
        __m512 r = _mm512_permutex2var_ps(in[0], _mm512_loadu_si512(records.Index[o][0]), in[1]);
        for (int p = 1; p < 3; ++p)
        {
          r = _mm512_mask_blend_ps(records.Mask[o][p], r,
            _mm512_permutex2var_ps(
              in[2 * p], _mm512_loadu_si512(records.Index[o][p]), in[2 * p + 1]));
        }
        _mm512_stream_ps(to + 6 * j0 + 16 * o, r);
      }
    }
#else
    (void)d;
    (void)m;
    (void)to;
#endif
    return j0;
  }

  // The first n values of `from` to `to` by streaming stores (see StreamDirections), 16 at a
  // time; returns how many it stored.
  SURFACEDETAIL_TARGET_AVX512 static int StreamIds(
    const std::int32_t* from, int n, std::int32_t* to)
  {
    int i = 0;
#if SURFACEDETAIL_MIKK_INTRINSICS
    if (reinterpret_cast<std::uintptr_t>(to) % 64 != 0)
    {
      return 0;
    }
    for (; i + 16 <= n; i += 16)
    {
      _mm512_stream_si512(reinterpret_cast<__m512i*>(to + i), _mm512_loadu_si512(from + i));
    }
#else
    (void)from;
    (void)n;
    (void)to;
#endif
    return i;
  }

  // One loop over a block's triangles (with gathers in the AVX2 build).
  template <int Size>
  VTK_ALWAYS_INLINE void TriangleColumns(const std::int32_t (&x)[3][Size],
    const std::int32_t (&u)[3][Size], int m, double* __restrict good, double* __restrict sign,
    float (&d)[6][Size]) const
  {
    const PT* __restrict p = this->P;
    const TT* __restrict tc = this->T;
    for (int j = 0; j < m; ++j)
    {
      const std::int32_t a = x[0][j], b = x[1][j], c = x[2][j];
      const std::int32_t ua = u[0][j], ub = u[1][j], uc = u[2][j];
      const double v1[3] = { double(p[a]), double(p[a + 1]), double(p[a + 2]) };
      const double v2[3] = { double(p[b]), double(p[b + 1]), double(p[b + 2]) };
      const double v3[3] = { double(p[c]), double(p[c + 1]), double(p[c + 2]) };
      // Two equal corners make a degenerate triangle.
      double g = v1[0] != v2[0] ? 1.0 : (v1[1] != v2[1] ? 1.0 : (v1[2] != v2[2] ? 1.0 : 0.0));
      g = v1[0] != v3[0] ? g : (v1[1] != v3[1] ? g : (v1[2] != v3[2] ? g : 0.0));
      g = v2[0] != v3[0] ? g : (v2[1] != v3[1] ? g : (v2[2] != v3[2] ? g : 0.0));
      const double t21x = double(tc[ub]) - double(tc[ua]),
                   t21y = double(tc[ub + 1]) - double(tc[ua + 1]);
      const double t31x = double(tc[uc]) - double(tc[ua]),
                   t31y = double(tc[uc + 1]) - double(tc[ua + 1]);
      const double d1[3] = { v2[0] - v1[0], v2[1] - v1[1], v2[2] - v1[2] };
      const double d2[3] = { v3[0] - v1[0], v3[1] - v1[1], v3[2] - v1[2] };
      const double area2 = t21x * t31y - t21y * t31x;
      const double os[3] = { t31y * d1[0] - t21y * d2[0], t31y * d1[1] - t21y * d2[1],
        t31y * d1[2] - t21y * d2[2] };
      const double ot[3] = { t21x * d2[0] - t31x * d1[0], t21x * d2[1] - t31x * d1[1],
        t21x * d2[2] - t31x * d1[2] };
      // The general path's tests (cancellation of dP/ds or dP/dt, usable derivatives),
      // made stricter so that no square root or division is needed to pass them:
      // (a + b)^2 <= 2 (a^2 + b^2), and a margin of 2 on the division-free ratios.
      const double absArea = std::abs(area2);
      const double l1 = d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2];
      const double l2 = d2[0] * d2[0] + d2[1] * d2[1] + d2[2] * d2[2];
      const double lenOs2 = os[0] * os[0] + os[1] * os[1] + os[2] * os[2];
      const double lenOt2 = ot[0] * ot[0] + ot[1] * ot[1] + ot[2] * ot[2];
      constexpr double eps2 = 2.0 * CancellationEps * CancellationEps;
      const double floor2 = 4.0 * (FLT_MIN * absArea) * (FLT_MIN * absArea);
      g = absArea > FLT_MIN ? g : 0.0;
      g = lenOs2 > eps2 * (t31y * t31y * l1 + t21y * t21y * l2) ? g : 0.0;
      g = lenOt2 > eps2 * (t31x * t31x * l1 + t21x * t21x * l2) ? g : 0.0;
      g = lenOs2 > floor2 ? g : 0.0;
      g = lenOt2 > floor2 ? g : 0.0;
      g = lenOs2 > 4.0 * FLT_MIN * FLT_MIN ? g : 0.0;
      g = lenOt2 > 4.0 * FLT_MIN * FLT_MIN ? g : 0.0;
      good[j] = g;
      const double s = area2 > 0.0 ? 1.0 : -1.0;
      sign[j] = s;
      const double ss = s / std::sqrt(lenOs2), st = s / std::sqrt(lenOt2);
      for (int i = 0; i < 3; ++i)
      {
        d[i][j] = static_cast<float>(ss * os[i]);
        d[3 + i][j] = static_cast<float>(st * ot[i]);
      }
    }
  }

  // Vertex -> its corners (4 * triangle + corner), each list in triangle order, and beside
  // each corner the (welded) points after and before it in its triangle. Two tasks: the
  // first half of the triangles counts into one array and fills each list from its front,
  // the second half into another and fills from the back, walking backwards; no atomics,
  // and the order does not depend on the number of threads. False, with no lists, if a
  // vertex has more than MaxFastFan corners.
  bool VertexCorners(const std::int32_t* w, vtkIdType nTris, std::int32_t* first,
    std::int32_t* corners, std::int32_t* nextIds, std::int32_t* prevIds) const
  {
    const std::size_t nv = static_cast<std::size_t>(this->NumberOfPoints);
    const vtkIdType half = 3 * (nTris / 2), end = 3 * nTris;
    Block<std::int32_t> count0(nv), count1(nv);
    vtkSMPTools::For(0, 2, 1,
      [&](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType part = b; part < e; ++part)
        {
          std::int32_t* count = part == 0 ? count0.Get() : count1.Get();
          std::memset(count, 0, nv * sizeof(std::int32_t));
          for (vtkIdType c = part == 0 ? 0 : half; c < (part == 0 ? half : end); ++c)
          {
            ++count[w[c]];
          }
        }
      });
    // The prefix sum in two parallel passes over fixed chunks of vertices: each chunk's
    // total, then the chunk's sums from the totals of the chunks before it.
    const FixedChunks chunks(static_cast<vtkIdType>(nv));
    std::vector<std::int32_t> chunkFirst(static_cast<std::size_t>(chunks.Count) + 1, 0);
    std::atomic<bool> largeFan(false);
    chunks.For(
      [&](vtkIdType c, vtkIdType b, vtkIdType e)
      {
        std::int32_t sum = 0, largest = 0;
        for (vtkIdType v = b; v < e; ++v)
        {
          const std::int32_t k = count0[v] + count1[v];
          sum += k;
          largest = std::max(largest, k);
        }
        chunkFirst[c + 1] = sum;
        if (largest > MaxFastFan)
        {
          largeFan.store(true, std::memory_order_relaxed);
        }
      });
    if (largeFan)
    {
      return false;
    }
    for (vtkIdType c = 0; c < chunks.Count; ++c)
    {
      chunkFirst[c + 1] += chunkFirst[c];
    }
    chunks.For(
      [&](vtkIdType c, vtkIdType b, vtkIdType e)
      {
        std::int32_t sum = chunkFirst[c];
        for (vtkIdType v = b; v < e; ++v)
        {
          const std::int32_t n0 = count0[v], n1 = count1[v];
          first[v] = sum;
          count0[v] = sum; // the front cursor
          sum += n0 + n1;
          count1[v] = sum; // the back cursor
        }
      });
    first[nv] = chunkFirst[chunks.Count];
    vtkSMPTools::For(0, 2, 1,
      [&](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType part = b; part < e; ++part)
        {
          if (part == 0)
          {
            for (vtkIdType t = 0; t < half / 3; ++t)
            {
              for (int i = 0; i < 3; ++i)
              {
                const std::int32_t c = count0[w[3 * t + i]]++;
                corners[c] = static_cast<std::int32_t>(t << 2 | i);
                nextIds[c] = w[3 * t + (i + 1) % 3];
                prevIds[c] = w[3 * t + (i + 2) % 3];
              }
            }
          }
          else
          {
            for (vtkIdType t = end / 3 - 1; t >= half / 3; --t)
            {
              for (int i = 2; i >= 0; --i)
              {
                const std::int32_t c = --count1[w[3 * t + i]];
                corners[c] = static_cast<std::int32_t>(t << 2 | i);
                nextIds[c] = w[3 * t + (i + 1) % 3];
                prevIds[c] = w[3 * t + (i + 2) % 3];
              }
            }
          }
        }
      });
    return true;
  }

  // Every vertex's fan from the global vertex lists (VertexCorners).
  bool Vertices(const std::int32_t* nextIds, const std::int32_t* prevIds,
    const std::array<float, 6>* dir, const unsigned char* orient, const std::int32_t* first,
    const std::int32_t* corners, const std::int32_t* weld, float* out) const
  {
    std::atomic<bool> fail(false);
    vtkSMPTools::For(0, vtkIdType(this->NumberOfPoints),
      [&](vtkIdType b, vtkIdType e)
      {
        if (fail.load(std::memory_order_relaxed))
        {
          return;
        }
        const FlushSubnormals flush(std::is_same<Real, float>::value);
        const bool done = vtkSurfaceDetailVectorize::HaveAVX512()
          ? FansAVX512(*this, std::int32_t(b), std::int32_t(e), nextIds, prevIds, dir, orient,
              first, corners, weld, out)
          : vtkSurfaceDetailVectorize::HaveAVX2()
          ? FansAVX2(*this, std::int32_t(b), std::int32_t(e), nextIds, prevIds, dir, orient, first,
              corners, weld, out)
          : this->Fans<false>(std::int32_t(b), std::int32_t(e), nextIds, prevIds, dir, orient,
              first, corners, weld, out);
        if (!done)
        {
          fail.store(true, std::memory_order_relaxed);
        }
      });
    return !fail;
  }

  // In the AVX-512 and AVX2 builds, the vertices go in tasks of TaskVertices, each of which reads
  // the chunks of SpanTriangles triangles that may have corners among its vertices (TaskChunks) in
  // triangle order and copies its vertices' corners straight into its fans' slots (LocalSlots): no
  // global vertex lists (VertexCorners: 36 MB written on the 1M torus, 13% of the cycles) and no
  // copies from them into the slots (GatherSlots: half the fan pass). A task's slots (~800 kB on
  // the torus, of 4 MB of address space) stay in the level-2 cache from their copy to the corner
  // loop. Tasks of 4096 vertices read each chunk of the 1M torus about 1.26 times, 2048 1.52 times
  // (2% more cycles since the triangle pass streams its output), 1024 more still. In the AVX2 build
  // on a Zen 4 (1 MB of level-2 cache), the task-local slots took the 1M torus from 71-72 to 58-59
  // ms on one thread.
  static constexpr vtkIdType SpanTriangles = 128;
  static constexpr std::int32_t TaskVertices = 4096;
  // The tasks may read each chunk this many times on average (each read is two passes: the
  // count and the copy); meshes whose welded ids are more scattered (a mesh numbered at
  // random) use the global lists. The 1M torus: about 1.26 times.
  static constexpr vtkIdType MaxScans = 3;

  // Per task, the chunks whose corners' least and largest welded ids (lo and hi, which are
  // turned into task numbers) enclose some of its vertices, in increasing order (taskFirst:
  // CSR starts). False if that is more than MaxScans chunks per chunk.
  bool TaskChunks(std::vector<std::int32_t>& lo, std::vector<std::int32_t>& hi,
    std::vector<std::int32_t>& taskFirst, std::vector<std::int32_t>& taskChunks) const
  {
    const vtkIdType nChunks = static_cast<vtkIdType>(lo.size());
    const vtkIdType nTasks = (vtkIdType(this->NumberOfPoints) + TaskVertices - 1) / TaskVertices;
    for (vtkIdType ch = 0; ch < nChunks; ++ch)
    {
      lo[ch] /= TaskVertices;
      hi[ch] /= TaskVertices;
    }
    vtkIdType scans = 0;
    for (vtkIdType ch = 0; ch < nChunks; ++ch)
    {
      scans += hi[ch] - lo[ch] + 1;
    }
    if (scans > MaxScans * nChunks)
    {
      return false;
    }
    taskFirst.assign(static_cast<std::size_t>(nTasks) + 1, 0);
    for (vtkIdType ch = 0; ch < nChunks; ++ch)
    {
      for (std::int32_t t = lo[ch]; t <= hi[ch]; ++t)
      {
        ++taskFirst[t + 1];
      }
    }
    std::partial_sum(taskFirst.begin(), taskFirst.end(), taskFirst.begin());
    std::vector<std::int32_t> cursor(taskFirst.begin(), taskFirst.end() - 1);
    taskChunks.resize(static_cast<std::size_t>(scans));
    for (vtkIdType ch = 0; ch < nChunks; ++ch)
    {
      for (std::int32_t t = lo[ch]; t <= hi[ch]; ++t)
      {
        taskChunks[cursor[t]++] = static_cast<std::int32_t>(ch);
      }
    }
    return true;
  }

  // One task's lanes and slots; kept per thread from task to task.
  struct TaskSlots
  {
    // Per vertex x of the task: its next slot.
    std::vector<std::int32_t> Cursor;
    // The vertices that are not copies of smaller ones, one to a lane; per lane its number of
    // corners; per group of Lanes lanes its largest fan.
    std::vector<std::int32_t> Lane, K, GroupSlots;
    // The slots (see SlotBlock): each group has room for GroupRows rows of corners, and a
    // row is Lanes records, one per lane, of eight values (RowStride 8 Lanes, LaneStride 8):
    // the next id at [c], the previous id at [c + 1] (its top bit the triangle's texture
    // orientation), dP/ds and dP/dt at [c + 2 + q]. A copy
    // into a slot is then one 32-byte store (eight scattered stores, one into each of eight
    // arrays side by side, took 5% more cycles on the 1M torus), and WeighSlots transposes
    // each row (TransposeRow). Room for the largest task (2 MB or more: huge pages, from
    // vtkSurfaceDetailMemory's cache at the next execution).
    std::shared_ptr<Block<unsigned char>> Slots;
  };
  // Room for the largest fan: only the rows that the fans fill are touched. (Groups 33 rows
  // apart, 16.5 kB rather than 16, so that their rows fall into other cache sets, took the
  // same cycles.)
  static constexpr int GroupRows = MaxFastFan;
  static constexpr std::size_t MaxTaskSlots =
    std::size_t(8 * SlotBlock<Real>::Lanes) * GroupRows * (TaskVertices / SlotBlock<Real>::Lanes);

  // A SlotBlock, and its first corners' directions for References, allocated by each task:
  // the compiler then knows that they alias nothing else, and vectorises the loops over
  // their lanes.
  struct TaskBlock
  {
    SlotBlock<Real> Fans;
    alignas(64) float FirstDir[6][SlotBlock<Real>::MaxVertices];
  };

  // The fans of the vertices [vb, ve) in the AVX-512 or AVX2 build, from the triangles of the
  // chunks [cb, ce) of taskChunks (see TaskChunks). The task gives each vertex that is not a copy
  // of a smaller one a lane (in vertex order, as SlotFans does, but in one layout for the
  // whole task) and room for the largest fan, copies each corner of its vertices, in
  // triangle order (the order of VertexCorners' lists, so each fan's sums are SlotFans' to
  // the bit), straight into its slot, reading the triangles' directions in their order, and
  // counts the corners by the slots' cursors (no pass of its own). A lane with no corners (a
  // vertex no triangle uses) stays empty, with copies of another lane's corners, as the
  // lanes past the vertices in SlotFans. Then SlotFans' steps per block of SlotBlock's
  // vertices. False if a check fails or a fan is too large.
  template <bool Wide512>
  VTK_ALWAYS_INLINE bool LocalSlots(const std::int32_t* w, vtkIdType nTris, const std::int32_t* cb,
    const std::int32_t* ce, std::int32_t vb, std::int32_t ve, const std::array<float, 6>* dir,
    const unsigned char* orient, const std::int32_t* weld, TaskSlots& ts, float* out) const
  {
    constexpr int Lanes = SlotBlock<Real>::Lanes;
    constexpr int RowStride = 8 * Lanes;
    constexpr int GroupStride = GroupRows * RowStride;
    const std::uint32_t nv = static_cast<std::uint32_t>(ve - vb);
    if (ts.Cursor.size() < nv)
    {
      ts.Cursor.resize(nv);
      ts.Lane.resize(nv);
      ts.K.resize(nv);
      ts.GroupSlots.resize(nv / Lanes + 1);
    }
    std::int32_t* __restrict lane = ts.Lane.data();
    std::int32_t* __restrict cursor = ts.Cursor.data();
    int nl = 0;
    for (std::uint32_t x = 0; x < nv; ++x)
    {
      if (this->Welded &&
        weld[vb + static_cast<std::int32_t>(x)] != vb + static_cast<std::int32_t>(x))
      {
        continue; // a copy of a smaller point, filled later
      }
      cursor[x] = GroupStride * (nl / Lanes) + 8 * (nl % Lanes);
      lane[nl++] = static_cast<std::int32_t>(x);
    }
    if (!ts.Slots)
    {
      ts.Slots = std::make_shared<Block<unsigned char>>(MaxTaskSlots * sizeof(float));
    }
    std::int32_t* __restrict ids = reinterpret_cast<std::int32_t*>(ts.Slots->Get());
    float* __restrict d = reinterpret_cast<float*>(ts.Slots->Get());
    // A fan too large writes over other lanes' slots (the task then fails) but no further
    // than the last row.
    constexpr std::int32_t lastSlot = static_cast<std::int32_t>(MaxTaskSlots) - RowStride;
    for (const std::int32_t* ch = cb; ch < ce; ++ch)
    {
      const vtkIdType t0 = SpanTriangles * *ch, t1 = std::min(nTris, t0 + SpanTriangles);
      for (vtkIdType t = t0; t < t1; ++t)
      {
        const std::int32_t a = w[3 * t], b = w[3 * t + 1], c = w[3 * t + 2];
        // The triangle's texture orientation as the top bit of each corner's previous id (see
        // WeighSlots).
        const std::int32_t mark = static_cast<std::int32_t>(std::uint32_t(orient[t]) << 31);
#if SURFACEDETAIL_MIKK_INTRINSICS
        // The triangle's ids times 3 and its directions as two vectors (each reading past the
        // triangle: see Finish), and each corner's record one permutation of the two.
        typedef float Record __attribute__((vector_size(32)));
        typedef std::int32_t Ids __attribute__((vector_size(32)));
        typedef std::int32_t Ids4 __attribute__((vector_size(16)));
        typedef float Floats4 __attribute__((vector_size(16)));
        Ids4 ids;
        Record dirs;
        std::memcpy(&ids, w + 3 * t, sizeof(Ids4));
        std::memcpy(&dirs, dir[t].data(), sizeof(Record));
        const Floats4 ids3 = reinterpret_cast<Floats4>(ids * 3);
        const Floats4 marked = reinterpret_cast<Floats4>((ids * 3) | mark);
        const Record tri = __builtin_shufflevector(ids3, marked, 0, 1, 2, 3, 4, 5, 6, 7);
        const Record records[3] = { __builtin_shuffle(dirs, tri, Ids{ 9, 14, 0, 1, 2, 3, 4, 5 }),
          __builtin_shuffle(dirs, tri, Ids{ 10, 12, 0, 1, 2, 3, 4, 5 }),
          __builtin_shuffle(dirs, tri, Ids{ 8, 13, 0, 1, 2, 3, 4, 5 }) };
#endif
        // Corner i, at point id: one store of its record.
        auto copy = [&](int i, std::int32_t id)
        {
          const std::uint32_t x = static_cast<std::uint32_t>(id - vb);
          if (x < nv)
          {
            const std::int32_t at = cursor[x];
            cursor[x] = at + RowStride;
            float* to = d + std::min(at, lastSlot);
#if SURFACEDETAIL_MIKK_INTRINSICS
            std::memcpy(to, &records[i], sizeof(Record));
#else
            const std::int32_t np[2] = { 3 * w[3 * t + (i + 1) % 3],
              (3 * w[3 * t + (i + 2) % 3]) | mark };
            std::memcpy(to, np, sizeof(np));
            std::copy_n(dir[t].data(), 6, to + 2);
#endif
          }
        };
        copy(0, a);
        copy(1, b);
        copy(2, c);
      }
    }
    std::int32_t* __restrict count = ts.K.data();
    std::int32_t* __restrict groupSlots = ts.GroupSlots.data();
    std::int32_t largest = 0;
    for (int g = 0; g < (nl + Lanes - 1) / Lanes; ++g)
    {
      // The group's largest fan in a local (in memory, each lane's max waited on the last).
      std::int32_t slots = 0;
      for (int j = Lanes * g; j < std::min(nl, Lanes * (g + 1)); ++j)
      {
        const std::int32_t k = (cursor[lane[j]] - (GroupStride * g + 8 * (j % Lanes))) / RowStride;
        count[j] = k;
        slots = std::max(slots, k);
      }
      groupSlots[g] = slots;
      largest = std::max(largest, slots);
    }
    if (largest > MaxFastFan)
    {
      return false;
    }
    std::unique_ptr<TaskBlock> block(new TaskBlock);
    SlotBlock<Real>& fb = block->Fans;
    fb.Next = ids;
    fb.Prev = ids + 1;
    for (int q = 0; q < 6; ++q)
    {
      fb.Dir[q] = d + 2 + q;
    }
    fb.RowStride = RowStride;
    fb.LaneStride = 8;
    constexpr int MaxVertices = SlotBlock<Real>::MaxVertices;
    for (int l0 = 0; l0 < nl; l0 += MaxVertices)
    {
      const int nb = std::min(MaxVertices, nl - l0);
      for (int g = 0; g < (nb + Lanes - 1) / Lanes; ++g)
      {
        fb.GroupFirst[g] = GroupStride * (l0 / Lanes + g);
        fb.GroupSlots[g] = groupSlots[l0 / Lanes + g];
      }
      // Checks fold into a flag (loops with an early exit do not vectorise).
      int bad = 0;
      for (int j = 0; j < nb; ++j)
      {
        fb.Vertex[j] = vb + lane[l0 + j];
        fb.K[j] = count[l0 + j];
      }
      // Lanes in vertex order: the last one nb - 1 after the first if no welded copy is
      // among them.
      bad |= fb.Vertex[nb - 1] - fb.Vertex[0] == nb - 1
        ? LaneVertices<true>(fb, nb, this->N, this->P)
        : LaneVertices<false>(fb, nb, this->N, this->P);
      if (bad)
      {
        return false;
      }
      fb.NumberOfVertices = nb;
      Pad(fb);
      // Each lane's first corner; empty lanes and the lanes past the block's vertices repeat
      // another lane's, as Pad made them.
      float(*__restrict firstDir)[SlotBlock<Real>::MaxVertices] = block->FirstDir;
      for (int g = 0; g < (nb + Lanes - 1) / Lanes; ++g)
      {
        alignas(64) std::int32_t rowIds[2][Lanes];
        alignas(64) float rowDir[6][Lanes];
        TransposeRow<Wide512>(d + fb.GroupFirst[g], rowIds, rowDir);
        for (int q = 0; q < 6; ++q)
        {
          std::copy_n(rowDir[q], Lanes, firstDir[q] + Lanes * g);
        }
        // The first corner's orientation (WeighSlots checks the others against it).
        for (int i = 0; i < Lanes; ++i)
        {
          fb.Handedness[Lanes * g + i] = rowIds[1][i] < 0 ? 1.0f : -1.0f;
        }
      }
      ReferencesOf(
        fb, (nb + Lanes - 1) & ~(Lanes - 1), [firstDir](int j, int q) { return firstDir[q][j]; });
      // The fan's ids in corner order, as in VertexCorners' lists.
      auto oneRun = [&](int j)
      {
        std::int32_t n[MaxFastFan + 8] = {}, p[MaxFastFan + 8] = {};
        const int c0 = fb.GroupFirst[j / Lanes] + fb.LaneStride * (j % Lanes);
        for (int a = 0; a < fb.K[j]; ++a)
        {
          n[a] = fb.Next[c0 + fb.RowStride * a] / 3;
          p[a] = (fb.Prev[c0 + fb.RowStride * a] & std::numeric_limits<std::int32_t>::max()) / 3;
        }
        return FanIsOneRun<true>(n, p, fb.K[j]);
      };
      if (!this->WeighSlots<true, Wide512>(fb) || !SumSlots(fb, oneRun, out))
      {
        return false;
      }
    }
    return true;
  }

  // Each lane's unit normal (from the normals) and position; 1 if a lane with corners has a
  // normal not of unit length. Consecutive: the lanes' vertices follow one another, so the
  // compiler reads their values as consecutive triples (permutations) instead of emulated
  // gathers.
  template <bool Consecutive>
  VTK_ALWAYS_INLINE static int LaneVertices(
    SlotBlock<Real>& fb, int nb, const NT* __restrict normals, const PT* __restrict pts)
  {
    int bad = 0;
    const std::size_t v0 = static_cast<std::size_t>(fb.Vertex[0]);
    for (int j = 0; j < nb; ++j)
    {
      const std::size_t v =
        Consecutive ? v0 + static_cast<std::size_t>(j) : static_cast<std::size_t>(fb.Vertex[j]);
      double u[3];
      UnitNormalOf(normals + 3 * v, u);
      // An empty lane's vertex gets the default frame from its normal, as it is.
      bad |= (fb.K[j] > 0) & !(std::abs(u[0] * u[0] + u[1] * u[1] + u[2] * u[2] - 1.0) < 1e-6);
      for (int q = 0; q < 3; ++q)
      {
        fb.NV[q][j] = u[q];
        fb.NR[q][j] = static_cast<Real>(u[q]);
        fb.Position[q][j] = Real(pts[3 * v + q]);
      }
    }
    return bad;
  }

  // One row of a task's slots, Lanes records of eight values (next and previous ids, dP/ds,
  // dP/dt), as eight arrays of Lanes values: in the AVX-512 build three steps of two-vector
  // permutations, 24 in all, in place of the copies' seven more scattered stores per corner
  // (in the AVX2 build TransposeRowAVX2).
  template <bool Wide512>
  VTK_ALWAYS_INLINE static void TransposeRow(const float* __restrict records,
    std::int32_t (*__restrict ids)[SlotBlock<Real>::Lanes],
    float (*__restrict dirs)[SlotBlock<Real>::Lanes])
  {
    static_assert(SlotBlock<Real>::Lanes == 16, "sixteen records of eight");
#if SURFACEDETAIL_MIKK_INTRINSICS
    if constexpr (!Wide512)
    {
      TransposeRowAVX2(records, ids, dirs);
      return;
    }
    else
    {
      typedef float V __attribute__((vector_size(64)));
      typedef std::int32_t M __attribute__((vector_size(64)));
      // Register k holds records 2k and 2k + 1. The first step takes from two registers (four
      // records) their values 0-3 or 4-7, in the order (value, record); the second, from two
      // of those, two values of eight records; the third one value of all sixteen.
      const M lo4 = { 0, 8, 16, 24, 1, 9, 17, 25, 2, 10, 18, 26, 3, 11, 19, 27 };
      const M hi4 = { 4, 12, 20, 28, 5, 13, 21, 29, 6, 14, 22, 30, 7, 15, 23, 31 };
      const M lo2 = { 0, 1, 2, 3, 16, 17, 18, 19, 4, 5, 6, 7, 20, 21, 22, 23 };
      const M hi2 = { 8, 9, 10, 11, 24, 25, 26, 27, 12, 13, 14, 15, 28, 29, 30, 31 };
      const M lo1 = { 0, 1, 2, 3, 4, 5, 6, 7, 16, 17, 18, 19, 20, 21, 22, 23 };
      const M hi1 = { 8, 9, 10, 11, 12, 13, 14, 15, 24, 25, 26, 27, 28, 29, 30, 31 };
      V r[8], a[8], b[8];
      for (int k = 0; k < 8; ++k)
      {
        std::memcpy(&r[k], records + 16 * k, sizeof(V));
      }
      for (int m = 0; m < 4; ++m) // a[2 m + h]: records 4m to 4m + 3, values 4h to 4h + 3
      {
        a[2 * m] = __builtin_shuffle(r[2 * m], r[2 * m + 1], lo4);
        a[2 * m + 1] = __builtin_shuffle(r[2 * m], r[2 * m + 1], hi4);
      }
      for (int n = 0; n < 2; ++n) // b[4 n + 2 h + e]: records 8n to 8n + 7, values 4h + 2e, + 1
      {
        for (int h = 0; h < 2; ++h)
        {
          b[4 * n + 2 * h] = __builtin_shuffle(a[4 * n + h], a[4 * n + 2 + h], lo2);
          b[4 * n + 2 * h + 1] = __builtin_shuffle(a[4 * n + h], a[4 * n + 2 + h], hi2);
        }
      }
      for (int q = 0; q < 8; ++q)
      {
        const V v = __builtin_shuffle(b[q / 2], b[4 + q / 2], q % 2 ? hi1 : lo1);
        std::memcpy(
          q < 2 ? static_cast<void*>(ids[q]) : static_cast<void*>(dirs[q - 2]), &v, sizeof(V));
      }
      return;
    }
#endif
    for (int i = 0; i < SlotBlock<Real>::Lanes; ++i)
    {
      std::memcpy(&ids[0][i], records + 8 * i, sizeof(float));
      std::memcpy(&ids[1][i], records + 8 * i + 1, sizeof(float));
      for (int q = 0; q < 6; ++q)
      {
        dirs[q][i] = records[8 * i + 2 + q];
      }
    }
  }

#if SURFACEDETAIL_MIKK_INTRINSICS
  // TransposeRow in the AVX2 build: each half of the row (eight records) one 8 x 8 transposition,
  // 24 unpacks, shuffles and 128-bit permutations (the plain loop's 128 scalar loads and stores
  // took a tenth of the task-local slots' time on the 1M torus). Not forced inline, as
  // GatherRow.
  SURFACEDETAIL_TARGET_AVX2 static void TransposeRowAVX2(const float* __restrict records,
    std::int32_t (*__restrict ids)[SlotBlock<Real>::Lanes],
    float (*__restrict dirs)[SlotBlock<Real>::Lanes])
  {
    for (int h = 0; h < 2; ++h)
    {
      __m256 r[8], t[8], u[8];
      for (int k = 0; k < 8; ++k)
      {
        r[k] = _mm256_loadu_ps(records + 8 * (8 * h + k));
      }
      for (int k = 0; k < 4; ++k) // t[2 k]: values 0, 1 | 4, 5 of records 2 k and 2 k + 1
      {
        t[2 * k] = _mm256_unpacklo_ps(r[2 * k], r[2 * k + 1]);
        t[2 * k + 1] = _mm256_unpackhi_ps(r[2 * k], r[2 * k + 1]);
      }
      for (int m = 0; m < 2; ++m) // u[4 m + v]: value v | v + 4 of records 4 m to 4 m + 3
      {
        u[4 * m] = _mm256_shuffle_ps(t[4 * m], t[4 * m + 2], _MM_SHUFFLE(1, 0, 1, 0));
        u[4 * m + 1] = _mm256_shuffle_ps(t[4 * m], t[4 * m + 2], _MM_SHUFFLE(3, 2, 3, 2));
        u[4 * m + 2] = _mm256_shuffle_ps(t[4 * m + 1], t[4 * m + 3], _MM_SHUFFLE(1, 0, 1, 0));
        u[4 * m + 3] = _mm256_shuffle_ps(t[4 * m + 1], t[4 * m + 3], _MM_SHUFFLE(3, 2, 3, 2));
      }
      for (int v = 0; v < 4; ++v) // values v and v + 4 of the eight records
      {
        float* to = v < 2 ? reinterpret_cast<float*>(ids[v]) : dirs[v - 2];
        _mm256_store_ps(to + 8 * h, _mm256_permute2f128_ps(u[v], u[4 + v], 0x20));
        _mm256_store_ps(dirs[v + 2] + 8 * h, _mm256_permute2f128_ps(u[v], u[4 + v], 0x31));
      }
    }
  }
#endif

  // The point id (an end of a corner's edge: which 0 or 1) in record i of a row of records (eight
  // floats each) for GatherRow and GatherRowAVX2. A previous id's top bit is its triangle's
  // texture orientation (see LocalSlots): cleared.
  VTK_ALWAYS_INLINE static std::int32_t RecordPointId(const float* records, int i, int which)
  {
    std::int32_t x;
    std::memcpy(&x, records + 8 * i + which, sizeof(x));
    return x & std::numeric_limits<std::int32_t>::max();
  }

  // The positions of the next points (ends[0-2]: x, y, z) and previous points (ends[3-5]) of
  // a row of a task's slots (float points; records as in TransposeRow). The corner loop
  // read them with emulated gathers, a lane's id moved out of its vector and a scalar load
  // for each coordinate (~6 instructions a value, a tenth of the filter's cycles on the 1M
  // torus); here each id is read as a scalar from its record and each point is one masked
  // load (the fourth float, past the last point's, is not read), four points to a vector,
  // transposed by permutations.
  // Not forced inline: it is built for AVX-512 (its intrinsics need that target), and its
  // callers, always inlined, are not (see WeighSlots); the compiler inlines it into the
  // AVX-512 build that runs them.
  SURFACEDETAIL_TARGET_AVX512 static void GatherRow(const float* __restrict p,
    const float* __restrict records, float (*__restrict ends)[SlotBlock<Real>::Lanes])
  {
    constexpr int Lanes = SlotBlock<Real>::Lanes;
    static_assert(Lanes == 16, "sixteen records of eight");
#if SURFACEDETAIL_MIKK_INTRINSICS
    // Lanes (4 a, 4 a + 1, ...) from a and (4 a + 16, ...) from b: x of points 0-7, then y; z.
    const __m512i xy = _mm512_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28, 1, 5, 9, 13, 17, 21, 25, 29);
    const __m512i zz =
      _mm512_setr_epi32(2, 6, 10, 14, 18, 22, 26, 30, 2, 6, 10, 14, 18, 22, 26, 30);
    for (int which = 0; which < 2; ++which)
    {
      __m512 four[4]; // points 4 k to 4 k + 3, one to each 128-bit block
      for (int k = 0; k < 4; ++k)
      {
        __m128 pt[4]; // (lambdas do not take the function's target: no intrinsics in them)
        for (int l = 0; l < 4; ++l)
        {
          pt[l] = _mm_maskz_loadu_ps(0x7, p + RecordPointId(records, 4 * k + l, which));
        }
        const __m256 lo = _mm256_insertf128_ps(_mm256_castps128_ps256(pt[0]), pt[1], 1);
        const __m256 hi = _mm256_insertf128_ps(_mm256_castps128_ps256(pt[2]), pt[3], 1);
        four[k] = _mm512_insertf32x8(_mm512_castps256_ps512(lo), hi, 1);
      }
      const __m512 a = _mm512_permutex2var_ps(four[0], xy, four[1]);
      const __m512 b = _mm512_permutex2var_ps(four[2], xy, four[3]);
      const __m512 c = _mm512_permutex2var_ps(four[0], zz, four[1]);
      const __m512 d = _mm512_permutex2var_ps(four[2], zz, four[3]);
      // (_mm512_shuffle_f32x4 leaves GCC 12 warning of an uninitialised value; with the whole
      // mask it is the same instruction.)
      constexpr __mmask16 all = 0xffff;
      _mm512_store_ps(
        ends[3 * which], _mm512_mask_shuffle_f32x4(a, all, a, b, _MM_SHUFFLE(1, 0, 1, 0)));
      _mm512_store_ps(
        ends[3 * which + 1], _mm512_mask_shuffle_f32x4(a, all, a, b, _MM_SHUFFLE(3, 2, 3, 2)));
      _mm512_store_ps(
        ends[3 * which + 2], _mm512_mask_shuffle_f32x4(c, all, c, d, _MM_SHUFFLE(1, 0, 1, 0)));
    }
#else
    for (int which = 0; which < 2; ++which)
    {
      for (int i = 0; i < Lanes; ++i)
      {
        const float* x = p + RecordPointId(records, i, which);
        for (int q = 0; q < 3; ++q)
        {
          ends[3 * which + q][i] = x[q];
        }
      }
    }
#endif
  }

#if SURFACEDETAIL_MIKK_INTRINSICS
  // GatherRow in the AVX2 build: each point one masked load of its three floats (vmaskmovps,
  // which does not read the fourth), points k and k + 4 to one vector, and each eight points
  // transposed by unpacks and shuffles within the 128-bit halves. Not forced inline, as
  // GatherRow.
  SURFACEDETAIL_TARGET_AVX2 static void GatherRowAVX2(const float* __restrict p,
    const float* __restrict records, float (*__restrict ends)[SlotBlock<Real>::Lanes])
  {
    static_assert(SlotBlock<Real>::Lanes == 16, "sixteen records of eight");
    const __m128i xyz = _mm_setr_epi32(-1, -1, -1, 0);
    for (int which = 0; which < 2; ++which)
    {
      for (int h = 0; h < 2; ++h) // lanes 8 h to 8 h + 7
      {
        __m256 q[4]; // point 8 h + k, then point 8 h + k + 4: (x, y, z, 0) each
        for (int k = 0; k < 4; ++k)
        {
          const std::int32_t lo = RecordPointId(records, 8 * h + k, which);
          const std::int32_t hi = RecordPointId(records, 8 * h + k + 4, which);
          q[k] = _mm256_insertf128_ps(
            _mm256_castps128_ps256(_mm_maskload_ps(p + lo, xyz)), _mm_maskload_ps(p + hi, xyz), 1);
        }
        const __m256 xy01 = _mm256_unpacklo_ps(q[0], q[1]); // x0 x1 y0 y1 | x4 x5 y4 y5
        const __m256 xy23 = _mm256_unpacklo_ps(q[2], q[3]);
        const __m256 z01 = _mm256_unpackhi_ps(q[0], q[1]); // z0 z1 0 0 | z4 z5 0 0
        const __m256 z23 = _mm256_unpackhi_ps(q[2], q[3]);
        _mm256_store_ps(
          ends[3 * which] + 8 * h, _mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(1, 0, 1, 0)));
        _mm256_store_ps(
          ends[3 * which + 1] + 8 * h, _mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(3, 2, 3, 2)));
        _mm256_store_ps(
          ends[3 * which + 2] + 8 * h, _mm256_shuffle_ps(z01, z23, _MM_SHUFFLE(1, 0, 1, 0)));
      }
    }
  }
#endif

  // GatherRow of the build: AVX-512 or (where the intrinsics are compiled) AVX2.
  template <bool Wide512>
  VTK_ALWAYS_INLINE static void GatherRowOf(const float* __restrict p,
    const float* __restrict records, float (*__restrict ends)[SlotBlock<Real>::Lanes])
  {
    if constexpr (Wide512)
    {
      GatherRow(p, records, ends);
    }
    else
    {
#if SURFACEDETAIL_MIKK_INTRINSICS
      GatherRowAVX2(p, records, ends);
#else
      static_assert(Wide512, "the AVX2 build gathers in the corner loop without intrinsics");
#endif
    }
  }

  SURFACEDETAIL_TARGET_AVX512 static bool LocalSlotsAVX512(const FastMikk& self,
    const std::int32_t* w, vtkIdType nTris, const std::int32_t* cb, const std::int32_t* ce,
    std::int32_t vb, std::int32_t ve, const std::array<float, 6>* dir, const unsigned char* orient,
    const std::int32_t* weld, TaskSlots& ts, float* out)
  {
    return self.LocalSlots<true>(w, nTris, cb, ce, vb, ve, dir, orient, weld, ts, out);
  }

  SURFACEDETAIL_TARGET_AVX2 static bool LocalSlotsAVX2(const FastMikk& self, const std::int32_t* w,
    vtkIdType nTris, const std::int32_t* cb, const std::int32_t* ce, std::int32_t vb,
    std::int32_t ve, const std::array<float, 6>* dir, const unsigned char* orient,
    const std::int32_t* weld, TaskSlots& ts, float* out)
  {
    return self.LocalSlots<false>(w, nTris, cb, ce, vb, ve, dir, orient, weld, ts, out);
  }

  // Every vertex's fan by tasks (LocalSlots), in the AVX-512 or the AVX2 build.
  bool LocalVertices(const std::int32_t* w, vtkIdType nTris,
    const std::vector<std::int32_t>& taskFirst, const std::vector<std::int32_t>& taskChunks,
    const std::array<float, 6>* dir, const unsigned char* orient, const std::int32_t* weld,
    float* out) const
  {
    std::atomic<bool> fail(false);
    vtkSMPThreadLocal<TaskSlots> slots;
    const bool wide512 = vtkSurfaceDetailVectorize::HaveAVX512();
    const vtkIdType nTasks = static_cast<vtkIdType>(taskFirst.size()) - 1;
    vtkSMPTools::For(0, nTasks, 1,
      [&](vtkIdType b, vtkIdType e)
      {
        TaskSlots& ts = slots.Local();
        const FlushSubnormals flush(std::is_same<Real, float>::value);
        for (vtkIdType task = b; task < e; ++task)
        {
          if (fail.load(std::memory_order_relaxed))
          {
            return;
          }
          const std::int32_t vb = static_cast<std::int32_t>(task * TaskVertices);
          const std::int32_t ve = std::min(this->NumberOfPoints, vb + TaskVertices);
          const std::int32_t* cb = taskChunks.data() + taskFirst[task];
          const std::int32_t* ce = taskChunks.data() + taskFirst[task + 1];
          if (!(wide512
                  ? LocalSlotsAVX512(*this, w, nTris, cb, ce, vb, ve, dir, orient, weld, ts, out)
                  : LocalSlotsAVX2(*this, w, nTris, cb, ce, vb, ve, dir, orient, weld, ts, out)))
          {
            fail.store(true, std::memory_order_relaxed);
          }
        }
      });
    return !fail;
  }

  // Welded points share their vertex's frame if a polygon uses them; the frame of a point
  // no polygon uses is the default one, as in the general path.
  void CopyWelded(
    const std::int32_t* weld, const std::atomic<unsigned char>* referenced, float* out) const
  {
    auto unused = [&](std::int32_t p, float* t)
    {
      const V3 n = this->UnitNormal(p);
      FinalTangent(n, TSpace{ { { 0.0, 0.0, 0.0 } }, true, -1 }, t);
    };
    vtkSMPTools::For(0, vtkIdType(this->NumberOfPoints),
      [&](vtkIdType b, vtkIdType e)
      {
        for (std::int32_t p = std::int32_t(b); p < std::int32_t(e); ++p)
        {
          if (weld[p] == p)
          {
            continue;
          }
          if (referenced[p].load(std::memory_order_relaxed))
          {
            std::copy_n(out + 4 * std::size_t(weld[p]), 4, out + 4 * std::size_t(p));
          }
          else
          {
            unused(p, out + 4 * std::size_t(p));
          }
        }
      });
    vtkSMPTools::For(0, vtkIdType(this->NumberOfPoints),
      [&](vtkIdType b, vtkIdType e)
      {
        for (std::int32_t p = std::int32_t(b); p < std::int32_t(e); ++p)
        {
          if (weld[p] == p && !referenced[p].load(std::memory_order_relaxed))
          {
            unused(p, out + 4 * std::size_t(p));
          }
        }
      });
  }

  VTK_ALWAYS_INLINE V3 UnitNormal(std::int32_t v) const
  {
    V3 n{ double(this->N[3 * std::size_t(v)]), double(this->N[3 * std::size_t(v) + 1]),
      double(this->N[3 * std::size_t(v) + 2]) };
    const double len = std::sqrt(Dot(n, n));
    if (len > 0.0 && std::isfinite(len))
    {
      n = Scale(1.0 / len, n);
    }
    return n;
  }

  // The fans in the AVX2 build (see vtkSurfaceDetailVectorize.h): the corners' arithmetic
  // four to a vector, the small fans' links found in eight lanes; the same results bit
  // for bit (no fused multiply-add, and sums stay in order).
  SURFACEDETAIL_TARGET_AVX2 static bool FansAVX2(const FastMikk& self, std::int32_t b,
    std::int32_t e, const std::int32_t* nextIds, const std::int32_t* prevIds,
    const std::array<float, 6>* dir, const unsigned char* orient, const std::int32_t* first,
    const std::int32_t* corners, const std::int32_t* weld, float* out)
  {
    return self.Fans<true>(b, e, nextIds, prevIds, dir, orient, first, corners, weld, out);
  }

  // The fans in the AVX-512 build, slot-major (see SlotBlock): sixteen floats or eight
  // doubles to a vector; same bits (no contraction into fused multiply-adds: see
  // CMakeLists, and sums in the same order).
  SURFACEDETAIL_TARGET_AVX512 static bool FansAVX512(const FastMikk& self, std::int32_t b,
    std::int32_t e, const std::int32_t* nextIds, const std::int32_t* prevIds,
    const std::array<float, 6>* dir, const unsigned char* orient, const std::int32_t* first,
    const std::int32_t* corners, const std::int32_t* weld, float* out)
  {
    return self.SlotFans(b, e, nextIds, prevIds, dir, orient, first, corners, weld, out);
  }

  template <bool Wide>
  VTK_ALWAYS_INLINE bool Fans(std::int32_t b, std::int32_t e, const std::int32_t* nextIds,
    const std::int32_t* prevIds, const std::array<float, 6>* dir, const unsigned char* orient,
    const std::int32_t* first, const std::int32_t* corners, const std::int32_t* weld,
    float* out) const
  {
    std::unique_ptr<FanBlock<Real>> block(new FanBlock<Real>);
    FanBlock<Real>& fb = *block;
    for (std::int32_t v = b; v < e;)
    {
      fb.NumberOfVertices = 0;
      fb.NumberOfCorners = 0;
      fb.First[0] = 0;
      for (; v < e && fb.NumberOfVertices < FanBlock<Real>::MaxVertices; ++v)
      {
        if (this->Welded && weld[v] != v)
        {
          continue; // a copy of a smaller point, filled later
        }
        const int k = first[v + 1] - first[v];
        if (k > FanBlock<Real>::MaxCorners - fb.NumberOfCorners)
        {
          break;
        }
        auto gather = [&](const V3& n, const std::int32_t* list, const std::int32_t* next,
                        const std::int32_t* prev)
        { return this->GatherFan<Wide>(v, k, n, list, next, prev, orient, fb); };
        if (!this->WithFan(
              v, k, nextIds, prevIds, first, corners, out + 4 * std::size_t(v), gather))
        {
          return false;
        }
      }
      References(fb, dir, fb.NumberOfVertices);
      this->WeighCorners<Wide>(fb, dir);
      if (!SumFans<Wide>(fb, dir, nextIds, prevIds, first, out))
      {
        return false;
      }
    }
    return true;
  }

  // The start of GatherFan and GatherSlots: a vertex that no triangle uses gets the default
  // frame at once, a normal not of unit length fails the fast path; else gather(n, corners,
  // next ids, previous ids) with v's unit normal and its fan's lists.
  template <typename Gather>
  VTK_ALWAYS_INLINE bool WithFan(std::int32_t v, int k, const std::int32_t* nextIds,
    const std::int32_t* prevIds, const std::int32_t* first, const std::int32_t* corners, float* out,
    Gather&& gather) const
  {
    const double* u = this->UnitNormals + 3 * std::size_t(v);
    const V3 n{ u[0], u[1], u[2] };
    if (k == 0)
    {
      FinalTangent(n, TSpace{ { { 0.0, 0.0, 0.0 } }, true, -1 }, out);
      return true;
    }
    if (!(std::abs(Dot(n, n) - 1.0) < 1e-6))
    {
      return false;
    }
    const std::int32_t f = first[v];
    return gather(n, corners + f, nextIds + f, prevIds + f);
  }

  // Checks the fan of v and appends its corners to the block. Whether the fan is one run is
  // decided here in the baseline build, in SumFans in the others (see WeighCorners).
  template <bool Wide>
  VTK_ALWAYS_INLINE bool GatherFan(std::int32_t v, int k, const V3& n, const std::int32_t* list,
    const std::int32_t* next, const std::int32_t* prev, const unsigned char* orient,
    FanBlock<Real>& fb) const
  {
    const unsigned char o = orient[list[0] >> 2];
    std::int32_t* tri = fb.Triangle + fb.NumberOfCorners;
    int same = 1;
    for (int a = 0; a < k; ++a)
    {
      const std::int32_t t = list[a] >> 2;
      tri[a] = t;
      same &= orient[t] == o;
    }
    if (!same)
    {
      return false;
    }
    if constexpr (!Wide)
    {
      if (!FanIsOneRun<Wide>(next, prev, k))
      {
        return false;
      }
    }
    const int j = fb.NumberOfVertices;
    fb.NV[0][j] = n[0];
    fb.NV[1][j] = n[1];
    fb.NV[2][j] = n[2];
    fb.First6[j] = 6 * tri[0];
    for (int a = 0, c = fb.NumberOfCorners; a < k; ++a, ++c)
    {
      fb.Self[c] = 3 * v;
      fb.Next[c] = 3 * next[a];
      fb.Prev[c] = 3 * prev[a];
      fb.N[0][c] = static_cast<Real>(n[0]);
      fb.N[1][c] = static_cast<Real>(n[1]);
      fb.N[2][c] = static_cast<Real>(n[2]);
    }
    fb.Handedness[fb.NumberOfVertices] = o != 0 ? 1.0f : -1.0f;
    fb.Vertex[fb.NumberOfVertices++] = v;
    fb.NumberOfCorners += k;
    fb.First[fb.NumberOfVertices] = fb.NumberOfCorners;
    return true;
  }

  // What the fans need of one corner: e1 and e2 its edges (to the next and the previous point),
  // n its vertex's unit normal, os its triangle's unit dP/ds. Weight: its angle between the
  // edges projected onto the tangent plane, over the length of os projected, NaN if a check
  // fails (which fails the fan's final test); the projected edges have the cross product
  // n (n . (e1 x e2)) and the dot product e1 . e2 - (e1 . n)(e2 . n), and for a direction d,
  // |proj d|^2 = d.d - (d.n)^2. Turn: the closed-fan test's value (see FastTurn): its angle if
  // within the margins, plus TurnBack if it turns the other way about n, else TurnOff.
  struct Corner
  {
    Real Weight;
    Real Turn;
  };
  VTK_ALWAYS_INLINE static Corner WeighCorner(Real e1x, Real e1y, Real e1z, Real e2x, Real e2y,
    Real e2z, Real nx, Real ny, Real nz, Real osx, Real osy, Real osz)
  {
    constexpr bool Single = std::is_same<Real, float>::value;
    const Real n1 = e1x * nx + e1y * ny + e1z * nz;
    const Real n2 = e2x * nx + e2y * ny + e2z * nz;
    const Real l1 = e1x * e1x + e1y * e1y + e1z * e1z;
    const Real l2 = e2x * e2x + e2y * e2y + e2z * e2z;
    const Real pl1 = l1 - n1 * n1;
    const Real pl2 = l2 - n2 * n2;
    const Real x = e1y * e2z - e1z * e2y;
    const Real y = e1z * e2x - e1x * e2z;
    const Real z = e1x * e2y - e1y * e2x;
    const Real cross = x * nx + y * ny + z * nz;
    const Real angle =
      FastAngle<Real>(std::abs(cross), e1x * e2x + e1y * e2y + e1z * e2z - n1 * n2);
    const Real on = osx * nx + osy * ny + osz * nz;
    bool projected;
    Real osLength;
    if constexpr (Single)
    {
      // The general path normalises a projected edge only when some component is above
      // FLT_MIN. In float, FLT_MIN^2 underflows: a projected edge must be longer than
      // 2^-50. The float rounding of e1.e2 - n1 n2 and of l - n^2 is ~1e-7 of the
      // edges' lengths, so the angle between projected edges keeps the general path's
      // frames (to ~1e-5 degrees) only if each projection is a good part of its edge:
      // squared, above 0.1 of the edge's (the edge 18 degrees or more off the normal;
      // at 1e-3, cone tips gave frames 1e-3 degrees off). For the same reason the
      // projection of the unit dP/ds, explicit (d.d - (d.n)^2 would cancel), must be
      // longer than 0.1: the general path projects it in double.
      const Real px = osx - on * nx, py = osy - on * ny, pz = osz - on * nz;
      const Real pos2 = px * px + py * py + pz * pz;
      projected =
        (std::min(pl1, pl2) > 0x1p-100f) & (pl1 > 0.1f * l1) & (pl2 > 0.1f * l2) & (pos2 > 1e-2f);
      osLength = std::sqrt(pos2);
    }
    else
    {
      // The general path normalises a projected edge only when some component is above
      // FLT_MIN; a squared length above 12 FLT_MIN^2 guarantees that (3 components, a
      // margin of 4), so shorter projections (an edge along the normal) go that way.
      projected = std::min(pl1, pl2) > 12.0 * FLT_MIN * FLT_MIN;
      osLength = std::sqrt(osx * osx + osy * osy + osz * osz - on * on);
    }
    // In float, projected implies the edges' projections that FastTurn's margins need.
    const bool edgesProjected =
      Single || ((pl1 > Real(FastEdgeProjection) * l1) & (pl2 > Real(FastEdgeProjection) * l2));
    const bool turns =
      edgesProjected & (angle > Real(FastTurn)) & (angle < Real(vtkMath::Pi() - FastTurn));
    return { (projected ? angle : std::numeric_limits<Real>::quiet_NaN()) / osLength,
      turns ? (cross > Real(0) ? angle : angle + Real(TurnBack)) : Real(TurnOff) };
  }

  // WeighCorner for every corner of the block, in one loop that the compiler vectorises (with
  // gathers in the AVX2 build). Wide: the AVX2 and AVX-512 builds, which also prepare the
  // closed-fan test; the baseline build (SSE2) has no 64-bit vector multiply, where the ids' mix
  // costs more than the edge matching it saves (3.6% more cycles on the 1M torus), so there every
  // fan goes through FanIsOneRun in GatherFan, as before the test. Both ways take the same
  // decisions.
  template <bool Wide>
  VTK_ALWAYS_INLINE void WeighCorners(FanBlock<Real>& fb, const std::array<float, 6>* dir) const
  {
    constexpr int Lanes = FanBlock<Real>::Lanes;
    const int nc = (fb.NumberOfCorners + Lanes - 1) & ~(Lanes - 1);
    const int last = fb.NumberOfCorners - 1;
    for (int c = last + 1; c < nc; ++c)
    {
      fb.Triangle[c] = fb.Triangle[last];
      fb.Self[c] = fb.Self[last];
      fb.Next[c] = fb.Next[last];
      fb.Prev[c] = fb.Prev[last];
      fb.N[0][c] = fb.N[0][last];
      fb.N[1][c] = fb.N[1][last];
      fb.N[2][c] = fb.N[2][last];
    }
    const PT* __restrict p = this->P;
    const float* __restrict d = dir[0].data();
    const std::int32_t* __restrict self = fb.Self, * __restrict next = fb.Next, * __restrict prev = fb.Prev, * __restrict tri = fb.Triangle;
    const Real* __restrict nx = fb.N[0], * __restrict ny = fb.N[1], * __restrict nz = fb.N[2];
    Real* __restrict wx = fb.WeightedOs[0], * __restrict wy = fb.WeightedOs[1], * __restrict wz = fb.WeightedOs[2];
    Real* __restrict turn = fb.Turn;
    std::uint64_t* __restrict cycle = fb.Cycle;
    if constexpr (Wide)
    {
      // Next and Prev hold 3 * id, the same multisets as the ids.
      for (int c = 0; c < nc; ++c)
      {
        cycle[c] = IdMix(next[c]) - IdMix(prev[c]);
      }
    }
    for (int c = 0; c < nc; ++c)
    {
      const std::int32_t x0 = self[c], x1 = next[c], x2 = prev[c], t = 6 * tri[c];
      const Real pv[3] = { Real(p[x0]), Real(p[x0 + 1]), Real(p[x0 + 2]) };
      const Real e1x = Real(p[x1]) - pv[0], e1y = Real(p[x1 + 1]) - pv[1],
                 e1z = Real(p[x1 + 2]) - pv[2];
      const Real e2x = Real(p[x2]) - pv[0], e2y = Real(p[x2 + 1]) - pv[1],
                 e2z = Real(p[x2 + 2]) - pv[2];
      const Real osx = d[t], osy = d[t + 1], osz = d[t + 2];
      const Corner w =
        WeighCorner(e1x, e1y, e1z, e2x, e2y, e2z, nx[c], ny[c], nz[c], osx, osy, osz);
      if constexpr (Wide)
      {
        turn[c] = w.Turn;
      }
      const Real weight = w.Weight;
      wx[c] = weight * osx;
      wy[c] = weight * osy;
      wz[c] = weight * osz;
    }
  }

  // One vertex's references: its first triangle's directions x (dP/ds) and y (dP/dt)
  // projected into the plane of its unit normal n and normalised, and whether both
  // projections are long enough for the fast path (good: 1 or 0). References and
  // ReferencesOf run it in their loops over a block's vertices, which it does not stop from
  // vectorising (it is inlined, its outputs the loops' restrict-qualified arrays).
  template <typename RT>
  VTK_ALWAYS_INLINE static void Reference(const double x[3], const double y[3], double nx,
    double ny, double nz, double& good, RT& r0x, RT& r0y, RT& r0z, RT& r1x, RT& r1y, RT& r1z)
  {
    const double xn = x[0] * nx + x[1] * ny + x[2] * nz;
    const double yn = y[0] * nx + y[1] * ny + y[2] * nz;
    const double p[3] = { x[0] - xn * nx, x[1] - xn * ny, x[2] - xn * nz };
    const double q[3] = { y[0] - yn * nx, y[1] - yn * ny, y[2] - yn * nz };
    const double lp = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
    const double lq = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    good = std::min(lp, lq) > FastProjection2 ? 1.0 : 0.0;
    const double ip = 1.0 / std::sqrt(lp), iq = 1.0 / std::sqrt(lq);
    r0x = RT(ip * p[0]);
    r0y = RT(ip * p[1]);
    r0z = RT(ip * p[2]);
    r1x = RT(iq * q[0]);
    r1y = RT(iq * q[1]);
    r1z = RT(iq * q[2]);
  }

  // Per vertex, the projections of its first triangle's dP/ds and dP/dt onto the tangent
  // plane, as unit vectors: at the default threshold MikkTSpace separates only opposite
  // directions, and with every direction within a quarter turn of these (with a margin),
  // no two are. For the first @a count vertices of a FanBlock or a SlotBlock (whose
  // references are in double or in Real).
  template <typename BlockT>
  VTK_ALWAYS_INLINE static void References(BlockT& fb, const std::array<float, 6>* dir, int count)
  {
    using RT = std::remove_reference_t<decltype(fb.R[0][0])>;
    const float* __restrict d = dir[0].data();
    const std::int32_t* __restrict first6 = fb.First6;
    const double* __restrict nx = fb.NV[0], * __restrict ny = fb.NV[1], * __restrict nz = fb.NV[2];
    double* __restrict good = fb.Good;
    RT* __restrict r0x = fb.R[0], * __restrict r0y = fb.R[1], * __restrict r0z = fb.R[2];
    RT* __restrict r1x = fb.R[3], * __restrict r1y = fb.R[4], * __restrict r1z = fb.R[5];
    for (int j = 0; j < count; ++j)
    {
      const std::int32_t t = first6[j];
      const double x[3] = { d[t], d[t + 1], d[t + 2] }, y[3] = { d[t + 3], d[t + 4], d[t + 5] };
      Reference(x, y, nx[j], ny[j], nz[j], good[j], r0x[j], r0y[j], r0z[j], r1x[j], r1y[j], r1z[j]);
    }
  }

  // The same from the directions dirOf(j, q), q < 6, of each vertex j's first triangle (the
  // task-local slots: their own copies, read without gathers, which made this loop scalar).
  template <typename BlockT, typename DirOf>
  VTK_ALWAYS_INLINE static void ReferencesOf(BlockT& fb, int count, DirOf&& dirOf)
  {
    using RT = std::remove_reference_t<decltype(fb.R[0][0])>;
    const double* __restrict nx = fb.NV[0], * __restrict ny = fb.NV[1], * __restrict nz = fb.NV[2];
    double* __restrict good = fb.Good;
    RT* __restrict r0x = fb.R[0], * __restrict r0y = fb.R[1], * __restrict r0z = fb.R[2];
    RT* __restrict r1x = fb.R[3], * __restrict r1y = fb.R[4], * __restrict r1z = fb.R[5];
    for (int j = 0; j < count; ++j)
    {
      const double x[3] = { dirOf(j, 0), dirOf(j, 1), dirOf(j, 2) },
                   y[3] = { dirOf(j, 3), dirOf(j, 4), dirOf(j, 5) };
      Reference(x, y, nx[j], ny[j], nz[j], good[j], r0x[j], r0y[j], r0z[j], r1x[j], r1y[j], r1z[j]);
    }
  }

  // Per vertex, the weighted sum of dP/ds projected (the projection of the sum): the sums
  // in corner order, then the rest in one loop over the block's vertices. A fan that the
  // closed-fan test (see FastTurn) does not show to be one run must pass FanIsOneRun: each
  // edge at v joins exactly two triangles or bounds the fan (then the general path's greedy
  // pairing finds the same links), and the links chain all the triangles into one run.
  template <bool Wide>
  VTK_ALWAYS_INLINE static bool SumFans(FanBlock<Real>& fb, const std::array<float, 6>* dir,
    const std::int32_t* nextIds, const std::int32_t* prevIds, const std::int32_t* first, float* out)
  {
    const int nv = fb.NumberOfVertices;
    int ok = 1;
    for (int j = 0; j < nv; ++j)
    {
      Real turns = 0;
      std::uint64_t cycle = 0;
      // In float for float points: its rounding (1e-7) is far inside the margin FastCos.
      const Real r0[3] = { Real(fb.R[0][j]), Real(fb.R[1][j]), Real(fb.R[2][j]) };
      const Real r1[3] = { Real(fb.R[3][j]), Real(fb.R[4][j]), Real(fb.R[5][j]) };
      Real sum[3] = { 0, 0, 0 };
      for (int c = fb.First[j]; c < fb.First[j + 1]; ++c)
      {
        const auto& d = dir[fb.Triangle[c]];
        const Real os[3] = { d[0], d[1], d[2] }, ot[3] = { d[3], d[4], d[5] };
        ok &= os[0] * r0[0] + os[1] * r0[1] + os[2] * r0[2] > Real(FastCos);
        ok &= ot[0] * r1[0] + ot[1] * r1[1] + ot[2] * r1[2] > Real(FastCos);
        sum[0] += fb.WeightedOs[0][c];
        sum[1] += fb.WeightedOs[1][c];
        sum[2] += fb.WeightedOs[2][c];
        if constexpr (Wide)
        {
          turns += fb.Turn[c];
          cycle += fb.Cycle[c];
        }
      }
      fb.Turns[j] = turns;
      fb.Cycles[j] = cycle;
      fb.S[0][j] = sum[0];
      fb.S[1][j] = sum[1];
      fb.S[2][j] = sum[2];
    }
    if (!ok)
    {
      return false;
    }
    const double* __restrict nx = fb.NV[0], * __restrict ny = fb.NV[1], * __restrict nz = fb.NV[2];
    const double* __restrict sx = fb.S[0], * __restrict sy = fb.S[1], * __restrict sz = fb.S[2];
    double* __restrict good = fb.Good;
    float* __restrict tx = fb.Tangent[0], * __restrict ty = fb.Tangent[1], * __restrict tz = fb.Tangent[2];
    const Real* __restrict turns = fb.Turns;
    const std::uint64_t* __restrict cycles = fb.Cycles;
    const int* __restrict firsts = fb.First;
    std::int32_t* __restrict closed = fb.Closed;
    constexpr Real fullTurn = Real(2.0 * vtkMath::Pi());
    for (int j = 0; j < nv; ++j)
    {
      const Real back = Real(TurnBack) * Real(firsts[j + 1] - firsts[j]);
      closed[j] = !Wide ||
        (((std::abs(turns[j] - fullTurn) < Real(1)) |
           (std::abs(turns[j] - back - fullTurn) < Real(1))) &
          (cycles[j] == 0));
      const double sumN = sx[j] * nx[j] + sy[j] * ny[j] + sz[j] * nz[j];
      const double t[3] = { sx[j] - sumN * nx[j], sy[j] - sumN * ny[j], sz[j] - sumN * nz[j] };
      const double len2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
      // Not finite is not above 1e-12 or not below the largest double.
      good[j] = std::min(len2 - 1e-12, DBL_MAX - len2) > 0.0 ? good[j] : 0.0;
      const double inv = 1.0 / std::sqrt(len2);
      tx[j] = static_cast<float>(inv * t[0]);
      ty[j] = static_cast<float>(inv * t[1]);
      tz[j] = static_cast<float>(inv * t[2]);
    }
    for (int j = 0; j < nv; ++j)
    {
      if (fb.Good[j] == 0.0)
      {
        return false;
      }
      if (!fb.Closed[j])
      {
        const std::int32_t f = first[fb.Vertex[j]];
        if (!FanIsOneRun<Wide>(nextIds + f, prevIds + f, fb.First[j + 1] - fb.First[j]))
        {
          return false;
        }
      }
      float* o = out + 4 * std::size_t(fb.Vertex[j]);
      o[0] = fb.Tangent[0][j];
      o[1] = fb.Tangent[1][j];
      o[2] = fb.Tangent[2][j];
      o[3] = fb.Handedness[j];
    }
    return true;
  }
  SURFACEDETAIL_TARGET_AVX512 VTK_ALWAYS_INLINE bool SlotFans(std::int32_t b, std::int32_t e,
    const std::int32_t* nextIds, const std::int32_t* prevIds, const std::array<float, 6>* dir,
    const unsigned char* orient, const std::int32_t* first, const std::int32_t* corners,
    const std::int32_t* weld, float* out) const
  {
    using Block = SlotBlock<Real>;
    std::unique_ptr<Block> block(new Block);
    std::unique_ptr<SlotStorage> storage(new SlotStorage);
    Block& fb = *block;
    storage->Attach(fb);
    for (std::int32_t v = b; v < e;)
    {
      fb.NumberOfVertices = 0;
      for (; v < e && fb.NumberOfVertices < Block::MaxVertices; ++v)
      {
        if (this->Welded && weld[v] != v)
        {
          continue; // a copy of a smaller point, filled later
        }
        const int k = first[v + 1] - first[v];
        if (fb.SlotsWith(k) > Block::MaxSlots)
        {
          break;
        }
        auto gather = [&](const V3& n, const std::int32_t* list, const std::int32_t* next,
                        const std::int32_t* prev)
        { return this->GatherSlots(v, k, n, list, next, prev, dir, orient, fb); };
        if (!this->WithFan(
              v, k, nextIds, prevIds, first, corners, out + 4 * std::size_t(v), gather))
        {
          return false;
        }
      }
      Pad(fb);
      // The last group's lanes past the block's vertices too (Pad gave them copies).
      References(fb, dir,
        (fb.NumberOfVertices + SlotBlock<Real>::Lanes - 1) & ~(SlotBlock<Real>::Lanes - 1));
      auto oneRun = [&](int j)
      {
        const std::int32_t f = first[fb.Vertex[j]];
        return FanIsOneRun<true>(nextIds + f, prevIds + f, fb.K[j]);
      };
      if (!this->WeighSlots<false, true>(fb) || !SumSlots(fb, oneRun, out))
      {
        return false;
      }
    }
    return true;
  }

  // Checks the fan of v and copies it into the block's next lane.
  VTK_ALWAYS_INLINE bool GatherSlots(std::int32_t v, int k, const V3& n, const std::int32_t* list,
    const std::int32_t* next, const std::int32_t* prev, const std::array<float, 6>* dir,
    const unsigned char* orient, SlotBlock<Real>& fb) const
  {
    constexpr int Lanes = SlotBlock<Real>::Lanes;
    const int j = fb.NumberOfVertices;
    const int g = j / Lanes, i = j % Lanes;
    if (i == 0)
    {
      fb.GroupFirst[g] = fb.GroupStart(g);
      fb.GroupSlots[g] = 0;
    }
    fb.GroupSlots[g] = std::max(fb.GroupSlots[g], k);
    const unsigned char o = orient[list[0] >> 2];
    const int c0 = fb.GroupFirst[g] + i;
    int same = 1;
    for (int a = 0, c = c0; a < k; ++a, c += Lanes)
    {
      const std::int32_t t = list[a] >> 2;
      same &= orient[t] == o;
      fb.Next[c] = 3 * next[a];
      fb.Prev[c] = 3 * prev[a];
      for (int x = 0; x < 6; ++x)
      {
        fb.Dir[x][c] = dir[t][x];
      }
    }
    if (!same)
    {
      return false;
    }
    fb.Vertex[j] = v;
    fb.K[j] = k;
    fb.Handedness[j] = o != 0 ? 1.0f : -1.0f;
    fb.First6[j] = 6 * (list[0] >> 2);
    for (int x = 0; x < 3; ++x)
    {
      fb.NV[x][j] = n[x];
      fb.NR[x][j] = static_cast<Real>(n[x]);
      fb.Position[x][j] = Real(this->P[3 * std::size_t(v) + x]);
    }
    ++fb.NumberOfVertices;
    return true;
  }

  // Fills each lane's slots past its fan with copies of its last corner (masked off in
  // WeighSlots), and the last group's lanes past the block's vertices with copies of the
  // group's first lane, with no corners; a lane with no corners gets the corners of the
  // group's first lane that has some.
  VTK_ALWAYS_INLINE static void Pad(SlotBlock<Real>& fb)
  {
    constexpr int Lanes = SlotBlock<Real>::Lanes;
    const int nv = fb.NumberOfVertices;
    const int nl = (nv + Lanes - 1) & ~(Lanes - 1);
    for (int j = nv; j < nl; ++j)
    {
      const int j0 = j & ~(Lanes - 1);
      fb.Vertex[j] = fb.Vertex[j0];
      fb.K[j] = 0;
      fb.Handedness[j] = fb.Handedness[j0];
      fb.First6[j] = fb.First6[j0];
      for (int x = 0; x < 3; ++x)
      {
        fb.NV[x][j] = fb.NV[x][j0];
        fb.NR[x][j] = fb.NR[x][j0];
        fb.Position[x][j] = fb.Position[x][j0];
      }
    }
    for (int g = 0; g < nl / Lanes; ++g)
    {
      const int j0 = Lanes * g;
      // Most groups (every lane's fan as large as the group's largest) need nothing.
      int uneven = 0;
      for (int i = 0; i < Lanes; ++i)
      {
        uneven |= fb.K[j0 + i] != fb.GroupSlots[g];
      }
      if (!uneven)
      {
        continue;
      }
      int full = j0; // the group's first lane with corners
      while (fb.K[full] == 0 && full < j0 + Lanes - 1)
      {
        ++full;
      }
      const int kf = fb.K[full];
      for (int i = 0; i < Lanes; ++i)
      {
        const int k = fb.K[j0 + i];
        for (int s = k; s < fb.GroupSlots[g]; ++s)
        {
          const int c = fb.GroupFirst[g] + fb.RowStride * s + fb.LaneStride * i;
          const int from = fb.GroupFirst[g] +
            (k > 0 ? fb.RowStride * (k - 1) + fb.LaneStride * i
                   : fb.RowStride * std::min(s, kf - 1) + fb.LaneStride * (full % Lanes));
          fb.Next[c] = fb.Next[from];
          fb.Prev[c] = fb.Prev[from];
          for (int x = 0; x < 6; ++x)
          {
            fb.Dir[x][c] = fb.Dir[x][from];
          }
        }
      }
    }
  }

  // WeighCorner for every corner: the weighted dP/ds go into each vertex's sum, and its dP/ds and
  // dP/dt are checked against its references (a quarter turn), and the closed-fan test's turns and
  // id mix are summed. One loop over each group's slots, vectorised over its lanes (gathers for the
  // corners' points only). False if a check failed.
  // Records: the slots are records (a task's slots), transposed a row at a time.
  // Wide512: the AVX-512 build, else the AVX2 one (GatherRowOf, TransposeRow). WeighSlots and
  // LocalSlots take no target of their own: they are inlined into LocalSlotsAVX512,
  // LocalSlotsAVX2 and SlotFans, whose target they are compiled for.
  template <bool Records, bool Wide512>
  VTK_ALWAYS_INLINE bool WeighSlots(SlotBlock<Real>& fb) const
  {
    constexpr int Lanes = SlotBlock<Real>::Lanes;
    // A task's slots with float points: the corners' ends from GatherRow.
    constexpr bool Gathered =
      (Wide512 || SURFACEDETAIL_MIKK_INTRINSICS) && Records && std::is_same<PT, float>::value;
    const PT* __restrict p = this->P;
    const int groups = (fb.NumberOfVertices + Lanes - 1) / Lanes;
    std::int32_t within = 1;
    for (int g = 0; g < groups; ++g)
    {
      const int j0 = Lanes * g;
      const std::int32_t* __restrict kk = fb.K + j0;
      const Real* __restrict vx = fb.Position[0] + j0, * __restrict vy = fb.Position[1] + j0, * __restrict vz = fb.Position[2] + j0;
      const Real* __restrict nx = fb.NR[0] + j0, * __restrict ny = fb.NR[1] + j0, * __restrict nz = fb.NR[2] + j0;
      const Real* __restrict r0x = fb.R[0] + j0, * __restrict r0y = fb.R[1] + j0, * __restrict r0z = fb.R[2] + j0;
      const Real* __restrict r1x = fb.R[3] + j0, * __restrict r1y = fb.R[4] + j0, * __restrict r1z = fb.R[5] + j0;
      // The sums in local arrays (in registers): the compiler then knows that they alias
      // none of the values read, wherever the slots are (a task's slots: see LocalSlots).
      alignas(64) Real sx[Lanes], sy[Lanes], sz[Lanes], turns[Lanes];
      alignas(64) std::uint64_t cycles[Lanes];
      alignas(64) std::int32_t ok[Lanes];
      // One array at a time, whole vectors: stores of single lanes would stall the loads
      // of the loop below (no store forwarding from several stores to one load).
      std::fill_n(sx, Lanes, Real(0));
      std::fill_n(sy, Lanes, Real(0));
      std::fill_n(sz, Lanes, Real(0));
      std::fill_n(turns, Lanes, Real(0));
      std::fill_n(cycles, Lanes, std::uint64_t(0));
      std::fill_n(ok, Lanes, 1);
      // Set at the first slot, before any use; filled first all the same, as GCC does not see
      // that in the AVX2 build.
      alignas(64) std::int32_t firstOrient[Lanes];
      std::fill_n(firstOrient, Lanes, 0);
      for (int s = 0; s < fb.GroupSlots[g]; ++s)
      {
        const int c0 = fb.GroupFirst[g] + fb.RowStride * s;
        alignas(64) std::int32_t rowIds[2][Lanes];
        alignas(64) float rowDir[6][Lanes];
        if constexpr (Records)
        {
          TransposeRow<Wide512>(fb.Dir[0] - 2 + c0, rowIds, rowDir);
          // The top bit of a previous id is its triangle's texture orientation (see
          // LocalSlots): every corner's must be its lane's first corner's.
          alignas(64) std::int32_t orient[Lanes];
          for (int i = 0; i < Lanes; ++i)
          {
            orient[i] = rowIds[1][i] < 0 ? 1 : 0;
            rowIds[1][i] &= std::numeric_limits<std::int32_t>::max();
          }
          if (s == 0)
          {
            std::copy_n(orient, Lanes, firstOrient);
          }
          for (int i = 0; i < Lanes; ++i)
          {
            ok[i] &= (s >= kk[i]) | (orient[i] == firstOrient[i]);
          }
        }
        auto dirs = [&](int q) { return Records ? rowDir[q] : fb.Dir[q] + c0; };
        const std::int32_t* __restrict next = Records ? rowIds[0] : fb.Next + c0;
        const std::int32_t* __restrict prev = Records ? rowIds[1] : fb.Prev + c0;
        const float* __restrict dsx = dirs(0), * __restrict dsy = dirs(1), * __restrict dsz = dirs(2);
        const float* __restrict dtx = dirs(3), * __restrict dty = dirs(4), * __restrict dtz = dirs(5);
        alignas(64) float ends[6][Lanes];
        if constexpr (Gathered)
        {
          GatherRowOf<Wide512>(p, fb.Dir[0] - 2 + c0, ends);
        }
        // Next and Prev hold 3 * id, the same multisets as the ids.
        for (int i = 0; i < Lanes; ++i)
        {
          cycles[i] += (IdMix(next[i]) - IdMix(prev[i])) & (0 - std::uint64_t(s < kk[i]));
        }
        for (int i = 0; i < Lanes; ++i)
        {
          const bool live = s < kk[i];
          const std::int32_t x1 = next[i], x2 = prev[i];
          const Real osx = dsx[i], osy = dsy[i], osz = dsz[i];
          const Real otx = dtx[i], oty = dty[i], otz = dtz[i];
          auto end = [&](int q, std::int32_t x)
          { return Gathered ? ends[q][i] : Real(p[x + q % 3]); };
          const Corner w = WeighCorner(end(0, x1) - vx[i], end(1, x1) - vy[i], end(2, x1) - vz[i],
            end(3, x2) - vx[i], end(4, x2) - vy[i], end(5, x2) - vz[i], nx[i], ny[i], nz[i], osx,
            osy, osz);
          turns[i] += live ? w.Turn : Real(0);
          // In float for float points: its rounding (1e-7) is far inside the margin FastCos.
          const bool quarter = (osx * r0x[i] + osy * r0y[i] + osz * r0z[i] > Real(FastCos)) &
            (otx * r1x[i] + oty * r1y[i] + otz * r1z[i] > Real(FastCos));
          ok[i] &= !live | quarter;
          const Real weight = w.Weight;
          sx[i] = live ? sx[i] + weight * osx : sx[i];
          sy[i] = live ? sy[i] + weight * osy : sy[i];
          sz[i] = live ? sz[i] + weight * osz : sz[i];
        }
      }
      std::copy_n(sx, Lanes, fb.S[0] + j0);
      std::copy_n(sy, Lanes, fb.S[1] + j0);
      std::copy_n(sz, Lanes, fb.S[2] + j0);
      std::copy_n(turns, Lanes, fb.Turns + j0);
      std::copy_n(cycles, Lanes, fb.Cycles + j0);
      for (int i = 0; i < Lanes; ++i)
      {
        within &= ok[i];
      }
    }
    return within != 0;
  }

  // Per vertex, the sum of weighted dP/ds projected (the projection of the sum), normalised,
  // and the closed-fan test's answer. A fan that the closed-fan test (see FastTurn) does
  // not show to be one run must pass FanIsOneRun: each edge at v joins exactly two
  // triangles or bounds the fan (then the general path's greedy pairing finds the same
  // links), and the links chain all the triangles into one run.
  // OneRun(j): whether FanIsOneRun holds for lane j's fan.
  template <typename OneRun>
  VTK_ALWAYS_INLINE static bool SumSlots(SlotBlock<Real>& fb, OneRun&& oneRun, float* out)
  {
    const int nv = fb.NumberOfVertices;
    const double* __restrict nx = fb.NV[0], * __restrict ny = fb.NV[1], * __restrict nz = fb.NV[2];
    const Real* __restrict sx = fb.S[0], * __restrict sy = fb.S[1], * __restrict sz = fb.S[2];
    double* __restrict good = fb.Good;
    float* __restrict tx = fb.Tangent[0], * __restrict ty = fb.Tangent[1], * __restrict tz = fb.Tangent[2];
    const Real* __restrict turns = fb.Turns;
    const std::uint64_t* __restrict cycles = fb.Cycles;
    const std::int32_t* __restrict kk = fb.K;
    std::int32_t* __restrict closed = fb.Closed;
    constexpr Real fullTurn = Real(2.0 * vtkMath::Pi());
    for (int j = 0; j < nv; ++j)
    {
      const Real back = Real(TurnBack) * Real(kk[j]);
      closed[j] = (((std::abs(turns[j] - fullTurn) < Real(1)) |
                     (std::abs(turns[j] - back - fullTurn) < Real(1))) &
        (cycles[j] == 0));
      const double s[3] = { sx[j], sy[j], sz[j] };
      const double sumN = s[0] * nx[j] + s[1] * ny[j] + s[2] * nz[j];
      const double t[3] = { s[0] - sumN * nx[j], s[1] - sumN * ny[j], s[2] - sumN * nz[j] };
      const double len2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
      // Not finite is not above 1e-12 or not below the largest double.
      good[j] = std::min(len2 - 1e-12, DBL_MAX - len2) > 0.0 ? good[j] : 0.0;
      const double inv = 1.0 / std::sqrt(len2);
      tx[j] = static_cast<float>(inv * t[0]);
      ty[j] = static_cast<float>(inv * t[1]);
      tz[j] = static_cast<float>(inv * t[2]);
    }
    // The usual block: every lane's fan taken, its vertices one after another; its tangents
    // are then stored as one run of records (permutations, no scalar stores).
    int plain = fb.Vertex[nv - 1] - fb.Vertex[0] == nv - 1 ? 1 : 0;
    for (int j = 0; j < nv; ++j)
    {
      plain &= (kk[j] > 0) & (good[j] != 0.0) & (closed[j] != 0);
    }
    if (plain)
    {
      const float* __restrict hand = fb.Handedness;
      float* __restrict o = out + 4 * std::size_t(fb.Vertex[0]);
      for (int j = 0; j < nv; ++j)
      {
        o[4 * j] = tx[j];
        o[4 * j + 1] = ty[j];
        o[4 * j + 2] = tz[j];
        o[4 * j + 3] = hand[j];
      }
      return true;
    }
    for (int j = 0; j < nv; ++j)
    {
      float* o = out + 4 * std::size_t(fb.Vertex[j]);
      if (kk[j] == 0)
      {
        // A vertex that no triangle uses (the task-local slots' empty lanes).
        FinalTangent(V3{ nx[j], ny[j], nz[j] }, TSpace{ { { 0.0, 0.0, 0.0 } }, true, -1 }, o);
        continue;
      }
      if (fb.Good[j] == 0.0)
      {
        return false;
      }
      if (!fb.Closed[j] && !oneRun(j))
      {
        return false;
      }
      o[0] = fb.Tangent[0][j];
      o[1] = fb.Tangent[1][j];
      o[2] = fb.Tangent[2][j];
      o[3] = fb.Handedness[j];
    }
    return true;
  }
};

// Calls f with the values of a float or double array; false for other arrays.
template <typename F>
bool WithValues(vtkDataArray* array, F&& f)
{
  if (auto* fa = vtkFloatArray::FastDownCast(array))
  {
    f(static_cast<const float*>(fa->GetPointer(0)));
    return true;
  }
  if (auto* da = vtkDoubleArray::FastDownCast(array))
  {
    f(static_cast<const double*>(da->GetPointer(0)));
    return true;
  }
  return false;
}

// The tangents of every input point by the fast path, or nullptr if the input needs the
// general one.
vtkSmartPointer<vtkFloatArray> FastTangents(
  vtkPolyData* input, vtkDataArray* normals, vtkDataArray* tcoords, std::vector<vtkIdType>& weld)
{
  vtkCellArray* polys = input->GetPolys();
  const vtkIdType nPts = input->GetNumberOfPoints();
  const vtkIdType nTris = polys->GetNumberOfCells();
  if (input->GetNumberOfStrips() > 0 || nTris == 0 ||
    nPts >=
      std::numeric_limits<std::int32_t>::max() / std::max(3, tcoords->GetNumberOfComponents()) ||
    nTris > MaxFastTriangles)
  {
    return nullptr;
  }
  auto tangents = vtkSmartPointer<vtkFloatArray>::New();
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(4);
  if (!vtkSurfaceDetailMemory::AllocateTuples(tangents.Get(), nPts))
  {
    return nullptr;
  }
  float* out = tangents->GetPointer(0);
  const int tcStride = tcoords->GetNumberOfComponents();
  bool done = false;
  try
  {
    WithValues(input->GetPoints()->GetData(),
      [&](auto p)
      {
        WithValues(normals,
          [&](auto n)
          {
            WithValues(tcoords,
              [&](auto t)
              {
                using PT = std::remove_const_t<std::remove_pointer_t<decltype(p)>>;
                using NT = std::remove_const_t<std::remove_pointer_t<decltype(n)>>;
                using TT = std::remove_const_t<std::remove_pointer_t<decltype(t)>>;
                FastMikk<PT, NT, TT> fast(p, n, t, tcStride, nPts);
                done = polys->IsStorage64Bit()
                  ? fast.Run(polys->GetOffsetsArray64()->GetPointer(0),
                      polys->GetConnectivityArray64()->GetPointer(0), nTris, out, weld)
                  : fast.Run(polys->GetOffsetsArray32()->GetPointer(0),
                      polys->GetConnectivityArray32()->GetPointer(0), nTris, out, weld);
              });
          });
      });
  }
  catch (const std::bad_alloc&)
  {
    done = false;
  }
  return done ? tangents : nullptr;
}

vtkSmartPointer<vtkIdList> IdRange(vtkIdType n)
{
  auto ids = vtkSmartPointer<vtkIdList>::New();
  ids->SetNumberOfIds(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    ids->SetId(i, i);
  }
  return ids;
}
} // anonymous namespace

//------------------------------------------------------------------------------
void vtkMikkTSpaceTangents::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AngularThreshold: " << this->AngularThreshold << "\n";
}

//------------------------------------------------------------------------------
int vtkMikkTSpaceTangents::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{

  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro("The input must be a vtkPolyData.");
    return 0;
  }
  const vtkIdType nPts = input->GetNumberOfPoints();
  if (nPts == 0 || !input->GetPoints())
  {
    vtkErrorMacro("The input has no points; give it a surface with points, normals and "
                  "texture coordinates.");
    return 0;
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("The input has no polygons or triangle strips; tangents need a surface.");
    return 0;
  }
  auto idsInRange = [&]()
  {
    if (vtkSurfaceDetailCells::PointIdsInRange(input->GetPolys(), nPts) &&
      vtkSurfaceDetailCells::PointIdsInRange(input->GetStrips(), nPts))
    {
      return true;
    }
    vtkErrorMacro("A polygon or triangle strip of the input names a point id outside [0, "
      << nPts << "); fix the connectivity (e.g. with vtkCleanPolyData) first.");
    return false;
  };
  // The fast path checks the ids as it reads them, which saves a pass over the connectivity;
  // it goes first only with given normals (computing them reads the ids) and no strips, and
  // if it gives up, the ids are checked before anything else reads them.
  vtkDataArray* givenNormals = input->GetPointData()->GetNormals();
  const bool fastFirst = this->AngularThreshold >= 180.0 && input->GetNumberOfStrips() == 0 &&
    givenNormals && givenNormals->GetNumberOfComponents() == 3;
  if (!fastFirst && !idsInRange())
  {
    return 0;
  }
  vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
  if (!tcoords || tcoords->GetNumberOfComponents() < 2)
  {
    vtkErrorMacro("The input has no 2-component point texture coordinates; set them as the "
                  "point data's TCoords (e.g. with vtkTextureMapToPlane or a parametric "
                  "source) before computing tangents.");
    return 0;
  }

  // The point data that goes to the output: the input's, plus normals if we make them.
  vtkNew<vtkPointData> inPD;
  inPD->ShallowCopy(input->GetPointData());
  vtkDataArray* normals = inPD->GetNormals();
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
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
    if (!computed || computed->GetNumberOfTuples() != nPts)
    {
      vtkErrorMacro("The input has no point normals and vtkPolyDataNormals could not make "
                    "them; set the point data's Normals.");
      return 0;
    }
    inPD->SetNormals(computed);
    normals = computed;
  }
  if (tcoords->GetNumberOfTuples() != nPts || normals->GetNumberOfTuples() != nPts)
  {
    vtkErrorMacro("The texture coordinates or normals do not have one tuple per point.");
    return 0;
  }

  std::vector<vtkIdType> weld; // the fast path's, when it gives up after welding
  if (this->AngularThreshold >= 180.0)
  {
    if (vtkSmartPointer<vtkFloatArray> tangents = FastTangents(input, normals, tcoords, weld))
    {
      // Every point kept its one frame: the input's surface with one more array.
      output->SetPoints(input->GetPoints());
      output->GetPointData()->PassData(inPD);
      output->GetPointData()->RemoveArray("Tangents");
      output->GetPointData()->AddArray(tangents);
      output->SetVerts(input->GetVerts());
      output->SetLines(input->GetLines());
      output->SetPolys(input->GetPolys());
      output->GetCellData()->PassData(input->GetCellData());
      output->GetFieldData()->PassData(input->GetFieldData());
      return 1;
    }
  }

  if (fastFirst && !idsInRange())
  {
    return 0;
  }
  MikkMesh mesh;
  mesh.NumberOfPoints = nPts;
  {
    ReadAttributes(input->GetPoints(), normals, tcoords, mesh);
    if (weld.empty())
    {
      Weld(mesh);
    }
    else
    {
      mesh.Weld = std::move(weld);
    }
    NormalizeNormals(mesh);
  }
  BuildFaces(input, mesh);
  BuildTriangles(mesh);
  this->UpdateProgress(0.2);

  const vtkIdType nFaces = mesh.NumberOfFaces;
  const vtkIdType nCorners = mesh.NumberOfCorners;
  // Not zero-filled: 16 bytes per corner that the per-vertex pass writes anyway.
  RawVector<std::array<float, 4>> cornerTangents(static_cast<size_t>(nCorners));
  std::vector<char> cornerSet;
  {
    MikkTSpace mikk(mesh, this->AngularThreshold);
    mikk.Run(cornerTangents.data(), cornerSet);
  }
  this->UpdateProgress(0.7);

  // Corners of faces MikkTSpace handles (3 or 4 corners) that no group reached keep the
  // reference's default space, (1, 0, 0) with w = -1, made orthogonal to the normal.
  std::vector<char> cornerUsed(nCorners, 0);
  vtkSMPTools::For(0, nFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        if (mesh.FaceFirstTri[f] == mesh.FaceFirstTri[f + 1])
        {
          continue;
        }
        for (vtkIdType c = mesh.Offsets[f]; c < mesh.Offsets[f + 1]; ++c)
        {
          if (!cornerSet[c])
          {
            FinalTangent(mesh.N[mesh.Points[c]], TSpace(), cornerTangents[c].data());
          }
          cornerUsed[c] = 1;
        }
      }
    });

  // A point keeps the frame of its first corner, every other distinct frame at it becomes
  // a new point. Usually there is none (no mirrored shell or hard seam on shared points):
  // then the per-point corner lists below are not needed.
  std::vector<vtkIdType> firstCorner(nPts, -1);
  for (vtkIdType c = 0; c < nCorners; ++c)
  {
    if (cornerUsed[c] && firstCorner[mesh.Points[c]] < 0)
    {
      firstCorner[mesh.Points[c]] = c;
    }
  }
  std::atomic<bool> splits(false);
  vtkSMPTools::For(0, nCorners,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType c = begin; c < end; ++c)
      {
        if (cornerUsed[c] &&
          std::memcmp(cornerTangents[c].data(), cornerTangents[firstCorner[mesh.Points[c]]].data(),
            4 * sizeof(float)) != 0)
        {
          splits.store(true, std::memory_order_relaxed);
          return;
        }
      }
    });

  // Point -> its corners, in corner order.
  std::vector<vtkIdType> pointCornerOffsets, pointCorners;
  if (splits)
  {
    pointCornerOffsets.assign(nPts + 1, 0);
    for (vtkIdType c = 0; c < nCorners; ++c)
    {
      pointCornerOffsets[mesh.Points[c] + 1] += cornerUsed[c];
    }
    for (vtkIdType p = 0; p < nPts; ++p)
    {
      pointCornerOffsets[p + 1] += pointCornerOffsets[p];
    }
    pointCorners.resize(pointCornerOffsets[nPts]);
    std::vector<vtkIdType> fill(pointCornerOffsets.begin(), pointCornerOffsets.end() - 1);
    for (vtkIdType c = 0; c < nCorners; ++c)
    {
      if (cornerUsed[c])
      {
        pointCorners[fill[mesh.Points[c]]++] = c;
      }
    }
  }
  std::vector<vtkIdType> extraCount(nPts + 1, 0);
  // The distinct frames at point p in order of first appearance: ranks[k] is the frame
  // number of p's k-th corner, firsts[d] the first corner with frame d.
  auto rankFrames = [&](vtkIdType p, std::vector<vtkIdType>& ranks, std::vector<vtkIdType>& firsts,
                      std::vector<vtkIdType>& order, std::vector<vtkIdType>& groups)
  {
    const vtkIdType off = pointCornerOffsets[p];
    const vtkIdType m = pointCornerOffsets[p + 1] - off;
    auto frame = [&](vtkIdType k) { return cornerTangents[pointCorners[off + k]].data(); };
    ranks.resize(m);
    firsts.clear();
    if (m <= static_cast<vtkIdType>(SmallFan))
    {
      for (vtkIdType k = 0; k < m; ++k)
      {
        size_t d = 0;
        while (d < firsts.size() &&
          std::memcmp(frame(k), cornerTangents[firsts[d]].data(), 4 * sizeof(float)) != 0)
        {
          ++d;
        }
        if (d == firsts.size())
        {
          firsts.push_back(pointCorners[off + k]);
        }
        ranks[k] = static_cast<vtkIdType>(d);
      }
      return;
    }
    // Many corners (a pole): sort by frame, then number the frames by first appearance.
    order.resize(m);
    for (vtkIdType k = 0; k < m; ++k)
    {
      order[k] = k;
    }
    std::sort(order.begin(), order.end(),
      [&](vtkIdType x, vtkIdType y)
      {
        const int c = std::memcmp(frame(x), frame(y), 4 * sizeof(float));
        return c < 0 || (c == 0 && x < y);
      });
    groups.clear(); // first corner position of each frame, in frame order
    for (vtkIdType i = 0; i < m; ++i)
    {
      if (i == 0 || std::memcmp(frame(order[i - 1]), frame(order[i]), 4 * sizeof(float)) != 0)
      {
        groups.push_back(order[i]);
      }
      ranks[order[i]] = static_cast<vtkIdType>(groups.size()) - 1;
    }
    std::vector<vtkIdType> byFirst(groups.size());
    for (size_t g = 0; g < groups.size(); ++g)
    {
      byFirst[g] = static_cast<vtkIdType>(g);
    }
    std::sort(byFirst.begin(), byFirst.end(),
      [&](vtkIdType x, vtkIdType y) { return groups[x] < groups[y]; });
    std::vector<vtkIdType> rankOf(groups.size());
    for (size_t r = 0; r < byFirst.size(); ++r)
    {
      rankOf[byFirst[r]] = static_cast<vtkIdType>(r);
      firsts.push_back(pointCorners[off + groups[byFirst[r]]]);
    }
    for (vtkIdType k = 0; k < m; ++k)
    {
      ranks[k] = rankOf[ranks[k]];
    }
  };
  if (splits)
  {
    vtkSMPTools::For(0, nPts,
      [&](vtkIdType begin, vtkIdType end)
      {
        std::vector<vtkIdType> ranks, firsts, order, groups;
        for (vtkIdType p = begin; p < end; ++p)
        {
          rankFrames(p, ranks, firsts, order, groups);
          extraCount[p + 1] = firsts.empty() ? 0 : static_cast<vtkIdType>(firsts.size()) - 1;
        }
      });
    for (vtkIdType p = 0; p < nPts; ++p)
    {
      extraCount[p + 1] += extraCount[p];
    }
  }
  const vtkIdType nExtra = extraCount[nPts];
  const vtkIdType nOutPts = nPts + nExtra;
  // Without split points the input's polygons go out as they are (shared, not copied).
  vtkSmartPointer<vtkIdTypeArray> connectivity;
  vtkIdType* cornerPoint = nullptr;
  if (nExtra > 0 || !mesh.InputFaces)
  {
    connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    connectivity->SetNumberOfValues(nCorners);
    cornerPoint = connectivity->GetPointer(0);
    std::copy(mesh.Points, mesh.Points + nCorners, cornerPoint);
  }
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(4);
  tangents->SetNumberOfTuples(nOutPts);
  float* tOut = tangents->GetPointer(0);
  std::vector<vtkIdType> extraSource(nExtra);
  vtkSMPTools::For(0, nPts,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<vtkIdType> ranks, firsts, order, groups;
      for (vtkIdType p = begin; p < end; ++p)
      {
        if (nExtra == 0)
        {
          // One frame per point: its first corner's, no ranking needed.
          firsts.clear();
          if (firstCorner[p] >= 0)
          {
            firsts.push_back(firstCorner[p]);
          }
        }
        else
        {
          rankFrames(p, ranks, firsts, order, groups);
        }
        if (firsts.empty())
        {
          // Not on any polygon: any frame orthogonal to the normal.
          FinalTangent(mesh.N[p], TSpace{ { { 0.0, 0.0, 0.0 } }, true, -1 }, tOut + 4 * p);
          continue;
        }
        auto idOf = [&](vtkIdType d) { return d == 0 ? p : nPts + extraCount[p] + d - 1; };
        for (size_t d = 0; d < firsts.size(); ++d)
        {
          const vtkIdType id = idOf(static_cast<vtkIdType>(d));
          std::copy_n(cornerTangents[firsts[d]].data(), 4, tOut + 4 * id);
          if (d > 0)
          {
            extraSource[id - nPts] = p;
          }
        }
        if (nExtra == 0)
        {
          continue; // every corner keeps its point
        }
        const vtkIdType off = pointCornerOffsets[p];
        for (size_t k = 0; k < ranks.size(); ++k)
        {
          cornerPoint[pointCorners[off + k]] = idOf(ranks[k]);
        }
      }
    });
  this->UpdateProgress(0.9);

  // Points and point data, extended by the split points.
  if (nExtra == 0)
  {
    output->SetPoints(input->GetPoints());
    output->GetPointData()->PassData(inPD);
  }
  else
  {
    vtkNew<vtkIdList> src;
    src->SetNumberOfIds(nOutPts);
    for (vtkIdType i = 0; i < nPts; ++i)
    {
      src->SetId(i, i);
    }
    for (vtkIdType i = 0; i < nExtra; ++i)
    {
      src->SetId(nPts + i, extraSource[i]);
    }
    vtkNew<vtkPoints> points;
    points->SetDataType(input->GetPoints()->GetDataType());
    points->SetNumberOfPoints(nOutPts);
    input->GetPoints()->GetData()->GetTuples(src, points->GetData());
    output->SetPoints(points);
    vtkPointData* outPD = output->GetPointData();
    outPD->CopyAllocate(inPD, nOutPts);
    outPD->CopyData(inPD, src, IdRange(nOutPts));
  }
  // VTK 9.1 accepts only 3-component tangent attributes, so the frame is the named array
  // DESIGN.md fixes; a stale input array of that name must not survive next to it.
  output->GetPointData()->RemoveArray("Tangents");
  output->GetPointData()->AddArray(tangents);

  // Cells: vertices and lines as they are; polygons renumbered; strips as triangles.
  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());
  if (cornerPoint)
  {
    vtkNew<vtkIdTypeArray> offsets;
    offsets->SetNumberOfValues(nFaces + 1);
    std::copy(mesh.Offsets, mesh.Offsets + nFaces + 1, offsets->GetPointer(0));
    vtkNew<vtkCellArray> polys;
    polys->SetData(offsets, connectivity);
    output->SetPolys(polys);
  }
  else
  {
    output->SetPolys(input->GetPolys());
  }

  const vtkIdType nLead = input->GetNumberOfVerts() + input->GetNumberOfLines();
  const bool sameCells = input->GetNumberOfStrips() == 0 && nFaces == input->GetNumberOfPolys();
  if (sameCells)
  {
    output->GetCellData()->PassData(input->GetCellData());
  }
  else
  {
    const vtkIdType nOutCells = nLead + nFaces;
    vtkNew<vtkIdList> src;
    src->SetNumberOfIds(nOutCells);
    for (vtkIdType i = 0; i < nLead; ++i)
    {
      src->SetId(i, i);
    }
    for (vtkIdType f = 0; f < nFaces; ++f)
    {
      src->SetId(nLead + f, mesh.FaceCell[f]);
    }
    output->GetCellData()->CopyAllocate(input->GetCellData(), nOutCells);
    output->GetCellData()->CopyData(input->GetCellData(), src, IdRange(nOutCells));
  }
  output->GetFieldData()->PassData(input->GetFieldData());

  // Non-finite input gives arbitrary (finite) frames: say so.
  const vtkIdType nonFinite = std::count_if(mesh.P.begin(), mesh.P.end(),
    [](const V3& p)
    { return !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])); });
  if (nonFinite > 0)
  {
    vtkWarningMacro(<< nonFinite
                    << " points have non-finite coordinates; the tangents "
                       "around them are arbitrary unit vectors orthogonal to the normal.");
  }
  return 1;
}
