// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNormalMapBaker.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMikkTSpaceTangents.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkSurfaceDetailBVH.h"
#include "vtkSurfaceDetailCells.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailProgress.h"
#include "vtkSurfaceDetailTangents.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkNormalMapBaker);

namespace
{
using namespace vtkSurfaceDetail;

// Texture sizes beyond this would need gigabytes of working memory: surely a mistake.
constexpr int MaxTextureSide = 65536;
constexpr double MaxTexels = double(1 << 28);
// How many triangles a warning names before it says "...".
constexpr size_t NamedTriangles = 5;
// A texel centre on an edge shared by two triangles belongs to both (no cracks); only one
// inside both by more than this (in barycentric units) is an overlap.
constexpr double CoverTolerance = 1e-9;
constexpr double OverlapMargin = 1e-6;

//------------------------------------------------------------------------------
// Triangles of a mesh and the cells they came from (polygons as fans, strips as strips).
struct TriangleList
{
  std::vector<vtkIdType> Corners; // 3 per triangle
  std::vector<vtkIdType> Cells;   // the mesh's cell id of each triangle
  vtkIdType Size() const { return static_cast<vtkIdType>(this->Cells.size()); }
};

TriangleList CollectTriangles(vtkPolyData* mesh)
{
  TriangleList list;
  // VTK numbers cells vertices first, then lines, polygons and strips.
  vtkIdType cellId = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  auto add = [&](vtkIdType a, vtkIdType b, vtkIdType c)
  {
    list.Corners.insert(list.Corners.end(), { a, b, c });
    list.Cells.push_back(cellId);
  };
  vtkIdType n;
  const vtkIdType* ids;
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cellId)
  {
    polys->GetCurrentCell(n, ids);
    for (vtkIdType k = 2; k < n; ++k)
    {
      add(ids[0], ids[k - 1], ids[k]);
    }
  }
  auto strips = vtk::TakeSmartPointer(mesh->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cellId)
  {
    strips->GetCurrentCell(n, ids);
    for (vtkIdType k = 2; k < n; ++k)
    {
      // Every other triangle of a strip is wound the other way round.
      if (k % 2 == 0)
      {
        add(ids[k - 2], ids[k - 1], ids[k]);
      }
      else
      {
        add(ids[k - 1], ids[k - 2], ids[k]);
      }
    }
  }
  return list;
}

std::vector<double> Tuples(vtkDataArray* array, int components)
{
  const vtkIdType n = array->GetNumberOfTuples();
  std::vector<double> values(static_cast<size_t>(n) * components, 0.0);
  const int have = std::min(components, array->GetNumberOfComponents());
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        for (int c = 0; c < have; ++c)
        {
          values[i * components + c] = array->GetComponent(i, c);
        }
      }
    });
  return values;
}

vtkDataArray* TangentArray(vtkPolyData* mesh)
{
  vtkDataArray* t = mesh->GetPointData()->GetTangents();
  return t && t->GetNumberOfTuples() == mesh->GetNumberOfPoints() ? t : nullptr;
}

vtkDataArray* NormalArray(vtkPolyData* mesh)
{
  vtkDataArray* n = mesh->GetPointData()->GetNormals();
  return n && n->GetNumberOfComponents() == 3 && n->GetNumberOfTuples() == mesh->GetNumberOfPoints()
    ? n
    : nullptr;
}

std::string NameCells(const std::vector<vtkIdType>& cells, size_t total)
{
  std::ostringstream names;
  for (size_t k = 0; k < cells.size(); ++k)
  {
    names << (k ? ", " : "") << cells[k];
  }
  if (total > cells.size())
  {
    names << ", ...";
  }
  return names.str();
}

//------------------------------------------------------------------------------
// The coarse mesh as the rays need it: positions, unit normals and the per-vertex frame that
// vtkSurfaceDetailMapper's vertex shader builds, and each triangle's texture-space
// barycentric map.
struct CoarseMesh
{
  std::vector<double> Points, Normals, Tangents, Bitangents, UV;
  TriangleList Triangles;
  // Per triangle: b1 = A[0] + A[1]*s + A[2]*t, b2 = A[3] + A[4]*s + A[5]*t; empty (NaN) when
  // the triangle has no area in texture space.
  std::vector<double> Barycentric;

  void Prepare(vtkPolyData* mesh);
  void Interpolate(
    vtkIdType tri, const double b[3], double p[3], double n[3], double t[3], double bt[3]) const;
};

