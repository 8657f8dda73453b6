// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkDisplacementPolygons.h
 * @brief  Private: vtkDisplacementMapFilter's work on polygons: sums over each point's
 *         polygons, and the boundary points where seams may be.
 *
 * The polygons are read in the storage the input has (32- or 64-bit ids), never copied.
 *
 * Several results are sums at each point over the polygons around it (the seam test, fitted
 * derivatives, Mesh normals). They are made without point links, atomics or a copy of the
 * point arrays per thread: the cells are cut into runs of consecutive cells, each knowing the
 * range of point ids it uses, and the points into ranges, one task each. A task visits, in
 * increasing order, the runs that use one of its points, and adds each cell's contribution to
 * the points it owns only. Every point thus gets its contributions from its cells in
 * increasing order, as a serial loop over the cells would give them: the same bits for any
 * number of threads and any split of the points, and in a piece as in the whole (a piece keeps
 * the order of its cells). Meshes whose points are numbered along their cells (those of VTK's
 * sources and of vtkParametricSurfaceSource) visit each cell about once; for others the point
 * ranges grow until the tasks together visit at most a few times the cells.
 *
 * Part of SurfaceDetail::Filters; not installed.
 */
#ifndef vtkDisplacementPolygons_h
#define vtkDisplacementPolygons_h

#include "vtkCellArray.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace vtkDisplacement
{
/// The polygons as raw offsets and connectivity of their own id type.
template <typename Id>
struct Polygons
{
  const Id* Offsets = nullptr;
  const Id* Conn = nullptr;
  vtkIdType Count = 0;

  vtkIdType Size(vtkIdType cell) const { return this->Offsets[cell + 1] - this->Offsets[cell]; }
  const Id* Points(vtkIdType cell) const { return this->Conn + this->Offsets[cell]; }
};

/// Calls @a body with @a cells as Polygons<vtkTypeInt32> or Polygons<vtkTypeInt64>.
template <typename F>
void WithPolygons(vtkCellArray* cells, F&& body)
{
  if (cells->IsStorage64Bit())
  {
    Polygons<vtkTypeInt64> p;
    p.Offsets = cells->GetOffsetsArray64()->GetPointer(0);
    p.Conn = cells->GetConnectivityArray64()->GetPointer(0);
    p.Count = cells->GetNumberOfCells();
    body(p);
  }
  else
  {
    Polygons<vtkTypeInt32> p;
    p.Offsets = cells->GetOffsetsArray32()->GetPointer(0);
    p.Conn = cells->GetConnectivityArray32()->GetPointer(0);
    p.Count = cells->GetNumberOfCells();
    body(p);
  }
}

/// Whether point id @a id lies in [@a a, @a b).
inline bool Owns(vtkIdType a, vtkIdType b, vtkIdType id)
{
  return static_cast<std::uint64_t>(id - a) < static_cast<std::uint64_t>(b - a);
}

/// The polygons cut into runs of consecutive cells with the point ids each uses, for sums over
/// each point's polygons made by ranges of points (see the file's comment).
class CellRuns
{
public:
  template <typename Id>
  explicit CellRuns(const Polygons<Id>& polys)
    : Cells(polys.Count)
  {
    const vtkIdType numRuns = (polys.Count + RunSize - 1) / RunSize;
    this->Low.resize(numRuns);
    this->High.resize(numRuns);
    vtkSMPTools::For(0, numRuns,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType r = begin; r < end; ++r)
        {
          const Id* first = polys.Points(r * RunSize);
          const Id* last = polys.Points(std::min(polys.Count, (r + 1) * RunSize));
          const auto range = std::minmax_element(first, last);
          this->Low[r] = first == last ? std::numeric_limits<vtkIdType>::max() : *range.first;
          this->High[r] = first == last ? std::numeric_limits<vtkIdType>::min() : *range.second;
        }
      });
  }

  /// Whether every point id of the polygons lies in [0, @a numPts): the sums write through
  /// them, so a mesh whose cells name points it does not have must be refused first.
  bool IdsWithin(vtkIdType numPts) const
  {
    for (size_t r = 0; r < this->Low.size(); ++r)
    {
      if (this->Low[r] <= this->High[r] && (this->Low[r] < 0 || this->High[r] >= numPts))
      {
        return false;
      }
    }
    return true;
  }

  /**
   * How many points a task should own: a few thousand, or more where the points are not
   * numbered along the cells, so that the tasks together visit at most a few times the cells.
   */
  vtkIdType Grain(vtkIdType numPts) const
  {
    vtkIdType ranges = std::max<vtkIdType>(1, numPts / 4096);
    for (;; ranges = (ranges + 1) / 2)
    {
      const vtkIdType size = (numPts + ranges - 1) / ranges;
      vtkIdType visited = 0;
      for (size_t r = 0; r < this->Low.size(); ++r)
      {
        if (this->Low[r] <= this->High[r])
        {
          visited += RunSize * (this->High[r] / size - this->Low[r] / size + 1);
        }
      }
      if (ranges == 1 || visited <= 4 * this->Cells)
      {
        return std::max<vtkIdType>(1, size);
      }
    }
  }

  /// Calls @a body(firstCell, endCell) for each run that uses a point in [@a a, @a b), in order.
  template <typename F>
  void ForRunsMeeting(vtkIdType a, vtkIdType b, F&& body) const
  {
    for (size_t r = 0; r < this->Low.size(); ++r)
    {
      if (this->Low[r] < b && this->High[r] >= a)
      {
        const vtkIdType first = static_cast<vtkIdType>(r) * RunSize;
        body(first, std::min(this->Cells, first + RunSize));
      }
    }
  }

