/**
 * @file   vtkSurfaceDetailMemory.h
 * @brief  Private: big output arrays in transparent huge pages, and a cache of freed ones.
 *
 * A filter that writes a new 10-100 MB array at every execution spends a large part of
 * its time in the kernel: each first touch of a 4 kB page faults, and the kernel zeroes
 * the page. Two things cut that cost:
 * - 2 MB-aligned memory with `madvise(MADV_HUGEPAGE)` (Debian's default THP setting is
 *   `madvise`): one fault per 2 MB instead of per 4 kB (the zeroing stays);
 * - a bounded cache of freed big blocks, as tcmalloc and jemalloc keep freed pages: VTK
 *   frees a source's previous output arrays before the source executes again (our
 *   sources and vtkDataObject::PrepareForNewData release them first), so a re-executing
 *   pipeline (a user dragging a resolution or parameter slider) gets warm memory back,
 *   with no page fault and no zeroing. The cache holds at most GetCacheLimit() bytes
 *   (default 1 GiB; the environment variable SURFACEDETAIL_ARRAY_CACHE_MB sets it in MiB
 *   when the process first allocates, 0 turns the cache off), and blocks unused for
 *   GetCacheIdleTime() seconds (default 5) go back to the system at the next
 *   Allocate() or Release().
 *
 * The array stays an ordinary VTK array: VTK releases its memory through the array's free
 * function (Release below), and when VTK grows such an array it copies it into memory of
 * its own. Small blocks (below one huge page) and systems other than Linux take the
 * ordinary malloc. Thread-safe.
 *
 * Shared by the filters of this module; not installed.
 */
#ifndef vtkSurfaceDetailMemory_h
#define vtkSurfaceDetailMemory_h

#include "SurfaceDetailFiltersModule.h" // For export macro
#include "vtkAOSDataArrayTemplate.h"

#include <cstddef>
#include <cstdint>

namespace vtkSurfaceDetailMemory
{
constexpr std::size_t HugePageBytes = std::size_t(2) << 20;

/// Memory of at least `bytes`, to be given back with Release(); huge-page backed (and
/// taken from the cache when a freed block fits) when `bytes` is at least one huge page
/// and the system supports it. Not initialised. nullptr on failure.
SURFACEDETAILFILTERS_EXPORT void* Allocate(std::size_t bytes);

/// Gives back memory from Allocate() (nullptr is allowed): big blocks go to the cache
/// while it has room, the rest to the system.
SURFACEDETAILFILTERS_EXPORT void Release(void* p);

///@{
/// Most bytes the cache keeps (0: no cache). Lowering it gives back the excess at once.
SURFACEDETAILFILTERS_EXPORT void SetCacheLimit(std::size_t bytes);
SURFACEDETAILFILTERS_EXPORT std::size_t GetCacheLimit();
///@}

///@{
/// Seconds a cached block may stay unused before the next Allocate() or Release() gives
/// it back to the system (default 5).
SURFACEDETAILFILTERS_EXPORT void SetCacheIdleTime(double seconds);
SURFACEDETAILFILTERS_EXPORT double GetCacheIdleTime();
///@}

/// Gives back to the system every cached block unused for at least `idleSeconds`
/// (0: all of them); returns the bytes given back.
SURFACEDETAILFILTERS_EXPORT std::size_t TrimCache(double idleSeconds = 0.0);

/// The limit SURFACEDETAIL_ARRAY_CACHE_MB asks for now (the default when it is unset or
/// not a whole number of MiB); the cache reads it once, when the process first allocates.
SURFACEDETAILFILTERS_EXPORT std::size_t CacheLimitFromEnvironment();

/// What the cache holds and how often it served a big Allocate().
struct CacheStatistics
{
  std::size_t CachedBytes = 0;
  std::size_t CachedBlocks = 0;
  std::uint64_t Hits = 0;   // big allocations served from the cache
  std::uint64_t Misses = 0; // big allocations that asked the system
};
SURFACEDETAILFILTERS_EXPORT CacheStatistics GetCacheStatistics();

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
  array->SetArray(static_cast<ValueT*>(p), values, 0,
    vtkAOSDataArrayTemplate<ValueT>::VTK_DATA_ARRAY_USER_DEFINED);
  array->SetArrayFreeFunction(&Release);
  return true;
}
} // namespace vtkSurfaceDetailMemory

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailMemory.h
