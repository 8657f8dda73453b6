// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter against the VTK chain a user would build today, in the same run:
//   vtkImageInterpolator (samples the height image at the texture coordinates) ->
//   vtkWarpScalar (along the normals) -> vtkPolyDataNormals -> vtkPolyDataTangents.
// The surface is the closed-form torus of the accuracy test (DisplacementTestSurfaces.h),
// so every run also reports its error against the exact displaced surface as counters:
// max normal angle error (degrees) and max vertex position error. Our filter samples with
// Linear interpolation, what the chain's interpolator does (like for like), in each normal
// mode: Approximate, Exact with the surface's dNdu/dNdv, Exact by fits (the same mesh without
// dNdu/dNdv: n_s, n_t fitted to the neighbours' normals) and Mesh. Both sides run on one
// thread and on two. Our filter is timed on a first execution (the mesh's points, polygons
// and arrays modified before each) and on a re-execution with a new Scale (a slider); it keeps
// nothing between executions, so the two should agree. BM_Floor writes the output bytes alone,
// fresh and warm, and BM_FusedKernel does Approximate mode's arithmetic in one pass with no
// mesh work: the floors the filter is measured against.
//
//   build/bin/BenchDisplacementMapFilter --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true --benchmark_out=displacement.json

#include "BenchmarkMemory.h"
#include "DisplacementTestSurfaces.h"

#include "vtkDisplacementMapFilter.h"

#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkImageInterpolator.h>
#include <vtkImageWrapPad.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkPolyDataTangents.h>
#include <vtkSMPTools.h>
#include <vtkWarpScalar.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <thread>

using namespace DisplacementTest;

namespace
{
constexpr double Scale = 0.1;
constexpr double Mid = 0.5;

struct Case
{
  vtkSmartPointer<vtkPolyData> Mesh; // with dPdu, dPdv, dNdu, dNdv
  vtkSmartPointer<vtkPolyData> WithoutNormalDerivatives;
  std::vector<Vec> TruePosition, TrueNormal;
};

const Surface& TheTorus()
{
  static const Surface s = Torus(Scale);
  return s;
}

vtkImageData* HeightImage()
{
  static vtkSmartPointer<vtkImageData> image = MakeHeightImage(TheTorus().Height, 4096, 2048);
  return image;
}

// Meshes and their truth, made once per resolution (U x U/2 quads).
const Case& GetCase(int U)
{
  static std::map<int, std::unique_ptr<Case>> cases;
  auto& c = cases[U];
  if (!c)
  {
    c.reset(new Case);
    const int V = U / 2;
    c->Mesh = MakeMesh(TheTorus(), U, V, true, true, true);
    c->WithoutNormalDerivatives = vtkSmartPointer<vtkPolyData>::New();
    c->WithoutNormalDerivatives->ShallowCopy(c->Mesh);
    c->WithoutNormalDerivatives->GetPointData()->RemoveArray("dNdu");
    c->WithoutNormalDerivatives->GetPointData()->RemoveArray("dNdv");
    c->TruePosition.resize(c->Mesh->GetNumberOfPoints());
    c->TrueNormal.resize(c->Mesh->GetNumberOfPoints());
    for (int j = 0; j <= V; ++j)
    {
      for (int i = 0; i <= U; ++i)
      {
        const size_t id = static_cast<size_t>(j) * (U + 1) + i;
        const double u = static_cast<double>(i) / U, v = static_cast<double>(j) / V;
        c->TruePosition[id] = TheTorus().Displaced(u, v);
        c->TrueNormal[id] = TheTorus().DisplacedNormal(u, v);
      }
    }
  }
  return *c;
}

void Report(benchmark::State& state, const Case& c, vtkPolyData* out, vtkDataArray* normals)
{
  double angle = 0.0, position = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    Vec p, n;
    out->GetPoint(i, p.data());
    normals->GetTuple(i, n.data());
    angle = std::max(angle, AngleDeg(n, c.TrueNormal[i]));
    const Vec d = Add(p, c.TruePosition[i], -1.0);
    position = std::max(position, std::sqrt(DotV(d, d)));
  }
  state.counters["points"] = static_cast<double>(out->GetNumberOfPoints());
  state.counters["angle_deg"] = angle;
  state.counters["position"] = position;
  state.SetItemsProcessed(state.iterations() * out->GetNumberOfPoints());
}

