// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkHeightMapToNormalMap on a 4096x4096 float height map, per scheme and output type,
// against the fastest pipeline of VTK's own imaging filters that produces the same encoded
// normal map:
//   heights with spacing (1/(k*W), 1/(k*H))  -> vtkImageGradient (or vtkImageSobel2D)
//   -> vtkImageAppendComponents with a constant -1 -> vtkImageNormalize
//   -> vtkImageShiftScale (shift -(1 + 1/(2*max)), scale -max/2, clamped): encoded 0.5*n + 0.5.
// The spacing folds Strength into the gradient and the negative scale folds the sign of
// (-k*h_s, -k*h_t, 1) into the encoding, so VTK runs four filters, not five. The constant
// image is built once, outside the timing. Each iteration marks the heights modified so
// both pipelines re-execute fully. The counter max_diff is the largest difference, in output
// units, between the VTK pipeline's map and ours (Central/Sobel, ClampToEdge, as VTK's
// boundary handling duplicates the edge texels) -- a check that both do the same job.

#include "BenchmarkMemory.h"

#include "vtkHeightMapToNormalMap.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageAppendComponents.h>
#include <vtkImageData.h>
#include <vtkImageGradient.h>
#include <vtkImageNormalize.h>
#include <vtkImageShiftScale.h>
#include <vtkImageSobel2D.h>
#include <vtkMultiThreader.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <string>

namespace
{
constexpr int Size = 4096;
constexpr double Strength = 0.05;

// The same heights as 8-bit texels, as most height maps on disk are.
vtkImageData* Heights();
vtkImageData* ByteHeights()
{
  static vtkSmartPointer<vtkImageData> image;
  if (!image)
  {
    vtkNew<vtkImageShiftScale> quantise;
    quantise->SetInputData(Heights());
    quantise->SetScale(255.0);
    quantise->SetOutputScalarTypeToUnsignedChar();
    quantise->ClampOverflowOn();
    quantise->Update();
    image = quantise->GetOutput();
  }
  return image;
}

vtkImageData* Heights()
{
  static vtkSmartPointer<vtkImageData> image;
  if (!image)
  {
    image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(Size, Size, 1);
    vtkNew<vtkFloatArray> h;
    h->SetNumberOfTuples(static_cast<vtkIdType>(Size) * Size);
    for (int j = 0; j < Size; ++j)
    {
      const double t = (j + 0.5) / Size;
      for (int i = 0; i < Size; ++i)
      {
        const double s = (i + 0.5) / Size;
        h->SetValue(static_cast<vtkIdType>(j) * Size + i,
          static_cast<float>(
            0.5 + 0.2 * std::sin(40.0 * s) * std::cos(23.0 * t) + 0.1 * std::sin(310.0 * s * t)));
      }
    }
    image->GetPointData()->SetScalars(h);
  }
  return image;
}

// Limits both thread pools (vtkSMPTools for ours, vtkMultiThreader for VTK's threaded
// imaging filters) for one benchmark; 0 leaves the defaults. With one thread the process
// CPU time is the work done, which the other helpers' compiles on this machine cannot
// inflate the way they inflate wall time.
class ScopedThreads
{
public:
  explicit ScopedThreads(int n)
    : Limited(n > 0)
  {
    if (this->Limited)
    {
      vtkSMPTools::Initialize(n);
      vtkMultiThreader::SetGlobalMaximumNumberOfThreads(n);
    }
  }
  ~ScopedThreads()
  {
    if (this->Limited)
    {
      vtkSMPTools::Initialize();
      vtkMultiThreader::SetGlobalMaximumNumberOfThreads(0);
    }
  }

private:
  bool Limited;
};

const char* TypeName(int type)
{
  return type == VTK_UNSIGNED_CHAR ? "uchar" : type == VTK_UNSIGNED_SHORT ? "ushort" : "float";
}

double TypeTop(int type)
{
  return type == VTK_UNSIGNED_CHAR ? 255.0 : type == VTK_UNSIGNED_SHORT ? 65535.0 : 1.0;
}

double MaxDifference(vtkDataArray* a, vtkDataArray* b)
{
  double worst = 0.0;
  for (vtkIdType v = 0; v < a->GetNumberOfValues(); ++v)
  {
    worst = std::max(
      worst, std::abs(a->GetVariantValue(v).ToDouble() - b->GetVariantValue(v).ToDouble()));
  }
  return worst;
}

void BM_HeightMapToNormalMap(benchmark::State& state)
{
  const int scheme = static_cast<int>(state.range(0));
  const int type = static_cast<int>(state.range(1));
  const bool bytes = state.range(2) != 0;
  const ScopedThreads threads(static_cast<int>(state.range(3)));
  vtkImageData* heights = bytes ? ByteHeights() : Heights();
  vtkNew<vtkHeightMapToNormalMap> filter;
  filter->SetInputData(heights);
  filter->SetDifferenceScheme(scheme);
  filter->SetBumpScale(Strength);
  filter->SetOutputScalarType(type);
  for (auto _ : state)
  {
    heights->Modified();
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetScalarPointer());
  }
  state.SetLabel(std::string(state.range(3) == 1 ? "1 thread/" : "") +
    (bytes ? "uchar heights/" : "") + filter->GetDifferenceSchemeAsString() + "/" + TypeName(type));
  state.SetItemsProcessed(state.iterations() * Size * Size);
}

