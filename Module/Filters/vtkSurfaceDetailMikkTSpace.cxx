// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSurfaceDetailMikkTSpace.h"
#include "vtkSurfaceDetailMikkTSpaceTopology.h"

#include "vtkAlgorithm.h"
#include "vtkArrayDispatch.h"
#include "vtkDoubleArray.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include "vtkSurfaceDetailProgress.h"

#include <algorithm>
#include <cstring>
#include <numeric>

namespace vtkSurfaceDetailMikkTSpace
{
namespace
{
/// The input's values, read in place: positions, normals and texture coordinates, each a
/// float or a double array (a float widens to double exactly).
template <typename PT, typename NT, typename TT>
struct Mesh
{
  const PT* P;
  const NT* N;
  const TT* T;
  size_t TStride;
  double Position(Index i, int k) const { return this->P[3 * static_cast<size_t>(i) + k]; }
  double Normal(Index i, int k) const { return this->N[3 * static_cast<size_t>(i) + k]; }
  double TCoord(Index i, int k) const { return this->T[this->TStride * i + k]; }
};

/// The stages that read the mesh's values, over one instantiation of Mesh.
template <typename M>
class MikkTSpace : public Topology
{
public:
  MikkTSpace(const M& mesh, Index nPts, vtkCellArray* faces, double threshold)
    : Topology(nPts, faces, threshold)
    , Values(mesh)
  {
  }

  // False when the filter's AbortExecute stopped it.
  bool Run(vtkAlgorithm* filter)
  {
    this->Weld();
    this->BuildTriangles();
    this->BuildLinks();
    filter->UpdateProgress(0.3);
    this->ResolveGroupWithAnyOrientation();
    vtkSurfaceDetail::Progress progress(filter, 0.3, 0.7, this->NumberOfPoints);
    this->EvaluateVertices(progress);
    if (progress.Aborted())
    {
      return false;
    }
    this->FixQuadsWithOneDegenerateTriangle();
    this->SetPointFrames();
    this->SplitMixedPoints();
    return true;
  }

private:
  const M Values;

  bool SamePosition(Index a, Index b) const
  {
    const M& m = this->Values;
    return m.Position(a, 0) == m.Position(b, 0) && m.Position(a, 1) == m.Position(b, 1) &&
      m.Position(a, 2) == m.Position(b, 2);
  }

  bool SameValues(Index a, Index b) const
  {
    const M& m = this->Values;
    return this->SamePosition(a, b) && m.Normal(a, 0) == m.Normal(b, 0) &&
      m.Normal(a, 1) == m.Normal(b, 1) && m.Normal(a, 2) == m.Normal(b, 2) &&
      m.TCoord(a, 0) == m.TCoord(b, 0) && m.TCoord(a, 1) == m.TCoord(b, 1);
  }

  // The point's normal, normalised (the reference assumes unit normals).
  void UnitNormal(Index pt, double n[3]) const
  {
    n[0] = this->Values.Normal(pt, 0);
    n[1] = this->Values.Normal(pt, 1);
    n[2] = this->Values.Normal(pt, 2);
    NormalizeIfNotZero(n);
  }

  // A hash of a point's values, the same for equal values (-0 and 0 included). A point
  // with a NaN equals nothing, not even itself, and hashes its id, so that many such points
  // do not make one long run to compare.
  std::uint32_t Hash(Index i) const
  {
    const M& m = this->Values;
    const double values[8] = { m.Position(i, 0), m.Position(i, 1), m.Position(i, 2), m.Normal(i, 0),
      m.Normal(i, 1), m.Normal(i, 2), m.TCoord(i, 0), m.TCoord(i, 1) };
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

  // MikkTSpace identifies corners by value: points with identical position, normal and
  // texture coordinates are one vertex even if the cells do not share them. The points are
  // sorted by a hash of their values (hashed in parallel, then radix sorted), so that equal
  // points meet in runs of equal hashes, where they are compared value by value; each run
  // is in point order, so a vertex is its smallest point id.
  void Weld()
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
          keys[i] = (std::uint64_t{ this->Hash(i) } << 32) | static_cast<std::uint32_t>(i);
          count += !(std::isfinite(this->Values.Position(i, 0)) &&
            std::isfinite(this->Values.Position(i, 1)) &&
            std::isfinite(this->Values.Position(i, 2)));
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
        // A run that began before this range belongs to the range that has its start.
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

  // One triangle per triangle face, two per quad, split along the shorter texture diagonal
  // (the shorter position diagonal on a tie), in parallel over blocks of faces whose first
  // triangles come from a count per block. A quad's two triangles are forced to one
  // orientation.
  //
  // The decisions (which diagonal, the sign of the texture area, whether the derivatives
  // are usable) are the reference's own expressions in its single precision, on the values
  // it would be given as floats, so that every tool that bakes with MikkTSpace takes the
  // same ones: near zero, double precision would give another sign or call a float
  // cancellation a direction.
  void BuildTriangles()
  {
    const Ids& off = this->Offsets;
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
    vtkSMPTools::For(0, nBlocks,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType b = begin; b < end; ++b)
        {
          Index t = first[b];
          for (vtkIdType f = b * Block; f < std::min(nFaces, (b + 1) * Block); ++f)
          {
            const int nt = trianglesOf(f);
            if (nt == 1)
            {
              this->MakeTriangle(t, off[f], 0, 1, 2);
            }
            else if (nt == 2)
            {
              this->MakeQuad(t, off[f]);
            }
            t += nt;
          }
        }
      });
  }

