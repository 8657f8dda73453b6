// vtkDisplacementMapFilter against the VTK chain a user would build today, in the same run:
//   vtkImageInterpolator (samples the height image at the texture coordinates) ->
//   vtkWarpScalar (along the normals) -> vtkPolyDataNormals -> vtkPolyDataTangents.
// The surface is the closed-form torus of the accuracy test (DisplacementTestSurfaces.h),
// so every run also reports its error against the exact displaced surface as counters:
// max normal angle error (degrees) and max vertex position error. Our filter runs with
// each interpolation: Linear is what the chain's probe does (like for like), Cubic the more
// accurate and more expensive one, Nearest the cheapest. Both sides run on every core
// (threads 0, each one's default) and on one thread. Our filter keeps what depends on the
// mesh alone between executions, so it is timed both ways: a first execution (the mesh's
// points and polygons modified before each) and a re-execution with a new Scale (a slider).
//
//   build/bin/BenchDisplacementMapFilter --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true --benchmark_out=displacement.json
// (one line)
//   /usr/bin/python3 scripts/displacement_benchmark_plot.py displacement.json

#include "DisplacementTestSurfaces.h"

#include "vtkDisplacementMapFilter.h"

#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkImageInterpolator.h>
#include <vtkImageWrapPad.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkPolyDataTangents.h>
#include <vtkSMPTools.h>
#include <vtkWarpScalar.h>

#include <benchmark/benchmark.h>

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
  vtkSmartPointer<vtkPolyData> Mesh;
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
    c->Mesh = MakeMesh(TheTorus(), U, V, true, true);
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

// threads 0: every core (the default); 1: one thread. (VTK 9.1's TBB backend keeps 1 thread
// after Initialize(1) even when Initialize(0) follows: the count is explicit.)
void SetThreads(int threads)
{
  vtkSMPTools::Initialize(
    threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency()));
}

void BM_DisplacementMapFilter(benchmark::State& state)
{
  const Case& c = GetCase(static_cast<int>(state.range(0)));
  SetThreads(static_cast<int>(state.range(3)));
  vtkNew<vtkDisplacementMapFilter> filter;
  filter->SetInputData(0, c.Mesh);
  filter->SetInputData(1, HeightImage());
  filter->SetScale(Scale);
  filter->SetMidlevel(Mid);
  filter->SetNormalMode(static_cast<int>(state.range(1)));
  filter->SetInterpolation(static_cast<int>(state.range(2)));
  const bool reexecute = state.range(4) != 0;
  if (reexecute)
  {
    filter->Update();
  }
  int k = 0;
  for (auto _ : state)
  {
    if (reexecute)
    {
      // A Scale slider: a new Scale each time, the mesh untouched.
      filter->SetScale(Scale * (1.0 + 1e-6 * (++k % 2)));
    }
    else
    {
      // A new mesh each time, as when the source upstream re-executes (same values, so that
      // the errors stay comparable): points, polygons and every point-data array are new, so
      // nothing kept from the previous execution is reused.
      c.Mesh->GetPoints()->Modified();
      c.Mesh->GetPolys()->Modified();
      vtkPointData* pd = c.Mesh->GetPointData();
      for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
      {
        pd->GetAbstractArray(a)->Modified();
      }
    }
    filter->Update();
  }
  filter->SetScale(Scale);
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
  SetThreads(static_cast<int>(state.range(3)));
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

// Resolutions U (torus U x U/2): the last two are about 1M and 4M points. Arguments:
// U, normal mode (0 for the chain), interpolation (the chain's is Linear), threads, and for
// our filter reexec: 0 a first execution on a changed mesh, 1 a re-execution on the same
// mesh with a new Scale (from 131841 points up).
void Sizes(benchmark::internal::Benchmark* b, bool modes)
{
  for (int U : { 128, 256, 512, 1414, 2828 })
  {
    for (int threads : { 0, 1 })
    {
      if (!modes)
      {
        b->Args({ U, 0, vtkDisplacementMapFilter::Linear, threads });
        continue;
      }
      for (int reexec : { 0, 1 })
      {
        if (reexec && U < 512)
        {
          continue;
        }
        for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
               vtkDisplacementMapFilter::Mesh })
        {
          for (int interp : { vtkDisplacementMapFilter::Nearest, vtkDisplacementMapFilter::Linear,
                 vtkDisplacementMapFilter::Cubic })
          {
            b->Args({ U, mode, interp, threads, reexec });
          }
        }
      }
    }
  }
  if (modes)
  {
    b->ArgNames({ "U", "mode", "interp", "threads", "reexec" });
  }
  else
  {
    b->ArgNames({ "U", "mode", "interp", "threads" });
  }
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}
} // namespace

BENCHMARK(BM_DisplacementMapFilter)
  ->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, true); });
BENCHMARK(BM_VTKChain)->Apply([](benchmark::internal::Benchmark* b) { Sizes(b, false); });

BENCHMARK_MAIN();
