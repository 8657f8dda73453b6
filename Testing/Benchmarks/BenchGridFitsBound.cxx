// What a triangulated-grid fast path would add to vtkDisplacementMapFilter's Approximate first
// execution to make Exact's normals (issue 5's unmet 20x). Exact needs, per point, the one-ring
// least-squares fit of the unit normal's derivatives n_s, n_t in texture space. The filter fits
// them on any mesh by walking its polygons. A mesh known to be a grid would need no walk: each
// point's one-ring is then fixed, and the fits become a gather stencil over the neighbouring rows
// that fills SIMD lanes. This program times the stages of such a path, on the benchmark's own
// 1M-point torus mesh (float arrays, 64-bit cell storage):
//   GridCheck:      every polygon compared with the grid pattern (a path must prove the grid);
//   UnitNormalsSoA: the input normals made unit, and (s, t), as float structure of arrays;
//   StencilFits:    n_s and n_t at the interior points (rows and columns 1 .. n-2) as 6 float
//                   arrays;
//   StencilFitsNoStores: the same fits kept in cache only: their reads and arithmetic, what
//                   a path fusing them into pass 1 (using each fit at once) would still pay.
// Boundary points, seam groups and pass 1's use of the fits are left out. The stages as timed
// are an unfused path's; fusing could save the normals' stage and the fits' stores, not the
// arithmetic.
// Each stage runs in the widest instruction set the processor has (RunWidest), compiled with the
// filter's flags, as the filter's own passes do.
// StencilFits reports its error against n_s and n_t from central differences of the closed-form
// unit normal at sampled interior points (fit_rel_err, relative to each derivative's largest
// size): the stencil is a consistent estimate of the derivatives. It is the filter's estimator
// for an interior grid point (the same six neighbours, each in two of the point's triangles;
// doubling every term leaves the solution unchanged), in float rather than double.
//
//   build/bin/BenchGridFitsBound --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// BENCHMARKS.md (issue 5) compares the sum with the time 20x leaves beyond Approximate's first
// execution, from BenchDisplacementMapFilter run just before it.

#include "DisplacementTestSurfaces.h"
#include "vtkSurfaceDetailVectorize.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkTypeInt64Array.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

using namespace DisplacementTest;

