// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: vtkOIIOImageReader on arbitrary bytes, written to a temporary file whose
// extension is the format the first bytes claim (so OpenImageIO's decoder for that format
// gets them, as it would for a damaged file of that name).
#include "vtkOIIOImageReader.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkObject.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <unistd.h>

namespace
{
const char* Extension(const std::uint8_t* data, std::size_t size)
{
  auto starts = [&](const char* magic, std::size_t n)
  { return size >= n && std::memcmp(data, magic, n) == 0; };
  if (starts("\x89PNG", 4))
  {
    return ".png";
  }
  if (starts("\xFF\xD8", 2))
  {
    return ".jpg";
  }
  if (starts("II*\0", 4) || starts("MM\0*", 4))
  {
    return ".tif";
  }
  if (starts("\x76\x2F\x31\x01", 4))
  {
    return ".exr";
  }
  if (starts("BM", 2))
  {
    return ".bmp";
  }
  if (starts("P5", 2) || starts("P6", 2))
  {
    return ".pnm";
  }
  return ".png";
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  vtkObject::GlobalWarningDisplayOff();
  const std::string path =
    "/tmp/surfacedetail-fuzz-" + std::to_string(getpid()) + Extension(data, size);
  if (FILE* file = std::fopen(path.c_str(), "wb"))
  {
    std::fwrite(data, 1, size, file);
    std::fclose(file);
  }
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(path.c_str());
  // Headers are read whatever they claim; pixels only for pictures of at most 16M values, so
  // that the fuzzer's memory limit is not what stops a run (a header claiming more than
  // memory holds is the reader's check of its allocation, tested in TestOIIOImageIO).
  reader->UpdateInformation();
  int extent[6];
  reader->GetDataExtent(extent);
  const double values = double(extent[1] - extent[0] + 1) * double(extent[3] - extent[2] + 1) *
    double(extent[5] - extent[4] + 1) * reader->GetNumberOfScalarComponents();
  if (values <= double(1 << 24))
  {
    reader->Update();
  }
  std::remove(path.c_str());
  return 0;
}
