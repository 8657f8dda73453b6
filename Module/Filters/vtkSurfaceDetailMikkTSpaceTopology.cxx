// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSurfaceDetailMikkTSpaceTopology.h"

#include "vtkMath.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <numeric>
#include <unordered_map>

namespace vtkSurfaceDetailMikkTSpace
{
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

namespace
{
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

// Normalises (x, y, z) if it has a length, as NormalizeIfNotZero does (a scale of 1 where
// it has none: selects of one comparison each, which vectorise).
inline void NormalizeLane(double& x, double& y, double& z)
{
  const double len = std::sqrt(x * x + y * y + z * z);
  const double finite = std::abs(len) <= DBL_MAX ? 1.0 / len : 1.0;
  const double inv = len > 0.0 ? finite : 1.0;
  x *= inv;
  y *= inv;
  z *= inv;
}

// (x, y, z) minus its part along unit (nx, ny, nz), normalised, as ProjectNormalize does.
inline void ProjectLane(double nx, double ny, double nz, double& x, double& y, double& z)
{
  const double d = nx * x + ny * y + nz * z;
  x = x - d * nx;
  y = y - d * ny;
  z = z - d * nz;
  NormalizeLane(x, y, z);
}

} // anonymous namespace

void EvaluateBlock(const double n[3], int lanes, CornerBlock& b)
{
  const double nx = n[0], ny = n[1], nz = n[2];
  for (int l = 0; l < lanes; ++l)
  {
    double sx = b.Dir[0][l], sy = b.Dir[1][l], sz = b.Dir[2][l];
    double tx = b.Dir[3][l], ty = b.Dir[4][l], tz = b.Dir[5][l];
    ProjectLane(nx, ny, nz, sx, sy, sz);
    ProjectLane(nx, ny, nz, tx, ty, tz);
    b.Os[0][l] = sx;
    b.Os[1][l] = sy;
    b.Os[2][l] = sz;
    b.Ot[0][l] = tx;
    b.Ot[1][l] = ty;
    b.Ot[2][l] = tz;
    const double n1 = nx * b.Edge1[0][l] + ny * b.Edge1[1][l] + nz * b.Edge1[2][l];
    const double n2 = nx * b.Edge2[0][l] + ny * b.Edge2[1][l] + nz * b.Edge2[2][l];
    const double e1x = b.Edge1[0][l] - n1 * nx, e1y = b.Edge1[1][l] - n1 * ny,
                 e1z = b.Edge1[2][l] - n1 * nz;
    const double e2x = b.Edge2[0][l] - n2 * nx, e2y = b.Edge2[1][l] - n2 * ny,
                 e2z = b.Edge2[2][l] - n2 * nz;
    const double cx = e1y * e2z - e1z * e2y, cy = e1z * e2x - e1x * e2z, cz = e1x * e2y - e1y * e2x;
    // Selects of one comparison each: the form that the vectoriser turns into masks.
    const double e11 = e1x * e1x + e1y * e1y + e1z * e1z, e22 = e2x * e2x + e2y * e2y + e2z * e2z;
    const double angle =
      CornerAngle(std::sqrt(cx * cx + cy * cy + cz * cz), e1x * e2x + e1y * e2y + e1z * e2z);
    const double right = 0.5 * vtkMath::Pi();
    const double weight = e11 == 0.0 ? right : (e22 == 0.0 ? right : angle);
    const double finite = std::abs(weight) <= DBL_MAX ? weight : 0.0;
    b.Weight[l] = b.Usable[l] != 0.0 ? finite : 0.0;
  }
}

namespace
{
// Visits the triangles linked to fan entry @a s, depth first: enter(a) says whether a
// joins (and records it); only those that join spread further. @a stack holds 2 K + 1.
template <typename Enter>
void Flood(const Fan& fan, int s, int* stack, Enter&& enter)
{
  int top = 0;
  stack[top++] = s;
  while (top > 0)
  {
    const int a = stack[--top];
    if (enter(a))
    {
      for (int b : { fan.Out[a], fan.In[a] })
      {
        if (b >= 0)
        {
          stack[top++] = b;
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
  const int k = fan.K;
  size_t size = 8;
  while (size < 2 * static_cast<size_t>(k))
  {
    size *= 2;
  }
  const size_t mask = size - 1;
  if (fan.SlotKey.size() < size)
  {
    fan.SlotKey.resize(size);
    fan.SlotHead.resize(size);
    fan.SlotTail.resize(size);
  }
  std::fill_n(fan.SlotKey.begin(), size, -1);
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
    fan.Chain[b] = -1;
    fan.In[b] = -1;
  }
  for (int a = 0; a < k; ++a)
  {
    const size_t s = slotOf(fan.Next[a]);
    const int b = fan.SlotKey[s] >= 0 ? fan.SlotHead[s] : -1;
    fan.Out[a] = b;
    if (b >= 0)
    {
      fan.SlotHead[s] = fan.Chain[b];
      fan.In[b] = a;
    }
  }
}

} // anonymous namespace

// The vertex -> triangles links, with VTK's static links over the triangles' welded
// vertices.
void Topology::BuildLinks()
{
  vtkNew<vtkCellArray> triangles;
  triangles->SetData(3, this->TriVertexArray);
  this->Links.SerialBuildLinks(this->NumberOfPoints, this->NumberOfTriangles, triangles);
}

// The triangles around v from its links, and their neighbours there.
void Topology::BuildFan(Index v, Fan& fan)
{
  const vtkIdType nLinks = this->Links.GetNcells(v);
  const Index* links = this->Links.GetCells(v);
  fan.Reserve(static_cast<int>(nLinks));
  fan.Degenerate.clear();
  int k = 0;
  for (vtkIdType l = nLinks - 1; l >= 0; --l)
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
    const Index* tv = &this->TriVertex[3 * static_cast<size_t>(t)];
    const int i = tv[0] == v ? 0 : (tv[1] == v ? 1 : 2);
    fan.Tri[k] = t;
    fan.Corner[k] = i;
    fan.Next[k] = tv[i == 2 ? 0 : i + 1];
    fan.Prev[k] = tv[i == 0 ? 2 : i - 1];
    ++k;
  }
  fan.K = k;
  MatchEdges(fan);
}

// A triangle without usable derivatives takes the orientation of the first group that
// reaches it, at any of its vertices: the reference's one order dependency. Its group
// building is replayed (seeds in triangle and corner order, each flooding across linked
// neighbours of its orientation) at the vertices that have such triangles; elsewhere it
// cannot matter. Afterwards every vertex's groups depend on its own triangles only.
void Topology::ResolveGroupWithAnyOrientation()
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
      const int seed = static_cast<int>(
        std::lower_bound(fan.Tri.begin(), fan.Tri.begin() + fan.K, t) - fan.Tri.begin());
      Flood(fan, seed, const_cast<int*>(fan.Stack.data()),
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

// The groups of a fan, seeded in triangle order, each the linked triangles of its seed's
// orientation, and each member's space. The members of each group are listed in fan order
// by a counting sort on their seeds.
void Topology::EvaluateGroups(Fan& fan) const
{
  const int k = fan.K;
  std::fill_n(fan.Group.begin(), k, -1);
  for (int s = 0; s < k; ++s)
  {
    if (fan.Group[s] >= 0 || (this->TriFlag[fan.Tri[s]] & GroupWithAny))
    {
      continue;
    }
    const bool orient = this->Orient(fan.Tri[s]);
    Flood(fan, s, fan.Stack.data(),
      [&](int a)
      {
        if (fan.Group[a] >= 0 || this->Orient(fan.Tri[a]) != orient)
        {
          return false;
        }
        fan.Group[a] = s;
        return true;
      });
  }
  int* start = fan.Start.data();
  std::fill_n(start, k + 1, 0);
  for (int a = 0; a < k; ++a)
  {
    start[fan.Group[a] + 1] += fan.Group[a] >= 0;
  }
  std::partial_sum(start, start + k + 1, start);
  for (int a = 0; a < k; ++a)
  {
    if (fan.Group[a] >= 0)
    {
      fan.Members[start[fan.Group[a]]++] = a;
    }
  }
  for (int s = 0, first = 0; s < k; first = start[s++])
  {
    if (start[s] > first)
    {
      this->EvaluateGroup(fan, fan.Members.data() + first, start[s] - first);
    }
  }
}

// The space of each of the @a m members of a group: the angle-weighted average, in
// increasing triangle order, of the projected dP/ds directions of its sub-group, the
// members whose dP/ds and dP/dt are both within the angular threshold of its own (the whole
// group at 180 degrees, unless two are exactly opposite). Triangles of one quad, and those
// without usable derivatives, always join.
void Topology::EvaluateGroup(Fan& fan, const int* members, int m) const
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
  auto average = [&](const int* subset, int n)
  {
    std::array<double, 3> sum{ 0.0, 0.0, 0.0 };
    for (int i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        sum[c] += fan.Weight[subset[i]] * fan.Os[subset[i]][c];
      }
    }
    NormalizeIfNotZero(sum.data());
    return sum;
  };
  bool allJoin = true;
  for (int x = 0; x < m && m <= MaxSubGroupTest && allJoin; ++x)
  {
    const double* osx = fan.Os[members[x]].data();
    const double* otx = fan.Ot[members[x]].data();
    for (int y = x + 1; y < m && allJoin; ++y)
    {
      const double dos = vtkSurfaceDetail::Dot(osx, fan.Os[members[y]].data());
      const double dot = vtkSurfaceDetail::Dot(otx, fan.Ot[members[y]].data());
      allJoin =
        (dos > this->ThresholdCos && dot > this->ThresholdCos) || joins(members[x], members[y]);
    }
  }
  if (allJoin)
  {
    const std::array<double, 3> all = average(members, m);
    for (int i = 0; i < m; ++i)
    {
      fan.Result[members[i]] = all;
    }
    return;
  }
  int* subset = fan.Subset.data();
  for (int x = 0; x < m; ++x)
  {
    int n = 0;
    for (int y = 0; y < m; ++y)
    {
      if (joins(members[x], members[y]))
      {
        subset[n++] = members[y];
      }
    }
    fan.Result[members[x]] = average(subset, n);
  }
}

// The frames of v's corners, from the spaces of its fan (the unit normal @a n): a quad's
// corner on its diagonal has a space from each triangle, which the reference averages
// unless they are equal (the later group's orientation wins); corners of degenerate
// triangles take the frame of the vertex's first good triangle. Most corners of a vertex
// share one space: its frame is made, and compared with the vertex's, once.
void Topology::SetFrames(Index v, const double n[3], Fan& fan, CornerFrames& differing)
{
  const int k = fan.K;
  const std::array<double, 3> placeholder{ 1.0, 0.0, 0.0 };
  std::array<double, 3> last{ 0.0, 0.0, 0.0 };
  int lastOrient = -1;
  Frame frame{};
  bool isVertexFrame = false;
  for (int a = 0; a < k; ++a)
  {
    // Both triangles of a quad have its diagonal's corners, one after the other.
    const Index t = fan.Tri[a];
    const Index c = this->Corner(t, fan.Corner[a]);
    const int b =
      a + 1 < k && fan.Tri[a + 1] == t + 1 && this->Corner(t + 1, fan.Corner[a + 1]) == c ? a + 1
                                                                                          : a;
    const int ga = fan.Group[a], gb = fan.Group[b];
    std::array<double, 3> os = ga >= 0 ? fan.Result[a] : (gb >= 0 ? fan.Result[b] : placeholder);
    if (b != a && ga >= 0 && gb >= 0 && fan.Result[a] != fan.Result[b])
    {
      for (int i = 0; i < 3; ++i)
      {
        os[i] += fan.Result[b][i];
      }
      NormalizeIfNotZero(os.data());
    }
    const int g = std::max(ga, gb);
    const int orient = g >= 0 && this->Orient(fan.Tri[g]) ? 1 : 0;
    if (orient != lastOrient || os != last)
    {
      frame = FinalFrame(n, os.data(), orient != 0);
      lastOrient = orient;
      last = os;
      isVertexFrame = this->State[v] == NoFrame ||
        std::memcmp(this->VertexFrame[v].data(), frame.data(), sizeof(Frame)) == 0;
    }
    if (this->State[v] == NoFrame)
    {
      this->State[v] = OneFrame;
      this->VertexFrame[v] = frame;
    }
    else if (!isVertexFrame)
    {
      this->State[v] = Mixed;
      differing.emplace_back(c, frame);
    }
    a = b;
  }
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
          k > 0 ? this->VertexFrame[v] : FinalFrame(n, placeholder.data(), false), differing);
      }
    }
  }
}