// The floor: the bytes of the normal map the filter must write (3 components of the output
// type per texel), written with std::fill into a new array at every iteration. Arguments:
// output type, threads (0 = all; 1 = one), fresh (1: fresh pages, as a first execution's
// output; 0: memory used before).
void BM_Floor(benchmark::State& state)
{
  const int type = static_cast<int>(state.range(0));
  const ScopedThreads threads(static_cast<int>(state.range(1)));
  const bool fresh = state.range(2) != 0;
  BenchmarkMemory::UseFreshPages(fresh);
  vtkSmartPointer<vtkDataArray> map;
  for (auto _ : state)
  {
    BenchmarkMemory::BeginIteration(state, fresh, [&] { map = nullptr; });
    map = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
    map->SetNumberOfComponents(3);
    map->SetNumberOfTuples(static_cast<vtkIdType>(Size) * Size);
    auto* bytes = static_cast<unsigned char*>(map->GetVoidPointer(0));
    const vtkIdType n = map->GetDataSize() * map->GetDataTypeSize();
    vtkSMPTools::For(
      0, n, 1 << 20, [bytes](vtkIdType b, vtkIdType e) { std::fill(bytes + b, bytes + e, 1); });
    benchmark::ClobberMemory();
  }
  state.SetLabel(std::string(state.range(1) == 1 ? "1 thread/" : "") + TypeName(type) +
    (fresh ? "/fresh" : "/warm"));
}

void VtkPipeline(benchmark::State& state, bool sobel)
{
  const int type = static_cast<int>(state.range(0));
  const bool bytes = state.range(1) != 0;
  const ScopedThreads threads(static_cast<int>(state.range(2)));
  vtkNew<vtkImageData> heights;
  heights->ShallowCopy(bytes ? ByteHeights() : Heights());
  // Integer heights are normalised by 255: fold that into the spacing too.
  const double unit = (bytes ? 255.0 : 1.0) / (Strength * Size);
  heights->SetSpacing(unit, unit, 1.0);

  vtkNew<vtkImageData> minusOne;
  minusOne->SetDimensions(Size, Size, 1);
  minusOne->SetSpacing(heights->GetSpacing());
  minusOne->AllocateScalars(VTK_DOUBLE, 1);
  auto* m = vtkDoubleArray::SafeDownCast(minusOne->GetPointData()->GetScalars());
  m->FillValue(-1.0);

  vtkSmartPointer<vtkAlgorithm> gradient;
  if (sobel)
  {
    gradient = vtkSmartPointer<vtkImageSobel2D>::New();
  }
  else
  {
    auto g = vtkSmartPointer<vtkImageGradient>::New();
    g->SetDimensionality(2);
    g->HandleBoundariesOn();
    gradient = g;
  }
  gradient->SetInputDataObject(heights);
  vtkNew<vtkImageAppendComponents> append;
  append->AddInputConnection(gradient->GetOutputPort());
  append->AddInputData(minusOne);
  vtkNew<vtkImageNormalize> normalize;
  normalize->SetInputConnection(append->GetOutputPort());
  vtkNew<vtkImageShiftScale> encode;
  encode->SetInputConnection(normalize->GetOutputPort());
  const double top = TypeTop(type);
  // (v + shift)*scale with v = -n: 0.5*top*n + 0.5*top, plus 0.5 so that the truncating
  // cast rounds to nearest for integer types.
  encode->SetShift(type == VTK_FLOAT ? -1.0 : -(1.0 + 1.0 / top));
  encode->SetScale(-0.5 * top);
  encode->SetOutputScalarType(type);
  encode->ClampOverflowOn();
  for (auto _ : state)
  {
    heights->Modified();
    encode->Update();
    benchmark::DoNotOptimize(encode->GetOutput()->GetScalarPointer());
  }

  vtkNew<vtkHeightMapToNormalMap> ours;
  ours->SetInputData(bytes ? ByteHeights() : Heights());
  ours->SetDifferenceScheme(
    sobel ? vtkHeightMapToNormalMap::Sobel : vtkHeightMapToNormalMap::Central);
  ours->SetWrapToClampToEdge();
  ours->SetBumpScale(Strength);
  ours->SetOutputScalarType(type);
  ours->Update();
  state.counters["max_diff"] = MaxDifference(encode->GetOutput()->GetPointData()->GetScalars(),
    ours->GetOutput()->GetPointData()->GetScalars());
  state.SetLabel(std::string(state.range(2) == 1 ? "1 thread/" : "") +
    (bytes ? "uchar heights/" : "") + (sobel ? "vtkImageSobel2D" : "vtkImageGradient") + "/" +
    TypeName(type));
  state.SetItemsProcessed(state.iterations() * Size * Size);
}

