// vtkMikkTSpaceTangents against VTK's vtkPolyDataTangents on the same tori of about 1M and
// 4M points (2M and 8M triangles), at 1 and 2 threads; then the reference MikkTSpace (npm
// package "mikktspace", run by node) on the same triangles, whose median time it prints
// (one thread: it is single-threaded WebAssembly).
// See BENCHMARKS.md.
#include "MikkTSpaceTestMeshes.h"

#include "vtkMikkTSpaceTangents.h"
#include "vtkPolyDataTangents.h"
#include "vtkSMPTools.h"

#include <benchmark/benchmark.h>

#include <iostream>
#include <string>

namespace
{
// Torus of (nu+1) x (nv+1) points, nu = 2 nv: about 1M points for size 0, 4M for size 1.
vtkPolyData* Torus(int size)
{
  static vtkSmartPointer<vtkPolyData> meshes[2];
  if (!meshes[size])
  {
    const int nv = size == 0 ? 706 : 1413;
    meshes[size] = mikktest::MakeTorus(2 * nv, nv);
  }
  return meshes[size];
}

template <typename Filter>
void RunFilter(benchmark::State& state)
{
  // One thread is the sequential backend: with VTK 9.1's TBB backend, Initialize(1) did not
  // always hold (the 1-thread rows ran on both cores: wall time below the process's CPU
  // time), while the sequential backend cannot use a second core.
  const std::string backend = vtkSMPTools::GetBackend();
  const int threads = static_cast<int>(state.range(0));
  if (threads == 1)
  {
    vtkSMPTools::SetBackend("Sequential");
  }
  else
  {
    vtkSMPTools::Initialize(threads);
  }
  vtkPolyData* mesh = Torus(static_cast<int>(state.range(1)));
  for (auto _ : state)
  {
    vtkNew<Filter> filter;
    filter->SetInputData(mesh);
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetNumberOfPoints());
  }
  state.counters["points"] = static_cast<double>(mesh->GetNumberOfPoints());
  state.counters["triangles"] = static_cast<double>(mesh->GetNumberOfPolys());
  vtkSMPTools::SetBackend(backend.c_str());
  vtkSMPTools::Initialize(0);
}

void BM_vtkPolyDataTangents(benchmark::State& state)
{
  RunFilter<vtkPolyDataTangents>(state);
}

void BM_vtkMikkTSpaceTangents(benchmark::State& state)
{
  RunFilter<vtkMikkTSpaceTangents>(state);
}
} // namespace

// CPU time of the whole process: with TBB the work can run on worker threads even at one
// thread, and the main thread's own CPU time then leaves part of it out.
BENCHMARK(BM_vtkPolyDataTangents)
  ->ArgsProduct({ { 1, 2 }, { 0, 1 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MeasureProcessCPUTime();
BENCHMARK(BM_vtkMikkTSpaceTangents)
  ->ArgsProduct({ { 1, 2 }, { 0, 1 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MeasureProcessCPUTime();

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
  {
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  // The reference on the same triangles, unindexed as it takes them (single-threaded WASM).
  for (int size : { 0, 1 })
  {
    vtkPolyData* mesh = Torus(size);
    mikktest::Corners corners;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    {
      mesh->GetCellPoints(c, ids);
      for (vtkIdType k = 0; k < 3; ++k)
      {
        corners.Add(mesh, ids->GetId(k));
      }
    }
    std::cout << "reference, " << mesh->GetNumberOfPoints() << " points: " << std::flush;
    // Three timed calls at 1M points, one at 4M (the reference is slow there), each after
    // an untimed one.
    if (mikktest::ReferenceTangents(corners, "bench", size == 0 ? 3 : 1).empty())
    {
      std::cerr << "The reference did not run: build the tests' fixture first (ctest -R "
                   "MikkTSpaceReferenceInstall) so that " MIKKTSPACE_NPM_DIR " has the package.\n";
      return 1;
    }
  }
  return 0;
}