// The thread count, explicit (VTK 9.1's TBB backend keeps 1 thread after Initialize(1) even
// when Initialize(0) follows).
void SetThreads(int threads)
{
  vtkSMPTools::Initialize(threads);
}

// Arguments: U, normal mode (Exact by fits is ExactByFits), threads, reexec (0: a first
// execution on a changed mesh, 1: a re-execution with a new Scale).
constexpr int ExactByFits = 4;

void BM_DisplacementMapFilter(benchmark::State& state)
{
  const Case& c = GetCase(static_cast<int>(state.range(0)));
  SetThreads(static_cast<int>(state.range(2)));
  const int mode = static_cast<int>(state.range(1));
  vtkPolyData* mesh = mode == ExactByFits ? c.WithoutNormalDerivatives.Get() : c.Mesh.Get();
  vtkNew<vtkDisplacementMapFilter> filter;
  filter->SetInputData(0, mesh);
  filter->SetInputData(1, HeightImage());
  filter->SetScaleFactor(Scale);
  filter->SetMidlevel(Mid);
  filter->SetNormalMode(mode == ExactByFits ? vtkDisplacementMapFilter::Exact : mode);
  filter->SetInterpolationToLinear();
  const bool reexecute = state.range(3) != 0;
  BenchmarkMemory::UseFreshPages(!reexecute);
  if (reexecute)
  {
    filter->Update();
  }
  int k = 0;
  for (auto _ : state)
  {
    BenchmarkMemory::BeginIteration(state, !reexecute, [&] { filter->GetOutput()->ReleaseData(); });
    if (reexecute)
    {
      // A Scale slider: a new Scale each time, the mesh untouched.
      filter->SetScaleFactor(Scale * (1.0 + 1e-6 * (++k % 2)));
    }
    else
    {
      // A new mesh each time, as when the source upstream re-executes (same values, so that
      // the errors stay comparable).
      mesh->GetPoints()->Modified();
      mesh->GetPolys()->Modified();
      vtkPointData* pd = mesh->GetPointData();
      for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
      {
        pd->GetAbstractArray(a)->Modified();
      }
    }
    filter->Update();
  }
  filter->SetScaleFactor(Scale);
  filter->Update();
  Report(state, c, filter->GetOutput(), filter->GetOutput()->GetPointData()->GetNormals());
  state.counters["threads"] = vtkSMPTools::GetEstimatedNumberOfThreads();
}

