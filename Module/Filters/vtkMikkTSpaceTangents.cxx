#include "vtkMikkTSpaceTangents.h"

#include "vtkSurfaceDetailCells.h"
#include "vtkSurfaceDetailConventions.h"

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
#include "vtkSMPTools.h"
#include "vtkStaticCellLinksTemplate.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
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
    v[0] /= len;
    v[1] /= len;
    v[2] /= len;
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
  double nn[3] = { n[0], n[1], n[2] };
  if (!(std::abs(vtkSurfaceDetail::Dot(nn, nn) - 1.0) < 1e-6))
  {
    nn[0] = 0.0;
    nn[1] = 0.0;
    nn[2] = 1.0;
  }
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

inline bool SameFrame(const Frame& a, const Frame& b)
{
  return std::memcmp(a.data(), b.data(), sizeof(Frame)) == 0;
}

// Copies the first nc components of every tuple into doubles (typed access for float and
// double arrays, the generic one for the rest).
struct ReadComponents
{
  template <typename ArrayT>
  void operator()(ArrayT* array, int nc, double* out) const
  {
    const auto tuples = vtk::DataArrayTupleRange(array);
    vtkSMPTools::For(0, tuples.size(),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          for (int c = 0; c < nc; ++c)
          {
            out[nc * i + c] = static_cast<double>(tuples[i][c]);
          }
        }
      });
  }
};

std::vector<double> Read(vtkDataArray* array, int nc)
{
  std::vector<double> out(static_cast<size_t>(nc) * array->GetNumberOfTuples());
  ReadComponents worker;
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(
        array, worker, nc, out.data()))
  {
    worker(array, nc, out.data());
  }
  return out;
}

/// Per triangle: the directions of dP/ds and dP/dt (zero when unusable) and its flags.
struct Triangle
{
  double Os[3], Ot[3];
  int Flag;
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
  void Assemble(vtkPointData* inPD, vtkPolyData* output) const;
  vtkIdType CountNonFinitePoints() const;

private:
  struct Fan;
  void BuildFan(vtkIdType v, Fan& fan);
  void EvaluateVertex(vtkIdType v, Fan& fan);
  void EvaluateGroup(Fan& fan) const;
  vtkIdType CornerVertex(vtkIdType tri, int k) const { return this->TriVertex->GetValue(3 * tri + k); }
  bool Orient(vtkIdType tri) const { return (this->Tris[tri].Flag & OrientPreserving) != 0; }
  const double* Normal(vtkIdType pt) const { return &this->N[3 * pt]; }

  vtkPolyData* Input;
  const vtkIdType NumberOfPoints;
  std::vector<double> P, N, T; // N is normalised after the weld
  const double ThresholdCos;
  std::vector<vtkIdType> WeldOf; // point -> vertex: the smallest point id with its values

  // Output polygons ("faces"): the input's triangles and quads, larger polygons and strips
  // triangulated. FaceCell: the input cell each came from.
  vtkNew<vtkIdTypeArray> Offsets, Connectivity;
  std::vector<vtkIdType> FaceCell;
  bool FacesAreInputPolys = true;

  // Triangles of the faces with 3 or 4 corners, in face order (MikkTSpace's triangles).
  std::vector<vtkIdType> FaceFirstTri;
  std::vector<vtkIdType> TriCorner; // 3 per triangle: face corner (connectivity index)
  vtkNew<vtkIdTypeArray> TriVertex; // 3 per triangle: welded vertex
  std::vector<Triangle> Tris;
  vtkStaticCellLinksTemplate<vtkIdType> VertexLinks; // vertex -> triangles, decreasing

  std::vector<Frame> CornerFrame; // per face corner
  std::vector<char> CornerHasFrame;

  // Output points: the input's, then one per extra frame of a split point.
  std::vector<Frame> PointFrame;
  std::vector<vtkIdType> ExtraSource;
};

