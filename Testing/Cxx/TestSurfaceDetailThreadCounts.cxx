// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Every threaded filter, run again and again on one input with 1, 2, 3, 4 and 8 threads, under
// each SMP backend VTK was built with (TBB, whose tasks are split and stolen differently from
// run to run; STDThread, whose chunks follow the thread count, up to the machine's cores), gives
// the output of the sequential backend bit for bit: points, every point and cell array, and
// the cells. The inputs are a few hundred rows or texels wide, so that each loop is split into
// many chunks.
//
// With VTK_SMP_BACKEND_IN_USE set (as the ThreadSanitizer stage sets it), only that backend
// runs.

#include "vtkDisplacementMapFilter.h"
#include "vtkHeightMapToNormalMap.h"
#include "vtkMikkTSpaceTangents.h"
#include "vtkNormalMapBaker.h"
#include "vtkParametricDonut.h"
#include "vtkParametricSurfaceSource.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMP.h> // VTK_SMP_ENABLE_*: the backends built in
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace
{
constexpr int Repeats = 2;
const int ThreadCounts[] = { 1, 2, 3, 4, 8 };

// The backends to run: the one the environment names, or every parallel one built in.
std::vector<std::string> Backends()
{
  if (const char* named = std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    return { named };
  }
  std::vector<std::string> backends;
#if VTK_SMP_ENABLE_TBB
  backends.emplace_back("TBB");
#endif
#if VTK_SMP_ENABLE_STDTHREAD
  backends.emplace_back("STDThread");
#endif
#if VTK_SMP_ENABLE_OPENMP
  backends.emplace_back("OpenMP");
#endif
  return backends;
}

// Restores the backend and the default thread count when a test ends.
struct SMPState
{
  std::string Backend = vtkSMPTools::GetBackend();
  ~SMPState()
  {
    vtkSMPTools::SetBackend(this->Backend.c_str());
    // VTK 9.1 keeps the last count on Initialize(0): ask for every core again.
    vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
  }
};

bool SameArray(vtkDataArray* a, vtkDataArray* b, std::string& why)
{
  const std::string name = a && a->GetName() ? a->GetName() : "";
  if (!a || !b)
  {
    why = "array missing";
    return a == b;
  }
  if (a->GetDataType() != b->GetDataType() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents() ||
    a->GetNumberOfTuples() != b->GetNumberOfTuples())
  {
    why = "array " + name + ": layout differs";
    return false;
  }
  if (a->GetNumberOfValues() == 0)
  {
    return true; // an empty array has no storage to compare (its pointer may be null)
  }
  // Every array here stores its values contiguously (VTK's default layout).
  const size_t size = a->GetDataTypeSize();
  const auto* x = static_cast<const char*>(a->GetVoidPointer(0));
  const auto* y = static_cast<const char*>(b->GetVoidPointer(0));
  if (std::memcmp(x, y, size * a->GetNumberOfValues()) == 0)
  {
    return true;
  }
  vtkIdType v = 0;
  while (std::memcmp(x + v * size, y + v * size, size) == 0)
  {
    ++v;
  }
  why = "array " + name + ": value " + std::to_string(v) + " differs";
  return false;
}

bool SameAttributes(vtkFieldData* a, vtkFieldData* b, const char* what, std::string& why)
{
  if (a->GetNumberOfArrays() != b->GetNumberOfArrays())
  {
    why = std::string(what) + ": number of arrays differs";
    return false;
  }
  for (int k = 0; k < a->GetNumberOfArrays(); ++k)
  {
    if (!SameArray(a->GetArray(k), b->GetArray(k), why))
    {
      why = std::string(what) + " " + why;
      return false;
    }
  }
  return true;
}

bool SameCells(vtkCellArray* a, vtkCellArray* b, const char* what, std::string& why)
{
  if (!SameArray(a->GetOffsetsArray(), b->GetOffsetsArray(), why) ||
    !SameArray(a->GetConnectivityArray(), b->GetConnectivityArray(), why))
  {
    why = std::string(what) + " " + why;
    return false;
  }
  return true;
}

bool SameOutput(vtkDataObject* x, vtkDataObject* y, std::string& why)
{
  auto* a = vtkPolyData::SafeDownCast(x);
  auto* b = vtkPolyData::SafeDownCast(y);
  if (a && b)
  {
    return a->GetNumberOfPoints() > 0 &&
      SameArray(a->GetPoints()->GetData(), b->GetPoints()->GetData(), why) &&
      SameAttributes(a->GetPointData(), b->GetPointData(), "point data", why) &&
      SameAttributes(a->GetCellData(), b->GetCellData(), "cell data", why) &&
      SameCells(a->GetVerts(), b->GetVerts(), "verts", why) &&
      SameCells(a->GetLines(), b->GetLines(), "lines", why) &&
      SameCells(a->GetPolys(), b->GetPolys(), "polys", why) &&
      SameCells(a->GetStrips(), b->GetStrips(), "strips", why);
  }
  auto* p = vtkImageData::SafeDownCast(x);
  auto* q = vtkImageData::SafeDownCast(y);
  if (p && q)
  {
    int e[6], f[6];
    p->GetExtent(e);
    q->GetExtent(f);
    if (!std::equal(e, e + 6, f) || p->GetNumberOfPoints() == 0)
    {
      why = "extent differs or is empty";
      return false;
    }
    return SameAttributes(p->GetPointData(), q->GetPointData(), "point data", why);
  }
  why = "output types differ";
  return false;
}

// Runs @a produce (which returns the outputs of one fresh execution) with the sequential
// backend, then Repeats times per backend and thread count, and compares every output.
void ExpectSameAtEveryThreadCount(
  const std::function<std::vector<vtkSmartPointer<vtkDataObject>>()>& produce)
{
  SMPState restore;
  ASSERT_TRUE(vtkSMPTools::SetBackend("Sequential"));
  const std::vector<vtkSmartPointer<vtkDataObject>> reference = produce();
  for (const std::string& backend : Backends())
  {
    ASSERT_TRUE(vtkSMPTools::SetBackend(backend.c_str())) << backend;
    for (int threads : ThreadCounts)
    {
      vtkSMPTools::Initialize(threads);
      if (threads == ThreadCounts[4])
      {
        std::printf("%s: %d threads asked, %d estimated\n", backend.c_str(), threads,
          vtkSMPTools::GetEstimatedNumberOfThreads());
      }
      for (int run = 0; run < Repeats; ++run)
      {
        const std::vector<vtkSmartPointer<vtkDataObject>> outputs = produce();
        ASSERT_EQ(outputs.size(), reference.size());
        for (size_t k = 0; k < outputs.size(); ++k)
        {
          std::string why;
          EXPECT_TRUE(SameOutput(reference[k], outputs[k], why))
            << backend << ", " << threads << " threads, run " << run << ", output " << k << ": "
            << why;
        }
      }
    }
  }
}

template <typename T>
vtkSmartPointer<vtkDataObject> Copy(T* output)
{
  auto copy = vtkSmartPointer<T>::New();
  copy->DeepCopy(output);
  return copy;
}

// The donut with every array the source makes (its texture repeated @a repeat times round).
vtkSmartPointer<vtkPolyData> Donut(int u, int v, bool derivatives, double repeat = 3.0)
{
  vtkNew<vtkParametricDonut> donut;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(donut);
  source->SetUResolution(u);
  source->SetVResolution(v);
  source->GenerateTangentsOn();
  source->SetGenerateDerivatives(derivatives);
  source->SetTextureRepeat(repeat, 1.0);
  source->Update();
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(source->GetOutput());
  return copy;
}

// Every triangle on its own three points, with its corners' point data.
vtkSmartPointer<vtkPolyData> Soup(vtkPolyData* mesh)
{
  vtkNew<vtkIdList> corners, source;
  vtkNew<vtkCellArray> polys;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, corners);
    polys->InsertNextCell(static_cast<int>(corners->GetNumberOfIds()));
    for (vtkIdType k = 0; k < corners->GetNumberOfIds(); ++k)
    {
      polys->InsertCellPoint(source->GetNumberOfIds());
      source->InsertNextId(corners->GetId(k));
    }
  }
  const vtkIdType n = source->GetNumberOfIds();
  auto soup = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  points->SetNumberOfPoints(n);
  mesh->GetPoints()->GetData()->GetTuples(source, points->GetData());
  soup->SetPoints(points);
  soup->SetPolys(polys);
  soup->GetPointData()->CopyAllocate(mesh->GetPointData(), n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    soup->GetPointData()->CopyData(mesh->GetPointData(), source->GetId(i), i);
  }
  return soup;
}