// The VTK chain: vtkImageInterpolator (linear, on the image wrap-padded by one texel so
// that the texture wraps as ours does) samples the height at each point's texture coordinates, with
// the image placed so that its pixel centres sit at the texel centres ((i + 0.5)/W, (j + 0.5)/H);
// then vtkWarpScalar along the normals, vtkPolyDataNormals (no splitting, no consistency
// pass: its fastest setting) and vtkPolyDataTangents.
void BM_VTKChain(benchmark::State& state)
{
  const Case& c = GetCase(static_cast<int>(state.range(0)));
  // vtkWarpScalar and vtkPolyDataTangents are threaded with vtkSMPTools in VTK 9.1.
  SetThreads(static_cast<int>(state.range(1)));
  BenchmarkMemory::UseFreshPages(true);
  vtkNew<vtkImageData> image;
  image->ShallowCopy(HeightImage());
  int dims[3];
  image->GetDimensions(dims);
  image->SetSpacing(1.0 / dims[0], 1.0 / dims[1], 1.0);
  image->SetOrigin(0.5 / dims[0], 0.5 / dims[1], 0.0);

  // vtkImageInterpolator returns its OutValue outside the image bounds, whatever the border
  // mode, so the texels of the other side are padded on (once, outside the timing).
  vtkNew<vtkImageWrapPad> pad;
  pad->SetInputData(image);
  pad->SetOutputWholeExtent(-1, dims[0], -1, dims[1], 0, 0);
  pad->Update();
  vtkNew<vtkImageInterpolator> interpolator;
  interpolator->SetInterpolationModeToLinear();
  interpolator->SetBorderModeToRepeat();
  vtkNew<vtkWarpScalar> warp;
  vtkNew<vtkPolyDataNormals> normals;
  vtkNew<vtkPolyDataTangents> tangents;
  vtkPolyData* out = nullptr;
  for (auto _ : state)
  {
    BenchmarkMemory::BeginIteration(state, true,
      [&]
      {
        for (vtkAlgorithm* a : { static_cast<vtkAlgorithm*>(warp),
               static_cast<vtkAlgorithm*>(normals), static_cast<vtkAlgorithm*>(tangents) })
        {
          if (vtkDataObject* o = a->GetExecutive()->GetOutputData(0))
          {
            o->ReleaseData();
          }
        }
      });
    interpolator->Initialize(pad->GetOutput());
    interpolator->Update();
    const vtkIdType n = c.Mesh->GetNumberOfPoints();
    vtkDataArray* tc = c.Mesh->GetPointData()->GetTCoords();
    vtkNew<vtkFloatArray> d;
    d->SetName("d");
    d->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double h = 0.0;
      const double x[3] = { tc->GetComponent(i, 0), tc->GetComponent(i, 1), 0.0 };
      interpolator->Interpolate(x, &h);
      d->SetValue(i, static_cast<float>(h - Mid));
    }
    vtkNew<vtkPolyData> surface;
    surface->ShallowCopy(c.Mesh);
    surface->GetPointData()->SetScalars(d);
    warp->SetInputData(surface);
    warp->SetScaleFactor(Scale);
    normals->SetInputConnection(warp->GetOutputPort());
    normals->SplittingOff();
    normals->ConsistencyOff();
    tangents->SetInputConnection(normals->GetOutputPort());
    tangents->Update();
    out = tangents->GetOutput();
  }
  Report(state, c, out, out->GetPointData()->GetNormals());
  state.counters["threads"] = vtkSMPTools::GetEstimatedNumberOfThreads();
}

// The floor: the 40 bytes per point that any filter making this benchmark's outputs must write
// (float points, normals and tangents), written with the least work, std::fill.
// Arguments: U, threads, fresh (1: the arrays allocated anew each time, as a first execution's
// outputs are; 0: written again into arrays allocated once).
void BM_Floor(benchmark::State& state)
{
  const vtkIdType n = GetCase(static_cast<int>(state.range(0))).Mesh->GetNumberOfPoints();
  SetThreads(static_cast<int>(state.range(1)));
  const bool fresh = state.range(2) != 0;
  BenchmarkMemory::UseFreshPages(fresh);
  vtkSmartPointer<vtkFloatArray> arrays[3];
  auto allocate = [&]()
  {
    const int components[3] = { 3, 3, 4 };
    for (int a = 0; a < 3; ++a)
    {
      arrays[a] = vtkSmartPointer<vtkFloatArray>::New();
      arrays[a]->SetNumberOfComponents(components[a]);
      arrays[a]->SetNumberOfTuples(n);
    }
  };
  allocate();
  for (auto _ : state)
  {
    BenchmarkMemory::BeginIteration(state, fresh,
      [&]
      {
        for (auto& a : arrays)
        {
          a = nullptr;
        }
      });
    if (fresh)
    {
      allocate();
    }
    for (auto& a : arrays)
    {
      float* values = a->GetPointer(0);
      const int nc = a->GetNumberOfComponents();
      vtkSMPTools::For(0, n, 16384,
        [=](vtkIdType b, vtkIdType e) { std::fill(values + nc * b, values + nc * e, 1.0f); });
    }
    benchmark::ClobberMemory();
  }
  state.counters["points"] = static_cast<double>(n);
  state.counters["threads"] = vtkSMPTools::GetEstimatedNumberOfThreads();
  state.SetBytesProcessed(state.iterations() * n * 40);
}

