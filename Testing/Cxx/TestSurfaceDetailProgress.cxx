// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Every long algorithm reports progress that only grows and reaches 1, and stops early with an
// empty output (and no error) when a progress observer sets AbortExecute part-way.

#include "vtkDisplacementMapFilter.h"
#include "vtkHeightMapToNormalMap.h"
#include "vtkMikkTSpaceTangents.h"
#include "vtkNormalMapBaker.h"
#include "vtkParametricDonut.h"
#include "vtkParametricSurfaceSource.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace
{
// The progress values an algorithm reports; with AbortAt > 0, sets AbortExecute at the first
// value at or above it.
struct Watcher
{
  std::vector<double> Values;
  double AbortAt = 0.0;
  int Errors = 0;

  static void OnProgress(vtkObject* caller, unsigned long, void* data, void* callData)
  {
    auto* self = static_cast<Watcher*>(data);
    const double value = *static_cast<double*>(callData);
    self->Values.push_back(value);
    if (self->AbortAt > 0.0 && value >= self->AbortAt)
    {
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  }

  static void OnError(vtkObject*, unsigned long, void* data, void*)
  {
    ++static_cast<Watcher*>(data)->Errors;
  }

  void Watch(vtkAlgorithm* algorithm)
  {
    vtkNew<vtkCallbackCommand> progress, error;
    progress->SetCallback(&Watcher::OnProgress);
    progress->SetClientData(this);
    error->SetCallback(&Watcher::OnError);
    error->SetClientData(this);
    algorithm->AddObserver(vtkCommand::ProgressEvent, progress);
    algorithm->AddObserver(vtkCommand::ErrorEvent, error);
  }
};

vtkSmartPointer<vtkPolyData> Donut(int u, int v)
{
  vtkNew<vtkParametricDonut> donut;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(donut);
  source->SetUResolution(u);
  source->SetVResolution(v);
  source->GenerateTangentsOn();
  source->Update();
  return source->GetOutput();
}

vtkSmartPointer<vtkImageData> Heights(int w, int h)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* data = static_cast<float*>(image->GetScalarPointer());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      data[j * w + i] = static_cast<float>(0.5 + 0.5 * std::sin(0.05 * i) * std::cos(0.07 * j));
    }
  }
  return image;
}

// The number of points or texels of @a algorithm's first output.
vtkIdType OutputSize(vtkAlgorithm* algorithm)
{
  return vtkDataSet::SafeDownCast(algorithm->GetOutputDataObject(0))->GetNumberOfPoints();
}

// Runs @a algorithm (made by @a make) once watched to the end, once aborted at 0.4.
void CheckProgressAndAbort(
  const std::string& what, std::function<vtkSmartPointer<vtkAlgorithm>()> make)
{
  SCOPED_TRACE(what);
  {
    vtkSmartPointer<vtkAlgorithm> algorithm = make();
    Watcher watcher;
    watcher.Watch(algorithm);
    algorithm->Update();
    ASSERT_GT(OutputSize(algorithm), 0);
    ASSERT_GE(watcher.Values.size(), 5u) << "too few progress events to show the loop's";
    for (size_t k = 1; k < watcher.Values.size(); ++k)
    {
      EXPECT_GE(watcher.Values[k], watcher.Values[k - 1]) << "event " << k;
    }
    EXPECT_EQ(watcher.Values.back(), 1.0);
    EXPECT_EQ(watcher.Errors, 0);
  }
  {
    vtkSmartPointer<vtkAlgorithm> algorithm = make();
    Watcher watcher;
    watcher.AbortAt = 0.4;
    watcher.Watch(algorithm);
    algorithm->Update();
    EXPECT_EQ(OutputSize(algorithm), 0);
    EXPECT_EQ(watcher.Errors, 0);
    // The loop stops where it was told to: the event that asked for it is the last one, and
    // none reports the work finished.
    const auto asked = std::find_if(
      watcher.Values.begin(), watcher.Values.end(), [&](double v) { return v >= watcher.AbortAt; });
    ASSERT_NE(asked, watcher.Values.end());
    EXPECT_EQ(asked + 1, watcher.Values.end())
      << "after " << *asked << ": " << watcher.Values.back() << " ("
      << (watcher.Values.end() - asked - 1) << " more)";
    EXPECT_LT(watcher.Values.back(), 1.0);
  }
}
}

TEST(SurfaceDetailProgress, ParametricSurfaceSource)
{
  CheckProgressAndAbort("source",
    []
    {
      vtkNew<vtkParametricDonut> donut;
      auto source = vtkSmartPointer<vtkParametricSurfaceSource>::New();
      source->SetParametricFunction(donut);
      source->SetUResolution(600);
      source->SetVResolution(300);
      source->GenerateTangentsOn();
      return vtkSmartPointer<vtkAlgorithm>(source);
    });
}

TEST(SurfaceDetailProgress, DisplacementMapFilter)
{
  auto mesh = Donut(600, 300);
  auto image = Heights(256, 128);
  for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
         vtkDisplacementMapFilter::Mesh })
  {
    CheckProgressAndAbort("displacement, mode " + std::to_string(mode),
      [&]
      {
        auto filter = vtkSmartPointer<vtkDisplacementMapFilter>::New();
        filter->SetInputData(mesh);
        filter->SetSourceData(image);
        filter->SetNormalMode(mode);
        filter->SetScaleFactor(0.05);
        return vtkSmartPointer<vtkAlgorithm>(filter);
      });
  }
}

TEST(SurfaceDetailProgress, MikkTSpaceTangents)
{
  auto mesh = Donut(600, 300);
  CheckProgressAndAbort("MikkTSpace",
    [&]
    {
      auto filter = vtkSmartPointer<vtkMikkTSpaceTangents>::New();
      filter->SetInputData(mesh);
      return vtkSmartPointer<vtkAlgorithm>(filter);
    });
}

TEST(SurfaceDetailProgress, HeightMapToNormalMap)
{
  auto image = Heights(2048, 1024);
  CheckProgressAndAbort("height map",
    [&]
    {
      auto filter = vtkSmartPointer<vtkHeightMapToNormalMap>::New();
      filter->SetInputData(image);
      return vtkSmartPointer<vtkAlgorithm>(filter);
    });
}

TEST(SurfaceDetailProgress, NormalMapBaker)
{
  auto coarse = Donut(32, 16);
  auto detailed = Donut(400, 200);
  CheckProgressAndAbort("baker",
    [&]
    {
      auto baker = vtkSmartPointer<vtkNormalMapBaker>::New();
      baker->SetInputData(coarse);
      baker->SetSourceData(detailed);
      baker->SetTextureSize(512, 256);
      baker->SetMaxRayDistance(0.05);
      return vtkSmartPointer<vtkAlgorithm>(baker);
    });
}
