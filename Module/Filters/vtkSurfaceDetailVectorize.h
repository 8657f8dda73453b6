/**
 * @file   vtkSurfaceDetailVectorize.h
 * @brief  Private: one way for the module's hot loops to get an AVX2 build beside the
 *         baseline one.
 *
 * Square roots, divisions and stores bound the per-point loops of the sources and filters;
 * AVX does four doubles per instruction where the x86-64 baseline (SSE2) does two. The
 * module is built for the baseline, so such loops are compiled twice and the AVX2 copy runs
 * only on processors that have it. Neither copy contracts `a*b+c` into a fused multiply-add
 * (AVX2 does not imply FMA, and the module does not ask for it), so both give the same bits
 * and results do not depend on the processor.
 *
 * - SURFACEDETAIL_WIDE_VECTORS on a plain (non-template, non-member) function: the loader
 *   picks the copy (GCC/clang `target_clones`; clang does not take it on templates).
 * - SURFACEDETAIL_TARGET_AVX2 on a function that a caller runs only when
 *   vtkSurfaceDetailVectorize::HaveAVX2() says so: for members of class templates, where
 *   `target_clones` is not available.
 *
 * Elsewhere (other compilers or processors) both macros are empty and HaveAVX2() is false.
 * Shared by the filters of this module; not installed.
 */
#ifndef vtkSurfaceDetailVectorize_h
#define vtkSurfaceDetailVectorize_h

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

namespace vtkSurfaceDetailVectorize
{
/// Whether this processor runs SURFACEDETAIL_TARGET_AVX2 code (asked once).
inline bool HaveAVX2()
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  static const bool have = __builtin_cpu_supports("avx2");
  return have;
#else
  return false;
#endif
}
} // namespace vtkSurfaceDetailVectorize

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailVectorize.h
