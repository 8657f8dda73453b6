#include "vtkMikkTSpaceTangents.h"

#include "vtkSurfaceDetailCells.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailGhosts.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArrayRange.h"
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
#include "vtkStaticCellLinksTemplate.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <map>
#include <memory>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkMikkTSpaceTangents);

namespace
{
// Triangle flags, with the meanings of the reference implementation's.
constexpr int OrientPreserving = 1;  // signed texture area > 0
constexpr int GroupWithAny = 2;      // no usable texture derivatives: joins any group
constexpr int Degenerate = 4;        // two corners at the same position
constexpr int QuadOneDegenerate = 8; // a quad whose other triangle is degenerate

// Groups of more than this many triangles at one vertex (poles of hundreds of triangles)
// are not split into sub-groups: the pairwise test is quadratic.
constexpr size_t MaxSubGroupTest = 1024;

using Frame = std::array<float, 4>;
using CornerFrames = std::vector<std::pair<vtkIdType, Frame>>; // (face corner, frame)

// Sorts a list of corner frames by corner, for lookups.
void SortByCorner(CornerFrames& frames)
{
  std::sort(frames.begin(), frames.end(),
    [](const std::pair<vtkIdType, Frame>& x, const std::pair<vtkIdType, Frame>& y)
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

// The first nc components of every tuple, as doubles (typed access for float and double
// arrays, the generic one for the rest).
std::vector<double> Read(vtkDataArray* array, int nc)
{
  std::vector<double> out(static_cast<size_t>(nc) * array->GetNumberOfTuples());
  auto copy = [&](auto* typed)
  {
    const auto tuples = vtk::DataArrayTupleRange(typed);
    vtkSMPTools::For(0, tuples.size(),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          std::copy_n(tuples[i].begin(), nc, &out[nc * i]);
        }
      });
  };
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(array, copy))
  {
    copy(array);
  }
  return out;
}

/// Per triangle: the directions of dP/ds and dP/dt (zero when unusable) and its flags.
struct Triangle
{
  double Os[3], Ot[3];
  vtkIdType Base; // its face's first corner
  int Flag;       // the flags above; bits 4-9: its corners' offsets from Base, 2 bits each
};

/// The algorithm, stage by stage, on one input.
class MikkTSpace
{
public:
  MikkTSpace(vtkPolyData* input, vtkDataArray* normals, vtkDataArray* tcoords, double threshold)
    : Input(input)
    , NumberOfPoints(input->GetNumberOfPoints())
    , P(Read(input->GetPoints()->GetData(), 3))
    , N(Read(normals, 3))
    , T(Read(tcoords, 2))
    , ThresholdCos(std::cos(vtkMath::RadiansFromDegrees(threshold)))
  {
  }

  void Weld();
  void BuildFaces();
  void BuildTriangles();
  void ResolveGroupWithAnyOrientation();
  void EvaluateVertices();
  void FixQuadsWithOneDegenerateTriangle();
  void SplitPoints();
  void DistinctFrames(const vtkIdType* corners, vtkIdType m, vtkIdType v,
    std::vector<vtkIdType>& rank, std::vector<vtkIdType>& firsts) const;
  void Assemble(vtkPointData* inPD, vtkPolyData* output) const;
  vtkIdType NonFinitePoints = 0; // points with a non-finite coordinate

  struct Fan;

private:
  float EvaluateTriangle(const vtkIdType c[3], Triangle& tri) const;
  void BuildFan(vtkIdType v, Fan& fan);
  void EvaluateVertex(vtkIdType v, Fan& fan, CornerFrames& differing);
  void EvaluateGroup(Fan& fan) const;
  vtkIdType CornerVertex(vtkIdType tri, int k) const { return this->TriVertexIds[3 * tri + k]; }
  void SetCornerFrame(vtkIdType v, vtkIdType c, const Frame& frame, CornerFrames& differing);
  Frame FrameOf(vtkIdType c, vtkIdType v) const;
  vtkIdType Corner(vtkIdType tri, int k) const
  {
    return this->Tris[tri].Base + ((this->Tris[tri].Flag >> (4 + 2 * k)) & 3);
  }
  bool Orient(vtkIdType tri) const { return (this->Tris[tri].Flag & OrientPreserving) != 0; }
  const double* Normal(vtkIdType pt) const { return &this->N[3 * pt]; }