// The floor with the arithmetic: a minimal fused kernel that does what Approximate mode does
// for this mesh in one pass into fresh arrays: the bilinear height (Repeat) and its slope,
// the displaced point, the seed's normal from dPdu/dPdv and the tangent made orthogonal to it.
// No seams, no checks, no fallbacks for degenerate frames. Arguments: U, threads.
void BM_FusedKernel(benchmark::State& state)
{
  const Case& c = GetCase(static_cast<int>(state.range(0)));
  SetThreads(static_cast<int>(state.range(1)));
  vtkPointData* pd = c.Mesh->GetPointData();
  auto floats = [&](vtkDataArray* a) -> const float*
  {
    auto* f = vtkFloatArray::SafeDownCast(a);
    return f ? f->GetPointer(0) : nullptr;
  };
  const float* points = floats(c.Mesh->GetPoints()->GetData());
  const float* normals = floats(pd->GetNormals());
  const float* tcoords = floats(pd->GetTCoords());
  const float* tangents = floats(pd->GetTangents());
  const float* du = floats(pd->GetArray("dPdu"));
  const float* dv = floats(pd->GetArray("dPdv"));
  vtkImageData* image = HeightImage();
  const double* texels = static_cast<const double*>(image->GetScalarPointer());
  if (!points || !normals || !tcoords || !tangents || !du || !dv ||
    image->GetScalarType() != VTK_DOUBLE)
  {
    state.SkipWithError(
      "the benchmark's mesh or image does not have the expected float/double arrays");
    return;
  }
  int dims[3];
  image->GetDimensions(dims);
  const int W = dims[0], H = dims[1];
  const vtkIdType n = c.Mesh->GetNumberOfPoints();
  BenchmarkMemory::UseFreshPages(true);
  vtkSmartPointer<vtkFloatArray> outPoints, outNormals, outTangents;
  for (auto _ : state)
  {
    BenchmarkMemory::BeginIteration(state, true,
      [&]
      {
        outPoints = nullptr;
        outNormals = nullptr;
        outTangents = nullptr;
      });
    outPoints = vtkSmartPointer<vtkFloatArray>::New();
    outNormals = vtkSmartPointer<vtkFloatArray>::New();
    outTangents = vtkSmartPointer<vtkFloatArray>::New();
    outPoints->SetNumberOfComponents(3);
    outNormals->SetNumberOfComponents(3);
    outTangents->SetNumberOfComponents(3);
    outPoints->SetNumberOfTuples(n);
    outNormals->SetNumberOfTuples(n);
    outTangents->SetNumberOfTuples(n);
    float* op = outPoints->GetPointer(0);
    float* on = outNormals->GetPointer(0);
    float* ot = outTangents->GetPointer(0);
    vtkSMPTools::For(0, n, 16384,
      [&](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType i = b; i < e; ++i)
        {
          // Texel centres at (k + 0.5) / W, as the filter and vtkTexture sample; Repeat for
          // coordinates in [0, 1] (this mesh's) without a division.
          const double x = tcoords[2 * i] * W - 0.5, y = tcoords[2 * i + 1] * H - 0.5;
          const double fx0 = std::floor(x), fy0 = std::floor(y);
          const double fx = x - fx0, fy = y - fy0;
          int i0 = static_cast<int>(fx0), j0 = static_cast<int>(fy0);
          i0 += i0 < 0 ? W : 0;
          j0 += j0 < 0 ? H : 0;
          i0 -= i0 >= W ? W : 0;
          j0 -= j0 >= H ? H : 0;
          const int i1 = i0 + 1 < W ? i0 + 1 : 0, j1 = j0 + 1 < H ? j0 + 1 : 0;
          const double* r0 = texels + static_cast<vtkIdType>(j0) * W;
          const double* r1 = texels + static_cast<vtkIdType>(j1) * W;
          const double a = r0[i0], b0 = r0[i1], c0 = r1[i0], d0 = r1[i1];
          const double h = (1 - fy) * (a + fx * (b0 - a)) + fy * (c0 + fx * (d0 - c0));
          const double d = Scale * (h - Mid);
          const double ds = Scale * W * ((1 - fy) * (b0 - a) + fy * (d0 - c0));
          const double dt = Scale * H * ((c0 + fx * (d0 - c0)) - (a + fx * (b0 - a)));
          const double nn[3] = { normals[3 * i], normals[3 * i + 1], normals[3 * i + 2] };
          const double ps[3] = { du[3 * i], du[3 * i + 1], du[3 * i + 2] };
          const double pt[3] = { dv[3 * i], dv[3 * i + 1], dv[3 * i + 2] };
          // m = (n . (Ps x Pt)) n + ds (n x Pt) - dt (n x Ps)
          const double area = nn[0] * (ps[1] * pt[2] - ps[2] * pt[1]) +
            nn[1] * (ps[2] * pt[0] - ps[0] * pt[2]) + nn[2] * (ps[0] * pt[1] - ps[1] * pt[0]);
          double m[3];
          for (int k = 0; k < 3; ++k)
          {
            const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            m[k] = area * nn[k] + ds * (nn[k1] * pt[k2] - nn[k2] * pt[k1]) -
              dt * (nn[k1] * ps[k2] - nn[k2] * ps[k1]);
          }
          const double inv =
            (area < 0 ? -1.0 : 1.0) / std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
          double t[3] = { tangents[3 * i], tangents[3 * i + 1], tangents[3 * i + 2] };
          const double along = (t[0] * m[0] + t[1] * m[1] + t[2] * m[2]) * inv * inv;
          for (int k = 0; k < 3; ++k)
          {
            t[k] -= along * m[k];
          }
          const double tinv = 1.0 / std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
          for (int k = 0; k < 3; ++k)
          {
            op[3 * i + k] = static_cast<float>(points[3 * i + k] + d * nn[k]);
            on[3 * i + k] = static_cast<float>(m[k] * inv);
            ot[3 * i + k] = static_cast<float>(t[k] * tinv);
          }
        }
      });
    benchmark::ClobberMemory();
  }
  // The kernel must compute what it claims to: its normals against the filter's in
  // Approximate mode, as the largest angle (degrees) in the counter vs_filter.
  vtkNew<vtkDisplacementMapFilter> filter;
  filter->SetInputData(0, c.Mesh);
  filter->SetInputData(1, image);
  filter->SetScaleFactor(Scale);
  filter->SetMidlevel(Mid);
  filter->SetNormalModeToApproximate();
  filter->SetInterpolationToLinear();
  filter->Update();
  double worst = 0.0;
  vtkDataArray* ref = filter->GetOutput()->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < n; ++i)
  {
    Vec q, k;
    ref->GetTuple(i, q.data());
    outNormals->GetTuple(i, k.data());
    worst = std::max(worst, AngleDeg(q, k));
  }
  state.counters["vs_filter"] = worst;
  state.counters["points"] = static_cast<double>(n);
  state.counters["threads"] = vtkSMPTools::GetEstimatedNumberOfThreads();
  state.SetItemsProcessed(state.iterations() * n);
}

