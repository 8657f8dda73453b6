// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkDisplacementSeams.h
 * @brief  Private: vtkDisplacementMapFilter's seams: groups of coincident points that move
 *         together, and share a normal where they share their input normal.
 *
 * A texture seam or a pole repeats a point with other texture coordinates; sampled on its
 * own, each copy would move by its own height and a crack would open. The copies are found
 * among the mesh's boundary points (vtkDisplacementPolygons.h, SeamCandidates), grouped by
 * position, and then moved by the mean of their displacements. Copies with one input normal
 * get one output normal, the normalised sum of theirs; copies with different input normals (a
 * hard edge) keep their sides apart.
 *
 * Part of SurfaceDetail::Filters; not installed.
 */
#ifndef vtkDisplacementSeams_h
#define vtkDisplacementSeams_h

#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"
#include "vtkSurfaceDetailConventions.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace vtkDisplacement
{
/// Coincident points as (representative, member) pairs, sorted: a group is a run of pairs with
/// one representative, its first point, which is a member of its group too.
using GroupList = std::vector<std::pair<vtkIdType, vtkIdType>>;

/**
 * Groups the points @a ids that lie within @a tol of one another (transitively), sorted so
 * that every sum over a group has one order. Points that are not finite join no group.
 */
template <typename R>
GroupList CoincidentGroups(const R* points, const std::vector<vtkIdType>& ids, double tol)
{
  vtkNew<vtkPoints> candidates;
  candidates->SetDataTypeToDouble();
  std::vector<vtkIdType> finite; // index into ids of each candidate
  for (size_t k = 0; k < ids.size(); ++k)
  {
    const double p[3] = { points[3 * ids[k]], points[3 * ids[k] + 1], points[3 * ids[k] + 2] };
    if (std::isfinite(p[0] + p[1] + p[2]))
    {
      candidates->InsertNextPoint(p);
      finite.push_back(static_cast<vtkIdType>(k));
    }
  }
  std::vector<vtkIdType> parent(finite.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](vtkIdType k)
  {
    while (parent[k] != k)
    {
      k = parent[k] = parent[parent[k]];
    }
    return k;
  };
  if (finite.size() > 1)
  {
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(candidates);
    vtkNew<vtkStaticPointLocator> locator;
    locator->SetDataSet(cloud);
    locator->BuildLocator();
    vtkNew<vtkIdList> near;
    for (vtkIdType k = 0; k < static_cast<vtkIdType>(finite.size()); ++k)
    {
      locator->FindPointsWithinRadius(tol, candidates->GetPoint(k), near);
      for (vtkIdType q = 0; q < near->GetNumberOfIds(); ++q)
      {
        const vtkIdType a = find(k), b = find(near->GetId(q));
        parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  GroupList groups;
  std::vector<char> inGroup(finite.size(), 0);
  for (size_t k = 0; k < finite.size(); ++k)
  {
    const vtkIdType r = find(static_cast<vtkIdType>(k));
    if (r != static_cast<vtkIdType>(k))
    {
      groups.emplace_back(ids[finite[r]], ids[finite[k]]);
      inGroup[r] = 1;
    }
  }
  for (size_t k = 0; k < finite.size(); ++k)
  {
    if (inGroup[k])
    {
      groups.emplace_back(ids[finite[k]], ids[finite[k]]);
    }
  }
  std::sort(groups.begin(), groups.end());
  return groups;
}

/// Calls @a body(b, e) for each group [b, e) of @a groups.
template <typename F>
void ForEachGroup(const GroupList& groups, F&& body)
{
  for (size_t b = 0, e = 0; b < groups.size(); b = e)
  {
    while (e < groups.size() && groups[e].first == groups[b].first)
    {
      ++e;
    }
    body(b, e);
  }
}

/**
 * One displacement per group: the mean of the members' own. @a pass gives a member's
 * displacement (Displacement(i, offset)) and writes its point (WritePoint(i, offset)).
 */
template <typename Pass>
void MergeSeamPoints(const Pass& pass, const GroupList& groups)
{
  ForEachGroup(groups,
    [&](size_t b, size_t e)
    {
      double mean[3] = { 0.0, 0.0, 0.0 };
      for (size_t g = b; g < e; ++g)
      {
        double offset[3];
        pass.Displacement(groups[g].second, offset);
        for (int j = 0; j < 3; ++j)
        {
          mean[j] += offset[j];
        }
      }
      for (int j = 0; j < 3; ++j)
      {
        mean[j] /= static_cast<double>(e - b);
      }
      for (size_t g = b; g < e; ++g)
      {
        pass.WritePoint(groups[g].second, mean);
      }
    });
}

/**
 * One normal per group member: the sum of the members' that share its input normal. @a pass
 * gives a member's unit input normal (InputNormal(i, n)) and the normal written so far
 * (OutputNormal(i, m)), and writes its normal and tangent (WriteNormalAndTangent(i, n, m)).
 */
template <typename Pass>
void MergeSeamNormals(const Pass& pass, const GroupList& groups)
{
  ForEachGroup(groups,
    [&](size_t b, size_t e)
    {
      std::vector<double> unit(3 * (e - b)), sums(3 * (e - b), 0.0);
      for (size_t g = 0; g < e - b; ++g)
      {
        pass.InputNormal(groups[b + g].second, &unit[3 * g]);
      }
      for (size_t g = 0; g < e - b; ++g)
      {
        for (size_t h = 0; h < e - b; ++h)
        {
          if (vtkSurfaceDetail::Dot(&unit[3 * g], &unit[3 * h]) > 1.0 - 1e-9)
          {
            double m[3];
            pass.OutputNormal(groups[b + h].second, m);
            for (int j = 0; j < 3; ++j)
            {
              sums[3 * g + j] += m[j];
            }
          }
        }
      }
      for (size_t g = 0; g < e - b; ++g)
      {
        pass.WriteNormalAndTangent(groups[b + g].second, &unit[3 * g], &sums[3 * g]);
      }
    });
}
} // namespace vtkDisplacement

#endif
// VTK-HeaderTest-Exclude: vtkDisplacementSeams.h
