// Whether the big arrays a benchmark case allocates get fresh pages from the kernel or memory
// the process has used before.
//
// A filter's first execution writes its outputs into fresh pages, which the kernel must clear
// and map one by one; on the virtual machines these benchmarks run on that costs more than most
// of the arithmetic. A re-execution (a slider moved) frees the old outputs and allocates new
// ones of the same size, which glibc serves from memory it already holds. glibc moves between
// the two by itself (its mmap threshold adapts to what was freed), so that a loop of "first
// executions" would measure warm memory from its second iteration on. Each case therefore
// fixes the choice: fresh pages (every allocation of 128 KiB or more is mapped anew and
// unmapped when freed) or warm memory (no mapping, nothing given back).
#ifndef BenchmarkMemory_h
#define BenchmarkMemory_h

#include <cstdlib> // Defines __GLIBC__ where glibc is the C library

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace BenchmarkMemory
{
inline void UseFreshPages(bool fresh)
{
#ifdef __GLIBC__
  if (fresh)
  {
    mallopt(M_MMAP_MAX, 1 << 20);
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
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
}

#endif
