// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkHeightMapToConeMap's build time, conservative and relaxed cones, on the brick heights of
// the tests (BrickTextures.h, Repeat) at a given size and thread count, and on round caps
// (RoundCaps.h, the frame-time harness's `caps`), whose open floor gives the widest cones. VTK has no cone map to compare with; the counter
// wider is the mean ratio of relaxed to conservative cones (1 for conservative).
//
//   build/bin/BenchHeightMapToConeMap --benchmark_filter='Bricks/1024'

#include "BrickTextures.h"
#include "RoundCaps.h"

#include "vtkHeightMapToConeMap.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>

namespace
{
vtkImageData* Heights(bool caps, int size)
{
  static std::map<std::pair<bool, int>, vtkSmartPointer<vtkImageData>> made;
  auto& image = made[{ caps, size }];
  if (!image)
  {
    BrickTextures::Layout layout;
    layout.Size = size;
    image = caps ? RoundCaps(size) : BrickTextures::Heights(layout);
  }
  return image;
}

// Arguments: size, cone type, threads.
void Build(benchmark::State& state, bool caps)
{
  vtkSMPTools::Initialize(static_cast<int>(state.range(2)));
  vtkNew<vtkHeightMapToConeMap> filter;
  filter->SetInputData(Heights(caps, static_cast<int>(state.range(0))));
  filter->SetConeType(static_cast<int>(state.range(1)));
  for (auto _ : state)
  {
    filter->Modified();
    filter->Update();
  }
  if (state.range(1) == vtkHeightMapToConeMap::Relaxed)
  {
    vtkNew<vtkHeightMapToConeMap> conservative;
    conservative->SetInputData(filter->GetInput());
    conservative->SetConeTypeToConservative();
    conservative->Update();
    auto* relaxed = vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetScalars());
    auto* narrow =
      vtkFloatArray::SafeDownCast(conservative->GetOutput()->GetPointData()->GetScalars());
    double sum = 0.0;
    for (vtkIdType t = 0; t < relaxed->GetNumberOfTuples(); ++t)
    {
      sum += relaxed->GetValue(2 * t + 1) / narrow->GetValue(2 * t + 1);
    }
    state.counters["wider"] = sum / relaxed->GetNumberOfTuples();
  }
}

void Bricks(benchmark::State& state)
{
  Build(state, false);
}

void RoundCaps(benchmark::State& state)
{
  Build(state, true);
}
}

BENCHMARK(Bricks)
  ->ArgNames({ "size", "relaxed", "threads" })
  ->ArgsProduct({ { 256, 512, 1024, 4096 }, { 0, 1 }, { 1, 2 } })
  ->Unit(benchmark::kSecond)
  ->Iterations(1)
  ->UseRealTime();
BENCHMARK(RoundCaps)
  ->ArgNames({ "size", "relaxed", "threads" })
  ->ArgsProduct({ { 1024 }, { 0, 1 }, { 2 } })
  ->Unit(benchmark::kSecond)
  ->Iterations(1)
  ->UseRealTime();

BENCHMARK_MAIN();