void CoarseMesh::Prepare(vtkPolyData* mesh)
{
  this->Points = Tuples(mesh->GetPoints()->GetData(), 3);
  this->Normals = Tuples(NormalArray(mesh), 3);
  const std::vector<double> tangents = Tuples(TangentArray(mesh), 3);
  // Without a handedness array, w = +1 (as VTK's own normal mapping takes it).
  vtkDataArray* handedness = vtkSurfaceDetailTangents::GetHandedness(mesh->GetPointData());
  const std::vector<double> w = handedness ? Tuples(handedness, 1) : std::vector<double>();
  this->UV = Tuples(mesh->GetPointData()->GetTCoords(), 2);
  const vtkIdType n = mesh->GetNumberOfPoints();
  this->Tangents.assign(3 * n, 0.0);
  this->Bitangents.assign(3 * n, 0.0);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double* nn = &this->Normals[3 * i];
        if (Normalize(nn) == 0.0)
        {
          nn[2] = 1.0;
        }
        // As the mapper's vertex shader: T loses its part along N, B = w*cross(N, T).
        double* t = &this->Tangents[3 * i];
        const double* raw = &tangents[3 * i];
        const double along = Dot(nn, raw);
        for (int k = 0; k < 3; ++k)
        {
          t[k] = raw[k] - along * nn[k];
        }
        if (!(Normalize(t) > 0.0))
        {
          t[0] = t[1] = t[2] = 0.0;
        }
        double* bt = &this->Bitangents[3 * i];
        Cross(nn, t, bt);
        const double sign = (!w.empty() && w[i] < 0.0) ? -1.0 : 1.0;
        for (int k = 0; k < 3; ++k)
        {
          bt[k] *= sign;
        }
      }
    });
  this->Triangles = CollectTriangles(mesh);
  const vtkIdType nt = this->Triangles.Size();
  this->Barycentric.assign(6 * nt, std::numeric_limits<double>::quiet_NaN());
  for (vtkIdType tri = 0; tri < nt; ++tri)
  {
    const double* a = &this->UV[2 * this->Triangles.Corners[3 * tri]];
    const double* b = &this->UV[2 * this->Triangles.Corners[3 * tri + 1]];
    const double* c = &this->UV[2 * this->Triangles.Corners[3 * tri + 2]];
    const double ab[2] = { b[0] - a[0], b[1] - a[1] }, ac[2] = { c[0] - a[0], c[1] - a[1] };
    const double den = ab[0] * ac[1] - ab[1] * ac[0];
    if (den == 0.0 || !std::isfinite(den))
    {
      continue;
    }
    // b1 = cross(p - a, ac)/den, b2 = cross(ab, p - a)/den, written as affine maps of (s, t).
    double* m = &this->Barycentric[6 * tri];
    m[1] = ac[1] / den;
    m[2] = -ac[0] / den;
    m[0] = -(a[0] * m[1] + a[1] * m[2]);
    m[4] = -ab[1] / den;
    m[5] = ab[0] / den;
    m[3] = -(a[0] * m[4] + a[1] * m[5]);
  }
}

void CoarseMesh::Interpolate(
  vtkIdType tri, const double b[3], double p[3], double n[3], double t[3], double bt[3]) const
{
  for (int k = 0; k < 3; ++k)
  {
    p[k] = n[k] = t[k] = bt[k] = 0.0;
  }
  for (int c = 0; c < 3; ++c)
  {
    const vtkIdType id = this->Triangles.Corners[3 * tri + c];
    for (int k = 0; k < 3; ++k)
    {
      p[k] += b[c] * this->Points[3 * id + k];
      n[k] += b[c] * this->Normals[3 * id + k];
      t[k] += b[c] * this->Tangents[3 * id + k];
      bt[k] += b[c] * this->Bitangents[3 * id + k];
    }
  }
  // The fragment shader normalises the interpolated normal, not the tangent or bitangent.
  Normalize(n);
}

//------------------------------------------------------------------------------
// The detailed mesh: its triangles in a hierarchy, and the normal at any hit.
struct DetailedMesh
{
  std::vector<double> Points, PointNormals;
  TriangleList Triangles;
  TriangleBVH Hierarchy;

  void Prepare(vtkPolyData* mesh);
  void NormalAt(const RayHit& hit, double n[3]) const;
};

void DetailedMesh::Prepare(vtkPolyData* mesh)
{
  this->Points = Tuples(mesh->GetPoints()->GetData(), 3);
  vtkDataArray* normals = NormalArray(mesh);
  this->PointNormals = normals ? Tuples(normals, 3) : std::vector<double>();
  this->Triangles = CollectTriangles(mesh);
  this->Hierarchy.Build(
    this->Points.data(), this->Triangles.Corners.data(), this->Triangles.Size());
}