  vtkPolyData* Input;
  const vtkIdType NumberOfPoints;
  std::vector<double> P, N, T; // N is normalised after the weld
  const double ThresholdCos;
  std::vector<vtkIdType> WeldOf; // point -> vertex: the smallest point id with its values

  // Output polygons ("faces"): the input's triangles and quads (its own arrays when it has
  // nothing else), larger polygons and strips triangulated. FaceCell: the input cell each
  // came from, when they are not the input's polygons.
  vtkSmartPointer<vtkTypeInt64Array> Offsets, Connectivity;
  std::vector<vtkIdType> FaceCell;
  bool FacesAreInputPolys = true;
  bool Renumbered = false;

  // Triangles of the faces with 3 or 4 corners, in face order (MikkTSpace's triangles).
  // The per-triangle arrays are written entirely before they are read: not zero-filled.
  std::vector<vtkIdType> FaceFirstTri;
  vtkNew<vtkIdTypeArray> TriVertex;        // 3 per triangle: welded vertex
  const vtkIdType* TriVertexIds = nullptr; // its values
  std::unique_ptr<Triangle[]> Tris;
  vtkIdType NumberOfTriangles = 0;
  vtkStaticCellLinksTemplate<vtkIdType> VertexLinks; // vertex -> triangles, decreasing

  // Corner frames: most corners have their vertex's frame (VertexFrame); the others are
  // listed in Differing, sorted by corner.
  CornerFrames Differing;
  // Per vertex: NoFrame, OneFrame (VertexFrame, for all its corners) or Mixed.
  enum VertexState : char
  {
    NoFrame,
    OneFrame,
    Mixed
  };
  std::vector<VertexState> State;
  std::unique_ptr<Frame[]> VertexFrame;

  // Output points' frames: the input's points, then one per extra frame of a split point.
  vtkNew<vtkFloatArray> Tangents;
  std::vector<vtkIdType> ExtraSource;
};

// MikkTSpace identifies corners by value: points with identical position, normal and
// texture coordinates are one vertex even if the cells do not share them. A hash of the
// values (computed in parallel) places each point in an open-addressing table, inserted in
// point order, so that a vertex is its smallest point id; equal hashes are compared value
// by value. Points with a NaN equal nothing, as in the reference.
void MikkTSpace::Weld()
{
  const vtkIdType n = this->NumberOfPoints;
  auto same = [this](vtkIdType a, vtkIdType b)
  {
    return std::equal(&this->P[3 * a], &this->P[3 * a + 3], &this->P[3 * b]) &&
      std::equal(&this->N[3 * a], &this->N[3 * a + 3], &this->N[3 * b]) &&
      std::equal(&this->T[2 * a], &this->T[2 * a + 2], &this->T[2 * b]);
  };
  std::unique_ptr<std::uint64_t[]> hashes(new std::uint64_t[n]);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const double values[8] = { this->P[3 * i], this->P[3 * i + 1], this->P[3 * i + 2],
          this->N[3 * i], this->N[3 * i + 1], this->N[3 * i + 2], this->T[2 * i],
          this->T[2 * i + 1] };
        std::uint64_t h = 1469598103934665603ULL;
        for (double x : values)
        {
          x = x == 0.0 ? 0.0 : x; // -0 equals 0: same hash
          std::uint64_t bits;
          std::memcpy(&bits, &x, sizeof(bits));
          h = (h ^ bits) * 0x100000001b3ULL;
          h ^= h >> 29;
        }
        hashes[i] = h;
      }
    });
  std::uint64_t capacity = 16;
  while (capacity < 2 * static_cast<std::uint64_t>(n))
  {
    capacity *= 2;
  }
  std::vector<vtkIdType> table(capacity, -1);
  this->WeldOf.resize(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    this->WeldOf[i] = i;
    const double* p = &this->P[3 * i];
    this->NonFinitePoints += !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
    if (!same(i, i))
    {
      continue;
    }
    for (std::uint64_t slot = hashes[i] & (capacity - 1);; slot = (slot + 1) & (capacity - 1))
    {
      const vtkIdType o = table[slot];
      if (o < 0 || (hashes[o] == hashes[i] && same(i, o)))
      {
        (o < 0 ? table[slot] : this->WeldOf[i]) = o < 0 ? i : o;
        break;
      }
    }
  }
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        NormalizeIfNotZero(&this->N[3 * i]);
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
  if (input->GetNumberOfStrips() == 0 && inPolys->IsStorage64Bit() &&
    inPolys->GetMaxCellSize() <= 4)
  {
    // The input's own arrays, shared (SplitPoints copies the connectivity it renumbers).
    this->Offsets = inPolys->GetOffsetsArray64();
    this->Connectivity = inPolys->GetConnectivityArray64();
    return;
  }
  this->Offsets = vtkSmartPointer<vtkTypeInt64Array>::New();
  this->Connectivity = vtkSmartPointer<vtkTypeInt64Array>::New();
  const vtkIdType nLead = input->GetNumberOfVerts() + input->GetNumberOfLines();
  std::vector<vtkIdType> offsets{ 0 }, conn;
  conn.reserve(inPolys->GetNumberOfConnectivityIds());
  offsets.reserve(input->GetNumberOfPolys() + 1);
  this->FaceCell.reserve(input->GetNumberOfPolys());
  auto addFace = [&](const vtkIdType* ids, vtkIdType npts, vtkIdType cell)
  {
    conn.insert(conn.end(), ids, ids + npts);
    offsets.push_back(static_cast<vtkIdType>(conn.size()));
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
      addFace(pts, npts, cell);
      continue;
    }
    this->FacesAreInputPolys = false;
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
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cell)
  {
    this->FacesAreInputPolys = false;
    vtkIdType npts;
    const vtkIdType* pts;
    strips->GetCurrentCell(npts, pts);
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      const vtkIdType tri[3] = { pts[k + (k & 1)], pts[k + 1 - (k & 1)], pts[k + 2] };
      if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2])
      {
        addFace(tri, 3, cell);
      }
    }
  }
  this->Offsets->SetNumberOfValues(static_cast<vtkIdType>(offsets.size()));
  std::copy(offsets.begin(), offsets.end(), this->Offsets->GetPointer(0));
  this->Connectivity->SetNumberOfValues(static_cast<vtkIdType>(conn.size()));
  std::copy(conn.begin(), conn.end(), this->Connectivity->GetPointer(0));
}