// Smooth bumps with a few sharp ones, 300 x 200 texels (not a power of two).
vtkSmartPointer<vtkImageData> Heights()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(300, 200, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* h = static_cast<float*>(image->GetScalarPointer());
  for (int j = 0; j < 200; ++j)
  {
    for (int i = 0; i < 300; ++i)
    {
      const double s = (i + 0.5) / 300, t = (j + 0.5) / 200;
      h[j * 300 + i] =
        static_cast<float>(0.5 + 0.3 * std::sin(2 * M_PI * 5 * s) * std::cos(2 * M_PI * 3 * t) +
          ((i * 7 + j * 13) % 97 == 0 ? 0.2 : 0.0));
    }
  }
  return image;
}
} // namespace

TEST(SurfaceDetailThreadCounts, ParametricSurfaceSourceIsBitIdentical)
{
  ExpectSameAtEveryThreadCount(
    [] { return std::vector<vtkSmartPointer<vtkDataObject>>{ Donut(240, 200, true) }; });
}

// Every normal mode, and Exact both from the source's dNdu/dNdv and fitted without them (and
// without dPdu/dPdv), seams merged.
TEST(SurfaceDetailThreadCounts, DisplacementMapFilterIsBitIdenticalInEveryNormalMode)
{
  vtkSmartPointer<vtkPolyData> full = Donut(200, 150, true);
  auto bare = vtkSmartPointer<vtkPolyData>::New();
  bare->DeepCopy(full);
  for (const char* name : { "dPdu", "dPdv", "dNdu", "dNdv" })
  {
    bare->GetPointData()->RemoveArray(name);
  }
  vtkSmartPointer<vtkImageData> heights = Heights();
  ExpectSameAtEveryThreadCount(
    [&]
    {
      std::vector<vtkSmartPointer<vtkDataObject>> outputs;
      for (int mode : { vtkDisplacementMapFilter::Input, vtkDisplacementMapFilter::Approximate,
             vtkDisplacementMapFilter::Exact, vtkDisplacementMapFilter::Mesh })
      {
        for (vtkPolyData* input : { full.GetPointer(), bare.GetPointer() })
        {
          vtkNew<vtkDisplacementMapFilter> filter;
          filter->SetInputData(0, input);
          filter->SetInputData(1, heights);
          filter->SetNormalMode(mode);
          filter->SetScaleFactor(0.08);
          filter->SetMidlevel(0.5);
          filter->SetInterpolationToCubic();
          filter->Update();
          outputs.push_back(Copy(filter->GetOutput()));
        }
      }
      return outputs;
    });
}