void DetailedMesh::NormalAt(const RayHit& hit, double n[3]) const
{
  const vtkIdType* ids = &this->Triangles.Corners[3 * hit.Triangle];
  if (!this->PointNormals.empty())
  {
    const double w[3] = { 1.0 - hit.U - hit.V, hit.U, hit.V };
    for (int k = 0; k < 3; ++k)
    {
      n[k] = w[0] * this->PointNormals[3 * ids[0] + k] + w[1] * this->PointNormals[3 * ids[1] + k] +
        w[2] * this->PointNormals[3 * ids[2] + k];
    }
    if (Normalize(n) > 0.0 && std::isfinite(n[0] + n[1] + n[2]))
    {
      return;
    }
  }
  const double* a = &this->Points[3 * ids[0]];
  const double* b = &this->Points[3 * ids[1]];
  const double* c = &this->Points[3 * ids[2]];
  const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double ac[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  Cross(ab, ac, n);
  Normalize(n);
}

//------------------------------------------------------------------------------
// What the rays found, per texel.
enum TexelState : uint8_t
{
  Empty = 0,  // no coarse triangle covers the centre
  Hit = 1,    // baked
  Missed = 2, // covered, but no hit within reach
  Filled = 3  // given its neighbours' mean
};

struct BakeBuffers
{
  int W = 0, H = 0;
  std::vector<float> Normal; // 3 per texel
  std::vector<float> Height;
  std::vector<uint8_t> State;

  BakeBuffers(int w, int h)
    : W(w)
    , H(h)
    , Normal(size_t(w) * h * 3, 0.0f)
    , Height(size_t(w) * h, 0.0f)
    , State(size_t(w) * h, Empty)
  {
  }
};

struct RowReport
{
  vtkIdType Overlaps = 0;
  vtkIdType FirstTriangle = -1, SecondTriangle = -1;
};

// Coarse triangles by the texel rows whose centre lines their texture-space bounds cross.
struct RowBuckets
{
  std::vector<vtkIdType> Offsets; // H + 1
  std::vector<vtkIdType> Triangles;

  void Build(const CoarseMesh& mesh, int H);
};

void RowBuckets::Build(const CoarseMesh& mesh, int H)
{
  const vtkIdType nt = mesh.Triangles.Size();
  std::vector<int> first(nt, 0), last(nt, -1);
  this->Offsets.assign(static_cast<size_t>(H) + 1, 0);
  for (vtkIdType tri = 0; tri < nt; ++tri)
  {
    if (std::isnan(mesh.Barycentric[6 * tri]))
    {
      continue;
    }
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int c = 0; c < 3; ++c)
    {
      const double t = mesh.UV[2 * mesh.Triangles.Corners[3 * tri + c] + 1];
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    // Rows whose centre (j + 0.5)/H lies in [lo, hi], a little widened for rounding; clamped
    // in floating point first, as coordinates far outside [0,1] would overflow an int.
    first[tri] =
      static_cast<int>(std::min(std::max(0.0, std::ceil(lo * H - 0.5 - 1e-6)), double(H)));
    last[tri] =
      static_cast<int>(std::max(std::min(H - 1.0, std::floor(hi * H - 0.5 + 1e-6)), -1.0));
    for (int j = first[tri]; j <= last[tri]; ++j)
    {
      ++this->Offsets[j + 1];
    }
  }
  for (int j = 0; j < H; ++j)
  {
    this->Offsets[j + 1] += this->Offsets[j];
  }
  this->Triangles.resize(static_cast<size_t>(this->Offsets[H]));
  std::vector<vtkIdType> fill(this->Offsets.begin(), this->Offsets.end() - 1);
  for (vtkIdType tri = 0; tri < nt; ++tri) // in triangle order: the lower id comes first
  {
    for (int j = first[tri]; j <= last[tri]; ++j)
    {
      this->Triangles[fill[j]++] = tri;
    }
  }
}

//------------------------------------------------------------------------------
struct BakeSettings
{
  double MaxRayDistance = 0.0;
  double CageOffset = 0.0;
  bool TangentSpace = true;
};

// The ray pass: one texel row per iteration, texels owned by the first triangle covering
// their centre; every texel's result depends on the inputs only.
struct CastRows
{
  const CoarseMesh& Coarse;
  const DetailedMesh& Detailed;
  const RowBuckets& Rows;
  BakeBuffers& Out;
  std::vector<RowReport>& Reports;
  BakeSettings Settings;
  vtkSurfaceDetail::Progress& Progress;

  struct Scratch
  {
    std::vector<vtkIdType> Owner;
    std::vector<double> Inside; // the owner's smallest barycentric coordinate
  };
  vtkSMPThreadLocal<Scratch> Local;

  CastRows(const CoarseMesh& c, const DetailedMesh& d, const RowBuckets& r, BakeBuffers& o,
    std::vector<RowReport>& reports, const BakeSettings& settings,
    vtkSurfaceDetail::Progress& progress)
    : Coarse(c)
    , Detailed(d)
    , Rows(r)
    , Out(o)
    , Reports(reports)
    , Settings(settings)
    , Progress(progress)
  {
  }

  void Initialize()
  {
    Scratch& s = this->Local.Local();
    s.Owner.resize(this->Out.W);
    s.Inside.resize(this->Out.W);
  }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    Scratch& s = this->Local.Local();
    for (vtkIdType j = begin; j < end && !this->Progress.Aborted(); ++j)
    {
      this->Rasterise(static_cast<int>(j), s);
      for (int i = 0; i < this->Out.W; ++i)
      {
        if (s.Owner[i] >= 0)
        {
          this->BakeTexel(i, static_cast<int>(j), s.Owner[i]);
        }
      }
      this->Progress.Advance(1);
    }
  }

  void Reduce() {}

  void Barycentric(vtkIdType tri, double s, double t, double b[3]) const
  {
    const double* m = &this->Coarse.Barycentric[6 * tri];
    b[1] = m[0] + m[1] * s + m[2] * t;
    b[2] = m[3] + m[4] * s + m[5] * t;
    b[0] = 1.0 - b[1] - b[2];
  }

  // Which triangle owns each texel of row j; overlaps go to the row's report.
  void Rasterise(int j, Scratch& s)
  {
    const int W = this->Out.W;
    std::fill(s.Owner.begin(), s.Owner.end(), -1);
    const double t = TexelCentre(j, this->Out.H);
    RowReport& report = this->Reports[j];
    for (vtkIdType k = this->Rows.Offsets[j]; k < this->Rows.Offsets[j + 1]; ++k)
    {
      const vtkIdType tri = this->Rows.Triangles[k];
      int i0, i1;
      this->Span(tri, t, i0, i1);
      for (int i = std::max(i0, 0); i <= std::min(i1, W - 1); ++i)
      {
        double b[3];
        this->Barycentric(tri, TexelCentre(i, W), t, b);
        const double inside = std::min({ b[0], b[1], b[2] });
        if (!(inside >= -CoverTolerance))
        {
          continue;
        }
        if (s.Owner[i] < 0)
        {
          s.Owner[i] = tri;
          s.Inside[i] = inside;
        }
        else if (inside > OverlapMargin && s.Inside[i] > OverlapMargin)
        {
          if (report.Overlaps++ == 0)
          {
            report.FirstTriangle = s.Owner[i];
            report.SecondTriangle = tri;
          }
        }
      }
    }
  }

  // The texel columns whose centres may lie in triangle tri on the row at t.
  void Span(vtkIdType tri, double t, int& i0, int& i1) const
  {
    const double* m = &this->Coarse.Barycentric[6 * tri];
    // Each coordinate is a + c*s along the row; inside where all three are >= 0.
    const double a[3] = { 1.0 - m[0] - m[3] - (m[2] + m[5]) * t, m[0] + m[2] * t, m[3] + m[5] * t };
    const double c[3] = { -m[1] - m[4], m[1], m[4] };
    double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
    for (int k = 0; k < 3; ++k)
    {
      if (c[k] > 0.0)
      {
        lo = std::max(lo, -a[k] / c[k]);
      }
      else if (c[k] < 0.0)
      {
        hi = std::min(hi, -a[k] / c[k]);
      }
      else if (a[k] < -CoverTolerance)
      {
        hi = lo - 1.0;
      }
    }
    const int W = this->Out.W;
    // One texel of slack each way; the exact test in Rasterise decides. Clamped first: an int
    // cannot hold what a sliver of a triangle far outside [0,1] gives.
    lo = std::min(std::max(lo, -1.0), 2.0);
    hi = std::min(std::max(hi, -1.0), 2.0);
    i0 = static_cast<int>(std::floor(lo * W - 0.5));
    i1 = static_cast<int>(std::ceil(hi * W - 0.5));
    if (!(lo <= hi))
    {
      i1 = i0 - 1;
    }
  }

  void BakeTexel(int i, int j, vtkIdType tri)
  {
    double b[3], p[3], n[3], t[3], bt[3];
    this->Barycentric(tri, TexelCentre(i, this->Out.W), TexelCentre(j, this->Out.H), b);
    this->Coarse.Interpolate(tri, b, p, n, t, bt);
    const size_t texel = static_cast<size_t>(j) * this->Out.W + i;
    RayHit hit;
    double height = 0.0;
    if (!this->Cast(p, n, hit, height))
    {
      this->Out.State[texel] = Missed;
      return;
    }
    double detail[3], stored[3];
    this->Detailed.NormalAt(hit, detail);
    if (this->Settings.TangentSpace)
    {
      ToFrame(detail, t, bt, n, stored);
    }
    else
    {
      std::copy_n(detail, 3, stored);
    }
    if (!std::isfinite(stored[0] + stored[1] + stored[2] + height))
    {
      this->Out.State[texel] = Missed;
      return;
    }
    std::copy_n(stored, 3, &this->Out.Normal[3 * texel]);
    this->Out.Height[texel] = static_cast<float>(height);
    this->Out.State[texel] = Hit;
  }

  // Both ways from the surface, nearest hit; or inwards from the cage, first hit.
  bool Cast(const double p[3], const double n[3], RayHit& hit, double& height) const
  {
    const double cage = this->Settings.CageOffset, reach = this->Settings.MaxRayDistance;
    if (cage > 0.0)
    {
      const double o[3] = { p[0] + cage * n[0], p[1] + cage * n[1], p[2] + cage * n[2] };
      const double d[3] = { -n[0], -n[1], -n[2] };
      if (!this->Detailed.Hierarchy.Nearest(o, d, 0.0, cage + reach, hit))
      {
        return false;
      }
      height = cage - hit.T;
      return true;
    }
    if (!this->Detailed.Hierarchy.Nearest(p, n, -reach, reach, hit))
    {
      return false;
    }
    height = hit.T;
    return true;
  }

  // The coordinates x with normalize(x0*T + x1*B + x2*N) = v, normalised (Cramer's rule).
  static void ToFrame(
    const double v[3], const double t[3], const double b[3], const double n[3], double x[3])
  {
    double bxn[3], vxn[3], bxv[3];
    Cross(b, n, bxn);
    Cross(v, n, vxn);
    Cross(b, v, bxv);
    const double det = Dot(t, bxn);
    if (std::abs(det) > 1e-12)
    {
      x[0] = Dot(v, bxn) / det;
      x[1] = Dot(t, vxn) / det;
      x[2] = Dot(t, bxv) / det;
    }
    else
    {
      // A frame without a tangent (the mesh's tangents are degenerate here): the normal map
      // can only tilt along N.
      x[0] = 0.0;
      x[1] = 0.0;
      x[2] = Dot(v, n);
    }
    if (!(Normalize(x) > 0.0))
    {
      x[0] = x[1] = 0.0;
      x[2] = 1.0;
    }
  }
};