// MikkTSpace identifies corners by value: points with identical position, normal and
// texture coordinates are one vertex even if the cells do not share them. Points are
// sorted by a hash of their values, which only brings candidates together: runs of equal
// hashes are compared value by value. Points with a NaN equal nothing, as in the reference.
void MikkTSpace::Weld()
{
  const vtkIdType n = this->NumberOfPoints;
  auto values = [this](vtkIdType i)
  {
    return std::array<double, 8>{ this->P[3 * i], this->P[3 * i + 1], this->P[3 * i + 2],
      this->N[3 * i], this->N[3 * i + 1], this->N[3 * i + 2], this->T[2 * i], this->T[2 * i + 1] };
  };
  std::vector<std::pair<std::uint64_t, vtkIdType>> keys(n);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        std::uint64_t h = 1469598103934665603ULL;
        for (double x : values(i))
        {
          x = x == 0.0 ? 0.0 : x; // -0 equals 0: same hash
          std::uint64_t bits;
          std::memcpy(&bits, &x, sizeof(bits));
          h = (h ^ bits) * 0x100000001b3ULL;
          h ^= h >> 29;
        }
        keys[i] = { h, i };
      }
    });
  vtkSMPTools::Sort(keys.begin(), keys.end());
  this->WeldOf.resize(n);
  std::vector<vtkIdType> representatives;
  for (vtkIdType r = 0; r < n;)
  {
    vtkIdType e = r + 1;
    while (e < n && keys[e].first == keys[r].first)
    {
      ++e;
    }
    representatives.clear();
    for (vtkIdType k = r; k < e; ++k)
    {
      const vtkIdType i = keys[k].second;
      const auto vi = values(i);
      this->WeldOf[i] = i;
      if (vi != vi)
      {
        continue;
      }
      auto same = std::find_if(representatives.begin(), representatives.end(),
        [&](vtkIdType o) { return values(o) == vi; });
      if (same != representatives.end())
      {
        this->WeldOf[i] = *same;
      }
      else
      {
        representatives.push_back(i);
      }
    }
    r = e;
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
  const vtkIdType nLead = input->GetNumberOfVerts() + input->GetNumberOfLines();
  std::vector<vtkIdType> offsets{ 0 }, conn;
  conn.reserve(input->GetPolys()->GetNumberOfConnectivityIds());
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
  const vtkIdType nTris = this->FaceFirstTri[nFaces];
  this->TriCorner.resize(3 * nTris);
  this->TriVertex->SetNumberOfValues(3 * nTris);
  this->Tris.resize(nTris);
  vtkIdType* triVertex = this->TriVertex->GetPointer(0);
  auto pf = [this](vtkIdType pt, int c) { return static_cast<float>(this->P[3 * pt + c]); };
  auto tf = [this](vtkIdType pt, int c) { return static_cast<float>(this->T[2 * pt + c]); };
  // The reference's CalcTexArea and tangent directions of one triangle of corners c.
  auto evaluate = [&](const vtkIdType c[3], Triangle& tri, float& area)
  {
    const vtkIdType p[3] = { conn[c[0]], conn[c[1]], conn[c[2]] };
    const float t21x = tf(p[1], 0) - tf(p[0], 0), t21y = tf(p[1], 1) - tf(p[0], 1);
    const float t31x = tf(p[2], 0) - tf(p[0], 0), t31y = tf(p[2], 1) - tf(p[0], 1);
    area = t21x * t31y - t21y * t31x;
    float os2 = 0.0f, ot2 = 0.0f;
    for (int k = 0; k < 3; ++k)
    {
      const float d1 = pf(p[1], k) - pf(p[0], k), d2 = pf(p[2], k) - pf(p[0], k);
      const float os = t31y * d1 - t21y * d2, ot = -t31x * d1 + t21x * d2;
      os2 += os * os;
      ot2 += ot * ot;
    }
    const float absArea = std::abs(area);
    const bool usable = NotZeroF(area) && NotZeroF(std::sqrt(os2) / absArea) &&
      NotZeroF(std::sqrt(ot2) / absArea);
    tri.Flag = (area > 0.0f ? OrientPreserving : 0) | (usable ? 0 : GroupWithAny);
    const double* P = this->P.data();
    const double* T = this->T.data();
    const double s21 = T[2 * p[1] + 1] - T[2 * p[0] + 1], s31 = T[2 * p[2] + 1] - T[2 * p[0] + 1];
    const double r21 = T[2 * p[1]] - T[2 * p[0]], r31 = T[2 * p[2]] - T[2 * p[0]];
    const double sign = area > 0.0f ? 1.0 : -1.0;
    for (int k = 0; k < 3; ++k)
    {
      const double d1 = P[3 * p[1] + k] - P[3 * p[0] + k], d2 = P[3 * p[2] + k] - P[3 * p[0] + k];
      tri.Os[k] = usable ? sign * (s31 * d1 - s21 * d2) : 0.0;
      tri.Ot[k] = usable ? sign * (r21 * d2 - r31 * d1) : 0.0;
    }
    NormalizeIfNotZero(tri.Os);
    NormalizeIfNotZero(tri.Ot);
    const double* p0 = &P[3 * p[0]];
    const double* p1 = &P[3 * p[1]];
    const double* p2 = &P[3 * p[2]];
    auto same = [](const double* a, const double* b)
    { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; };
    if (same(p0, p1) || same(p0, p2) || same(p1, p2))
    {
      tri.Flag |= Degenerate;
    }
  };
  vtkSMPTools::For(0, nFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        const vtkIdType t = this->FaceFirstTri[f], nt = this->FaceFirstTri[f + 1] - t;
        if (nt == 0)
        {
          continue;
        }
        const vtkIdType b = off[f];
        vtkIdType* c = &this->TriCorner[3 * t];
        if (nt == 1)
        {
          c[0] = b;
          c[1] = b + 1;
          c[2] = b + 2;
        }
        else
        {
          auto dist2 = [&](bool position, int i, int j)
          {
            float s = 0.0f;
            for (int k = 0; k < (position ? 3 : 2); ++k)
            {
              const float d = position ? pf(conn[b + j], k) - pf(conn[b + i], k)
                                       : tf(conn[b + j], k) - tf(conn[b + i], k);
              s += d * d;
            }
            return s;
          };
          const float t02 = dist2(false, 0, 2), t13 = dist2(false, 1, 3);
          const bool diag02 =
            t02 < t13 || (!(t13 < t02) && !(dist2(true, 1, 3) < dist2(true, 0, 2)));
          const int split[2][6] = { { 0, 1, 3, 1, 2, 3 }, { 0, 1, 2, 0, 2, 3 } };
          for (int k = 0; k < 6; ++k)
          {
            c[k] = b + split[diag02][k];
          }
        }
        float area[2];
        for (vtkIdType i = 0; i < nt; ++i)
        {
          evaluate(c + 3 * i, this->Tris[t + i], area[i]);
          for (int k = 0; k < 3; ++k)
          {
            triVertex[3 * (t + i) + k] = this->WeldOf[conn[c[3 * i + k]]];
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
  const vtkIdType nTris = static_cast<vtkIdType>(this->Tris.size());
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
      if (!anyVertex[v] || (this->Tris[t].Flag & (GroupWithAny | Degenerate)) || assigned[3 * t + i])
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
      stack.assign(1,
        static_cast<int>(std::lower_bound(fan.Tri.begin(), fan.Tri.end(), t) - fan.Tri.begin()));
      while (!stack.empty())
      {
        const int a = stack.back();
        stack.pop_back();
        const vtkIdType u = fan.Tri[a];
        char& done = assigned[3 * u + fan.Corner[a]];
        if (done)
        {
          continue;
        }
        int& flag = this->Tris[u].Flag;
        if ((flag & GroupWithAny) && !assigned[3 * u] && !assigned[3 * u + 1] &&
          !assigned[3 * u + 2])
        {
          flag = (flag & ~OrientPreserving) | (orient ? OrientPreserving : 0);
        }
        if (this->Orient(u) != orient)
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

// Per vertex, in parallel: its groups (the linked triangles of one orientation, seeded by
// one with usable derivatives), each corner's tangent space (the angle-weighted average of
// its sub-group's projected dP/ds directions), a quad's two spaces at one corner averaged,
// and the corners of degenerate triangles at the vertex.
void MikkTSpace::EvaluateVertices()
{
  this->CornerFrame.resize(this->Connectivity->GetNumberOfValues());
  this->CornerHasFrame.assign(this->Connectivity->GetNumberOfValues(), 0);
  vtkSMPTools::For(0, this->NumberOfPoints,
    [&](vtkIdType begin, vtkIdType end)
    {
      Fan fan;
      for (vtkIdType v = begin; v < end; ++v)
      {
        if (this->WeldOf[v] == v)
        {
          this->EvaluateVertex(v, fan);
        }
      }
    });
}

void MikkTSpace::EvaluateVertex(vtkIdType v, Fan& fan)
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
    // As atan2 it keeps the tiny angles of slivers (acos of a cosine rounded to 1 gives 0,
    // and a group of slivers would have no direction at all); an edge along the normal
    // leaves no direction, and the reference then takes the angle as a right angle.
    const int i = fan.Corner[a];
    const double* p0 = &this->P[3 * this->CornerVertex(t, (i + 2) % 3)];
    const double* p2 = &this->P[3 * this->CornerVertex(t, (i + 1) % 3)];
    double e1[3] = { p0[0] - pv[0], p0[1] - pv[1], p0[2] - pv[2] };
    double e2[3] = { p2[0] - pv[0], p2[1] - pv[1], p2[2] - pv[2] };
    ProjectNormalize(e1, n, e1);
    ProjectNormalize(e2, n, e2);
    double cross[3];
    vtkSurfaceDetail::Cross(e1, e2, cross);
    const bool zero = vtkSurfaceDetail::Dot(e1, e1) == 0.0 || vtkSurfaceDetail::Dot(e2, e2) == 0.0;
    const double angle = zero
      ? 0.5 * vtkMath::Pi()
      : std::atan2(std::sqrt(vtkSurfaceDetail::Dot(cross, cross)), vtkSurfaceDetail::Dot(e1, e2));
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
    fan.Stack.assign(1, static_cast<int>(s));
    while (!fan.Stack.empty())
    {
      const int a = fan.Stack.back();
      fan.Stack.pop_back();
      if (fan.Group[a] >= 0 || this->Orient(fan.Tri[a]) != orient)
      {
        continue;
      }
      fan.Group[a] = static_cast<int>(s);
      fan.Members.push_back(a);
      for (int b : { fan.Out[a], fan.In[a] })
      {
        if (b >= 0)
        {
          fan.Stack.push_back(b);
        }
      }
    }
    std::sort(fan.Members.begin(), fan.Members.end());
    this->EvaluateGroup(fan);
  }
  // Per face corner: a quad's corner on its diagonal has a space from each triangle, which
  // the reference averages unless they are equal; the later group's orientation wins.
  const double placeholder[3] = { 1.0, 0.0, 0.0 };
  for (size_t a = 0; a < k; ++a)
  {
    const vtkIdType c = this->TriCorner[3 * fan.Tri[a] + fan.Corner[a]];
    const bool pair = a + 1 < k && this->TriCorner[3 * fan.Tri[a + 1] + fan.Corner[a + 1]] == c;
    const size_t b = pair ? a + 1 : a;
    const int ga = fan.Group[a], gb = fan.Group[b];
    double os[3];
    std::copy_n(ga >= 0 ? fan.Result[a].data() : (gb >= 0 ? fan.Result[b].data() : placeholder),
      3, os);
    if (ga >= 0 && gb >= 0 && fan.Result[a] != fan.Result[b])
    {
      for (int i = 0; i < 3; ++i)
      {
        os[i] += fan.Result[b][i];
      }
      NormalizeIfNotZero(os);
    }
    const int g = std::max(ga, gb);
    this->CornerFrame[c] = FinalFrame(n, os, g >= 0 && this->Orient(fan.Tri[g]));
    this->CornerHasFrame[c] = 1;
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
        const vtkIdType c = this->TriCorner[3 * d + j];
        this->CornerFrame[c] = k > 0
          ? this->CornerFrame[this->TriCorner[3 * fan.Tri[0] + fan.Corner[0]]]
          : FinalFrame(n, placeholder, false);
        this->CornerHasFrame[c] = 1;
      }
    }
  }
}

// The space of each member of a group: the angle-weighted average, in increasing triangle
// order, of the projected dP/ds directions of its sub-group, the members whose dP/ds and
// dP/dt are both within the angular threshold of its own (the whole group at 180
// degrees, unless two are exactly opposite). Triangles of one quad always join.
void MikkTSpace::EvaluateGroup(Fan& fan) const
{
  auto joins = [&](int f, int a)
  {
    const vtkIdType tf = fan.Tri[f], ta = fan.Tri[a];
    const vtkIdType* cf = &this->TriCorner[3 * std::min(tf, ta)];
    const vtkIdType first = this->TriCorner[3 * std::max(tf, ta)];
    const bool sameFace =
      tf == ta || (std::abs(tf - ta) == 1 && (cf[0] == first || cf[1] == first || cf[2] == first));
    return sameFace || ((this->Tris[tf].Flag | this->Tris[ta].Flag) & GroupWithAny) ||
      (vtkSurfaceDetail::Dot(fan.Os[f].data(), fan.Os[a].data()) > this->ThresholdCos &&
        vtkSurfaceDetail::Dot(fan.Ot[f].data(), fan.Ot[a].data()) > this->ThresholdCos);
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
// its own normal), or the placeholder if there is none.
void MikkTSpace::FixQuadsWithOneDegenerateTriangle()
{
  const vtkIdType nFaces = this->Offsets->GetNumberOfValues() - 1;
  vtkSMPTools::For(0, nFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      const vtkIdType* conn = this->Connectivity->GetPointer(0);
      const double placeholder[3] = { 1.0, 0.0, 0.0 };
      for (vtkIdType f = begin; f < end; ++f)
      {
        const vtkIdType t = this->FaceFirstTri[f];
        if (this->FaceFirstTri[f + 1] - t != 2 || !(this->Tris[t].Flag & QuadOneDegenerate))
        {
          continue;
        }
        const vtkIdType good = (this->Tris[t].Flag & Degenerate) ? t + 1 : t;
        const vtkIdType* c = &this->TriCorner[3 * good];
        const vtkIdType base = this->Offsets->GetValue(f);
        vtkIdType missing = base;
        while (missing == c[0] || missing == c[1] || missing == c[2])
        {
          ++missing;
        }
        const double* target = &this->P[3 * conn[missing]];
        const vtkIdType* src = std::find_if(c, c + 3,
          [&](vtkIdType s)
          {
            const double* p = &this->P[3 * conn[s]];
            return p[0] == target[0] && p[1] == target[1] && p[2] == target[2];
          });
        const double* n = this->Normal(conn[missing]);
        if (src == c + 3)
        {
          this->CornerFrame[missing] = FinalFrame(n, placeholder, false);
          continue;
        }
        const Frame& s = this->CornerFrame[*src];
        const double os[3] = { s[0], s[1], s[2] };
        this->CornerFrame[missing] = FinalFrame(n, os, s[3] > 0.0f);
      }
    });
}

// A point keeps the frame of its first corner; every other distinct frame among its
// corners becomes a new point after the input's, numbered in point order and then in
// order of first appearance, and its corners are renumbered.
void MikkTSpace::SplitPoints()
{
  const vtkIdType nPts = this->NumberOfPoints;
  vtkNew<vtkCellArray> faces;
  faces->SetData(this->Offsets, this->Connectivity);
  vtkStaticCellLinksTemplate<vtkIdType> links;
  links.SerialBuildLinks(nPts, faces->GetNumberOfCells(), faces);
  vtkIdType* conn = this->Connectivity->GetPointer(0);
  const vtkIdType* off = this->Offsets->GetPointer(0);
  // The point's corners that have a frame, in corner order.
  auto cornersOf = [&](vtkIdType p, std::vector<vtkIdType>& corners)
  {
    corners.clear();
    const vtkIdType* cells = links.GetCells(p);
    for (vtkIdType l = links.GetNumberOfCells(p) - 1; l >= 0; --l)
    {
      if (l + 1 < links.GetNumberOfCells(p) && cells[l] == cells[l + 1])
      {
        continue;
      }
      for (vtkIdType j = off[cells[l]]; j < off[cells[l] + 1]; ++j)
      {
        if (conn[j] == p && this->CornerHasFrame[j])
        {
          corners.push_back(j);
        }
      }
    }
  };
  // The distinct frames of the corners in order of first appearance: firsts[d] is the
  // first corner with frame d, rank[i] the frame number of corners[i].
  auto distinct = [&](const std::vector<vtkIdType>& corners, std::vector<size_t>& order,
                    std::vector<size_t>& rank, std::vector<vtkIdType>& firsts)
  {
    order.resize(corners.size());
    for (size_t i = 0; i < order.size(); ++i)
    {
      order[i] = i;
    }
    auto frame = [&](size_t i) { return this->CornerFrame[corners[i]].data(); };
    std::sort(order.begin(), order.end(),
      [&](size_t x, size_t y)
      {
        const int c = std::memcmp(frame(x), frame(y), sizeof(Frame));
        return c < 0 || (c == 0 && x < y);
      });
    firsts.clear();
    rank.resize(corners.size());
    for (size_t i = 0; i < order.size(); ++i)
    {
      if (i == 0 || std::memcmp(frame(order[i - 1]), frame(order[i]), sizeof(Frame)) != 0)
      {
        firsts.push_back(static_cast<vtkIdType>(order[i]));
      }
      rank[order[i]] = firsts.size() - 1;
    }
    std::vector<size_t> byFirst(firsts.size()), renumber(firsts.size());
    for (size_t d = 0; d < firsts.size(); ++d)
    {
      byFirst[d] = d;
    }
    std::sort(byFirst.begin(), byFirst.end(),
      [&](size_t x, size_t y) { return firsts[x] < firsts[y]; });
    std::vector<vtkIdType> sorted(firsts.size());
    for (size_t d = 0; d < byFirst.size(); ++d)
    {
      renumber[byFirst[d]] = d;
      sorted[d] = corners[firsts[byFirst[d]]];
    }
    firsts.swap(sorted);
    for (size_t& r : rank)
    {
      r = renumber[r];
    }
  };
  std::vector<vtkIdType> extra(nPts + 1, 0);
  this->PointFrame.resize(nPts);
  vtkSMPTools::For(0, nPts,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<vtkIdType> corners, firsts;
      std::vector<size_t> order, rank;
      const double zero[3] = { 0.0, 0.0, 0.0 };
      for (vtkIdType p = begin; p < end; ++p)
      {
        cornersOf(p, corners);
        if (corners.empty())
        {
          this->PointFrame[p] = FinalFrame(this->Normal(p), zero, true); // on no polygon
          continue;
        }
        const Frame& first = this->CornerFrame[corners[0]];
        this->PointFrame[p] = first;
        if (!std::all_of(corners.begin(), corners.end(),
              [&](vtkIdType c) { return SameFrame(this->CornerFrame[c], first); }))
        {
          distinct(corners, order, rank, firsts);
          extra[p + 1] = static_cast<vtkIdType>(firsts.size()) - 1;
        }
      }
    });
  for (vtkIdType p = 0; p < nPts; ++p)
  {
    extra[p + 1] += extra[p];
  }
  const vtkIdType nExtra = extra[nPts];
  if (nExtra == 0)
  {
    return;
  }
  this->PointFrame.resize(nPts + nExtra);
  this->ExtraSource.resize(nExtra);
  vtkSMPTools::For(0, nPts,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<vtkIdType> corners, firsts;
      std::vector<size_t> order, rank;
      for (vtkIdType p = begin; p < end; ++p)
      {
        if (extra[p + 1] == extra[p])
        {
          continue;
        }
        cornersOf(p, corners);
        distinct(corners, order, rank, firsts);
        auto idOf = [&](size_t d) { return d == 0 ? p : nPts + extra[p] + vtkIdType(d) - 1; };
        for (size_t d = 1; d < firsts.size(); ++d)
        {
          this->PointFrame[idOf(d)] = this->CornerFrame[firsts[d]];
          this->ExtraSource[idOf(d) - nPts] = p;
        }
        for (size_t i = 0; i < corners.size(); ++i)
        {
          conn[corners[i]] = idOf(rank[i]);
        }
      }
    });
  this->FacesAreInputPolys = false;
}

