/**
 * @file   vtkDisplacementPolygons.h
 * @brief  Private: vtkDisplacementMapFilter's work on polygons: scatters from cells to
 *         points, each point's polygons, and the boundary points where seams may be.
 *
 * The polygons are read in the storage the input has (32- or 64-bit ids), never copied.
 *
 * Scatters from cells to points (a sum at each point over its cells) must not race, and
 * their results must not depend on the number of threads. Rather than atomics or a copy of
 * the point arrays per thread, the cells are cut into chunks whose size depends only on the
 * mesh, and the chunks are run in two phases, even chunks then odd chunks, each in parallel
 * when no two of its chunks share a point. Meshes whose points are numbered along their cells
 * (those of VTK's sources and of vtkParametricSurfaceSource) pass that test; others run the
 * same chunks in the same order on one thread. Either way each point receives its
 * contributions in one order: the same bits for any number of threads.
 *
 * Part of SurfaceDetail::Filters; not installed.
 */
#ifndef vtkDisplacementPolygons_h
#define vtkDisplacementPolygons_h

#include "vtkCellArray.h"
#include "vtkSMPTools.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
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

/// The polygons cut into chunks for scatters from cells to points (see the file's comment).
class CellChunks
{
public:
  template <typename Id>
  explicit CellChunks(const Polygons<Id>& polys)
    : Cells(polys.Count)
  {
    // At most 32 chunks, so that a grid of more than a few dozen rows has chunks two apart
    // that share no point; at least a few thousand cells, so that a chunk outweighs its
    // scheduling.
    this->Size = std::max<vtkIdType>(4096, (polys.Count + 31) / 32);
    const vtkIdType numChunks = (polys.Count + this->Size - 1) / this->Size;
    std::vector<vtkIdType> low(numChunks), high(numChunks);
    vtkSMPTools::For(0, numChunks, 1,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType c = begin; c < end; ++c)
        {
          const Id* first = polys.Conn + polys.Offsets[this->First(c)];
          const Id* last = polys.Conn + polys.Offsets[this->Last(c)];
          const auto range = std::minmax_element(first, last);
          low[c] = first == last ? std::numeric_limits<vtkIdType>::max() : *range.first;
          high[c] = first == last ? std::numeric_limits<vtkIdType>::min() : *range.second;
        }
      });
    for (vtkIdType c = 0; c < numChunks; ++c)
    {
      this->Low = std::min(this->Low, low[c]);
      this->High = std::max(this->High, high[c]);
    }
    for (int parity = 0; parity < 2; ++parity)
    {
      // The chunks of one parity share no point if each starts above all before it end.
      vtkIdType reached = std::numeric_limits<vtkIdType>::min();
      bool disjoint = true;
      for (vtkIdType c = parity; c < numChunks && disjoint; c += 2)
      {
        disjoint = low[c] > reached || low[c] > high[c];
        reached = std::max(reached, high[c]);
      }
      this->Parallel[parity] = disjoint;
    }
  }

  /// Whether every point id of the polygons lies in [0, @a numPts): the scatters write through
  /// them, so a mesh whose cells name points it does not have must be refused first.
  bool IdsWithin(vtkIdType numPts) const { return this->Low >= 0 && this->High < numPts; }

  /// Calls @a body(firstCell, endCell) for every chunk: the even chunks, then the odd ones.
  template <typename F>
  void Scatter(F&& body) const
  {
    const vtkIdType numChunks = (this->Cells + this->Size - 1) / this->Size;
    for (int parity = 0; parity < 2; ++parity)
    {
      const vtkIdType count = (numChunks - parity + 1) / 2;
      auto run = [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          const vtkIdType c = 2 * k + parity;
          body(this->First(c), this->Last(c));
        }
      };
      if (this->Parallel[parity])
      {
        vtkSMPTools::For(0, count, 1, run);
      }
      else
      {
        run(0, count);
      }
    }
  }

private:
  vtkIdType First(vtkIdType chunk) const { return chunk * this->Size; }
  vtkIdType Last(vtkIdType chunk) const { return std::min(this->Cells, (chunk + 1) * this->Size); }

  vtkIdType Cells = 0;
  vtkIdType Size = 1;
  vtkIdType Low = 0;   // the smallest point id, 0 without ids
  vtkIdType High = -1; // the largest, -1 without ids
  bool Parallel[2] = { false, false };
};

/**
 * Each point's polygons, in increasing order, counted and filled by chunk scatters:
 * Offsets[i] .. Offsets[i + 1] index Cells.
 */