  // The two triangles t, t + 1 of the quad whose first corner is @a base.
  void MakeQuad(Index t, Index base)
  {
    // Squared distance between the points of face corners i and j, as floats, in texture
    // space or in space.
    auto dist2 = [&](bool tcoords, Index i, Index j)
    {
      const Index a = this->Connectivity[base + i], b = this->Connectivity[base + j];
      float d2 = 0.0f;
      for (int k = 0; k < (tcoords ? 2 : 3); ++k)
      {
        const float d = tcoords ? static_cast<float>(this->Values.TCoord(b, k)) -
            static_cast<float>(this->Values.TCoord(a, k))
                                : static_cast<float>(this->Values.Position(b, k)) -
            static_cast<float>(this->Values.Position(a, k));
        d2 += d * d;
      }
      return d2;
    };
    const bool diag02 = dist2(true, 0, 2) < dist2(true, 1, 3) ||
      (!(dist2(true, 1, 3) < dist2(true, 0, 2)) && !(dist2(false, 1, 3) < dist2(false, 0, 2)));
    const float area0 =
      diag02 ? this->MakeTriangle(t, base, 0, 1, 2) : this->MakeTriangle(t, base, 0, 1, 3);
    const float area1 =
      diag02 ? this->MakeTriangle(t + 1, base, 0, 2, 3) : this->MakeTriangle(t + 1, base, 1, 2, 3);
    std::uint16_t& fa = this->TriFlag[t];
    std::uint16_t& fb = this->TriFlag[t + 1];
    if (((fa ^ fb) & Degenerate) != 0)
    {
      fa |= QuadOneDegenerate;
      fb |= QuadOneDegenerate;
    }
    else if (!(fa & Degenerate) && ((fa ^ fb) & OrientPreserving) != 0)
    {
      // An inconsistently mapped quad: the larger texture area (or the triangle with usable
      // derivatives) decides its orientation.
      const bool keepFirst = (fb & GroupWithAny) || std::abs(area0) >= std::abs(area1);
      std::uint16_t& to = keepFirst ? fb : fa;
      to = (to & ~OrientPreserving) | ((keepFirst ? fa : fb) & OrientPreserving);
    }
  }

  // Triangle t, of face corners base + i, base + j, base + k: its welded vertices and its
  // flags (the reference's expressions in single precision: eq. 18, 19 of its
  // description, CalcTexArea). Returns the signed texture area as the reference computes it.
  float MakeTriangle(Index t, Index base, int i, int j, int k)
  {
    const int offsets[3] = { i, j, k };
    Index pt[3];
    float p[3][3], tc[3][2];
    for (int c = 0; c < 3; ++c)
    {
      pt[c] = this->Connectivity[base + offsets[c]];
      this->TriVertex[3 * static_cast<size_t>(t) + c] = this->WeldOf[pt[c]];
      for (int x = 0; x < 3; ++x)
      {
        p[c][x] = static_cast<float>(this->Values.Position(pt[c], x));
      }
      tc[c][0] = static_cast<float>(this->Values.TCoord(pt[c], 0));
      tc[c][1] = static_cast<float>(this->Values.TCoord(pt[c], 1));
    }
    const float t21x = tc[1][0] - tc[0][0], t21y = tc[1][1] - tc[0][1];
    const float t31x = tc[2][0] - tc[0][0], t31y = tc[2][1] - tc[0][1];
    const float area = t21x * t31y - t21y * t31x;
    float os2 = 0.0f, ot2 = 0.0f;
    for (int x = 0; x < 3; ++x)
    {
      const float d1 = p[1][x] - p[0][x], d2 = p[2][x] - p[0][x];
      const float os = t31y * d1 - t21y * d2, ot = -t31x * d1 + t21x * d2;
      os2 += os * os;
      ot2 += ot * ot;
    }
    const float absArea = std::abs(area);
    const bool usable =
      NotZeroF(area) && NotZeroF(std::sqrt(os2) / absArea) && NotZeroF(std::sqrt(ot2) / absArea);
    const bool degenerate = this->SamePosition(pt[0], pt[1]) || this->SamePosition(pt[0], pt[2]) ||
      this->SamePosition(pt[1], pt[2]);
    const int flag = (area > 0.0f ? OrientPreserving | PositiveArea : 0) |
      (usable ? 0 : GroupWithAny) | (degenerate ? Degenerate : 0) |
      ((i | (j << 2) | (k << 4)) << CornerShift);
    this->TriBase[t] = base;
    this->TriFlag[t] = static_cast<std::uint16_t>(flag);
    return area;
  }

