#include "vtkSurfaceDetailMemory.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <unordered_map>

#if defined(__linux__)
#include <sys/mman.h>
#define SURFACEDETAIL_MEMORY_MMAP 1
#endif

namespace vtkSurfaceDetailMemory
{
namespace
{
using Clock = std::chrono::steady_clock;

constexpr std::size_t DefaultCacheMiB = 1024;
constexpr double DefaultIdleSeconds = 5.0;

#if defined(SURFACEDETAIL_MEMORY_MMAP)
// Big blocks are mappings of their own, 2 MB-aligned, so that giving one back really
// returns its pages (free() may keep them in the heap) and a cached block can be split
// or joined at huge-page boundaries.
void* MapAligned(std::size_t bytes)
{
  const std::size_t span = bytes + HugePageBytes;
  void* raw = mmap(nullptr, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED)
  {
    return nullptr;
  }
  const auto begin = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (begin + HugePageBytes - 1) / HugePageBytes * HugePageBytes;
  if (aligned > begin)
  {
    munmap(raw, aligned - begin);
  }
  const std::uintptr_t end = begin + span;
  if (end > aligned + bytes)
  {
    munmap(reinterpret_cast<void*>(aligned + bytes), end - (aligned + bytes));
  }
  void* p = reinterpret_cast<void*>(aligned);
#if defined(MADV_HUGEPAGE)
  // Advice only: when the kernel declines, the memory is ordinary pages.
  madvise(p, bytes, MADV_HUGEPAGE);
#endif
  return p;
}

struct CachedBlock
{
  std::size_t Bytes;
  Clock::time_point LastUsed;
};

// Every piece of state behind one mutex: a few big allocations per filter execution.
struct State
{
  std::mutex Mutex;
  std::unordered_map<void*, std::size_t> Live; // big blocks handed out, with their size
  std::map<char*, CachedBlock> Cache;          // by address, so neighbours can be joined
  std::size_t CachedBytes = 0;
  std::size_t Limit = CacheLimitFromEnvironment();
  double IdleSeconds = DefaultIdleSeconds;
  std::uint64_t Hits = 0;
  std::uint64_t Misses = 0;

  // Gives the cached block at `it` back to the system.
  std::map<char*, CachedBlock>::iterator Unmap(std::map<char*, CachedBlock>::iterator it)
  {
    munmap(it->first, it->second.Bytes);
    this->CachedBytes -= it->second.Bytes;
    return this->Cache.erase(it);
  }

  std::size_t Trim(Clock::time_point now, double idleSeconds)
  {
    std::size_t given = 0;
    for (auto it = this->Cache.begin(); it != this->Cache.end();)
    {
      if (std::chrono::duration<double>(now - it->second.LastUsed).count() >= idleSeconds)
      {
        given += it->second.Bytes;
        it = this->Unmap(it);
      }
      else
      {
        ++it;
      }
    }
    return given;
  }

  // Oldest blocks first until the cache fits its limit; the last one only loses its tail
  // (joined blocks can be big, and what stays cached is still warm).
  void Evict()
  {
    while (this->CachedBytes > this->Limit)
    {
      auto oldest = std::min_element(this->Cache.begin(), this->Cache.end(),
        [](const auto& a, const auto& b) { return a.second.LastUsed < b.second.LastUsed; });
      const std::size_t excess =
        (this->CachedBytes - this->Limit + HugePageBytes - 1) / HugePageBytes * HugePageBytes;
      if (oldest->second.Bytes > excess)
      {
        oldest->second.Bytes -= excess;
        munmap(oldest->first + oldest->second.Bytes, excess);
        this->CachedBytes -= excess;
      }
      else
      {
        this->Unmap(oldest);
      }
    }
  }

  // The smallest cached block of at least `bytes`, split so that only `bytes` leave the
  // cache; nullptr when none fits.
  void* Take(std::size_t bytes)
  {
    auto best = this->Cache.end();
    for (auto it = this->Cache.begin(); it != this->Cache.end(); ++it)
    {
      if (it->second.Bytes >= bytes &&
        (best == this->Cache.end() || it->second.Bytes < best->second.Bytes))
      {
        best = it;
      }
    }
    if (best == this->Cache.end())
    {
      return nullptr;
    }
    char* p = best->first;
    const CachedBlock block = best->second;
    this->Cache.erase(best);
    this->CachedBytes -= block.Bytes;
    if (block.Bytes > bytes)
    {
      this->Cache.emplace(p + bytes, CachedBlock{ block.Bytes - bytes, block.LastUsed });
      this->CachedBytes += block.Bytes - bytes;
    }
    return p;
  }