// One triangle per triangle face, two per quad, split along the shorter texture diagonal
// (the shorter position diagonal on a tie). Per triangle, in parallel: degeneracy, texture
// orientation, usable derivatives and the directions of dP/ds and dP/dt (eq. 18, 19 of the
// reference's description); a quad's two triangles are forced to one orientation.
//
// The decisions (which diagonal, the sign of the texture area, whether the derivatives are
// usable) are the reference's own expressions in its single precision, on the values it
// would be given as floats, so that every tool that bakes with MikkTSpace takes the same
// ones: near zero, double precision would give another sign or call a float cancellation a
// direction. The directions themselves are in double.
void MikkTSpace::BuildTriangles()
{
  const vtkIdType nFaces = this->Offsets->GetNumberOfValues() - 1;
  const vtkIdType* off = this->Offsets->GetPointer(0);
  const vtkIdType* conn = this->Connectivity->GetPointer(0);
  this->FaceFirstTri.assign(nFaces + 1, 0);
  for (vtkIdType f = 0; f < nFaces; ++f)
  {
    const vtkIdType n = off[f + 1] - off[f];
    this->FaceFirstTri[f + 1] = this->FaceFirstTri[f] + (n == 3 ? 1 : (n == 4 ? 2 : 0));
  }
  const vtkIdType nTris = this->NumberOfTriangles = this->FaceFirstTri[nFaces];
  this->TriVertex->SetNumberOfValues(3 * nTris);
  this->Tris.reset(new Triangle[nTris]);
  vtkIdType* triVertex = this->TriVertex->GetPointer(0);
  this->TriVertexIds = triVertex;
  // Squared distance between the points of face corners i and j, as floats, in texture
  // space (2 components) or in space (3).
  auto dist2 = [&](const double* x, int nc, vtkIdType i, vtkIdType j)
  {
    float d2 = 0.0f;
    for (int k = 0; k < nc; ++k)
    {
      const float d =
        static_cast<float>(x[nc * conn[j] + k]) - static_cast<float>(x[nc * conn[i] + k]);
      d2 += d * d;
    }
    return d2;
  };
  vtkSMPTools::For(0, nFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      const int split[2][6] = { { 0, 1, 3, 1, 2, 3 }, { 0, 1, 2, 0, 2, 3 } };
      for (vtkIdType f = begin; f < end; ++f)
      {
        const vtkIdType t = this->FaceFirstTri[f], nt = this->FaceFirstTri[f + 1] - t, b = off[f];
        const double* T = this->T.data();
        const bool diag02 = nt != 2 || dist2(T, 2, b, b + 2) < dist2(T, 2, b + 1, b + 3) ||
          (!(dist2(T, 2, b + 1, b + 3) < dist2(T, 2, b, b + 2)) &&
            !(dist2(this->P.data(), 3, b + 1, b + 3) < dist2(this->P.data(), 3, b, b + 2)));
        float area[2];
        for (vtkIdType i = 0; i < nt; ++i)
        {
          vtkIdType c[3];
          Triangle& tri = this->Tris[t + i];
          for (int k = 0; k < 3; ++k)
          {
            c[k] = b + split[diag02][3 * i + k];
            triVertex[3 * (t + i) + k] = this->WeldOf[conn[c[k]]];
          }
          area[i] = this->EvaluateTriangle(c, tri);
          tri.Base = b;
          for (int k = 0; k < 3; ++k)
          {
            tri.Flag |= static_cast<int>(c[k] - b) << (4 + 2 * k);
          }
        }
        if (nt == 2)
        {
          int& fa = this->Tris[t].Flag;
          int& fb = this->Tris[t + 1].Flag;
          if (((fa ^ fb) & Degenerate) != 0)
          {
            fa |= QuadOneDegenerate;
            fb |= QuadOneDegenerate;
          }
          else if (!(fa & Degenerate) && ((fa ^ fb) & OrientPreserving) != 0)
          {
            // An inconsistently mapped quad: the larger texture area (or the triangle with
            // usable derivatives) decides its orientation.
            const bool first = (fb & GroupWithAny) || std::abs(area[0]) >= std::abs(area[1]);
            int& to = first ? fb : fa;
            to = (to & ~OrientPreserving) | ((first ? fa : fb) & OrientPreserving);
          }
        }
      }
    });
  vtkNew<vtkCellArray> triangles;
  triangles->SetData(3, this->TriVertex);
  this->VertexLinks.SerialBuildLinks(this->NumberOfPoints, nTris, triangles);
}

