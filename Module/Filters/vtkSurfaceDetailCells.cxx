// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSurfaceDetailCells.h"

#include "vtkCellArray.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <type_traits>

namespace
{
template <typename IdT>
bool InRange(const IdT* ids, vtkIdType n, vtkIdType numberOfPoints)
{
  using U = std::make_unsigned_t<IdT>;
  const U limit = static_cast<U>(numberOfPoints);
  std::atomic<bool> bad(false);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      // An OR over the chunk rather than an early exit: the loop vectorises, and valid
      // input (the usual case) reads every id anyway.
      bool out = false;
      for (vtkIdType i = begin; i < end; ++i)
      {
        out |= static_cast<U>(ids[i]) >= limit;
      }
      if (out)
      {
        bad.store(true, std::memory_order_relaxed);
      }
    });
  return !bad.load();
}
}

bool vtkSurfaceDetailCells::PointIdsInRange(vtkCellArray* cells, vtkIdType numberOfPoints)
{
  if (!cells || cells->GetNumberOfConnectivityIds() == 0)
  {
    return true;
  }
  if (numberOfPoints <= 0)
  {
    return false;
  }
  const vtkIdType n = cells->GetNumberOfConnectivityIds();
  if (cells->IsStorage64Bit())
  {
    return InRange(cells->GetConnectivityArray64()->GetPointer(0), n, numberOfPoints);
  }
  // 32-bit ids hold nothing at or above 2^31: a larger point count limits nothing more (and
  // would not fit the unsigned 32-bit comparison).
  return InRange(cells->GetConnectivityArray32()->GetPointer(0), n,
    std::min(numberOfPoints, vtkIdType(VTK_TYPE_INT32_MAX) + 1));
}
