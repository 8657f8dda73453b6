// vtkParametricSurfaceSource against VTK's own way of getting the same arrays, in one run:
// - torus: vtkParametricFunctionSource (points, normals, texture coordinates) followed by
//   vtkPolyDataTangents, both on vtkParametricTorus;
// - sphere: vtkTexturedSphereSource (points, normals, texture coordinates);
// - the bound: allocating and writing the same number of output bytes with memset, which
//   no generator can beat.
// Sizes are 1M and 4M points; the second argument is the number of threads given to
// vtkSMPTools::Initialize. See BENCHMARKS.md for the command and the figures.

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkParametricDonut.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkParametricTorus.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataTangents.h>
#include <vtkSMPTools.h>
#include <vtkTexturedSphereSource.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <memory>

namespace
{
// Grid side for a given number of points: side x side points.
int Side(benchmark::State& state)
{
  return static_cast<int>(std::lround(std::sqrt(static_cast<double>(state.range(0)))));
}

void SetThreads(benchmark::State& state)
{
  vtkSMPTools::Initialize(static_cast<int>(state.range(1)));
}

size_t OutputBytes(vtkPolyData* pd)
{
  size_t bytes = pd->GetPoints()->GetData()->GetActualMemorySize();
  for (int a = 0; a < pd->GetPointData()->GetNumberOfArrays(); ++a)
  {
    bytes += pd->GetPointData()->GetArray(a)->GetActualMemorySize();
  }
  bytes += pd->GetPolys()->GetActualMemorySize();
  return bytes * 1024;
}

void Report(benchmark::State& state, vtkPolyData* pd)
{
  state.counters["points"] = static_cast<double>(pd->GetNumberOfPoints());
  state.counters["MB"] = static_cast<double>(OutputBytes(pd)) / 1e6;
}

// Ours on VTK's own vtkParametricTorus (a virtual Evaluate with its trigonometry at every
// point): every array the VTK pair gives (normals, texture coordinates, tangents), and
// with range(2) the derivatives too.
void BM_SurfaceSourceTorus(benchmark::State& state)
{
  SetThreads(state);
  const int side = Side(state);
  vtkNew<vtkParametricTorus> torus;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(side - 1);
  source->SetVResolution(side - 1);
  source->GenerateTangentsOn();
  source->SetGenerateDerivatives(state.range(2) != 0);
  for (auto _ : state)
  {
    source->Modified();
    source->Update();
    benchmark::DoNotOptimize(source->GetOutput()->GetPoints());
  }
  Report(state, source->GetOutput());
}

// Ours on seed 000's donut: the same surface as vtkParametricTorus up to a mirror, but a
// vtkParametricSeparableFunction, so its trigonometry is done per row and column.
void BM_SurfaceSourceDonut(benchmark::State& state)
{
  SetThreads(state);
  const int side = Side(state);
  vtkNew<vtkParametricDonut> donut;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(donut);
  source->SetUResolution(side - 1);
  source->SetVResolution(side - 1);
  source->GenerateTangentsOn();
  source->SetGenerateDerivatives(state.range(2) != 0);
  for (auto _ : state)
  {
    source->Modified();
    source->Update();
    benchmark::DoNotOptimize(source->GetOutput()->GetPoints());
  }
  Report(state, source->GetOutput());
}

// VTK's pair on the same torus.
void BM_VTKFunctionSourceAndTangentsTorus(benchmark::State& state)
{
  SetThreads(state);
  const int side = Side(state);
  vtkNew<vtkParametricTorus> torus;
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(side);
  source->SetVResolution(side);
  source->GenerateTextureCoordinatesOn();
  source->SetScalarModeToNone();
  vtkNew<vtkPolyDataTangents> tangents;
  tangents->SetInputConnection(source->GetOutputPort());
  for (auto _ : state)
  {
    source->Modified();
    tangents->Update();
    benchmark::DoNotOptimize(tangents->GetOutput()->GetPoints());
  }
  Report(state, tangents->GetOutput());
}

// Ours, sphere: the arrays vtkTexturedSphereSource gives (normals, texture coordinates), and
// with range(2) tangents and derivatives as well.
void BM_SurfaceSourceSphere(benchmark::State& state)
{
  SetThreads(state);
  const int side = Side(state);
  vtkNew<vtkParametricSphere> sphere;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(sphere);
  source->SetUResolution(side - 1);
  source->SetVResolution(side - 1);
  source->SetGenerateTangents(state.range(2) != 0);
  source->SetGenerateDerivatives(state.range(2) != 0);
  for (auto _ : state)
  {
    source->Modified();
    source->Update();
    benchmark::DoNotOptimize(source->GetOutput()->GetPoints());
  }
  Report(state, source->GetOutput());
}

void BM_VTKTexturedSphereSource(benchmark::State& state)
{
  SetThreads(state);
  const int side = Side(state);
  vtkNew<vtkTexturedSphereSource> source;
  source->SetThetaResolution(side - 1);
  source->SetPhiResolution(side - 1);
  for (auto _ : state)
  {
    source->Modified();
    source->Update();
    benchmark::DoNotOptimize(source->GetOutput()->GetPoints());
  }
  Report(state, source->GetOutput());
}

// The bandwidth bound: allocate and write range(2) bytes per point (the output of the
// matching source configuration), split among the threads.
void BM_WriteBound(benchmark::State& state)
{
  SetThreads(state);
  const int side = Side(state);
  const size_t bytes = static_cast<size_t>(side) * side * static_cast<size_t>(state.range(2));
  for (auto _ : state)
  {
    std::unique_ptr<char[]> buffer(new char[bytes]);
    char* data = buffer.get();
    vtkSMPTools::For(0, static_cast<vtkIdType>(bytes), 1 << 20,
      [data](vtkIdType begin, vtkIdType end)
      { std::memset(data + begin, 1, static_cast<size_t>(end - begin)); });
    benchmark::DoNotOptimize(data);
    benchmark::ClobberMemory();
  }
  state.counters["MB"] = static_cast<double>(bytes) / 1e6;
}

// Bytes per point written by our source: points 12, normals 12, tcoords 8, tangents 16,
// derivatives 24, and 2 triangles = 2 x (3 + 1) 32-bit ids.
constexpr int BytesSphere = 12 + 12 + 8 + 32;
constexpr int BytesTorus = BytesSphere + 16;
constexpr int BytesAll = BytesTorus + 24;

void Sizes(benchmark::internal::Benchmark* b, int variants)
{
  for (int points : { 1000000, 4000000 })
  {
    for (int threads : { 1, 2 })
    {
      for (int variant = 0; variant < variants; ++variant)
      {
        b->Args({ points, threads, variant });
      }
    }
  }
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}
} // namespace

BENCHMARK(BM_SurfaceSourceTorus)->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 2); });
BENCHMARK(BM_SurfaceSourceDonut)->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 2); });
BENCHMARK(BM_VTKFunctionSourceAndTangentsTorus)
  ->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 1); });
BENCHMARK(BM_SurfaceSourceSphere)->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 2); });
BENCHMARK(BM_VTKTexturedSphereSource)
  ->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 1); });
BENCHMARK(BM_WriteBound)
  ->Apply(
    [](benchmark::internal::Benchmark* b)
    {
      for (int points : { 1000000, 4000000 })
      {
        for (int threads : { 1, 2 })
        {
          for (int bytes : { BytesSphere, BytesTorus, BytesAll })
          {
            b->Args({ points, threads, bytes });
          }
        }
      }
      b->Unit(benchmark::kMillisecond)->UseRealTime();
    });

BENCHMARK_MAIN();
