// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSurfaceDetailProgress.h
 * @brief  Progress events and AbortExecute for the threaded loops of SurfaceDetail's
 *         algorithms.
 *
 * A long loop run by vtkSMPTools reports its progress and stops early when the filter's
 * AbortExecute is set (typically by a ProgressEvent observer). Every thread counts the items
 * it has done; only the thread that started the loop calls UpdateProgress and reads
 * AbortExecute, so that observers run where VTK runs them; the others learn of an abort
 * through an atomic flag and skip the rest of their work.
 *
 * Shared by SurfaceDetail's modules.
 */
#ifndef vtkSurfaceDetailProgress_h
#define vtkSurfaceDetailProgress_h

#include "vtkAlgorithm.h"

#include <algorithm>
#include <atomic>
#include <thread>

// Not for the wrappers: a helper for C++ loops.
#ifndef __VTK_WRAP__
namespace vtkSurfaceDetail
{
class Progress
{
public:
  /// A loop over @a total items that takes the filter's progress from @a from to @a to.
  Progress(vtkAlgorithm* filter, double from, double to, vtkIdType total)
    : Filter(filter)
    , From(from)
    , To(to)
    , Total(std::max<vtkIdType>(total, 1))
    , Starter(std::this_thread::get_id())
  {
    this->Stopped = filter->GetAbortExecute() != 0;
  }

  /**
   * Counts @a done more items; on the starting thread, reports the progress every hundredth
   * of the loop and looks at AbortExecute. False once the filter should stop.
   */
  bool Advance(vtkIdType done)
  {
    if (this->Stopped.load(std::memory_order_relaxed))
    {
      return false;
    }
    const vtkIdType count = this->Count.fetch_add(done, std::memory_order_relaxed) + done;
    if (std::this_thread::get_id() == this->Starter && count >= this->NextReport)
    {
      this->NextReport = count + this->Total / 100 + 1;
      this->Filter->UpdateProgress(
        this->From + (this->To - this->From) * std::min(1.0, double(count) / this->Total));
      if (this->Filter->GetAbortExecute())
      {
        this->Stopped.store(true, std::memory_order_relaxed);
      }
    }
    return !this->Stopped.load(std::memory_order_relaxed);
  }

  /// Whether the loop was stopped (or the filter had been aborted before it began).
  bool Aborted() const { return this->Stopped.load(std::memory_order_relaxed); }

private:
  vtkAlgorithm* Filter;
  double From, To;
  vtkIdType Total;
  std::thread::id Starter;
  vtkIdType NextReport = 0; // read and written by the starting thread only
  std::atomic<vtkIdType> Count{ 0 };
  std::atomic<bool> Stopped{ false };
};
} // namespace vtkSurfaceDetail
#endif

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailProgress.h