//------------------------------------------------------------------------------
// One ring of growth: every texel in state @a from with a neighbour in state Hit or Filled
// takes their mean (normal renormalised) and becomes Filled. Reads only texels that were
// already known before the pass, so rows can run in any order. Returns how many changed.
vtkIdType GrowOnce(BakeBuffers& buf, uint8_t from)
{
  const int W = buf.W, H = buf.H;
  std::vector<uint8_t> next(buf.State);
  std::vector<vtkIdType> changed(H, 0);
  vtkSMPTools::For(0, H,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType j = begin; j < end; ++j)
      {
        for (int i = 0; i < W; ++i)
        {
          const size_t texel = static_cast<size_t>(j) * W + i;
          if (buf.State[texel] != from)
          {
            continue;
          }
          double sum[3] = { 0.0, 0.0, 0.0 }, height = 0.0;
          int count = 0;
          for (int dj = -1; dj <= 1; ++dj)
          {
            for (int di = -1; di <= 1; ++di)
            {
              const int ii = i + di, jj = static_cast<int>(j) + dj;
              if (ii < 0 || jj < 0 || ii >= W || jj >= H)
              {
                continue;
              }
              const size_t other = static_cast<size_t>(jj) * W + ii;
              if (buf.State[other] == Hit || buf.State[other] == Filled)
              {
                for (int k = 0; k < 3; ++k)
                {
                  sum[k] += buf.Normal[3 * other + k];
                }
                height += buf.Height[other];
                ++count;
              }
            }
          }
          if (count == 0)
          {
            continue;
          }
          if (!(Normalize(sum) > 0.0))
          {
            sum[0] = sum[1] = 0.0;
            sum[2] = 1.0;
          }
          for (int k = 0; k < 3; ++k)
          {
            buf.Normal[3 * texel + k] = static_cast<float>(sum[k]);
          }
          buf.Height[texel] = static_cast<float>(height / count);
          next[texel] = Filled;
          ++changed[j];
        }
      }
    });
  buf.State.swap(next);
  vtkIdType total = 0;
  for (vtkIdType c : changed)
  {
    total += c;
  }
  return total;
}