// The triangle of face corners c: its flags (the reference's expressions in single
// precision: eq. 18, 19 of its description, CalcTexArea) and its directions (in double).
// Returns the signed texture area as the reference computes it.
float MikkTSpace::EvaluateTriangle(const vtkIdType c[3], Triangle& tri) const
{
  const vtkIdType* conn = this->Connectivity->GetPointer(0);
  const double* p[3] = { &this->P[3 * conn[c[0]]], &this->P[3 * conn[c[1]]],
    &this->P[3 * conn[c[2]]] };
  const double* t[3] = { &this->T[2 * conn[c[0]]], &this->T[2 * conn[c[1]]],
    &this->T[2 * conn[c[2]]] };
  auto f = [](double x) { return static_cast<float>(x); };
  const float t21x = f(t[1][0]) - f(t[0][0]), t21y = f(t[1][1]) - f(t[0][1]);
  const float t31x = f(t[2][0]) - f(t[0][0]), t31y = f(t[2][1]) - f(t[0][1]);
  const float area = t21x * t31y - t21y * t31x;
  float os2 = 0.0f, ot2 = 0.0f;
  for (int k = 0; k < 3; ++k)
  {
    const float d1 = f(p[1][k]) - f(p[0][k]), d2 = f(p[2][k]) - f(p[0][k]);
    const float os = t31y * d1 - t21y * d2, ot = -t31x * d1 + t21x * d2;
    os2 += os * os;
    ot2 += ot * ot;
  }
  const float absArea = std::abs(area);
  const bool usable =
    NotZeroF(area) && NotZeroF(std::sqrt(os2) / absArea) && NotZeroF(std::sqrt(ot2) / absArea);
  auto same = [](const double* a, const double* b) { return std::equal(a, a + 3, b); };
  tri.Flag = (area > 0.0f ? OrientPreserving : 0) | (usable ? 0 : GroupWithAny) |
    (same(p[0], p[1]) || same(p[0], p[2]) || same(p[1], p[2]) ? Degenerate : 0);
  const double sign = area > 0.0f ? 1.0 : -1.0;
  const double s21 = t[1][1] - t[0][1], s31 = t[2][1] - t[0][1];
  const double r21 = t[1][0] - t[0][0], r31 = t[2][0] - t[0][0];
  for (int k = 0; k < 3; ++k)
  {
    const double d1 = p[1][k] - p[0][k], d2 = p[2][k] - p[0][k];
    tri.Os[k] = usable ? sign * (s31 * d1 - s21 * d2) : 0.0;
    tri.Ot[k] = usable ? sign * (r21 * d2 - r31 * d1) : 0.0;
  }
  NormalizeIfNotZero(tri.Os);
  NormalizeIfNotZero(tri.Ot);
  return area;
}