  // Per vertex, in parallel: its fan, the spaces of its groups and the frames of its
  // corners; a vertex's first frame goes to the output array at its point.
  void EvaluateVertices(vtkSurfaceDetail::Progress& progress)
  {
    const Index nPts = this->NumberOfPoints;
    this->State.reset(new VertexState[nPts]);
    std::fill_n(this->State.get(), nPts, NoFrame);
    this->Tangents->SetName("Tangents");
    this->Tangents->SetNumberOfComponents(4);
    this->Tangents->SetNumberOfTuples(nPts);
    this->VertexFrame = reinterpret_cast<Frame*>(this->Tangents->GetPointer(0));
    vtkSMPThreadLocal<CornerFrames> differing;
    vtkSMPThreadLocal<Fan> fans;
    vtkSMPThreadLocal<DirectionMemo> memos;
    vtkSMPTools::For(0, nPts,
      [&](vtkIdType begin, vtkIdType end)
      {
        Fan& fan = fans.Local();
        DirectionMemo& memo = memos.Local();
        memo.Reserve(this->NumberOfTriangles);
        CornerFrames& local = differing.Local();
        for (Index v = static_cast<Index>(begin); v < end && !progress.Aborted(); ++v)
        {
          if (this->Links.GetNcells(v) == 0)
          {
            continue;
          }
          double n[3];
          this->UnitNormal(v, n);
          this->BuildFan(v, fan);
          this->EvaluateCorners(v, n, fan, memo);
          this->EvaluateGroups(fan);
          this->SetFrames(v, n, fan, local);
        }
        progress.Advance(end - begin);
      });
    for (const auto& local : differing)
    {
      this->AddDiffering(local);
    }
  }

  // Triangle t's directions of dP/ds and dP/dt (eq. 18, 19 of the reference's description,
  // in double; zero when it has no usable derivatives), normalised, into @a dir.
  void TriangleDirections(Index t, double dir[6]) const
  {
    double p[3][3], tc[3][2];
    for (int c = 0; c < 3; ++c)
    {
      const Index pt = this->Vertex(t, c);
      for (int x = 0; x < 3; ++x)
      {
        p[c][x] = this->Values.Position(pt, x);
      }
      tc[c][0] = this->Values.TCoord(pt, 0);
      tc[c][1] = this->Values.TCoord(pt, 1);
    }
    const int flag = this->TriFlag[t];
    const bool usable = !(flag & GroupWithAny);
    const double sign = (flag & PositiveArea) ? 1.0 : -1.0;
    const double s21 = tc[1][1] - tc[0][1], s31 = tc[2][1] - tc[0][1];
    const double r21 = tc[1][0] - tc[0][0], r31 = tc[2][0] - tc[0][0];
    for (int x = 0; x < 3; ++x)
    {
      const double d1 = p[1][x] - p[0][x], d2 = p[2][x] - p[0][x];
      dir[x] = usable ? sign * (s31 * d1 - s21 * d2) : 0.0;
      dir[3 + x] = usable ? sign * (r21 * d2 - r31 * d1) : 0.0;
    }
    NormalizeIfNotZero(dir);
    NormalizeIfNotZero(dir + 3);
  }

