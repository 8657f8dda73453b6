// vtkMikkTSpaceTangents against VTK's vtkPolyDataTangents on the same 1,000,000-triangle
// torus, at 1 and 2 threads; then the reference MikkTSpace (npm package "mikktspace", run
// by node) on the same triangles, for a note of its time. See BENCHMARKS.md.
#include "MikkTSpaceTestMeshes.h"

#include "vtkMikkTSpaceTangents.h"
#include "vtkPolyDataTangents.h"
#include "vtkSMPTools.h"

#include <benchmark/benchmark.h>

#include <iostream>
#include <string>

namespace
{
vtkPolyData* Torus()
{
  // 1000 x 500 cells, two triangles each
  static vtkSmartPointer<vtkPolyData> mesh = mikktest::MakeTorus(1000, 500);
  return mesh;
}

template <typename Filter>
void RunFilter(benchmark::State& state)
{
  // One thread is the sequential backend: with VTK 9.1's TBB backend, Initialize(1) did not
  // always hold in this program (the 1-thread rows ran on both cores: wall time below the
  // process's CPU time), while the sequential backend cannot use a second core.
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
  vtkPolyData* mesh = Torus();
  for (auto _ : state)
  {
    vtkNew<Filter> filter;
    filter->SetInputData(mesh);
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetNumberOfPoints());
  }
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
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MeasureProcessCPUTime();
BENCHMARK(BM_vtkMikkTSpaceTangents)
  ->Arg(1)
  ->Arg(2)
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
  vtkPolyData* mesh = Torus();
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
  if (mikktest::ReferenceTangents(corners, "bench", 5).empty())
  {
    std::cerr << "The reference did not run: build the tests' fixture first (ctest -R "
                 "MikkTSpaceReferenceInstall) so that " MIKKTSPACE_NPM_DIR " has the package.\n";
    return 1;
  }
  return 0;
}