// Missed texels from their neighbours, ring by ring until none is left that can be reached;
// those that cannot (an island no ray hit) keep @a flat.
void FillMissed(BakeBuffers& buf, const float flat[3])
{
  while (GrowOnce(buf, Missed) > 0)
  {
  }
  for (size_t texel = 0; texel < buf.State.size(); ++texel)
  {
    if (buf.State[texel] == Missed)
    {
      std::copy_n(flat, 3, &buf.Normal[3 * texel]);
      buf.State[texel] = Filled;
    }
  }
}

void GrowMargin(BakeBuffers& buf, int margin)
{
  for (int ring = 0; ring < margin && GrowOnce(buf, Empty) > 0; ++ring)
  {
  }
}

//------------------------------------------------------------------------------
template <typename T>
T Quantise(double c)
{
  if (std::is_floating_point<T>::value)
  {
    return static_cast<T>(c);
  }
  const double top = static_cast<double>(std::numeric_limits<T>::max());
  return static_cast<T>(std::lround(std::min(std::max(c, 0.0), 1.0) * top));
}

template <typename T>
void Encode(const BakeBuffers& buf, const float background[3], bool greenUp, T* out)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(buf.State.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType texel = begin; texel < end; ++texel)
      {
        double n[3], rgb[3];
        const float* src = buf.State[texel] == Empty ? background : &buf.Normal[3 * texel];
        std::copy_n(src, 3, n);
        EncodeNormal(n, greenUp, rgb);
        for (int k = 0; k < 3; ++k)
        {
          out[3 * texel + k] = Quantise<T>(rgb[k]);
        }
      }
    });
}