// The frame of corner c of vertex v: the vertex's own (its first) or, where it differs,
// listed; a vertex with several frames is Mixed, and only its points may need splitting.
void Topology::AddDiffering(const CornerFrames& frames)
{
  this->Differing.insert(this->Differing.end(), frames.begin(), frames.end());
  std::sort(this->Differing.begin(), this->Differing.end(),
    [](const std::pair<Index, Frame>& x, const std::pair<Index, Frame>& y)
    { return x.first < y.first; });
}

void Topology::SetCornerFrame(Index v, Index c, const Frame& frame, CornerFrames& differing)
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

Frame Topology::FrameOf(Index c, Index v) const
{
  const auto found = std::lower_bound(this->Differing.begin(), this->Differing.end(), c,
    [](const std::pair<Index, Frame>& x, Index y) { return x.first < y; });
  return found != this->Differing.end() && found->first == c ? found->second : this->VertexFrame[v];
}

// A point of a vertex with several frames keeps the frame of its first corner; every other
// distinct frame among its corners becomes a new point after the input's, numbered in point
// order and then in order of first appearance, and its corners are renumbered. Only those
// points' corners are looked at, found through the links of their vertices. Rare, and in
// point order: serial.
void Topology::SplitMixedPoints()
{
  // (point, corner) of the points of mixed vertices, in point and corner order.
  std::vector<std::pair<Index, Index>> corners;
  for (Index v = 0; v < this->NumberOfPoints; ++v)
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
          corners.emplace_back(this->Connectivity[c], c);
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

  // The first frames are written after all the lookups, which read the vertices' own frames
  // at their points.
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
void Topology::DistinctFrames(const std::vector<Index>& corners, Index v, std::vector<int>& rank,
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

Frames Topology::Result()
{
  Frames frames;
  frames.Tangents = this->Tangents;
  frames.SplitSources.assign(this->ExtraSource.begin(), this->ExtraSource.end());
  frames.Connectivity = this->Renumbered;
  frames.NonFinitePoints = this->NonFinitePoints;
  return frames;
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

}