  // Each good triangle's directions in the tangent plane of v's unit normal @a n and its
  // weight (EvaluateBlock), from its directions (memoised) and the edges at v.
  void EvaluateCorners(Index v, const double n[3], Fan& fan, DirectionMemo& memo) const
  {
    const M& m = this->Values;
    const double pv[3] = { m.Position(v, 0), m.Position(v, 1), m.Position(v, 2) };
    CornerBlock& b = fan.Block;
    for (int first = 0; first < fan.K; first += CornerBlock::Lanes)
    {
      const int lanes = std::min(fan.K - first, CornerBlock::Lanes);
      for (int l = 0; l < lanes; ++l)
      {
        const int a = first + l;
        const Index t = fan.Tri[a];
        const double* dir = memo.Find(t);
        if (!dir)
        {
          double* added = memo.Add(t);
          this->TriangleDirections(t, added);
          dir = added;
        }
        for (int c = 0; c < 3; ++c)
        {
          b.Dir[c][l] = dir[c];
          b.Dir[3 + c][l] = dir[3 + c];
          b.Edge1[c][l] = m.Position(fan.Prev[a], c) - pv[c];
          b.Edge2[c][l] = m.Position(fan.Next[a], c) - pv[c];
        }
        b.Usable[l] = (this->TriFlag[t] & GroupWithAny) ? 0.0 : 1.0;
      }
      EvaluateBlock(n, lanes, b);
      for (int l = 0; l < lanes; ++l)
      {
        const int a = first + l;
        for (int c = 0; c < 3; ++c)
        {
          fan.Os[a][c] = b.Os[c][l];
          fan.Ot[a][c] = b.Ot[c][l];
        }
        fan.Weight[a] = b.Weight[l];
      }
    }
  }

  // A quad with one degenerate triangle: its corner that only the degenerate triangle has
  // takes the space of the good triangle's corner at the same position (made orthogonal to
  // its own normal), or the placeholder if there is none. Rare: one serial pass.
  void FixQuadsWithOneDegenerateTriangle()
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
      const Index target = this->Connectivity[missing];
      const Index* src = std::find_if(
        c, c + 3, [&](Index j) { return this->SamePosition(this->Connectivity[j], target); });
      double n[3];
      this->UnitNormal(target, n);
      const Frame from = src == c + 3 ? Frame{ 1.0f, 0.0f, 0.0f, -1.0f }
                                      : this->FrameOf(*src, this->WeldOf[this->Connectivity[*src]]);
      const double os[3] = { from[0], from[1], from[2] };
      this->SetCornerFrame(this->WeldOf[target], missing,
        FinalFrame(n, src == c + 3 ? placeholder : os, from[3] > 0.0f), added);
      ++t;
    }
    this->AddDiffering(added);
  }

  // Every point gets its vertex's first frame; a point of a vertex no triangle reaches,
  // some unit vector orthogonal to its normal.
  void SetPointFrames()
  {
    vtkSMPTools::For(0, this->NumberOfPoints,
      [&](vtkIdType begin, vtkIdType end)
      {
        const double zero[3] = { 0.0, 0.0, 0.0 };
        for (Index p = static_cast<Index>(begin); p < end; ++p)
        {
          const Index v = this->WeldOf[p];
          if (this->State[v] == NoFrame)
          {
            double n[3];
            this->UnitNormal(p, n);
            this->VertexFrame[p] = FinalFrame(n, zero, true);
          }
          else if (v != p)
          {
            this->VertexFrame[p] = this->VertexFrame[v];
          }
        }
      });
  }
};

/// Runs the algorithm over the arrays' value types.
struct Worker
{
  template <typename PA, typename NA, typename TA>
  void operator()(PA* p, NA* n, TA* t, vtkCellArray* faces, double threshold,
    vtkAlgorithm* progress, Frames& frames)
  {
    using M = Mesh<typename PA::ValueType, typename NA::ValueType, typename TA::ValueType>;
    const M mesh{ p->GetPointer(0), n->GetPointer(0), t->GetPointer(0),
      static_cast<size_t>(t->GetNumberOfComponents()) };
    MikkTSpace<M> mikk(mesh, static_cast<Index>(p->GetNumberOfTuples()), faces, threshold);
    if (mikk.Run(progress))
    {
      frames = mikk.Result();
    }
    else
    {
      frames.Aborted = true;
    }
  }
};

// @a array as a float or double array: itself, or converted to double.
vtkSmartPointer<vtkDataArray> AsReal(vtkDataArray* array)
{
  if (vtkAOSDataArrayTemplate<float>::FastDownCast(array) ||
    vtkAOSDataArrayTemplate<double>::FastDownCast(array))
  {
    return array;
  }
  auto copy = vtkSmartPointer<vtkDoubleArray>::New();
  copy->DeepCopy(array);
  return copy;
}
} // anonymous namespace

Frames Compute(vtkDataArray* points, vtkDataArray* normals, vtkDataArray* tcoords,
  vtkCellArray* faces, double angularThreshold, vtkAlgorithm* progress)
{
  using Reals =
    vtkTypeList::Create<vtkAOSDataArrayTemplate<float>, vtkAOSDataArrayTemplate<double>>;
  const auto p = AsReal(points);
  const auto n = AsReal(normals);
  const auto t = AsReal(tcoords);
  Frames frames;
  vtkArrayDispatch::Dispatch3ByArray<Reals, Reals, Reals>::Execute(
    p.Get(), n.Get(), t.Get(), Worker{}, faces, angularThreshold, progress, frames);
  return frames;
}
}