void ShapeImage(vtkImageData* image, int W, int H)
{
  image->SetExtent(0, W - 1, 0, H - 1, 0, 0);
  image->SetSpacing(1.0 / W, 1.0 / H, 1.0);
  image->SetOrigin(0.5 / W, 0.5 / H, 0.0);
}

//------------------------------------------------------------------------------

struct CastSummary
{
  vtkIdType Covered = 0, Unhit = 0, Overlapping = 0;
  std::vector<vtkIdType> OverlapCells; // a few of the cells involved, for the warning
};

CastSummary CastRays(const CoarseMesh& coarse, const DetailedMesh& detailed,
  const BakeSettings& settings, BakeBuffers& buffers, vtkSurfaceDetail::Progress& progress)
{
  RowBuckets rows;
  rows.Build(coarse, buffers.H);
  std::vector<RowReport> reports(buffers.H);
  CastRows cast(coarse, detailed, rows, buffers, reports, settings, progress);
  vtkSMPTools::For(0, buffers.H, cast);

  CastSummary summary;
  for (uint8_t state : buffers.State)
  {
    summary.Covered += state != Empty;
    summary.Unhit += state == Missed;
  }
  std::vector<vtkIdType>& named = summary.OverlapCells;
  for (const RowReport& r : reports)
  {
    summary.Overlapping += r.Overlaps;
    for (vtkIdType tri : { r.FirstTriangle, r.SecondTriangle })
    {
      const vtkIdType cell = tri >= 0 ? coarse.Triangles.Cells[tri] : -1;
      if (cell >= 0 && named.size() < 2 * NamedTriangles &&
        std::find(named.begin(), named.end(), cell) == named.end())
      {
        named.push_back(cell);
      }
    }
  }
  return summary;
}

// The warning about texture coordinates outside the unit square, or "" if there are none.
std::string OutsideUnitSquare(const std::vector<double>& uv, const TriangleList& triangles)
{
  std::vector<vtkIdType> named;
  size_t outside = 0;
  vtkIdType lastCell = -1;
  for (vtkIdType tri = 0; tri < triangles.Size(); ++tri)
  {
    bool out = false;
    for (int c = 0; c < 3; ++c)
    {
      const double* st = &uv[2 * triangles.Corners[3 * tri + c]];
      out = out || !(st[0] >= 0.0 && st[0] <= 1.0 && st[1] >= 0.0 && st[1] <= 1.0);
    }
    const vtkIdType cell = triangles.Cells[tri];
    if (out && cell != lastCell)
    {
      lastCell = cell;
      ++outside;
      if (named.size() < NamedTriangles)
      {
        named.push_back(cell);
      }
    }
  }
  if (outside == 0)
  {
    return std::string();
  }
  std::ostringstream message;
  message << outside << " cells of the coarse mesh have texture coordinates outside [0,1] (cells "
          << NameCells(named, outside) << "); their parts outside the unit square are not baked.";
  return message.str();
}

void WriteNormalMap(const BakeBuffers& buffers, const float background[3], bool greenUp, int type,
  vtkImageData* image)
{
  ShapeImage(image, buffers.W, buffers.H);
  auto array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
  array->SetName("NormalMap");
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(buffers.State.size()));
  switch (type)
  {
    case VTK_UNSIGNED_SHORT:
      Encode(buffers, background, greenUp, static_cast<unsigned short*>(array->GetVoidPointer(0)));
      break;
    case VTK_FLOAT:
      Encode(buffers, background, greenUp, static_cast<float*>(array->GetVoidPointer(0)));
      break;
    default:
      Encode(buffers, background, greenUp, static_cast<unsigned char*>(array->GetVoidPointer(0)));
  }
  image->GetPointData()->SetScalars(array);
}

void WriteHeightMap(const BakeBuffers& buffers, vtkImageData* image)
{
  ShapeImage(image, buffers.W, buffers.H);
  vtkNew<vtkFloatArray> heights;
  heights->SetName("Height");
  heights->SetNumberOfValues(static_cast<vtkIdType>(buffers.Height.size()));
  std::copy(buffers.Height.begin(), buffers.Height.end(), heights->GetPointer(0));
  image->GetPointData()->SetScalars(heights);
}

} // namespace

//------------------------------------------------------------------------------
vtkNormalMapBaker::vtkNormalMapBaker()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkImageData* vtkNormalMapBaker::GetHeightOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
const char* vtkNormalMapBaker::GetSpaceAsString()
{
  return this->Space == Object ? "Object" : "Tangent";
}

//------------------------------------------------------------------------------
void vtkNormalMapBaker::SetOutputScalarType(int type)
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
int vtkNormalMapBaker::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkNormalMapBaker::SetSourceData(vtkPolyData* detailed)
{
  this->SetInputData(1, detailed);
}

