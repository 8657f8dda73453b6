// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSurfaceDetailMikkTSpaceTopology.h
 * @brief  Private: the records and the connectivity stages of vtkSurfaceDetailMikkTSpace.
 *
 * What the stages of the MikkTSpace algorithm share: 32-bit triangle records, a vertex's
 * fan, the arithmetic kernel of its corners, and the stages that depend only on the
 * connectivity (links, fans, groups, corner frames, split points). The stages that read the
 * mesh's values, over its value types, are in vtkSurfaceDetailMikkTSpace.cxx.
 *
 * Private to vtkSurfaceDetailMikkTSpace; not installed.
 */
#ifndef vtkSurfaceDetailMikkTSpaceTopology_h
#define vtkSurfaceDetailMikkTSpaceTopology_h

#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailMikkTSpace.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkStaticCellLinksTemplate.h"
#include "vtkTypeInt32Array.h"

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace vtkSurfaceDetailMikkTSpace
{
// Points, triangles and face corners are numbered with 32 bits: the records stay compact,
// and an input with more (vtkMikkTSpaceTangents refuses it) can be processed in pieces.
using Index = vtkTypeInt32;

// Triangle flags, with the meanings of the reference implementation's, and whether its own
// texture area is positive (OrientPreserving may be forced to the other half of its quad's).
constexpr int OrientPreserving = 1;
constexpr int GroupWithAny = 2;      // no usable texture derivatives: joins any group
constexpr int Degenerate = 4;        // two corners at the same position
constexpr int QuadOneDegenerate = 8; // a quad whose other triangle is degenerate
constexpr int PositiveArea = 16;
constexpr int CornerShift = 5; // bits 5-10: its corners' offsets in their face, 2 bits each

// Groups of more than this many triangles at one vertex (poles of hundreds of triangles)
// are not split into sub-groups: the pairwise test is quadratic.
constexpr int MaxSubGroupTest = 1024;

using Frame = std::array<float, 4>;
using CornerFrames = std::vector<std::pair<Index, Frame>>; // (face corner, frame)

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

// The output frame of a corner from its tangent space: the direction made exactly
// orthogonal to the unit normal @a n, w from the orientation. A direction that leaves
// nothing across the normal (no usable texture derivatives, the reference's (1, 0, 0)
// placeholder along the normal, non-finite input) becomes any unit vector orthogonal to it.
Frame FinalFrame(const double n[3], const double os[3], bool orient);

/// The offsets or the connectivity of a vtkCellArray, 32- or 64-bit, read in place.
class Ids
{
public:
  Ids() = default;
  Ids(vtkCellArray* cells, bool offsets)
  {
    if (cells->IsStorage64Bit())
    {
      this->Wide =
        (offsets ? cells->GetOffsetsArray64() : cells->GetConnectivityArray64())->GetPointer(0);
    }
    else
    {
      this->Narrow =
        (offsets ? cells->GetOffsetsArray32() : cells->GetConnectivityArray32())->GetPointer(0);
    }
  }
  Index operator[](vtkIdType i) const
  {
    return static_cast<Index>(this->Wide ? this->Wide[i] : this->Narrow[i]);
  }

private:
  const vtkTypeInt64* Wide = nullptr;
  const vtkTypeInt32* Narrow = nullptr;
};

/// Eight corners of a fan, column by column, so that the arithmetic over them vectorises.
struct CornerBlock
{
  static constexpr int Lanes = 8;
  // In: the triangle's normalised dP/ds and dP/dt, the edges from the vertex to the corners
  // before and after it, 1 where the triangle has usable derivatives.
  double Dir[6][Lanes], Edge1[3][Lanes], Edge2[3][Lanes], Usable[Lanes];
  // Out: the directions projected onto the vertex's tangent plane and normalised, and the
  // corner's weight.
  double Os[3][Lanes], Ot[3][Lanes], Weight[Lanes];
};

// The first @a lanes corners of a block at a vertex of unit normal @a n: both directions projected
// onto the tangent plane, and the weight: the corner's angle between the edges projected onto that
// plane. From the cross and dot products it keeps the tiny angles of slivers (acos of a cosine
// rounded to 1 gives 0, and a group of slivers would have no direction at all); an edge along the
// normal leaves no direction, and the reference then takes the angle as a right angle. Without
// branches (every lane computes everything) the loop vectorises.
void EvaluateBlock(const double n[3], int lanes, CornerBlock& b);

/// One vertex's fan: its good triangles in increasing order (K of them), how they connect
/// there and their tangent spaces; reused from vertex to vertex (the arrays only grow).
struct Fan
{
  int K = 0;
  std::vector<Index> Tri;
  std::vector<int> Corner;       // the vertex's corner in each
  std::vector<Index> Next, Prev; // the vertices after and before the vertex there
  std::vector<int> Out, In;      // the neighbour across (v, next) and across (prev, v), or -1
  std::vector<int> Group;        // the first triangle of its group, or -1
  // Its dP/ds and dP/dt directions in the vertex's tangent plane, its weight, its space.
  std::vector<std::array<double, 3>> Os, Ot, Result;
  std::vector<double> Weight;
  std::vector<Index> Degenerate; // increasing
  // Scratch: the corners being evaluated, the edge table (open addressing on the other
  // vertex, chains in fan order), the flood's stack, the members of each group, a sub-group.
  CornerBlock Block{};
  std::vector<Index> SlotKey;
  std::vector<int> SlotHead, SlotTail, Chain, Stack, Start, Members, Subset;

  void Reserve(int k)
  {
    if (static_cast<int>(this->Tri.size()) >= k)
    {
      return;
    }
    for (auto* v : { &this->Tri, &this->Next, &this->Prev, &this->Corner, &this->Out, &this->In,
           &this->Group, &this->Chain, &this->Members, &this->Subset })
    {
      v->resize(k);
    }
    this->Stack.resize(2 * k + 1);
    this->Start.resize(k + 1);
    for (auto* v : { &this->Os, &this->Ot, &this->Result })
    {
      v->resize(k);
    }
    this->Weight.resize(k);
  }
};

/// The directions of dP/ds and dP/dt of recently seen triangles, by triangle id. A
/// triangle is seen at each of its three corners, and vertices processed one after the
/// other share most of their triangles (and the vertices of the next row of a regular mesh
/// those of this one): most are computed once instead of three times. What is found is
/// what would be computed, so the memo changes no result.
class DirectionMemo
{
public:
  // Makes room for up to 2^14 triangles, fewer for a smaller mesh.
  void Reserve(Index nTris)
  {
    size_t size = 16;
    while (size < (size_t(1) << 14) && size < static_cast<size_t>(nTris))
    {
      size *= 2;
    }
    if (this->Key.size() != size)
    {
      this->Key.assign(size, -1);
      this->Directions.resize(size);
    }
  }
  const double* Find(Index t) const
  {
    const size_t s = static_cast<size_t>(t) & (this->Key.size() - 1);
    return this->Key[s] == t ? this->Directions[s].data() : nullptr;
  }
  double* Add(Index t)
  {
    const size_t s = static_cast<size_t>(t) & (this->Key.size() - 1);
    this->Key[s] = t;
    return this->Directions[s].data();
  }

private:
  std::vector<Index> Key;
  std::vector<std::array<double, 6>> Directions; // dP/ds, then dP/dt
};

// Sorts @a keys by their upper 32 bits, stably, in parallel.
void SortByUpperHalf(std::vector<std::uint64_t>& keys);

/// The stages that depend only on the mesh's connectivity: triangles' links, fans, groups
/// and the bookkeeping of corner frames and split points.
class Topology
{
public:
  Topology(Index nPts, vtkCellArray* faces, double threshold)
    : NumberOfPoints(nPts)
    , ThresholdCos(std::cos(vtkMath::RadiansFromDegrees(threshold)))
    , Faces(faces)
    , Offsets(faces, true)
    , Connectivity(faces, false)
  {
  }

  Frames Result();

protected:
  void BuildLinks();
  void ResolveGroupWithAnyOrientation();
  void BuildFan(Index v, Fan& fan);
  void EvaluateGroups(Fan& fan) const;
  void EvaluateGroup(Fan& fan, const int* members, int m) const;
  void SetFrames(Index v, const double n[3], Fan& fan, CornerFrames& differing);
  void SetCornerFrame(Index v, Index c, const Frame& frame, CornerFrames& differing);
  void AddDiffering(const CornerFrames& frames);
  Frame FrameOf(Index c, Index v) const;
  void SplitMixedPoints();
  void DistinctFrames(const std::vector<Index>& corners, Index v, std::vector<int>& rank,
    std::vector<Index>& firsts) const;
  Index Vertex(Index t, int k) const { return this->TriVertex[3 * static_cast<size_t>(t) + k]; }
  Index Corner(Index t, int k) const
  {
    return this->TriBase[t] + ((this->TriFlag[t] >> (CornerShift + 2 * k)) & 3);
  }
  bool Orient(Index t) const { return (this->TriFlag[t] & OrientPreserving) != 0; }

  const Index NumberOfPoints;
  const double ThresholdCos;
  vtkIdType NonFinitePoints = 0;   // points with a non-finite coordinate
  std::unique_ptr<Index[]> WeldOf; // point -> vertex: the smallest point id with its values
  vtkCellArray* Faces;
  const Ids Offsets, Connectivity;
  vtkSmartPointer<vtkDataArray> Renumbered; // the faces' connectivity after splits

  // Triangles of the faces with 3 or 4 corners, in face order (MikkTSpace's triangles):
  // their welded vertices, their face's first corner and their flags.
  Index NumberOfTriangles = 0;
  vtkNew<vtkTypeInt32Array> TriVertexArray;
  Index* TriVertex = nullptr;
  std::unique_ptr<Index[]> TriBase;
  std::unique_ptr<std::uint16_t[]> TriFlag;
  vtkStaticCellLinksTemplate<Index> Links; // vertex -> triangles, decreasing

  // Corner frames: most corners have their vertex's frame (the first one set, kept in the
  // output array at the vertex's point); the others are listed in Differing, sorted by
  // corner. Per vertex: NoFrame, OneFrame (for all its corners) or Mixed.
  CornerFrames Differing;
  enum VertexState : char
  {
    NoFrame,
    OneFrame,
    Mixed
  };
  std::unique_ptr<VertexState[]> State;
  vtkNew<vtkFloatArray> Tangents;
  Frame* VertexFrame = nullptr;
  std::vector<Index> ExtraSource; // the input point of each split point
};

}

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailMikkTSpaceTopology.h