/// The good triangles around one vertex and how they connect there.
struct MikkTSpace::Fan
{
  std::vector<vtkIdType> Tri, Degenerate; // increasing
  std::vector<int> Corner;                // the vertex's corner in each good triangle
  std::vector<int> Out, In;               // neighbour across (v, next) and (prev, v), or -1
  std::vector<std::pair<vtkIdType, int>> Edges;
  std::vector<int> Pending[2];
  // Per good triangle while evaluating:
  std::vector<int> Group, Members, Stack, Subset;
  std::vector<std::array<double, 3>> Os, Ot, Result;
  std::vector<double> Angle;
};

// Visits the triangles linked to fan entry @a s, depth first: enter(a) says whether a
// joins (and records it); only those that join spread further.
template <typename Enter>
void Flood(const MikkTSpace::Fan& fan, int s, std::vector<int>& stack, Enter&& enter)
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
// with the first later unpaired one running the other way, which is a first-in first-out
// match of the two directions. Every triangle on an edge at v is around v, so v's
// triangles alone decide its links, and the same way as at the edge's other vertex.
void MikkTSpace::BuildFan(vtkIdType v, Fan& fan)
{
  fan.Tri.clear();
  fan.Degenerate.clear();
  fan.Corner.clear();
  fan.Edges.clear();
  const vtkIdType* links = this->VertexLinks.GetCells(v);
  const vtkIdType nLinks = this->VertexLinks.GetNumberOfCells(v);
  for (vtkIdType l = nLinks - 1; l >= 0; --l)
  {
    const vtkIdType t = links[l];
    if (this->Tris[t].Flag & Degenerate)
    {
      if (fan.Degenerate.empty() || fan.Degenerate.back() != t)
      {
        fan.Degenerate.push_back(t);
      }
      continue;
    }
    const int i = this->CornerVertex(t, 0) == v ? 0 : (this->CornerVertex(t, 1) == v ? 1 : 2);
    const int a = static_cast<int>(fan.Tri.size());
    fan.Tri.push_back(t);
    fan.Corner.push_back(i);
    fan.Edges.emplace_back(this->CornerVertex(t, (i + 1) % 3), 2 * a);     // v -> next
    fan.Edges.emplace_back(this->CornerVertex(t, (i + 2) % 3), 2 * a + 1); // prev -> v
  }
  const size_t k = fan.Tri.size();
  fan.Out.assign(k, -1);
  fan.In.assign(k, -1);
  std::sort(fan.Edges.begin(), fan.Edges.end());
  for (size_t g = 0; g < fan.Edges.size();)
  {
    fan.Pending[0].clear();
    fan.Pending[1].clear();
    size_t head[2] = { 0, 0 };
    size_t e = g;
    for (; e < fan.Edges.size() && fan.Edges[e].first == fan.Edges[g].first; ++e)
    {
      const int a = fan.Edges[e].second / 2, d = fan.Edges[e].second % 2;
      if (head[1 - d] < fan.Pending[1 - d].size())
      {
        const int b = fan.Pending[1 - d][head[1 - d]++];
        (d == 0 ? fan.Out[a] : fan.In[a]) = b;
        (d == 0 ? fan.In[b] : fan.Out[b]) = a;
      }
      else
      {
        fan.Pending[d].push_back(a);
      }
    }
    g = e;
  }
}

