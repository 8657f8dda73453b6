// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkOIIOImageReader / vtkOIIOImageWriter against VTK's own vtkPNGReader / vtkPNGWriter on
// the same 2048 x 2048 texture, in the same run. Both sides decode or encode the whole
// file through a pipeline Update(); the file is in the page cache after the first pass.
//
//   build/bin/BenchmarkOIIOImageIO --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true   (one command line)

#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkSmartPointer.h>

#include <vtksys/SystemTools.hxx>

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

namespace
{
constexpr int Size = 2048;

std::string Folder()
{
  const std::string folder =
    vtksys::SystemTools::GetCurrentWorkingDirectory() + "/BenchmarkOIIOImageIO";
  vtksys::SystemTools::MakeDirectory(folder);
  return folder;
}

/// A smooth colour field with fine detail, so that PNG's filters and deflate have real
/// work (neither constant nor noise). 8- or 16-bit, RGB.
vtkSmartPointer<vtkImageData> Texture(int type)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(Size, Size, 1);
  image->AllocateScalars(type, 3);
  const double scale = type == VTK_UNSIGNED_CHAR ? 255.0 : 65535.0;
  for (int j = 0; j < Size; ++j)
  {
    for (int i = 0; i < Size; ++i)
    {
      const double x = i / 64.0, y = j / 64.0;
      const double v[3] = { 0.5 + 0.5 * std::sin(x + 0.3 * std::sin(3.1 * y)),
        0.5 + 0.5 * std::sin(y * 1.7 + std::cos(x)), 0.5 + 0.25 * std::sin(x * y * 0.1) };
      for (int c = 0; c < 3; ++c)
      {
        image->SetScalarComponentFromDouble(i, j, 0, c, std::floor(v[c] * scale));
      }
    }
  }
  return image;
}

const std::string& PNGFile(int type)
{
  static std::string files[2];
  std::string& file = files[type == VTK_UNSIGNED_CHAR ? 0 : 1];
  if (file.empty())
  {
    file = Folder() + (type == VTK_UNSIGNED_CHAR ? "/texture8.png" : "/texture16.png");
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputData(Texture(type));
    writer->SetFileName(file.c_str());
    writer->Write();
  }
  return file;
}

template <class Reader>
void Read(benchmark::State& state, int type)
{
  const std::string& file = PNGFile(type);
  vtkNew<Reader> reader;
  reader->SetFileName(file.c_str());
  for (auto _ : state)
  {
    reader->Modified();
    reader->Update();
    benchmark::DoNotOptimize(reader->GetOutput()->GetScalarPointer());
  }
  state.SetItemsProcessed(state.iterations() * Size * Size);
}

template <class Writer>
void Write(benchmark::State& state, int type, const char* name)
{
  const auto image = Texture(type);
  const std::string file = Folder() + "/out_" + name;
  vtkNew<Writer> writer;
  writer->SetInputData(image);
  writer->SetFileName((file + ".png").c_str());
  for (auto _ : state)
  {
    writer->Write();
  }
  state.SetItemsProcessed(state.iterations() * Size * Size);
  state.counters["bytes"] = static_cast<double>(vtksys::SystemTools::FileLength(file + ".png"));
}

void BM_ReadPNG8_VTK(benchmark::State& s)
{
  Read<vtkPNGReader>(s, VTK_UNSIGNED_CHAR);
}
void BM_ReadPNG8_OIIO(benchmark::State& s)
{
  Read<vtkOIIOImageReader>(s, VTK_UNSIGNED_CHAR);
}
void BM_ReadPNG16_VTK(benchmark::State& s)
{
  Read<vtkPNGReader>(s, VTK_UNSIGNED_SHORT);
}
void BM_ReadPNG16_OIIO(benchmark::State& s)
{
  Read<vtkOIIOImageReader>(s, VTK_UNSIGNED_SHORT);
}
void BM_WritePNG8_VTK(benchmark::State& s)
{
  Write<vtkPNGWriter>(s, VTK_UNSIGNED_CHAR, "vtk");
}
void BM_WritePNG8_OIIO(benchmark::State& s)
{
  Write<vtkOIIOImageWriter>(s, VTK_UNSIGNED_CHAR, "oiio");
}
}

BENCHMARK(BM_ReadPNG8_VTK)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPNG8_OIIO)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPNG16_VTK)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPNG16_OIIO)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WritePNG8_VTK)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WritePNG8_OIIO)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