template <typename Id>
struct PointCells
{
  std::vector<Id> Offsets;
  std::unique_ptr<Id[]> Cells;

  void Build(const Polygons<Id>& polys, const CellChunks& chunks, vtkIdType numPts)
  {
    // Each point's count, summed so that Offsets[i] is where i's list ends ...
    this->Offsets.assign(numPts + 1, 0);
    Id* offsets = this->Offsets.data();
    chunks.Scatter(
      [&](vtkIdType begin, vtkIdType end)
      {
        for (const Id* id = polys.Points(begin); id != polys.Points(end); ++id)
        {
          ++offsets[*id];
        }
      });
    for (vtkIdType i = 1; i < numPts; ++i)
    {
      offsets[i] += offsets[i - 1];
    }
    offsets[numPts] = numPts > 0 ? offsets[numPts - 1] : 0;
    // ... and filling each list from its end moves that mark back to where the list starts.
    // Each chunk is filled from its last cell down, so that a list comes out in increasing
    // order wherever a point's cells are in one chunk.
    this->Cells.reset(new Id[offsets[numPts]]);
    Id* cells = this->Cells.get();
    chunks.Scatter(
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType cell = end - 1; cell >= begin; --cell)
        {
          for (const Id* id = polys.Points(cell); id != polys.Points(cell + 1); ++id)
          {
            cells[--offsets[*id]] = static_cast<Id>(cell);
          }
        }
      });
    // Every list in increasing order, as in any piece of the same mesh whose cells keep their
    // order: sums over a list then give a point the same bits in a piece as in the whole. Only
    // lists that cross a chunk's border are out of order, so insertion sort does little.
    vtkSMPTools::For(0, numPts,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          for (Id* a = cells + offsets[i] + 1; a < cells + offsets[i + 1]; ++a)
          {
            const Id value = *a;
            Id* b = a;
            for (; b > cells + offsets[i] && *(b - 1) > value; --b)
            {
              *b = *(b - 1);
            }
            *b = value;
          }
        }
      });
  }

  const Id* Begin(vtkIdType i) const { return this->Cells.get() + this->Offsets[i]; }
  const Id* End(vtkIdType i) const { return this->Cells.get() + this->Offsets[i + 1]; }
};

/**
 * A well-mixed hash of a point id (two multiply-xorshift rounds of splitmix64's finaliser),
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
 * Adds, for each corner of the polygon @a ids of @a n corners, the hash of the next corner's
 * point minus that of the previous one to the corner's own point's sum. @a N is the corner count
 * where the caller knows it (the loops are then unrolled), 0 otherwise.
 */
template <int N, typename Id>
void AddCornerHashes(const Id* ids, vtkIdType n, std::uint64_t* sums)
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
    const std::uint64_t next = at(k + 1 < count ? k + 1 : 0);
    const std::uint64_t previous = at(k > 0 ? k - 1 : count - 1);
    sums[ids[k]] = (sums[ids[k]] + next - previous) | 1;
  }
}

/**
 * The points where a seam may be. A texture seam cuts the mesh, so its duplicated points lie
 * on the mesh's boundary. Each corner adds the hash of its next point minus that of its
 * previous one to its point's sum; where every edge around a point is shared by two
 * consistently oriented polygons (an interior point) the sums cancel exactly, a boundary
 * edge leaves a non-zero sum. Inconsistent orientation or non-manifold edges only add
 * candidates, which the position test then discards; points in no polygon are candidates
 * too. Integer sums commute, so the result does not depend on the order.
 */
template <typename Id>
std::vector<vtkIdType> SeamCandidates(
  const Polygons<Id>& polys, const CellChunks& chunks, vtkIdType numPts)
{
  std::vector<std::uint64_t> sum(numPts, 0);
  std::uint64_t* sums = sum.data();
  chunks.Scatter(
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType cell = begin; cell < end; ++cell)
      {
        const Id* ids = polys.Points(cell);
        const vtkIdType n = polys.Size(cell);
        // Triangles, most of every mesh, with their corner count known to the compiler.
        if (n == 3)
        {
          AddCornerHashes<3>(ids, 3, sums);
        }
        else
        {
          AddCornerHashes<0>(ids, n, sums);
        }
      }
    });
  std::vector<vtkIdType> candidates;
  for (vtkIdType i = 0; i < numPts; ++i)
  {
    if (sums[i] != 1)
    {
      candidates.push_back(i);
    }
  }
  return candidates;
}
} // namespace vtkDisplacement

#endif
// VTK-HeaderTest-Exclude: vtkDisplacementPolygons.h