// A triangle without usable derivatives takes the orientation of the first group that
// reaches it, at any of its vertices: the reference's one order dependency. Its group
// building is replayed (seeds in triangle and corner order, each flooding across linked
// neighbours of its orientation) at the vertices that have such triangles; elsewhere it
// cannot matter. Afterwards every vertex's groups depend on its own triangles only.
void MikkTSpace::ResolveGroupWithAnyOrientation()
{
  const vtkIdType nTris = this->NumberOfTriangles;
  std::vector<char> anyVertex(this->NumberOfPoints, 0);
  bool any = false;
  for (vtkIdType t = 0; t < nTris; ++t)
  {
    if ((this->Tris[t].Flag & (GroupWithAny | Degenerate)) == GroupWithAny)
    {
      any = true;
      for (int k = 0; k < 3; ++k)
      {
        anyVertex[this->CornerVertex(t, k)] = 1;
      }
    }
  }
  if (!any)
  {
    return;
  }
  std::vector<char> assigned(3 * nTris, 0);
  std::unordered_map<vtkIdType, Fan> fans;
  std::vector<int> stack;
  for (vtkIdType t = 0; t < nTris; ++t)
  {
    for (int i = 0; i < 3; ++i)
    {
      const vtkIdType v = this->CornerVertex(t, i);
      if (!anyVertex[v] || (this->Tris[t].Flag & (GroupWithAny | Degenerate)) ||
        assigned[3 * t + i])
      {
        continue;
      }
      auto found = fans.find(v);
      if (found == fans.end())
      {
        found = fans.emplace(v, Fan()).first;
        this->BuildFan(v, found->second);
      }
      const Fan& fan = found->second;
      const bool orient = this->Orient(t);
      const int seed =
        static_cast<int>(std::lower_bound(fan.Tri.begin(), fan.Tri.end(), t) - fan.Tri.begin());
      Flood(fan, seed, stack,
        [&](int a)
        {
          const vtkIdType u = fan.Tri[a];
          char& done = assigned[3 * u + fan.Corner[a]];
          int& flag = this->Tris[u].Flag;
          if (done)
          {
            return false;
          }
          if ((flag & GroupWithAny) && !assigned[3 * u] && !assigned[3 * u + 1] &&
            !assigned[3 * u + 2])
          {
            flag = (flag & ~OrientPreserving) | (orient ? OrientPreserving : 0);
          }
          done = this->Orient(u) == orient ? 1 : 0;
          return done != 0;
        });
    }
  }
}