//------------------------------------------------------------------------------
int vtkNormalMapBaker::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const int W = std::max(this->TextureSize[0], 0), H = std::max(this->TextureSize[1], 0);
  const int extent[6] = { 0, W - 1, 0, H - 1, 0, W > 0 && H > 0 ? 0 : -1 };
  // Without BakeHeight the height map is not made: its port says so with an empty extent, so
  // that a filter downstream does not expect a W x H image.
  const int none[6] = { 0, -1, 0, -1, 0, -1 };
  const double spacing[3] = { W > 0 ? 1.0 / W : 1.0, H > 0 ? 1.0 / H : 1.0, 1.0 };
  const double origin[3] = { 0.5 * spacing[0], 0.5 * spacing[1], 0.0 };
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(),
      port == 1 && !this->BakeHeight ? none : extent, 6);
    info->Set(vtkDataObject::SPACING(), spacing, 3);
    info->Set(vtkDataObject::ORIGIN(), origin, 3);
  }
  vtkDataObject::SetPointDataActiveScalarInfo(
    outputVector->GetInformationObject(0), this->OutputScalarType, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outputVector->GetInformationObject(1), VTK_FLOAT, 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkNormalMapBaker::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every ray may reach any part of either mesh: both are needed whole.
  for (int port = 0; port < 2; ++port)
  {
    if (vtkInformation* info = inputVector[port]->GetInformationObject(0))
    {
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkNormalMapBaker::CheckInputs(vtkPolyData* coarse, vtkPolyData* detailed)
{
  const int W = this->TextureSize[0], H = this->TextureSize[1];
  if (W < 1 || H < 1 || W > MaxTextureSide || H > MaxTextureSide || double(W) * H > MaxTexels)
  {
    vtkErrorMacro("TextureSize " << W << " x " << H << " is not usable: each side must be in [1, "
                                 << MaxTextureSide << "] and the map at most 2^28 texels.");
    return false;
  }
  if (!(this->MaxRayDistance > 0.0) || !std::isfinite(this->MaxRayDistance) ||
    !std::isfinite(this->CageOffset))
  {
    vtkErrorMacro("MaxRayDistance must be positive and finite (it is "
      << this->MaxRayDistance << "), and CageOffset finite (" << this->CageOffset << ").");
    return false;
  }
  const char* names[2] = { "coarse mesh (port 0)", "detailed mesh (port 1)" };
  vtkPolyData* meshes[2] = { coarse, detailed };
  for (int k = 0; k < 2; ++k)
  {
    vtkPolyData* mesh = meshes[k];
    if (!mesh || !mesh->GetPoints() || mesh->GetNumberOfPoints() == 0 ||
      mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() == 0)
    {
      vtkErrorMacro(
        "The " << names[k] << " has no polygons or triangle strips: give it a surface.");
      return false;
    }
    const vtkIdType n = mesh->GetNumberOfPoints();
    if (!vtkSurfaceDetailCells::PointIdsInRange(mesh->GetPolys(), n) ||
      !vtkSurfaceDetailCells::PointIdsInRange(mesh->GetStrips(), n))
    {
      vtkErrorMacro("A polygon or strip of the " << names[k] << " names a point id outside [0, "
                                                 << n << "); fix its connectivity first.");
      return false;
    }
  }
  if (detailed->GetPolys()->GetNumberOfConnectivityIds() +
      detailed->GetStrips()->GetNumberOfConnectivityIds() >=
    VTK_INT_MAX)
  {
    vtkErrorMacro("The detailed mesh has more than 2^31 triangles; split it first.");
    return false;
  }
  vtkDataArray* tcoords = coarse->GetPointData()->GetTCoords();
  if (!tcoords || tcoords->GetNumberOfComponents() < 2 ||
    tcoords->GetNumberOfTuples() != coarse->GetNumberOfPoints())
  {
    vtkErrorMacro("The coarse mesh (port 0) has no 2-component point texture coordinates: the "
                  "map is laid out by them (set them as the point data's TCoords).");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkNormalMapBaker::WithTangentFrame(vtkPolyData* coarse)
{
  if (NormalArray(coarse) && TangentArray(coarse))
  {
    const std::string problem =
      vtkSurfaceDetailTangents::GetHandednessProblem(coarse->GetPointData());
    if (!problem.empty())
    {
      vtkWarningMacro(<< problem);
    }
    return coarse;
  }
  vtkWarningMacro("The coarse mesh has no point normals or no tangents; computing "
                  "them with vtkMikkTSpaceTangents. Render that filter's output with the map: "
                  "the map is right only with the frame it was baked against.");
  vtkNew<vtkPolyData> copy;
  copy->ShallowCopy(coarse);
  vtkNew<vtkMikkTSpaceTangents> tangents;
  tangents->SetInputData(copy);
  tangents->Update();
  vtkPolyData* framed = tangents->GetOutput();
  if (framed->GetNumberOfPoints() == 0 || !NormalArray(framed) || !TangentArray(framed))
  {
    vtkErrorMacro("vtkMikkTSpaceTangents could not give the coarse mesh a tangent frame.");
    return nullptr;
  }
  return framed;
}

//------------------------------------------------------------------------------
int vtkNormalMapBaker::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* normalMap = vtkImageData::GetData(outputVector, 0);
  vtkImageData* heightMap = vtkImageData::GetData(outputVector, 1);
  normalMap->Initialize();
  heightMap->Initialize();
  this->NumberOfCoveredTexels = this->NumberOfUnhitTexels = this->NumberOfOverlappingTexels = 0;
  vtkPolyData* coarseInput = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* detailedInput = vtkPolyData::GetData(inputVector[1]);
  if (!this->CheckInputs(coarseInput, detailedInput))
  {
    return 0;
  }
  vtkSmartPointer<vtkPolyData> framed = this->WithTangentFrame(coarseInput);
  if (!framed)
  {
    return 0;
  }
  const int W = this->TextureSize[0], H = this->TextureSize[1];

  CoarseMesh coarse;
  coarse.Prepare(framed);
  const std::string outside = OutsideUnitSquare(coarse.UV, coarse.Triangles);
  if (!outside.empty())
  {
    vtkWarningMacro(<< outside);
  }
  DetailedMesh detailed;
  detailed.Prepare(detailedInput);
  this->UpdateProgress(0.2);

  BakeBuffers buffers(W, H);
  BakeSettings settings;
  settings.MaxRayDistance = this->MaxRayDistance;
  settings.CageOffset = this->CageOffset;
  settings.TangentSpace = this->Space == Tangent;
  vtkSurfaceDetail::Progress progress(this, 0.2, 0.9, H);
  const CastSummary found = CastRays(coarse, detailed, settings, buffers, progress);
  if (progress.Aborted())
  {
    // Stopped by the user (AbortExecute): no error, and no half-baked maps.
    normalMap->Initialize();
    heightMap->Initialize();
    return 1;
  }
  this->ReportFindings(found.Covered, found.Unhit, found.Overlapping, found.OverlapCells);

  const float flat[3] = { 0.0f, 0.0f, settings.TangentSpace ? 1.0f : 0.0f };
  FillMissed(buffers, flat);
  GrowMargin(buffers, this->Margin);

  // Green down is a tangent-space convention; object-space maps hold the normal as it is.
  const bool greenUp = this->GreenUp || !settings.TangentSpace;
  WriteNormalMap(buffers, flat, greenUp, this->OutputScalarType, normalMap);
  if (this->BakeHeight)
  {
    WriteHeightMap(buffers, heightMap);
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkNormalMapBaker::ReportFindings(vtkIdType covered, vtkIdType unhit, vtkIdType overlapping,
  const std::vector<vtkIdType>& overlapCells)
{
  this->NumberOfCoveredTexels = covered;
  this->NumberOfUnhitTexels = unhit;
  this->NumberOfOverlappingTexels = overlapping;
  if (overlapping > 0)
  {
    vtkWarningMacro(<< overlapping
                    << " texels are covered by more than one triangle of the coarse mesh "
                       "(overlapping islands), e.g. by cells "
                    << NameCells(overlapCells, overlapCells.size() + 1)
                    << "; the lower-numbered triangle is baked. Give each triangle its own "
                       "part of the texture.");
  }
  if (unhit > 0)
  {
    vtkWarningMacro(<< unhit << " of " << covered
                    << " covered texels found no detailed surface within MaxRayDistance "
                    << this->MaxRayDistance << "; they are filled from their neighbours. "
                    << "Increase MaxRayDistance (or CageOffset) if the meshes are further apart.");
  }
}

//------------------------------------------------------------------------------
void vtkNormalMapBaker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TextureSize: " << this->TextureSize[0] << " x " << this->TextureSize[1] << "\n";
  os << indent << "MaxRayDistance: " << this->MaxRayDistance << "\n";
  os << indent << "CageOffset: " << this->CageOffset << "\n";
  os << indent << "Margin: " << this->Margin << "\n";
  os << indent << "Space: " << this->GetSpaceAsString() << "\n";
  os << indent << "OutputScalarType: " << vtkImageScalarTypeNameMacro(this->OutputScalarType)
     << "\n";
  os << indent << "GreenUp: " << (this->GreenUp ? "On" : "Off") << "\n";
  os << indent << "BakeHeight: " << (this->BakeHeight ? "On" : "Off") << "\n";
  os << indent << "NumberOfCoveredTexels: " << this->NumberOfCoveredTexels << "\n";
  os << indent << "NumberOfUnhitTexels: " << this->NumberOfUnhitTexels << "\n";
  os << indent << "NumberOfOverlappingTexels: " << this->NumberOfOverlappingTexels << "\n";
}
