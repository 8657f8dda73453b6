// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSurfaceDetailBVH.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace vtkSurfaceDetail
{
namespace
{
constexpr int LeafSize = 4;
// Levels built serially before the subtrees (up to 2^ParallelLevels of them) are built in
// parallel: enough tasks to balance any number of threads the machine is likely to have.
constexpr int ParallelLevels = 6;
// Deep enough for any tree of median splits over 2^31 triangles, with room to spare.
constexpr int StackDepth = 96;
// A ray through a shared edge or vertex must not slip between the triangles that share it.
constexpr double EdgeTolerance = 1e-9;

// The parameter interval over which the ray is inside the box, clipped to [lo, hi]; false if
// empty. A direction component of 0 constrains nothing when the origin is in that slab.
bool Slabs(const float boxLo[3], const float boxHi[3], const double o[3], const double inv[3],
  const double d[3], double lo, double hi, double& t0, double& t1)
{
  t0 = lo;
  t1 = hi;
  for (int k = 0; k < 3; ++k)
  {
    if (d[k] == 0.0)
    {
      if (o[k] < boxLo[k] || o[k] > boxHi[k])
      {
        return false;
      }
      continue;
    }
    double a = (boxLo[k] - o[k]) * inv[k];
    double b = (boxHi[k] - o[k]) * inv[k];
    if (a > b)
    {
      std::swap(a, b);
    }
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

// The smallest |t| over [t0, t1].
double DistanceFromOrigin(double t0, double t1)
{
  return t0 > 0.0 ? t0 : (t1 < 0.0 ? -t1 : 0.0);
}

float Down(float v);
float Up(float v);

// The triangle's single-precision corners, their box widened by one ulp (every rounding of the
// slab arithmetic stays inside that margin) and its centroid; false if a corner is not finite.
bool PrepareTriangle(
  const double* points, const vtkIdType* ids, float v[9], float box[6], float centroid[3])
{
  bool finite = true;
  for (int c = 0; c < 3; ++c)
  {
    const double* p = points + 3 * ids[c];
    for (int k = 0; k < 3; ++k)
    {
      v[3 * c + k] = static_cast<float>(p[k]);
      finite = finite && std::isfinite(v[3 * c + k]);
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    box[k] = Down(std::min({ v[k], v[3 + k], v[6 + k] }));
    box[3 + k] = Up(std::max({ v[k], v[3 + k], v[6 + k] }));
    centroid[k] = (v[k] + v[3 + k] + v[6 + k]) / 3.0f;
  }
  return finite;
}

float Down(float v)
{
  return std::nextafter(v, -std::numeric_limits<float>::infinity());
}

float Up(float v)
{
  return std::nextafter(v, std::numeric_limits<float>::infinity());
}
} // namespace

//------------------------------------------------------------------------------
// Median splits down to LeafSize: the tree's shape depends only on the number of triangles, so
// every subtree's place in the depth-first node array is known before it is built, and the
// subtrees below the first levels are built in parallel into their own parts of the array.
// Items carry their centroids, so that the median selection reads no other array; boxes are
// set for leaves during the build and for inner nodes in one sweep afterwards.
struct TriangleBVH::Builder
{
  struct Item
  {
    float Centroid[3];
    int32_t Triangle;
  };
  struct Task
  {
    int32_t Index, Begin, End;
  };

  std::vector<Node>& Nodes;
  std::vector<Item> Items;
  const std::vector<float>& Boxes;
  std::map<int32_t, int32_t> SubtreeSizes; // filled before the parallel part, then only read

  int32_t SubtreeSize(int32_t n)
  {
    if (n <= LeafSize)
    {
      return 1;
    }
    auto known = this->SubtreeSizes.find(n);
    if (known != this->SubtreeSizes.end())
    {
      return known->second;
    }
    const int32_t size = 1 + this->SubtreeSize(n / 2) + this->SubtreeSize(n - n / 2);
    this->SubtreeSizes[n] = size;
    return size;
  }

  int32_t KnownSubtreeSize(int32_t n) const { return n <= LeafSize ? 1 : this->SubtreeSizes.at(n); }

  // Fills node @a index for items [begin, end); below @a serialLevels levels the subtrees go
  // to @a deferred instead (when given).
  void Build(
    int32_t index, int32_t begin, int32_t end, int serialLevels, std::vector<Task>* deferred)
  {
    if (deferred && serialLevels == 0)
    {
      deferred->push_back({ index, begin, end });
      return;
    }
    Node& node = this->Nodes[index];
    if (end - begin <= LeafSize)
    {
      this->MakeLeaf(begin, end, node);
      return;
    }
    const int axis = this->SplitAxis(begin, end);
    const int32_t mid = begin + (end - begin) / 2;
    // Ties broken by triangle index: the tree depends on the mesh alone.
    std::nth_element(this->Items.begin() + begin, this->Items.begin() + mid,
      this->Items.begin() + end,
      [axis](const Item& a, const Item& b)
      {
        return a.Centroid[axis] < b.Centroid[axis] ||
          (a.Centroid[axis] == b.Centroid[axis] && a.Triangle < b.Triangle);
      });
    const int32_t right = index + 1 + this->KnownSubtreeSize(mid - begin);
    node.First = right;
    node.Count = 0;
    this->Build(index + 1, begin, mid, serialLevels - 1, deferred);
    this->Build(right, mid, end, serialLevels - 1, deferred);
  }

  // The axis along which the centroids spread most.
  int SplitAxis(int32_t begin, int32_t end) const
  {
    float lo[3], hi[3];
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::numeric_limits<float>::infinity();
      hi[k] = -lo[k];
    }
    for (int32_t i = begin; i < end; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        lo[k] = std::min(lo[k], this->Items[i].Centroid[k]);
        hi[k] = std::max(hi[k], this->Items[i].Centroid[k]);
      }
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
    {
      axis = (hi[k] - lo[k]) > (hi[axis] - lo[axis]) ? k : axis;
    }
    return axis;
  }

  void MakeLeaf(int32_t begin, int32_t end, Node& node) const
  {
    node.First = begin;
    node.Count = end - begin;
    for (int k = 0; k < 3; ++k)
    {
      node.Lo[k] = std::numeric_limits<float>::infinity();
      node.Hi[k] = -node.Lo[k];
    }
    for (int32_t i = begin; i < end; ++i)
    {
      const float* box = this->Boxes.data() + 6 * static_cast<size_t>(this->Items[i].Triangle);
      for (int k = 0; k < 3; ++k)
      {
        node.Lo[k] = std::min(node.Lo[k], box[k]);
        node.Hi[k] = std::max(node.Hi[k], box[3 + k]);
      }
    }
  }

  // Children come after their parent in the depth-first array: one backward sweep.
  void InnerBoxes()
  {
    for (size_t i = this->Nodes.size(); i-- > 0;)
    {
      Node& node = this->Nodes[i];
      if (node.Count > 0)
      {
        continue;
      }
      const Node& left = this->Nodes[i + 1];
      const Node& right = this->Nodes[node.First];
      for (int k = 0; k < 3; ++k)
      {
        node.Lo[k] = std::min(left.Lo[k], right.Lo[k]);
        node.Hi[k] = std::max(left.Hi[k], right.Hi[k]);
      }
    }
  }
};

//------------------------------------------------------------------------------
void TriangleBVH::Build(const double* points, const vtkIdType* corners, vtkIdType numberOfTriangles)
{
  const size_t n = static_cast<size_t>(numberOfTriangles);
  std::vector<float> vertices(n * 9), boxes(n * 6), centroids(n * 3);
  std::vector<uint8_t> finite(n, 0);
  vtkSMPTools::For(0, numberOfTriangles,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType t = first; t < last; ++t)
      {
        finite[t] = PrepareTriangle(points, corners + 3 * t, vertices.data() + 9 * t,
          boxes.data() + 6 * t, centroids.data() + 3 * t);
      }
    });
  Builder builder{ this->Nodes, {}, boxes, {} };
  builder.Items.reserve(n);
  for (size_t t = 0; t < n; ++t)
  {
    if (finite[t])
    {
      const float* c = centroids.data() + 3 * t;
      builder.Items.push_back({ { c[0], c[1], c[2] }, static_cast<int32_t>(t) });
    }
  }
  this->Nodes.clear();
  this->Vertices.clear();
  this->Order.clear();
  if (builder.Items.empty())
  {
    return;
  }
  const int32_t count = static_cast<int32_t>(builder.Items.size());
  this->Nodes.resize(static_cast<size_t>(builder.SubtreeSize(count)));
  std::vector<Builder::Task> tasks;
  builder.Build(0, 0, count, ParallelLevels, &tasks);
  vtkSMPTools::For(0, static_cast<vtkIdType>(tasks.size()),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType k = first; k < last; ++k)
      {
        builder.Build(tasks[k].Index, tasks[k].Begin, tasks[k].End, -1, nullptr);
      }
    });
  builder.InnerBoxes();
  this->Vertices.resize(static_cast<size_t>(count) * 9);
  this->Order.resize(static_cast<size_t>(count));
  vtkSMPTools::For(0, static_cast<vtkIdType>(count),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType slot = first; slot < last; ++slot)
      {
        const int32_t t = builder.Items[slot].Triangle;
        this->Order[slot] = t;
        std::copy_n(
          vertices.data() + 9 * static_cast<size_t>(t), 9, this->Vertices.data() + 9 * slot);
      }
    });
}