// The output: the input's points and point data (copied to the split points), the
// "Tangents" array, vertices and lines as they are, the faces with their cell data.
void MikkTSpace::Assemble(vtkPointData* inPD, vtkPolyData* output) const
{
  vtkPolyData* input = this->Input;
  const vtkIdType nPts = this->NumberOfPoints;
  const vtkIdType nOut = static_cast<vtkIdType>(this->PointFrame.size());
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
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(4);
  tangents->SetNumberOfTuples(nOut);
  std::copy_n(this->PointFrame.front().data(), 4 * nOut, tangents->GetPointer(0));
  // VTK 9.1 takes only 3-component tangent attributes, so the frame is the named array of
  // DESIGN.md; an input array of that name must not survive next to it.
  output->GetPointData()->RemoveArray("Tangents");
  output->GetPointData()->AddArray(tangents);

  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());
  if (this->FacesAreInputPolys)
  {
    output->SetPolys(input->GetPolys());
    output->GetCellData()->PassData(input->GetCellData());
  }
  else
  {
    vtkNew<vtkCellArray> polys;
    polys->SetData(this->Offsets, this->Connectivity);
    output->SetPolys(polys);
    const vtkIdType nLead = input->GetNumberOfVerts() + input->GetNumberOfLines();
    const vtkIdType nCells = nLead + polys->GetNumberOfCells();
    vtkNew<vtkIdList> src = identity(nCells);
    std::copy(this->FaceCell.begin(), this->FaceCell.end(), src->begin() + nLead);
    output->GetCellData()->CopyAllocate(input->GetCellData(), nCells);
    output->GetCellData()->CopyData(input->GetCellData(), src, identity(nCells));
  }
  output->GetFieldData()->PassData(input->GetFieldData());
}

vtkIdType MikkTSpace::CountNonFinitePoints() const
{
  vtkIdType count = 0;
  for (vtkIdType i = 0; i < this->NumberOfPoints; ++i)
  {
    const double* p = &this->P[3 * i];
    count += !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
  }
  return count;
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
  if (const vtkIdType nonFinite = mikk.CountNonFinitePoints())
  {
    vtkWarningMacro(<< nonFinite << " points have non-finite coordinates; the tangents around "
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