// The donut's own frames replaced (its seams split where MikkTSpace's frames differ), and the
// same surface as a triangle soup, which the weld must join up again.
TEST(SurfaceDetailThreadCounts, MikkTSpaceTangentsIsBitIdentical)
{
  vtkSmartPointer<vtkPolyData> donut = Donut(160, 120, false);
  donut->GetPointData()->RemoveArray("Tangents");
  vtkSmartPointer<vtkPolyData> soup = Soup(Donut(80, 60, false));
  soup->GetPointData()->RemoveArray("Tangents");
  ExpectSameAtEveryThreadCount(
    [&]
    {
      std::vector<vtkSmartPointer<vtkDataObject>> outputs;
      for (vtkPolyData* input : { donut.GetPointer(), soup.GetPointer() })
      {
        vtkNew<vtkMikkTSpaceTangents> filter;
        filter->SetInputData(input);
        filter->Update();
        outputs.push_back(Copy(filter->GetOutput()));
      }
      return outputs;
    });
}

TEST(SurfaceDetailThreadCounts, HeightMapToNormalMapIsBitIdentical)
{
  vtkSmartPointer<vtkImageData> heights = Heights();
  ExpectSameAtEveryThreadCount(
    [&]
    {
      std::vector<vtkSmartPointer<vtkDataObject>> outputs;
      for (int scheme : { vtkHeightMapToNormalMap::Forward, vtkHeightMapToNormalMap::Scharr })
      {
        vtkNew<vtkHeightMapToNormalMap> filter;
        filter->SetInputData(heights);
        filter->SetDifferenceScheme(scheme);
        filter->SetBumpScale(0.4);
        filter->SetOutputScalarTypeToFloat();
        filter->SetOutputRelief(scheme == vtkHeightMapToNormalMap::Scharr);
        filter->Update();
        outputs.push_back(Copy(filter->GetOutput()));
      }
      return outputs;
    });
}

// A coarse donut baked from the displaced fine one, both ways from the surface and from a cage.
TEST(SurfaceDetailThreadCounts, NormalMapBakerIsBitIdentical)
{
  // The texture square once round, so that the whole map is baked.
  vtkSmartPointer<vtkPolyData> coarse = Donut(24, 12, false, 1.0);
  vtkNew<vtkDisplacementMapFilter> displace;
  displace->SetInputData(0, Donut(160, 120, false, 1.0));
  displace->SetInputData(1, Heights());
  displace->SetScaleFactor(0.05);
  displace->SetMidlevel(0.5);
  displace->Update();
  auto detailed = vtkSmartPointer<vtkPolyData>::New();
  detailed->DeepCopy(displace->GetOutput());
  ExpectSameAtEveryThreadCount(
    [&]
    {
      std::vector<vtkSmartPointer<vtkDataObject>> outputs;
      for (double cage : { 0.0, 0.06 })
      {
        vtkNew<vtkNormalMapBaker> baker;
        baker->SetInputData(0, coarse);
        baker->SetInputData(1, detailed);
        baker->SetTextureSize(128, 64);
        baker->SetMaxRayDistance(0.1);
        baker->SetCageOffset(cage);
        baker->SetOutputScalarTypeToFloat();
        baker->BakeHeightOn();
        baker->Update();
        outputs.push_back(Copy(baker->GetOutput()));
        outputs.push_back(Copy(baker->GetHeightOutput()));
      }
      return outputs;
    });
}
