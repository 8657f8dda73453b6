/**
 * @file   vtkSurfaceDetailVectorize.h
 * @brief  Private: one way for the module's hot loops to get AVX2 and AVX-512 builds beside
 *         the baseline one.
 *
 * Square roots, divisions and stores bound the per-point loops of the sources and filters;
 * AVX does four doubles per instruction where the x86-64 baseline (SSE2) does two, AVX-512
 * eight. The module is built for the baseline, so such loops are compiled again for the wider
 * sets and those copies run only on processors that have them. No copy contracts `a*b+c` into
 * a fused multiply-add (AVX2 does not imply FMA; files with AVX-512 copies are compiled with
 * -ffp-contract=off), so all give the same bits and results do not depend on the processor.
 *
 * - SURFACEDETAIL_WIDE_VECTORS on a plain (non-template, non-member) function: the loader
 *   picks the copy (GCC/clang `target_clones`; clang does not take it on templates).
 * - SURFACEDETAIL_TARGET_AVX2 on a function that a caller runs only when
 *   vtkSurfaceDetailVectorize::HaveAVX2() says so: for templates, where `target_clones` is
 *   not available. RunWidest() does that for a vtkSMPTools worker.
 *
 * - SURFACEDETAIL_TARGET_AVX512 (GCC and clang) likewise, run only when HaveAVX512() says so:
 *   eight doubles to a vector (GCC's prefer-vector-width=512, clang's min_vector_width(512):
 *   otherwise both keep to 256-bit vectors). AVX-512 includes FMA, so a file using it must be
 *   compiled with -ffp-contract=off to keep the bits of the other builds.
 *
 * Elsewhere (other compilers or processors) the macros are empty and HaveAVX2() and
 * HaveAVX512() are false.
 *
 * The environment variable SURFACEDETAIL_MAX_ISA, read once, caps what HaveAVX2() and
 * HaveAVX512() (and so RunWidest) report, so that a machine with the widest instructions
 * can test the narrower builds: `avx2` (no AVX-512 build) or `baseline` (neither); unset or
 * anything else: the processor's best. SURFACEDETAIL_WIDE_VECTORS ignores it (the loader
 * picks those copies before main, from the processor alone).
 *
 * Shared by the filters of this module; not installed.
 */
#ifndef vtkSurfaceDetailVectorize_h
#define vtkSurfaceDetailVectorize_h

#include "vtkType.h"

#include <cstdlib>
#include <cstring>

#if defined(__x86_64__) && defined(__linux__) && (defined(__GNUC__) || defined(__clang__))
#define SURFACEDETAIL_WIDE_VECTORS __attribute__((target_clones("avx2", "default")))
#else
#define SURFACEDETAIL_WIDE_VECTORS
#endif

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define SURFACEDETAIL_TARGET_AVX2 __attribute__((target("avx2")))
#else
#define SURFACEDETAIL_TARGET_AVX2
#endif

#if defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
#define SURFACEDETAIL_TARGET_AVX512                                                                \
  __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw,avx2,fma"), min_vector_width(512)))
#elif defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define SURFACEDETAIL_TARGET_AVX512                                                                \
  __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw,prefer-vector-width=512")))
#else
#define SURFACEDETAIL_TARGET_AVX512
#endif

namespace vtkSurfaceDetailVectorize
{
/// The widest build the dispatch may pick, from SURFACEDETAIL_MAX_ISA (read once): 0 for
/// `baseline`, 1 for `avx2`, 2 (no cap) otherwise.
inline int MaxISALevel()
{
  static const int level = []
  {
    const char* isa = std::getenv("SURFACEDETAIL_MAX_ISA");
    if (isa && std::strcmp(isa, "baseline") == 0)
    {
      return 0;
    }
    return isa && std::strcmp(isa, "avx2") == 0 ? 1 : 2;
  }();
  return level;
}

/// Whether this processor runs SURFACEDETAIL_TARGET_AVX2 code and SURFACEDETAIL_MAX_ISA
/// allows it (asked once).
inline bool HaveAVX2()
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  static const bool have = MaxISALevel() >= 1 && __builtin_cpu_supports("avx2");
  return have;
#else
  return false;
#endif
}

/// Whether this processor runs SURFACEDETAIL_TARGET_AVX512 code and SURFACEDETAIL_MAX_ISA
/// allows it (asked once). AVX-512 implies FMA: files that use it are compiled with
/// -ffp-contract=off, so that its build gives the same bits as the others. GCC's avx512f
/// target also allows AVX2 and FMA instructions, so those are asked for too (a virtual
/// machine may hide a feature that the real processor has).
inline bool HaveAVX512()
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  static const bool have = MaxISALevel() >= 2 && __builtin_cpu_supports("avx512f") &&
    __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") &&
    __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx2") &&
    __builtin_cpu_supports("fma");
  return have;
#else
  return false;
#endif
}

/// worker.Run(begin, end) in the AVX2 build (see RunWidest).
template <typename Worker>
SURFACEDETAIL_TARGET_AVX2 void RunAVX2(const Worker& worker, vtkIdType begin, vtkIdType end)
{
  worker.Run(begin, end);
}

/// worker.Run(begin, end) in the AVX-512 build (see RunWidest).
template <typename Worker>
SURFACEDETAIL_TARGET_AVX512 void RunAVX512(const Worker& worker, vtkIdType begin, vtkIdType end)
{
  worker.Run(begin, end);
}

/// For a vtkSMPTools worker's operator(): runs worker.Run(begin, end) in its AVX-512 build where
/// the processor has it (HaveAVX512()), else in its AVX2 build where it has that, else in the
/// baseline one. Run must be VTK_ALWAYS_INLINE (and what it calls inlined too) so that the wider
/// builds compile all of it; the calling file must be compiled with -ffp-contract=off (see
/// SURFACEDETAIL_TARGET_AVX512).
template <typename Worker>
void RunWidest(const Worker& worker, vtkIdType begin, vtkIdType end)
{
  if (HaveAVX512())
  {
    RunAVX512(worker, begin, end);
  }
  else if (HaveAVX2())
  {
    RunAVX2(worker, begin, end);
  }
  else
  {
    worker.Run(begin, end);
  }
}
} // namespace vtkSurfaceDetailVectorize

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailVectorize.h
