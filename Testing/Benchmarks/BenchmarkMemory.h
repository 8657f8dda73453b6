// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Whether the big arrays a benchmark case allocates get fresh pages from the kernel or memory
// the process has used before.
//
// A filter's first execution writes its outputs into fresh pages, which the kernel must clear
// and map one by one; on the virtual machines these benchmarks run on that costs more than most
// of the arithmetic. A re-execution (a slider moved) frees the old outputs and allocates new
// ones of the same size, which glibc serves from memory it already holds. glibc moves between
// the two by itself (its mmap threshold adapts to what was freed, and freed chunks stay in its
// heap), so that a loop of "first executions" would measure warm memory from its second
// iteration on. Each case therefore fixes the choice:
// - fresh: before each timed iteration (untimed) what the previous one made is freed and the
//   process's free memory goes back to the kernel, and big allocations are mapped anew and
//   unmapped when freed, so that everything the iteration allocates is fresh wherever the
//   allocator takes it from;
// - warm: nothing is mapped or given back, so that freed memory is reused.
#ifndef BenchmarkMemory_h
#define BenchmarkMemory_h

#include <benchmark/benchmark.h>

#include <cstdlib> // Defines __GLIBC__ where glibc is the C library

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace BenchmarkMemory
{
/// Sets the allocator's policy for a case: fresh pages or warm memory.
inline void UseFreshPages(bool fresh)
{
#ifdef __GLIBC__
  if (fresh)
  {
    mallopt(M_MMAP_MAX, 1 << 20);
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
    mallopt(M_TRIM_THRESHOLD, 128 * 1024);
  }
  else
  {
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
  }
#else
  (void)fresh;
#endif
}

/// Call at the top of each timed iteration. In a fresh case, outside the timing, @a release
/// frees what the previous iteration made (a filter keeps its last output until the next
/// execution has made the new one, so its memory would otherwise be reused warm), and the free
/// memory goes back to the kernel.
template <typename Release>
void BeginIteration(benchmark::State& state, bool fresh, Release&& release)
{
  if (!fresh)
  {
    return;
  }
  state.PauseTiming();
  release();
#ifdef __GLIBC__
  malloc_trim(0);
#endif
  state.ResumeTiming();
}
}

#endif
