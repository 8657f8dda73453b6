// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkMikkTSpaceTangents against VTK's vtkPolyDataTangents and against the floor (the bytes
// the filter must write) on the same tori of about 1M and 4M points (2M and 8M triangles),
// at 1 and 2 threads, first execution (fresh pages, BenchmarkMemory.h) and re-execution
// (memory used before); then the ratios ours/floor and VTK/ours, and the
// reference MikkTSpace (npm package "mikktspace", run by node) on the same triangles, whose
// median time it prints (one thread: it is single-threaded WebAssembly).
// See BENCHMARKS.md.
#include "BenchmarkMemory.h"
#include "MikkTSpaceTestMeshes.h"

#include "vtkFloatArray.h"
#include "vtkMikkTSpaceTangents.h"
#include "vtkPolyDataTangents.h"
#include "vtkSMPTools.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <iostream>
#include <map>
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

// One thread is the sequential backend: with VTK 9.1's TBB backend, Initialize(1) did not
// always hold (the 1-thread rows ran on both cores: wall time below the process's CPU
// time), while the sequential backend cannot use a second core.
class Threads
{
public:
  explicit Threads(int threads)
    : Backend(vtkSMPTools::GetBackend())
  {
    if (threads == 1)
    {
      vtkSMPTools::SetBackend("Sequential");
    }
    else
    {
      vtkSMPTools::Initialize(threads);
    }
  }
  ~Threads()
  {
    vtkSMPTools::SetBackend(this->Backend.c_str());
    vtkSMPTools::Initialize(0);
  }

private:
  const std::string Backend;
};

// Arguments: threads, mesh size, 0 for first execution and 1 for re-execution.
template <typename Filter>
void RunFilter(benchmark::State& state)
{
  const Threads threads(static_cast<int>(state.range(0)));
  const bool fresh = state.range(2) == 0;
  BenchmarkMemory::UseFreshPages(fresh);
  vtkPolyData* mesh = Torus(static_cast<int>(state.range(1)));
  vtkNew<Filter> filter;
  filter->SetInputData(mesh);
  filter->Update();
  for (auto _ : state)
  {
    BenchmarkMemory::BeginIteration(state, fresh, [&] { filter->GetOutput()->ReleaseData(); });
    filter->Modified();
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetNumberOfPoints());
  }
  state.counters["points"] = static_cast<double>(mesh->GetNumberOfPoints());
  state.counters["triangles"] = static_cast<double>(mesh->GetNumberOfPolys());
}

void BM_vtkPolyDataTangents(benchmark::State& state)
{
  RunFilter<vtkPolyDataTangents>(state);
}

void BM_vtkMikkTSpaceTangents(benchmark::State& state)
{
  RunFilter<vtkMikkTSpaceTangents>(state);
}

// The floor: what vtkMikkTSpaceTangents must write on these meshes, 16 bytes per point (the
// 3-component float tangents and the float handedness; the points, point data and cells are
// passed on, and no point is split), written by the threads as one array. Fresh (first execution):
// a new array at every iteration, its pages faulted and cleared by the kernel; warm (re-execution):
// the same array again.
void BM_Floor(benchmark::State& state)
{
  const Threads threads(static_cast<int>(state.range(0)));
  const bool fresh = state.range(2) == 0;
  BenchmarkMemory::UseFreshPages(fresh);
  const vtkIdType n = Torus(static_cast<int>(state.range(1)))->GetNumberOfPoints();
  auto allocate = [n]()
  {
    auto tangents = vtkSmartPointer<vtkFloatArray>::New();
    tangents->SetNumberOfComponents(4);
    tangents->SetNumberOfTuples(n);
    return tangents;
  };
  vtkSmartPointer<vtkFloatArray> tangents = allocate();
  for (auto _ : state)
  {
    BenchmarkMemory::BeginIteration(state, fresh, [&] { tangents = nullptr; });
    if (fresh)
    {
      tangents = allocate();
    }
    float* t = tangents->GetPointer(0);
    vtkSMPTools::For(0, n,
      [t](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          t[4 * i] = static_cast<float>(i);
          t[4 * i + 1] = 0.0f;
          t[4 * i + 2] = 0.0f;
          t[4 * i + 3] = 1.0f;
        }
      });
    benchmark::DoNotOptimize(t);
    benchmark::ClobberMemory();
  }
  state.counters["MB"] = 16.0 * static_cast<double>(n) / 1e6;
}

// The console's report, and each case's real time (the median when there are repetitions)
// for the ratios.
class Reporter : public benchmark::ConsoleReporter
{
public:
  void ReportRuns(const std::vector<Run>& runs) override
  {
    this->ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs)
    {
      const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      if (run.run_type == Run::RT_Iteration || median)
      {
        const std::string name = run.run_name.function_name + "/" + run.run_name.args;
        if (median || !this->HasMedian.count(name))
        {
          this->Times[name] = run.GetAdjustedRealTime();
        }
        this->HasMedian[name] = this->HasMedian[name] || median;
      }
    }
  }

  // The ratios ours/floor and VTK/ours of each case that ran all three.
  void PrintRatios() const
  {
    std::printf("\n| threads | points | execution | ours / floor | VTK / ours |\n");
    std::printf("|---:|---:|---|---:|---:|\n");
    for (const char* threads : { "1", "2" })
    {
      for (const char* size : { "0", "1" })
      {
        for (const char* mode : { "0", "1" })
        {
          const std::string args = std::string(threads) + "/" + size + "/" + mode;
          const auto floor = this->Times.find("BM_Floor/" + args);
          const auto ours = this->Times.find("BM_vtkMikkTSpaceTangents/" + args);
          const auto vtk = this->Times.find("BM_vtkPolyDataTangents/" + args);
          if (floor == this->Times.end() || ours == this->Times.end() || vtk == this->Times.end())
          {
            continue;
          }
          std::printf("| %s | %s | %s | %.1f | %.2f |\n", threads, size[0] == '0' ? "1M" : "4M",
            mode[0] == '0' ? "first" : "re-execution", ours->second / floor->second,
            vtk->second / ours->second);
        }
      }
    }
  }

private:
  std::map<std::string, double> Times;
  std::map<std::string, bool> HasMedian;
};
} // namespace

// Threads x size x execution. CPU time of the whole process: with TBB the work can run on
// worker threads even at one thread, and the main thread's own CPU time then leaves part of
// it out.
void Cases(benchmark::internal::Benchmark* b)
{
  b->ArgsProduct({ { 1, 2 }, { 0, 1 }, { 0, 1 } })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
}
BENCHMARK(BM_Floor)->Apply(Cases);
BENCHMARK(BM_vtkPolyDataTangents)->Apply(Cases);
BENCHMARK(BM_vtkMikkTSpaceTangents)->Apply(Cases);

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
  {
    return 1;
  }
  Reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  reporter.PrintRatios();

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