void BM_VtkGradientPipeline(benchmark::State& state)
{
  VtkPipeline(state, false);
}

void BM_VtkSobel2DPipeline(benchmark::State& state)
{
  VtkPipeline(state, true);
}
} // namespace

// Arguments: scheme, output type, 8-bit heights?, threads (0 = all; 1 = one). The CPU column
// is the process CPU time (all threads): the work done, steadier than wall time on a loaded
// machine.
BENCHMARK(BM_HeightMapToNormalMap)
  ->ArgsProduct({ { vtkHeightMapToNormalMap::Forward, vtkHeightMapToNormalMap::Central,
                    vtkHeightMapToNormalMap::Sobel, vtkHeightMapToNormalMap::Scharr },
    { VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT, VTK_FLOAT }, { 0 }, { 0 } })
  ->Args({ vtkHeightMapToNormalMap::Central, VTK_UNSIGNED_CHAR, 1, 0 })
  ->Args({ vtkHeightMapToNormalMap::Sobel, VTK_UNSIGNED_CHAR, 1, 0 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MeasureProcessCPUTime();
BENCHMARK(BM_HeightMapToNormalMap)
  ->ArgsProduct({ { vtkHeightMapToNormalMap::Central, vtkHeightMapToNormalMap::Sobel },
    { VTK_UNSIGNED_CHAR, VTK_FLOAT }, { 0 }, { 1 } })
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime();
BENCHMARK(BM_Floor)
  ->ArgsProduct({ { VTK_UNSIGNED_CHAR, VTK_FLOAT }, { 0, 1 }, { 1, 0 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
// Arguments: output type, 8-bit heights?, threads.
BENCHMARK(BM_VtkGradientPipeline)
  ->ArgsProduct({ { VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT, VTK_FLOAT }, { 0 }, { 0 } })
  ->Args({ VTK_UNSIGNED_CHAR, 1, 0 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MeasureProcessCPUTime();
BENCHMARK(BM_VtkGradientPipeline)
  ->ArgsProduct({ { VTK_UNSIGNED_CHAR, VTK_FLOAT }, { 0 }, { 1 } })
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime();
BENCHMARK(BM_VtkSobel2DPipeline)
  ->ArgsProduct({ { VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT, VTK_FLOAT }, { 0 }, { 0 } })
  ->Args({ VTK_UNSIGNED_CHAR, 1, 0 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MeasureProcessCPUTime();
BENCHMARK(BM_VtkSobel2DPipeline)
  ->ArgsProduct({ { VTK_UNSIGNED_CHAR, VTK_FLOAT }, { 0 }, { 1 } })
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime();

BENCHMARK_MAIN();