namespace
{
constexpr int U = 1414, V = 707; // the benchmark's 1M-point torus: (U+1) x (V+1) points
constexpr vtkIdType NU = U + 1, NV = V + 1, N = NU * NV;

struct Grid
{
  vtkSmartPointer<vtkPolyData> Mesh;
  const float* Normals = nullptr;
  const float* TCoords = nullptr;
  const vtkTypeInt64* Offsets = nullptr;
  const vtkTypeInt64* Conn = nullptr;
  // The stages' outputs: unit normal and (s, t) per point; n_s (3 arrays) then n_t (3 arrays).
  std::vector<float> X, Y, Z, S, T, Fits;
};

Grid& TheGrid()
{
  static Grid g;
  if (!g.Mesh)
  {
    g.Mesh = MakeMesh(Torus(), U, V, false, true);
    vtkPointData* pd = g.Mesh->GetPointData();
    // MakeMesh's float arrays: checked anyway, since every stage reads them raw.
    vtkFloatArray* normals = vtkFloatArray::SafeDownCast(pd->GetNormals());
    vtkFloatArray* tcoords = vtkFloatArray::SafeDownCast(pd->GetTCoords());
    g.Normals = normals ? normals->GetPointer(0) : nullptr;
    g.TCoords = tcoords ? tcoords->GetPointer(0) : nullptr;
    vtkCellArray* polys = g.Mesh->GetPolys();
    if (polys->IsStorage64Bit())
    {
      g.Offsets = polys->GetOffsetsArray64()->GetPointer(0);
      g.Conn = polys->GetConnectivityArray64()->GetPointer(0);
    }
    for (auto* a : { &g.X, &g.Y, &g.Z, &g.S, &g.T })
    {
      a->assign(N, 0.0f);
    }
    g.Fits.assign(6 * N, 0.0f);
  }
  return g;
}

// Whether quad (i, j)'s two triangles are (a, b, d), (a, d, c) with a = j NU + i, b = a + 1,
// c = a + NU, d = c + 1, as MakeMesh makes them: quad rows [j0, j1). (A real path would also have
// to accept the parametric sources' other split and 32-bit cell storage.)
struct CheckWorker
{
  const Grid& G;
  std::atomic<bool>& Ok;
  void operator()(vtkIdType j0, vtkIdType j1) const
  {
    vtkSurfaceDetailVectorize::RunWidest(*this, j0, j1);
  }
  VTK_ALWAYS_INLINE void Run(vtkIdType j0, vtkIdType j1) const
  {
    int bad = 0;
    for (vtkIdType j = j0; j < j1; ++j)
    {
      const vtkTypeInt64* __restrict q = this->G.Conn + 6 * j * U;
      const vtkTypeInt64* __restrict o = this->G.Offsets + 2 * j * U;
      const vtkTypeInt64 first = 6 * j * U;
      for (vtkIdType i = 0; i < U; ++i)
      {
        const vtkTypeInt64 a = j * NU + i;
        bad |= (q[6 * i] != a) | (q[6 * i + 1] != a + 1) | (q[6 * i + 2] != a + NU + 1) |
          (q[6 * i + 3] != a) | (q[6 * i + 4] != a + NU + 1) | (q[6 * i + 5] != a + NU) |
          (o[2 * i] != first + 6 * i) | (o[2 * i + 1] != first + 6 * i + 3);
      }
    }
    if (bad)
    {
      this->Ok = false;
    }
  }
};

// Whether every quad is the grid's (CheckWorker), and the polygons end there.
bool GridCheck(const Grid& g)
{
  // The sizes first, so that the pattern's reads stay inside the arrays.
  vtkCellArray* polys = g.Mesh->GetPolys();
  const vtkIdType cells = 2 * static_cast<vtkIdType>(U) * V;
  if (g.Mesh->GetNumberOfPoints() != N || polys->GetNumberOfCells() != cells ||
    polys->GetNumberOfConnectivityIds() != 3 * cells)
  {
    return false;
  }
  std::atomic<bool> ok(true);
  vtkSMPTools::For(0, V, 16, CheckWorker{ g, ok });
  return ok && g.Offsets[cells] == 3 * cells;
}

struct UnitNormalsWorker
{
  Grid& G;
  void operator()(vtkIdType b, vtkIdType e) const
  {
    vtkSurfaceDetailVectorize::RunWidest(*this, b, e);
  }
  VTK_ALWAYS_INLINE void Run(vtkIdType b, vtkIdType e) const
  {
    const float* __restrict n = this->G.Normals;
    const float* __restrict tc = this->G.TCoords;
    float* __restrict x = this->G.X.data();
    float* __restrict y = this->G.Y.data();
    float* __restrict z = this->G.Z.data();
    float* __restrict s = this->G.S.data();
    float* __restrict t = this->G.T.data();
    for (vtkIdType k = b; k < e; ++k)
    {
      const float vx = n[3 * k], vy = n[3 * k + 1], vz = n[3 * k + 2];
      const float len2 = vx * vx + vy * vy + vz * vz;
      const float inv = len2 > 0.0f ? 1.0f / std::sqrt(len2) : 1.0f;
      x[k] = vx * inv;
      y[k] = vy * inv;
      z[k] = vz * inv;
      s[k] = tc[2 * k];
      t[k] = tc[2 * k + 1];
    }
  }
};

void UnitNormalsSoA(Grid& g)
{
  vtkSMPTools::For(0, N, 4096, UnitNormalsWorker{ g });
}

// The filter's fit at an interior point: its neighbours (+-1, 0), (0, +-1), (1, 1), (-1, -1), each
// shared by two of its triangles and so counted twice, which leaves the solution unchanged; the
// normal equations [ss st; st tt] [f_s; f_t] = [sum ds df; sum dt df] solved by Cramer's rule.
// Rows [j0, j1) of points. Store false: the results go to a small scratch that stays in cache
// instead of the 6 arrays, which leaves the fit's reads and arithmetic (what a path that used
// each fit at once in pass 1, without storing it, would still pay).
template <bool Store>
struct StencilWorker
{
  Grid& G;
  void operator()(vtkIdType j0, vtkIdType j1) const
  {
    vtkSurfaceDetailVectorize::RunWidest(*this, j0, j1);
  }
  VTK_ALWAYS_INLINE void Run(vtkIdType j0, vtkIdType j1) const
  {
    const float* __restrict x = this->G.X.data();
    const float* __restrict y = this->G.Y.data();
    const float* __restrict z = this->G.Z.data();
    const float* __restrict s = this->G.S.data();
    const float* __restrict t = this->G.T.data();
    // The scratch holds one row's fits (its 6 arrays a little more than a row apart, so that
    // they do not share cache sets).
    constexpr vtkIdType ScratchStride = NU + 40;
    std::vector<float> scratch(Store ? 0 : 6 * ScratchStride);
    const vtkIdType stride = Store ? N : ScratchStride;
    for (vtkIdType j = j0; j < j1; ++j)
    {
      const vtkIdType row = j * NU;
      float* __restrict out = Store ? this->G.Fits.data() + row : scratch.data();
      // Without this, GCC does not vectorise the loop (5x slower).
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#elif defined(__GNUC__)
#pragma GCC ivdep
#endif
      for (vtkIdType i = 1; i < NU - 1; ++i)
      {
        const vtkIdType k = row + i;
        const vtkIdType m[6] = { k + 1, k - 1, k + NU, k - NU, k + NU + 1, k - NU - 1 };
        float bx = 0, by = 0, bz = 0, ss = 0, tx = 0, ty = 0, tz = 0, st = 0, tt = 0;
        for (int q = 0; q < 6; ++q)
        {
          const float fx = x[m[q]] - x[k], fy = y[m[q]] - y[k], fz = z[m[q]] - z[k];
          const float ds = s[m[q]] - s[k], dt = t[m[q]] - t[k];
          bx += ds * fx;
          by += ds * fy;
          bz += ds * fz;
          ss += ds * ds;
          tx += dt * fx;
          ty += dt * fy;
          tz += dt * fz;
          st += dt * ds;
          tt += dt * dt;
        }
        const float det = ss * tt - st * st;
        const float inv = det != 0.0f ? 1.0f / det : 0.0f;
        out[i] = (tt * bx - st * tx) * inv;
        out[stride + i] = (tt * by - st * ty) * inv;
        out[2 * stride + i] = (tt * bz - st * tz) * inv;
        out[3 * stride + i] = (ss * tx - st * bx) * inv;
        out[4 * stride + i] = (ss * ty - st * by) * inv;
        out[5 * stride + i] = (ss * tz - st * bz) * inv;
      }
    }
    if (!Store)
    {
      benchmark::DoNotOptimize(scratch.data());
      benchmark::ClobberMemory();
    }
  }
};

template <bool Store>
void StencilFits(Grid& g)
{
  vtkSMPTools::For(1, NV - 1, 8, StencilWorker<Store>{ g });
}

// Per derivative, the largest |fit - truth| over interior points divided by the largest |truth|
// (n_s vanishes on the tube's top and bottom), the larger of the two; the truth from fourth-order
// central differences of the closed-form unit normal.
double FitError(const Grid& g)
{
  const Surface torus = Torus();
  const double h = 1e-3;
  double error[2] = { 0.0, 0.0 }, size[2] = { 0.0, 0.0 };
  for (vtkIdType j = 1; j < NV - 1; j += 7)
  {
    for (vtkIdType i = 1; i < NU - 1; i += 5)
    {
      const double u = static_cast<double>(i) / U, v = static_cast<double>(j) / V;
      const Vec du = Add(Add(Unit(torus.N(u - 2 * h, v)), Unit(torus.N(u + 2 * h, v)), -1.0),
        Add(Unit(torus.N(u + h, v)), Unit(torus.N(u - h, v)), -1.0), 8.0);
      const Vec dv = Add(Add(Unit(torus.N(u, v - 2 * h)), Unit(torus.N(u, v + 2 * h)), -1.0),
        Add(Unit(torus.N(u, v + h)), Unit(torus.N(u, v - h)), -1.0), 8.0);
      const vtkIdType k = j * NU + i;
      for (int a = 0; a < 2; ++a)
      {
        const Vec truth = a == 0 ? du : dv;
        Vec fit;
        for (int c = 0; c < 3; ++c)
        {
          fit[c] = g.Fits[(3 * a + c) * N + k] * (12.0 * h);
        }
        const Vec d = Add(fit, truth, -1.0);
        error[a] = std::max(error[a], std::sqrt(DotV(d, d)));
        size[a] = std::max(size[a], std::sqrt(DotV(truth, truth)));
      }
    }
  }
  return std::max(error[0] / size[0], error[1] / size[1]);
}

enum Stage
{
  Check = 1,
  Normals = 2,
  Fits = 4,
  FitsNoStores = 8,
  All = Check | Normals | Fits
};

// Times the @a stages, one after the other as a path would run them (the fits alone read unit
// normals made before the timing).
void BM_Stages(benchmark::State& state, int stages)
{
  // Every core, as the filter's benchmark runs it by default.
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
  Grid& g = TheGrid();
  if ((stages & Check) && !g.Conn)
  {
    state.SkipWithError("the mesh's cells are not in 64-bit storage");
    return;
  }
  if (!g.Normals || !g.TCoords)
  {
    state.SkipWithError("the mesh's normals or texture coordinates are not float arrays");
    return;
  }
  if ((stages & (Fits | FitsNoStores)) && !(stages & Normals))
  {
    UnitNormalsSoA(g);
  }
  bool ok = true;
  for (auto _ : state)
  {
    if (stages & Check)
    {
      ok = GridCheck(g);
    }
    if (stages & Normals)
    {
      UnitNormalsSoA(g);
    }
    if (stages & Fits)
    {
      StencilFits<true>(g);
    }
    if (stages & FitsNoStores)
    {
      StencilFits<false>(g);
    }
    benchmark::DoNotOptimize(ok);
    benchmark::ClobberMemory();
  }
  if (!ok)
  {
    state.SkipWithError("the benchmark's mesh was not recognised as the grid");
    return;
  }
  if (stages & Fits)
  {
    state.counters["fit_rel_err"] = FitError(g);
  }
  state.SetItemsProcessed(state.iterations() * N);
}
} // namespace

BENCHMARK_CAPTURE(BM_Stages, GridCheck, Check)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Stages, UnitNormalsSoA, Normals)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Stages, StencilFits, Fits)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Stages, StencilFitsNoStores, FitsNoStores)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK_CAPTURE(BM_Stages, AllStages, All)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
