// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkParametricSurfaceSource against VTK's own way of getting the same arrays, in one run:
// - torus: vtkParametricFunctionSource (points, normals, texture coordinates) followed by
//   vtkPolyDataTangents, both on vtkParametricTorus;
// - sphere: vtkTexturedSphereSource (points, normals, texture coordinates);
// - the floor: allocating and writing the same number of output bytes with memset, which
//   no generator can beat, into fresh pages and into memory used before
//   (BenchmarkMemory.h).
// Sizes are 1M and 4M points; the second argument is the number of threads given to
// vtkSMPTools::Initialize. See BENCHMARKS.md for the command and the figures.

#include <vtkBezierProfile.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkParametricDonut.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricRevolution.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkParametricTorus.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataTangents.h>
#include <vtkSMPTools.h>
#include <vtkTexturedSphereSource.h>

#include "BenchmarkMemory.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace
{
// Grid side for a given number of points: side x side points.
int Side(benchmark::State& state)
{
  return static_cast<int>(std::lround(std::sqrt(static_cast<double>(state.range(0)))));
}

// The thread count, and whether each execution writes into fresh pages (a first execution) or
// into memory used before (a re-execution): arguments 1 and 3.
void SetThreads(benchmark::State& state)
{
  vtkSMPTools::Initialize(static_cast<int>(state.range(1)));
  BenchmarkMemory::UseFreshPages(state.range(3) != 0);
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

// Runs our source on @a function at side x side points with the given arrays (normals and
// texture coordinates always), re-executing it at every iteration.
void RunSource(
  benchmark::State& state, vtkParametricFunction* function, bool tangents, bool derivatives)
{
  SetThreads(state);
  const int side = Side(state);
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(function);
  source->SetUResolution(side - 1);
  source->SetVResolution(side - 1);
  source->SetGenerateTangents(tangents);
  source->SetGenerateDerivatives(derivatives);
  for (auto _ : state)
  {
    BenchmarkMemory::BeginIteration(
      state, state.range(3) != 0, [&] { source->GetOutput()->ReleaseData(); });
    source->Modified();
    source->Update();
    benchmark::DoNotOptimize(source->GetOutput()->GetPoints());
  }
  Report(state, source->GetOutput());
}

// Ours on VTK's own vtkParametricTorus (a virtual Evaluate with its trigonometry at every
// point): every array the VTK pair gives (normals, texture coordinates, tangents), and
// with range(2) the derivatives too.
void BM_SurfaceSourceTorus(benchmark::State& state)
{
  vtkNew<vtkParametricTorus> torus;
  RunSource(state, torus, true, state.range(2) != 0);
}

// Ours on seed 000's donut: the same surface as vtkParametricTorus up to a mirror, but a
// vtkParametricSeparableFunction, so its trigonometry is done per row and column.
void BM_SurfaceSourceDonut(benchmark::State& state)
{
  vtkNew<vtkParametricDonut> donut;
  RunSource(state, donut, true, state.range(2) != 0);
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
    BenchmarkMemory::BeginIteration(state, state.range(3) != 0,
      [&]
      {
        source->GetOutput()->ReleaseData();
        tangents->GetOutput()->ReleaseData();
      });
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
  vtkNew<vtkParametricSphere> sphere;
  RunSource(state, sphere, state.range(2) != 0, state.range(2) != 0);
}

// Ours, seed 004's vase (a vtkBezierProfile turned about y), every array; range(2) turns
// the profile's arc-length parameterisation on, which inverts the length integral at
// every row.
void BM_SurfaceSourceVase(benchmark::State& state)
{
  vtkNew<vtkParametricRevolution> vase;
  vase->GetProfile()->SetArcLengthParameterization(state.range(2) != 0);
  RunSource(state, vase, true, true);
}

// One vtkBezierProfile::Evaluate per point, as a caller outside the source pays it (e.g.
// vtkParametricFunctionSource on a vtkParametricRevolution): range(2) = arc length.
void BM_BezierProfileEvaluate(benchmark::State& state)
{
  vtkNew<vtkBezierProfile> profile;
  profile->SetToVase();
  profile->SetArcLengthParameterization(state.range(2) != 0);
  const vtkIdType n = state.range(0);
  for (auto _ : state)
  {
    double sum = 0.0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[2], d1[2];
      profile->Evaluate(static_cast<double>(i) / static_cast<double>(n - 1), p, d1, nullptr);
      sum += p[0] + d1[1];
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["ns/eval"] = benchmark::Counter(static_cast<double>(n),
    benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
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
    BenchmarkMemory::BeginIteration(
      state, state.range(3) != 0, [&] { source->GetOutput()->ReleaseData(); });
    source->Modified();
    source->Update();
    benchmark::DoNotOptimize(source->GetOutput()->GetPoints());
  }
  Report(state, source->GetOutput());
}

// Bytes per point of each array our source writes: points 12, normals 12, tcoords 8, and
// 2 triangles = 24 bytes of 32-bit connectivity + 8 of offsets; then tangents 16; then
// dPdu, dPdv, dNdu and dNdv 12 each. range(2) = 0: sphere arrays, 1: + tangents,
// 2: + derivatives.
std::vector<size_t> ArrayBytesPerPoint(int variant)
{
  std::vector<size_t> bytes = { 12, 12, 8, 24, 8 };
  if (variant >= 1)
  {
    bytes.push_back(16);
  }
  if (variant >= 2)
  {
    bytes.insert(bytes.end(), { 12, 12, 12, 12 });
  }
  return bytes;
}

// The floor: writing the same arrays as the source (one allocation each, as VTK arrays are),
// split among the threads, with memset. range(3) = 1: allocated at every iteration into fresh
// pages, as a first execution's outputs are; 0: allocated at every iteration into memory used
// before, as a re-execution's are.
void BM_WriteBound(benchmark::State& state)
{
  SetThreads(state);
  const int side = Side(state);
  const size_t points = static_cast<size_t>(side) * side;
  std::vector<size_t> sizes;
  for (size_t perPoint : ArrayBytesPerPoint(static_cast<int>(state.range(2))))
  {
    sizes.push_back(perPoint * points);
  }
  std::vector<char*> buffers(sizes.size());
  for (auto _ : state)
  {
    BenchmarkMemory::BeginIteration(state, state.range(3) != 0, [] {});
    for (size_t a = 0; a < sizes.size(); ++a)
    {
      buffers[a] = new char[sizes[a]];
      char* data = buffers[a];
      vtkSMPTools::For(0, static_cast<vtkIdType>(sizes[a]), 1 << 20,
        [data](vtkIdType begin, vtkIdType end)
        { std::memset(data + begin, 1, static_cast<size_t>(end - begin)); });
      benchmark::DoNotOptimize(data);
    }
    benchmark::ClobberMemory();
    for (char* buffer : buffers)
    {
      delete[] buffer;
    }
  }
  size_t total = 0;
  for (size_t size : sizes)
  {
    total += size;
  }
  state.counters["MB"] = static_cast<double>(total) / 1e6;
}

// points x threads x variant x fresh (1: first executions, 0: re-executions).
void Sizes(benchmark::internal::Benchmark* b, int variants)
{
  for (int points : { 1000000, 4000000 })
  {
    for (int threads : { 1, 2 })
    {
      for (int variant = 0; variant < variants; ++variant)
      {
        for (int fresh : { 1, 0 })
        {
          b->Args({ points, threads, variant, fresh });
        }
      }
    }
  }
  b->ArgNames({ "points", "threads", "variant", "fresh" });
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}
} // namespace

BENCHMARK(BM_SurfaceSourceTorus)->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 2); });
BENCHMARK(BM_SurfaceSourceDonut)->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 2); });
BENCHMARK(BM_VTKFunctionSourceAndTangentsTorus)
  ->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 1); });
BENCHMARK(BM_SurfaceSourceSphere)->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 2); });
BENCHMARK(BM_SurfaceSourceVase)->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 2); });
BENCHMARK(BM_BezierProfileEvaluate)
  ->Args({ 1000000, 1, 0, 0 })
  ->Args({ 1000000, 1, 1, 0 })
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VTKTexturedSphereSource)
  ->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 1); });
BENCHMARK(BM_WriteBound)->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, 3); });

BENCHMARK_MAIN();
