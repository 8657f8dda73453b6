/**
 * @file   vtkSurfaceDetailMemory.h
 * @brief  Private: big output arrays in transparent huge pages where Linux offers them.
 *
 * A filter that writes a new 10-100 MB array at every execution spends a large part of
 * its time in the kernel: each first touch of a 4 kB page faults, and the faults contend
 * on the process's memory map when threads write. Asking for 2 MB-aligned memory with
 * `madvise(MADV_HUGEPAGE)` (Debian's default THP setting is `madvise`) makes that one
 * fault per 2 MB. The array stays an ordinary VTK array: VTK releases its memory through
 * the array's free function (Release below), and when VTK grows such an array it copies
 * it into memory of its own. Small arrays and other systems take the ordinary allocation.
 *
 * Shared by the filters of this module; not installed.
 */
#ifndef vtkSurfaceDetailMemory_h
#define vtkSurfaceDetailMemory_h

#include "vtkAOSDataArrayTemplate.h"

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace vtkSurfaceDetailMemory
{
constexpr std::size_t HugePageBytes = std::size_t(2) << 20;

/// Memory of at least `bytes`, to be given back with Release(); huge-page backed
/// when `bytes` is at least one huge page and the system supports it. nullptr on failure.
inline void* Allocate(std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes >= HugePageBytes)
  {
    const std::size_t rounded = (bytes + HugePageBytes - 1) / HugePageBytes * HugePageBytes;
    void* p = std::aligned_alloc(HugePageBytes, rounded);
    if (p)
    {
      // Advice only: when the kernel declines, the memory is ordinary pages.
      madvise(p, rounded, MADV_HUGEPAGE);
    }
    return p;
  }
#endif
  return std::malloc(bytes > 0 ? bytes : 1);
}

/// Gives back memory from Allocate() (nullptr is allowed).
inline void Release(void* p)
{
  std::free(p);
}

/// Gives `array` storage for `tuples` tuples of its current number of components, without
/// initialising the values (the caller writes every one). Returns false (array untouched)
/// when the memory is not available.
template <typename ValueT>
bool AllocateTuples(vtkAOSDataArrayTemplate<ValueT>* array, vtkIdType tuples)
{
  const vtkIdType values = tuples * array->GetNumberOfComponents();
  void* p = Allocate(static_cast<std::size_t>(values) * sizeof(ValueT));
  if (!p)
  {
    return false;
  }
  array->SetArray(
    static_cast<ValueT*>(p), values, 0, vtkAOSDataArrayTemplate<ValueT>::VTK_DATA_ARRAY_FREE);
  return true;
}
} // namespace vtkSurfaceDetailMemory

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailMemory.h