//------------------------------------------------------------------------------
bool TriangleBVH::IntersectLeaf(const Node& node, const double o[3], const double d[3], double tLow,
  double tHigh, double& best, RayHit& hit) const
{
  bool found = false;
  for (int32_t slot = node.First; slot < node.First + node.Count; ++slot)
  {
    const float* v = this->Vertices.data() + 9 * static_cast<size_t>(slot);
    const double e1[3] = { v[3] - double(v[0]), v[4] - double(v[1]), v[5] - double(v[2]) };
    const double e2[3] = { v[6] - double(v[0]), v[7] - double(v[1]), v[8] - double(v[2]) };
    const double p[3] = { d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2],
      d[0] * e2[1] - d[1] * e2[0] };
    const double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (det == 0.0 || !std::isfinite(det))
    {
      continue;
    }
    const double inv = 1.0 / det;
    const double s[3] = { o[0] - v[0], o[1] - v[1], o[2] - v[2] };
    const double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) * inv;
    if (u < -EdgeTolerance || u > 1.0 + EdgeTolerance)
    {
      continue;
    }
    const double q[3] = { s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2],
      s[0] * e1[1] - s[1] * e1[0] };
    const double w = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) * inv;
    if (w < -EdgeTolerance || u + w > 1.0 + EdgeTolerance)
    {
      continue;
    }
    const double t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) * inv;
    const double at = std::abs(t);
    const vtkIdType id = this->Order[slot];
    if (t < tLow || t > tHigh || at > best ||
      (at == best && hit.Triangle >= 0 && id > hit.Triangle))
    {
      continue;
    }
    best = at;
    hit.Triangle = id;
    hit.T = t;
    hit.U = std::min(std::max(u, 0.0), 1.0);
    hit.V = std::min(std::max(w, 0.0), 1.0 - hit.U);
    found = true;
  }
  return found;
}

