// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNormalMapBaker: the seed 000 torus displaced by vtkDisplacementMapFilter into 1M
// triangles, baked onto a 32 x 16 coarse torus into 1024^2 and 2048^2 maps at 1 and 2
// threads: time, rays per second (one ray per covered texel) and peak memory. A 64^2 bake
// shows the fixed cost (reading the meshes, building the hierarchy).
//
// Then the same rays, a sample of them, through VTK's locators (vtkStaticCellLocator,
// vtkModifiedBSPTree) as the baker would have to cast them: one segment each way, the nearer
// hit kept; the build of each locator is timed apart. See BENCHMARKS.md.
//
// With SURFACEDETAIL_BAKE_MESHES=<folder> set, nothing is timed: the coarse and the detailed
// mesh are written there as coarse.obj and detailed.obj (positions, texture coordinates and
// normals), so that another baker can be timed on exactly this pair
// (scripts/bench-blender-bake.sh, Testing/Benchmarks/BlenderBake.py).
#include "NormalMapBakerTestFrames.h"

#include "vtkNormalMapBaker.h"

#include <vtkGenericCell.h>
#include <vtkModifiedBSPTree.h>
#include <vtkOBJWriter.h>
#include <vtkSMPTools.h>
#include <vtkStaticCellLocator.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>

namespace
{
using namespace DisplacementTest;
constexpr int CoarseU = 32, CoarseV = 16;
constexpr double Reach = 0.2;

vtkPolyData* DetailedTorus()
{
  static vtkSmartPointer<vtkPolyData> mesh = Detailed(Torus(), 1000, 500); // 1,000,000 triangles
  return mesh;
}

vtkPolyData* CoarseTorus()
{
  static vtkSmartPointer<vtkPolyData> mesh = MakeMesh(Torus(), CoarseU, CoarseV, false);
  return mesh;
}

// A field of /proc/self/status in MiB (VmRSS: now; VmHWM: the peak since the last reset).
double StatusMiB(const std::string& field)
{
  std::ifstream status("/proc/self/status");
  std::string key;
  double kib = 0.0;
  while (status >> key)
  {
    if (key == field + ":")
    {
      status >> kib;
      return kib / 1024.0;
    }
    status.ignore(1 << 16, '\n');
  }
  return 0.0;
}

// Makes VmHWM start again from the resident size now (Linux 4.0 and later).
void ResetPeak()
{
  std::ofstream("/proc/self/clear_refs") << "5";
}

// One thread is the sequential backend: VTK 9.1's TBB backend did not always hold
// Initialize(1) (see BenchMikkTSpaceTangents.cxx).
void SetThreads(int threads)
{
  if (threads == 1)
  {
    vtkSMPTools::SetBackend("Sequential");
  }
  else
  {
    vtkSMPTools::SetBackend("TBB");
    vtkSMPTools::Initialize(threads);
  }
}

void BM_NormalMapBaker(benchmark::State& state)
{
  const int size = static_cast<int>(state.range(0));
  SetThreads(static_cast<int>(state.range(1)));
  vtkPolyData* detailed = DetailedTorus();
  vtkPolyData* coarse = CoarseTorus();
  const double resident = StatusMiB("VmRSS");
  double peak = 0.0;
  vtkIdType rays = 0;
  for (auto _ : state)
  {
    ResetPeak();
    vtkNew<vtkNormalMapBaker> baker;
    baker->SetInputData(0, coarse);
    baker->SetInputData(1, detailed);
    baker->SetTextureSize(size, size);
    baker->SetMaxRayDistance(Reach);
    baker->BakeHeightOn();
    baker->Update();
    rays = baker->GetNumberOfCoveredTexels();
    peak = std::max(peak, StatusMiB("VmHWM"));
  }
  state.counters["rays"] = static_cast<double>(rays);
  state.counters["rays_per_s"] =
    benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_MiB"] = peak;
  state.counters["above_inputs_MiB"] = peak - resident;
  vtkSMPTools::SetBackend("TBB");
  vtkSMPTools::Initialize(0);
}

// The nearer of the hits along +N and -N within Reach, one texel in every 8 x 8 of a 1024^2
// map (16,384 rays), on one thread.
template <typename Locator>
void BM_VTKLocator(benchmark::State& state)
{
  vtkPolyData* detailed = DetailedTorus();
  vtkPolyData* coarse = CoarseTorus();
  std::vector<Frame> frames;
  for (int j = 4; j < 1024; j += 8)
  {
    for (int i = 4; i < 1024; i += 8)
    {
      frames.push_back(CoarseFrame(coarse, CoarseU, CoarseV, (i + 0.5) / 1024, (j + 0.5) / 1024));
    }
  }
  double buildSeconds = 0.0, castSeconds = 0.0;
  int hits = 0;
  for (auto _ : state)
  {
    const auto start = std::chrono::steady_clock::now();
    vtkNew<Locator> locator;
    locator->SetDataSet(detailed);
    locator->BuildLocator();
    const auto built = std::chrono::steady_clock::now();
    vtkNew<vtkGenericCell> cell;
    hits = 0;
    for (const Frame& f : frames)
    {
      double nearest = VTK_DOUBLE_MAX;
      for (double sign : { 1.0, -1.0 })
      {
        const Vec end = Add(f.P, f.N, sign * Reach);
        double t, x[3], pcoords[3];
        int subId;
        vtkIdType cellId;
        const Vec p = f.P;
        if (locator->IntersectWithLine(
              p.data(), end.data(), 0.0, t, x, pcoords, subId, cellId, cell))
        {
          nearest = std::min(nearest, t);
        }
      }
      hits += nearest <= 1.0;
    }
    const auto cast = std::chrono::steady_clock::now();
    buildSeconds = std::chrono::duration<double>(built - start).count();
    castSeconds = std::chrono::duration<double>(cast - built).count();
  }
  state.counters["build_ms"] = 1000.0 * buildSeconds;
  state.counters["rays_per_s"] = static_cast<double>(frames.size()) / castSeconds;
  state.counters["hit_fraction"] = static_cast<double>(hits) / frames.size();
}

// A Wavefront OBJ of the mesh with its texture coordinates and normals.
bool WriteOBJ(vtkPolyData* mesh, const std::string& fileName)
{
  vtkNew<vtkOBJWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(fileName.c_str());
  return writer->Write() == 1;
}
} // namespace

BENCHMARK(BM_NormalMapBaker)
  ->ArgsProduct({ { 64, 1024, 2048 }, { 1, 2 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MeasureProcessCPUTime();
BENCHMARK_TEMPLATE(BM_VTKLocator, vtkStaticCellLocator)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->Iterations(1);
BENCHMARK_TEMPLATE(BM_VTKLocator, vtkModifiedBSPTree)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->Iterations(1);

int main(int argc, char** argv)
{
  if (const char* folder = std::getenv("SURFACEDETAIL_BAKE_MESHES"))
  {
    const std::string prefix = std::string(folder) + "/";
    return WriteOBJ(CoarseTorus(), prefix + "coarse.obj") &&
        WriteOBJ(DetailedTorus(), prefix + "detailed.obj")
      ? EXIT_SUCCESS
      : EXIT_FAILURE;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
  {
    return EXIT_FAILURE;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return EXIT_SUCCESS;
}