  // Keeps a released block, joined with the cached blocks right before and after it so
  // that a later, bigger request can still be served warm.
  void Keep(char* p, std::size_t bytes, Clock::time_point now)
  {
    auto next = this->Cache.lower_bound(p);
    if (next != this->Cache.end() && p + bytes == next->first)
    {
      bytes += next->second.Bytes;
      this->CachedBytes -= next->second.Bytes;
      next = this->Cache.erase(next);
    }
    if (next != this->Cache.begin())
    {
      auto previous = std::prev(next);
      if (previous->first + previous->second.Bytes == p)
      {
        p = previous->first;
        bytes += previous->second.Bytes;
        this->CachedBytes -= previous->second.Bytes;
        this->Cache.erase(previous);
      }
    }
    this->Cache.emplace(p, CachedBlock{ bytes, now });
    this->CachedBytes += bytes;
  }
};

// Never destroyed: VTK arrays held by static objects may be released after main().
State& GetState()
{
  static State* const state = new State;
  return *state;
}
#endif
} // namespace

//------------------------------------------------------------------------------
std::size_t CacheLimitFromEnvironment()
{
  const std::size_t fallback = DefaultCacheMiB << 20;
  const char* text = std::getenv("SURFACEDETAIL_ARRAY_CACHE_MB");
  if (!text || !*text)
  {
    return fallback;
  }
  char* end = nullptr;
  const unsigned long long mib = std::strtoull(text, &end, 10);
  if (*end != '\0' || std::strchr(text, '-') || mib > (SIZE_MAX >> 20))
  {
    return fallback;
  }
  return static_cast<std::size_t>(mib) << 20;
}

//------------------------------------------------------------------------------
void* Allocate(std::size_t bytes)
{
#if defined(SURFACEDETAIL_MEMORY_MMAP)
  State& state = GetState();
  std::lock_guard<std::mutex> lock(state.Mutex);
  state.Trim(Clock::now(), state.IdleSeconds);
  if (bytes >= HugePageBytes && bytes <= SIZE_MAX - 2 * HugePageBytes)
  {
    const std::size_t rounded = (bytes + HugePageBytes - 1) / HugePageBytes * HugePageBytes;
    void* p = state.Take(rounded);
    if (p)
    {
      ++state.Hits;
    }
    else
    {
      ++state.Misses;
      p = MapAligned(rounded);
      if (!p)
      {
        return nullptr;
      }
    }
    state.Live.emplace(p, rounded);
    return p;
  }
#endif
  return std::malloc(bytes > 0 ? bytes : 1);
}

//------------------------------------------------------------------------------
void Release(void* p)
{
#if defined(SURFACEDETAIL_MEMORY_MMAP)
  State& state = GetState();
  std::lock_guard<std::mutex> lock(state.Mutex);
  const Clock::time_point now = Clock::now();
  state.Trim(now, state.IdleSeconds);
  auto live = p ? state.Live.find(p) : state.Live.end();
  if (live != state.Live.end())
  {
    const std::size_t bytes = live->second;
    state.Live.erase(live);
    if (bytes > state.Limit)
    {
      munmap(p, bytes);
    }
    else
    {
      state.Keep(static_cast<char*>(p), bytes, now);
      state.Evict();
    }
    return;
  }
#endif
  std::free(p);
}

//------------------------------------------------------------------------------
void SetCacheLimit(std::size_t bytes)
{
#if defined(SURFACEDETAIL_MEMORY_MMAP)
  State& state = GetState();
  std::lock_guard<std::mutex> lock(state.Mutex);
  state.Limit = bytes;
  state.Evict();
#else
  (void)bytes;
#endif
}

std::size_t GetCacheLimit()
{
#if defined(SURFACEDETAIL_MEMORY_MMAP)
  State& state = GetState();
  std::lock_guard<std::mutex> lock(state.Mutex);
  return state.Limit;
#else
  return 0;
#endif
}

//------------------------------------------------------------------------------
void SetCacheIdleTime(double seconds)
{
#if defined(SURFACEDETAIL_MEMORY_MMAP)
  State& state = GetState();
  std::lock_guard<std::mutex> lock(state.Mutex);
  state.IdleSeconds = seconds >= 0.0 ? seconds : 0.0;
#else
  (void)seconds;
#endif
}

double GetCacheIdleTime()
{
#if defined(SURFACEDETAIL_MEMORY_MMAP)
  State& state = GetState();
  std::lock_guard<std::mutex> lock(state.Mutex);
  return state.IdleSeconds;
#else
  return 0.0;
#endif
}

//------------------------------------------------------------------------------
std::size_t TrimCache(double idleSeconds)
{
#if defined(SURFACEDETAIL_MEMORY_MMAP)
  State& state = GetState();
  std::lock_guard<std::mutex> lock(state.Mutex);
  return state.Trim(Clock::now(), idleSeconds);
#else
  (void)idleSeconds;
  return 0;
#endif
}

//------------------------------------------------------------------------------
CacheStatistics GetCacheStatistics()
{
  CacheStatistics statistics;
#if defined(SURFACEDETAIL_MEMORY_MMAP)
  State& state = GetState();
  std::lock_guard<std::mutex> lock(state.Mutex);
  statistics.CachedBytes = state.CachedBytes;
  statistics.CachedBlocks = state.Cache.size();
  statistics.Hits = state.Hits;
  statistics.Misses = state.Misses;
#endif
  return statistics;
}
} // namespace vtkSurfaceDetailMemory