// Resolutions U (torus U x U/2): about 1M and 4M points.
void Sizes(benchmark::internal::Benchmark* b, bool modes)
{
  for (int U : { 1414, 2828 })
  {
    for (int threads : { 1, 2 })
    {
      if (!modes)
      {
        b->Args({ U, threads });
        continue;
      }
      for (int reexec : { 0, 1 })
      {
        for (int mode : { static_cast<int>(vtkDisplacementMapFilter::Approximate),
               static_cast<int>(vtkDisplacementMapFilter::Exact), ExactByFits,
               static_cast<int>(vtkDisplacementMapFilter::Mesh) })
        {
          b->Args({ U, mode, threads, reexec });
        }
      }
    }
  }
  if (modes)
  {
    b->ArgNames({ "U", "mode", "threads", "reexec" });
  }
  else
  {
    b->ArgNames({ "U", "threads" });
  }
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}
} // namespace

BENCHMARK(BM_DisplacementMapFilter)
  ->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, true); });
BENCHMARK(BM_VTKChain)->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, false); });
BENCHMARK(BM_Floor)
  ->ArgsProduct({ { 1414, 2828 }, { 1, 2 }, { 1, 0 } })
  ->ArgNames({ "U", "threads", "fresh" })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_FusedKernel)
  ->ArgsProduct({ { 1414, 2828 }, { 1, 2 } })
  ->ArgNames({ "U", "threads" })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();

BENCHMARK_MAIN();