// Per vertex, in parallel: its groups (the linked triangles of one orientation, seeded by
// one with usable derivatives), each corner's tangent space (the angle-weighted average of
// its sub-group's projected dP/ds directions), a quad's two spaces at one corner averaged,
// and the corners of degenerate triangles at the vertex.
void MikkTSpace::EvaluateVertices()
{
  this->State.assign(this->NumberOfPoints, NoFrame);
  this->VertexFrame.reset(new Frame[this->NumberOfPoints]);
  vtkSMPThreadLocal<CornerFrames> differing;
  vtkSMPTools::For(0, this->NumberOfPoints,
    [&](vtkIdType begin, vtkIdType end)
    {
      Fan fan;
      for (vtkIdType v = begin; v < end; ++v)
      {
        if (this->WeldOf[v] == v)
        {
          this->EvaluateVertex(v, fan, differing.Local());
        }
      }
    });
  for (const auto& local : differing)
  {
    this->Differing.insert(this->Differing.end(), local.begin(), local.end());
  }
  SortByCorner(this->Differing);
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

void MikkTSpace::EvaluateVertex(vtkIdType v, Fan& fan, CornerFrames& differing)
{
  this->BuildFan(v, fan);
  const size_t k = fan.Tri.size();
  const double* n = this->Normal(v);
  const double* pv = &this->P[3 * v];
  fan.Os.resize(k);
  fan.Ot.resize(k);
  fan.Angle.resize(k);
  fan.Result.resize(k);
  for (size_t a = 0; a < k; ++a)
  {
    const vtkIdType t = fan.Tri[a];
    ProjectNormalize(this->Tris[t].Os, n, fan.Os[a].data());
    ProjectNormalize(this->Tris[t].Ot, n, fan.Ot[a].data());
    // The corner's weight: its angle, between the edges projected onto the tangent plane.
    // From the cross and dot products it keeps the tiny angles of slivers (acos of a
    // cosine rounded to 1 gives 0, and a group of slivers would have no direction at all);
    // an edge along the normal leaves no direction, and the reference then takes the
    // angle as a right angle.
    const int i = fan.Corner[a];
    const double* p0 = &this->P[3 * this->CornerVertex(t, (i + 2) % 3)];
    const double* p2 = &this->P[3 * this->CornerVertex(t, (i + 1) % 3)];
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
    fan.Angle[a] = (this->Tris[t].Flag & GroupWithAny) || !std::isfinite(angle) ? 0.0 : angle;
  }
  // Groups, seeded in triangle order, each the linked triangles of its seed's orientation.
  fan.Group.assign(k, -1);
  for (size_t s = 0; s < k; ++s)
  {
    if (fan.Group[s] >= 0 || (this->Tris[fan.Tri[s]].Flag & GroupWithAny))
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
    const vtkIdType c = this->Corner(fan.Tri[a], fan.Corner[a]);
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
  for (vtkIdType d : fan.Degenerate)
  {
    if (this->Tris[d].Flag & QuadOneDegenerate)
    {
      continue; // FixQuadsWithOneDegenerateTriangle
    }
    for (int j = 0; j < 3; ++j)
    {
      if (this->CornerVertex(d, j) == v)
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
void MikkTSpace::SetCornerFrame(
  vtkIdType v, vtkIdType c, const Frame& frame, CornerFrames& differing)
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

Frame MikkTSpace::FrameOf(vtkIdType c, vtkIdType v) const
{
  const auto found = std::lower_bound(this->Differing.begin(), this->Differing.end(), c,
    [](const std::pair<vtkIdType, Frame>& x, vtkIdType y) { return x.first < y; });
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
    // Triangles of one quad (which share a corner) and those without usable derivatives.
    const vtkIdType tf = fan.Tri[f], ta = fan.Tri[a];
    const vtkIdType lo = std::min(tf, ta), first = this->Corner(std::max(tf, ta), 0);
    const bool shared =
      this->Corner(lo, 0) == first || this->Corner(lo, 1) == first || this->Corner(lo, 2) == first;
    return tf == ta || (std::abs(tf - ta) == 1 && shared) ||
      ((this->Tris[tf].Flag | this->Tris[ta].Flag) & GroupWithAny);
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
  const vtkIdType nFaces = this->Offsets->GetNumberOfValues() - 1;
  const vtkIdType* conn = this->Connectivity->GetPointer(0);
  const double placeholder[3] = { 1.0, 0.0, 0.0 };
  CornerFrames added;
  for (vtkIdType f = 0; f < nFaces; ++f)
  {
    const vtkIdType t = this->FaceFirstTri[f];
    if (this->FaceFirstTri[f + 1] - t != 2 || !(this->Tris[t].Flag & QuadOneDegenerate))
    {
      continue;
    }
    const vtkIdType good = (this->Tris[t].Flag & Degenerate) ? t + 1 : t;
    const vtkIdType c[3] = { this->Corner(good, 0), this->Corner(good, 1), this->Corner(good, 2) };
    vtkIdType missing = this->Offsets->GetValue(f);
    while (missing == c[0] || missing == c[1] || missing == c[2])
    {
      ++missing;
    }
    const double* target = &this->P[3 * conn[missing]];
    const vtkIdType* src = std::find_if(
      c, c + 3, [&](vtkIdType j) { return std::equal(target, target + 3, &this->P[3 * conn[j]]); });
    const double* n = this->Normal(conn[missing]);
    const Frame from = src == c + 3 ? Frame{ 1.0f, 0.0f, 0.0f, -1.0f }
                                    : this->FrameOf(*src, this->WeldOf[conn[*src]]);
    const double os[3] = { from[0], from[1], from[2] };
    this->SetCornerFrame(this->WeldOf[conn[missing]], missing,
      FinalFrame(n, src == c + 3 ? placeholder : os, from[3] > 0.0f), added);
  }
  this->Differing.insert(this->Differing.end(), added.begin(), added.end());
  SortByCorner(this->Differing);
}

// A point keeps the frame of its first corner; every other distinct frame among its
// corners becomes a new point after the input's, numbered in point order and then in
// order of first appearance, and its corners are renumbered. Only the points of vertices
// with several frames are looked at corner by corner.
void MikkTSpace::SplitPoints()
{
  const vtkIdType nPts = this->NumberOfPoints;
  this->Tangents->SetName("Tangents");
  this->Tangents->SetNumberOfComponents(4);
  this->Tangents->SetNumberOfTuples(nPts);
  Frame* pointFrame = reinterpret_cast<Frame*>(this->Tangents->GetPointer(0));
  vtkSMPTools::For(0, nPts,
    [&](vtkIdType begin, vtkIdType end)
    {
      const double zero[3] = { 0.0, 0.0, 0.0 };
      for (vtkIdType p = begin; p < end; ++p)
      {
        const vtkIdType v = this->WeldOf[p];
        pointFrame[p] = this->State[v] == NoFrame ? FinalFrame(this->Normal(p), zero, true)
                                                  : this->VertexFrame[v];
      }
    });
  // Point -> its corners in corner order, for the points of mixed vertices only.
  std::vector<vtkIdType> slot(nPts, -1), mixed;
  for (vtkIdType p = 0; p < nPts; ++p)
  {
    if (this->State[this->WeldOf[p]] == Mixed)
    {
      slot[p] = static_cast<vtkIdType>(mixed.size());
      mixed.push_back(p);
    }
  }
  if (mixed.empty())
  {
    return;
  }
  const vtkIdType nFaces = this->Offsets->GetNumberOfValues() - 1;
  const vtkIdType* off = this->Offsets->GetPointer(0);
  auto forEachCorner = [&](const vtkIdType* conn, auto&& visit)
  {
    for (vtkIdType f = 0; f < nFaces; ++f)
    {
      for (vtkIdType j = off[f];
           j < off[f + 1] && this->FaceFirstTri[f + 1] > this->FaceFirstTri[f]; ++j)
      {
        if (slot[conn[j]] >= 0)
        {
          visit(slot[conn[j]], j);
        }
      }
    }
  };
  const vtkIdType nMixed = static_cast<vtkIdType>(mixed.size());
  std::vector<vtkIdType> start(nMixed + 1, 0);
  forEachCorner(this->Connectivity->GetPointer(0), [&](vtkIdType s, vtkIdType) { ++start[s + 1]; });
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<vtkIdType> corners(start.back()), fill(start.begin(), start.end() - 1);
  forEachCorner(
    this->Connectivity->GetPointer(0), [&](vtkIdType s, vtkIdType j) { corners[fill[s]++] = j; });

  // Rare, and in point order: serial. The connectivity is copied before it is renumbered
  // (it may be the input's own array).
  std::vector<vtkIdType> rank, firsts;
  vtkIdType* conn = nullptr;
  for (vtkIdType i = 0; i < nMixed; ++i)
  {
    const vtkIdType* pc = &corners[start[i]];
    this->DistinctFrames(pc, start[i + 1] - start[i], this->WeldOf[mixed[i]], rank, firsts);
    for (size_t d = 0; d < firsts.size(); ++d)
    {
      const Frame frame = this->FrameOf(firsts[d], this->WeldOf[mixed[i]]);
      if (d == 0)
      {
        pointFrame[mixed[i]] = frame;
        continue;
      }
      if (!conn)
      {
        auto renumbered = vtkSmartPointer<vtkTypeInt64Array>::New();
        renumbered->DeepCopy(this->Connectivity);
        this->Connectivity = renumbered;
        conn = renumbered->GetPointer(0);
        this->Renumbered = true;
      }
      firsts[d] = this->Tangents->InsertNextTypedTuple(frame.data());
      pointFrame = reinterpret_cast<Frame*>(this->Tangents->GetPointer(0));
      this->ExtraSource.push_back(mixed[i]);
    }
    for (size_t c = 0; c < rank.size(); ++c)
    {
      if (rank[c] > 0)
      {
        conn[pc[c]] = firsts[rank[c]];
      }
    }
  }
}

// The distinct frames of @a m corners in order of first appearance: firsts[d] is the
// first corner with frame d, rank[i] the frame number of corners[i]. Frames are told apart
// by their bits, as they are stored.
void MikkTSpace::DistinctFrames(const vtkIdType* corners, vtkIdType m, vtkIdType v,
  std::vector<vtkIdType>& rank, std::vector<vtkIdType>& firsts) const
{
  auto less = [](const Frame& x, const Frame& y)
  { return std::memcmp(x.data(), y.data(), sizeof(Frame)) < 0; };
  std::map<Frame, vtkIdType, decltype(less)> number(less);
  firsts.clear();
  rank.resize(m);
  for (vtkIdType i = 0; i < m; ++i)
  {
    const auto found =
      number.emplace(this->FrameOf(corners[i], v), static_cast<vtkIdType>(firsts.size()));
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
  if (this->FacesAreInputPolys && !this->Renumbered)
  {
    output->SetPolys(input->GetPolys());
  }
  else
  {
    vtkNew<vtkCellArray> polys;
    polys->SetData(this->Offsets, this->Connectivity);
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