private:
  static constexpr vtkIdType RunSize = 2048;
  vtkIdType Cells = 0;
  std::vector<vtkIdType> Low, High; // the smallest and largest point id of each run
};

/**
 * A well-mixed hash of a point id (two multiply-xorshift rounds with splitmix64's constants),
 * shifted up one bit: every hash and every sum of them is even, so the lowest bit is free to
 * mark the points some polygon uses. Mixing, not a near-additive hash, is what keeps the sums
 * at a point where several boundary fans meet (a bowtie) from cancelling by chance.
 */
inline std::uint64_t CornerHash(vtkIdType id)
{
  std::uint64_t z = static_cast<std::uint64_t>(id) * 0x9E3779B97F4A7C15ULL;
  z ^= z >> 29;
  z *= 0xBF58476D1CE4E5B9ULL;
  return (z ^ (z >> 32)) << 1;
}

/**
 * For each corner of the polygon @a ids of @a n corners whose point lies in [@a a, @a b), adds
 * the hash of the next corner's point minus that of the previous one to the point's sum in
 * @a sums (indexed from @a a). @a N is the corner count where the caller knows it (the loops
 * are then unrolled), 0 otherwise.
 */
template <int N, typename Id>
void AddCornerHashes(const Id* ids, vtkIdType n, vtkIdType a, vtkIdType b, std::uint64_t* sums)
{
  const vtkIdType count = N > 0 ? N : n;
  constexpr vtkIdType most = 8;
  std::uint64_t hashes[most];
  for (vtkIdType k = 0; k < std::min(count, most); ++k)
  {
    hashes[k] = CornerHash(ids[k]);
  }
  // Each corner's hash once; a polygon of more corners than fit hashes them twice.
  auto at = [&](vtkIdType k) { return count <= most ? hashes[k] : CornerHash(ids[k]); };
  for (vtkIdType k = 0; k < count; ++k)
  {
    if (Owns(a, b, ids[k]))
    {
      const std::uint64_t next = at(k + 1 < count ? k + 1 : 0);
      const std::uint64_t previous = at(k > 0 ? k - 1 : count - 1);
      std::uint64_t& sum = sums[ids[k] - a];
      sum = (sum + next - previous) | 1;
    }
  }
}

/**
 * The points where a seam may be, in increasing order. A texture seam cuts the mesh, so its
 * duplicated points lie on the mesh's boundary. Each corner adds the hash of its next point
 * minus that of its previous one to its point's sum; where every edge around a point is shared
 * by two consistently oriented polygons (an interior point) the sums cancel exactly, a boundary
 * edge leaves a non-zero sum. Inconsistent orientation or non-manifold edges only add
 * candidates, which the position test then discards; points in no polygon are candidates too.
 * Each task sums its range of points in a small array of its own.
 */
template <typename Id>
std::vector<vtkIdType> SeamCandidates(
  const Polygons<Id>& polys, const CellRuns& runs, vtkIdType numPts)
{
  using Found = std::vector<std::pair<vtkIdType, std::vector<vtkIdType>>>; // (first point, ids)
  vtkSMPThreadLocal<Found> found;
  vtkSMPThreadLocal<std::vector<std::uint64_t>> scratch;
  vtkSMPTools::For(0, numPts, runs.Grain(numPts),
    [&](vtkIdType a, vtkIdType b)
    {
      std::vector<std::uint64_t>& sums = scratch.Local();
      sums.assign(b - a, 0);
      runs.ForRunsMeeting(a, b,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType cell = begin; cell < end; ++cell)
          {
            const Id* ids = polys.Points(cell);
            const vtkIdType n = polys.Size(cell);
            // Triangles, most of every mesh, with their corner count known to the compiler.
            if (n == 3)
            {
              AddCornerHashes<3>(ids, 3, a, b, sums.data());
            }
            else
            {
              AddCornerHashes<0>(ids, n, a, b, sums.data());
            }
          }
        });
      std::vector<vtkIdType> mine;
      for (vtkIdType i = a; i < b; ++i)
      {
        if (sums[i - a] != 1)
        {
          mine.push_back(i);
        }
      }
      found.Local().emplace_back(a, std::move(mine));
    });
  Found all;
  for (Found& f : found)
  {
    std::move(f.begin(), f.end(), std::back_inserter(all));
  }
  std::sort(all.begin(), all.end(),
    [](const Found::value_type& x, const Found::value_type& y) { return x.first < y.first; });
  std::vector<vtkIdType> candidates;
  for (const auto& f : all)
  {
    candidates.insert(candidates.end(), f.second.begin(), f.second.end());
  }
  return candidates;
}
} // namespace vtkDisplacement

#endif
// VTK-HeaderTest-Exclude: vtkDisplacementPolygons.h
