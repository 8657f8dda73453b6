#include "vtkSurfaceDetailBVH.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vtkSurfaceDetail
{
namespace
{
constexpr int LeafSize = 4;
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
void TriangleBVH::Build(const double* points, const vtkIdType* corners, vtkIdType numberOfTriangles)
{
  this->Nodes.clear();
  this->Vertices.clear();
  this->Order.clear();
  std::vector<float> vertices(static_cast<size_t>(numberOfTriangles) * 9);
  std::vector<float> boxes(static_cast<size_t>(numberOfTriangles) * 6);
  std::vector<float> centroids(static_cast<size_t>(numberOfTriangles) * 3);
  std::vector<int32_t> items;
  items.reserve(static_cast<size_t>(numberOfTriangles));
  for (vtkIdType t = 0; t < numberOfTriangles; ++t)
  {
    float* v = vertices.data() + 9 * t;
    bool finite = true;
    for (int c = 0; c < 3; ++c)
    {
      const double* p = points + 3 * corners[3 * t + c];
      for (int k = 0; k < 3; ++k)
      {
        v[3 * c + k] = static_cast<float>(p[k]);
        finite = finite && std::isfinite(v[3 * c + k]);
      }
    }
    if (!finite)
    {
      continue;
    }
    // Boxes of the single-precision vertices, widened by one ulp: every rounding of the slab
    // arithmetic stays inside that margin.
    for (int k = 0; k < 3; ++k)
    {
      const float lo = std::min({ v[k], v[3 + k], v[6 + k] });
      const float hi = std::max({ v[k], v[3 + k], v[6 + k] });
      boxes[6 * t + k] = Down(lo);
      boxes[6 * t + 3 + k] = Up(hi);
      centroids[3 * t + k] = (v[k] + v[3 + k] + v[6 + k]) / 3.0f;
    }
    items.push_back(static_cast<int32_t>(t));
  }
  if (items.empty())
  {
    return;
  }
  this->Nodes.reserve(2 * (items.size() / LeafSize + 1));
  this->Nodes.emplace_back();
  const int32_t count = static_cast<int32_t>(items.size());
  this->BuildNode(0, items, centroids, boxes, 0, count);
  this->Vertices.resize(items.size() * 9);
  this->Order.resize(items.size());
  for (size_t slot = 0; slot < items.size(); ++slot)
  {
    std::copy_n(
      vertices.data() + 9 * static_cast<size_t>(items[slot]), 9, this->Vertices.data() + 9 * slot);
    this->Order[slot] = items[slot];
  }
}

//------------------------------------------------------------------------------
// Fills node @a index for items [begin, end); children are created in adjacent pairs.
void TriangleBVH::BuildNode(int32_t index, std::vector<int32_t>& items,
  const std::vector<float>& centroids, const std::vector<float>& boxes, int32_t begin, int32_t end)
{
  float lo[3], hi[3], clo[3], chi[3];
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = clo[k] = std::numeric_limits<float>::infinity();
    hi[k] = chi[k] = -std::numeric_limits<float>::infinity();
  }
  for (int32_t i = begin; i < end; ++i)
  {
    const size_t t = static_cast<size_t>(items[i]);
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], boxes[6 * t + k]);
      hi[k] = std::max(hi[k], boxes[6 * t + 3 + k]);
      clo[k] = std::min(clo[k], centroids[3 * t + k]);
      chi[k] = std::max(chi[k], centroids[3 * t + k]);
    }
  }
  Node node;
  std::copy_n(lo, 3, node.Lo);
  std::copy_n(hi, 3, node.Hi);
  int axis = 0;
  for (int k = 1; k < 3; ++k)
  {
    axis = (chi[k] - clo[k]) > (chi[axis] - clo[axis]) ? k : axis;
  }
  if (end - begin <= LeafSize || !(chi[axis] > clo[axis]))
  {
    node.First = begin;
    node.Count = end - begin;
    this->Nodes[index] = node;
    return;
  }
  const int32_t mid = begin + (end - begin) / 2;
  // Ties broken by triangle index: the tree depends on the mesh alone.
  std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
    [&](int32_t a, int32_t b)
    {
      const float ca = centroids[3 * static_cast<size_t>(a) + axis];
      const float cb = centroids[3 * static_cast<size_t>(b) + axis];
      return ca < cb || (ca == cb && a < b);
    });
  const int32_t left = static_cast<int32_t>(this->Nodes.size());
  node.First = left;
  node.Count = 0;
  this->Nodes[index] = node;
  this->Nodes.emplace_back();
  this->Nodes.emplace_back();
  this->BuildNode(left, items, centroids, boxes, begin, mid);
  this->BuildNode(left + 1, items, centroids, boxes, mid, end);
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
    for (int c = 0; c < 2; ++c)
    {
      const Node& child = this->Nodes[node.First + c];
      in[c] = Slabs(child.Lo, child.Hi, origin, inv, direction, lo, hi, t0, t1);
      dist[c] = in[c] ? DistanceFromOrigin(t0, t1) : 0.0;
    }
    // The farther child goes on the stack first, so that the nearer is searched first.
    const int nearer = (in[0] && in[1] && dist[1] < dist[0]) ? 1 : 0;
    for (int c : { 1 - nearer, nearer })
    {
      if (in[c] && top < StackDepth)
      {
        stackNode[top] = node.First + c;
        stackDist[top++] = dist[c];
      }
    }
  }
  return found;
}

} // namespace vtkSurfaceDetail