//------------------------------------------------------------------------------
bool TriangleBVH::Nearest(
  const double origin[3], const double direction[3], double tLow, double tHigh, RayHit& hit) const
{
  hit = RayHit();
  if (this->Nodes.empty() || !(tLow <= tHigh))
  {
    return false;
  }
  double inv[3];
  for (int k = 0; k < 3; ++k)
  {
    inv[k] = direction[k] != 0.0 ? 1.0 / direction[k] : 0.0;
  }
  double best = std::numeric_limits<double>::infinity();
  int32_t stackNode[StackDepth];
  double stackDist[StackDepth];
  int top = 0;
  double t0, t1;
  if (!Slabs(this->Nodes[0].Lo, this->Nodes[0].Hi, origin, inv, direction, tLow, tHigh, t0, t1))
  {
    return false;
  }
  stackNode[top] = 0;
  stackDist[top++] = DistanceFromOrigin(t0, t1);
  bool found = false;
  while (top > 0)
  {
    --top;
    if (stackDist[top] > best)
    {
      continue;
    }
    const Node& node = this->Nodes[stackNode[top]];
    if (node.Count > 0)
    {
      found = this->IntersectLeaf(node, origin, direction, tLow, tHigh, best, hit) || found;
      continue;
    }
    // Only hits nearer than the best so far matter: the interval narrows around 0.
    const double lo = std::max(tLow, -best), hi = std::min(tHigh, best);
    double dist[2];
    bool in[2];
    const int32_t children[2] = { stackNode[top] + 1, node.First };
    for (int c = 0; c < 2; ++c)
    {
      const Node& child = this->Nodes[children[c]];
      in[c] = Slabs(child.Lo, child.Hi, origin, inv, direction, lo, hi, t0, t1);
      dist[c] = in[c] ? DistanceFromOrigin(t0, t1) : 0.0;
    }
    // The farther child goes on the stack first, so that the nearer is searched first.
    const int nearer = (in[0] && in[1] && dist[1] < dist[0]) ? 1 : 0;
    for (int c : { 1 - nearer, nearer })
    {
      if (in[c] && top < StackDepth)
      {
        stackNode[top] = children[c];
        stackDist[top++] = dist[c];
      }
    }
  }
  return found;
}

} // namespace vtkSurfaceDetail
