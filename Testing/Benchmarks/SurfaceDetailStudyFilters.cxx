// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The study's CPU part: each filter's accuracy against a closed form, and its time.
// - vtkParametricSurfaceSource: the sphere and the donut at rising resolution; how far the
//   flat triangles stray from the surface (at their centroids) and how far the shading normal
//   (vertex normals interpolated to the centroid) and the facet normal turn from the true one.
// - vtkDisplacementMapFilter: a sphere displaced by a smooth analytic height field sampled into
//   a fine image; each NormalMode's vertex normals against the normal of the displaced surface
//   worked out from its parameterisation (central differences of the analytic P in double).
// - vtkHeightMapToNormalMap: each Scheme on a periodic analytic height field at several image
//   sizes; the decoded normal at each texel centre against (-k dh/ds, -k dh/dt, 1).
// Times are medians of repeated executions (Modified + Update) on an otherwise idle pipeline.

#include "SurfaceDetailStudy.h"

#include <vtkDataArray.h>
#include <vtkDisplacementMapFilter.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkParametricDonut.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <string>

namespace SurfaceDetailStudy
{
namespace
{
using Clock = std::chrono::steady_clock;
const double Pi = vtkMath::Pi();

double TimeUpdates(vtkAlgorithm* algorithm, int repeats)
{
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r)
  {
    algorithm->Modified();
    const auto start = Clock::now();
    algorithm->Update();
    times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  return Median(times);
}

double AngleDegrees(const double a[3], const double b[3])
{
  double na[3] = { a[0], a[1], a[2] }, nb[3] = { b[0], b[1], b[2] };
  vtkMath::Normalize(na);
  vtkMath::Normalize(nb);
  return vtkMath::DegreesFromRadians(std::atan2(
    [&]
    {
      double c[3];
      vtkMath::Cross(na, nb, c);
      return vtkMath::Norm(c);
    }(),
    vtkMath::Dot(na, nb)));
}

struct Stats
{
  double Sum = 0, Max = 0;
  long Count = 0;
  void Add(double v)
  {
    Sum += v;
    Max = std::max(Max, v);
    ++Count;
  }
  double Mean() const { return Count ? Sum / Count : 0.0; }
};

// ---- The source ---------------------------------------------------------------------------

struct Closed
{
  std::string Name;
  std::function<vtkSmartPointer<vtkParametricFunction>()> Function;
  // Signed distance to the surface and the unit normal at the closest point.
  std::function<double(const double p[3], double n[3])> Distance;
  int Aspect; // U resolution = Aspect * V resolution
};

std::vector<Closed> ClosedForms()
{
  Closed sphere{ "sphere R=1",
    []
    { return vtkSmartPointer<vtkParametricFunction>(vtkSmartPointer<vtkParametricSphere>::New()); },
    [](const double p[3], double n[3])
    {
      const double r = vtkMath::Norm(p);
      for (int k = 0; k < 3; ++k)
      {
        n[k] = p[k] / r;
      }
      return r - 1.0;
    },
    2 };
  Closed donut{ "donut R=1 r=0.4",
    []
    { return vtkSmartPointer<vtkParametricFunction>(vtkSmartPointer<vtkParametricDonut>::New()); },
    [](const double p[3], double n[3])
    {
      const double rho = std::hypot(p[0], p[1]);
      const double ring[3] = { p[0] / rho, p[1] / rho, 0.0 };
      const double d[3] = { p[0] - ring[0], p[1] - ring[1], p[2] };
      const double len = vtkMath::Norm(d);
      for (int k = 0; k < 3; ++k)
      {
        n[k] = d[k] / len;
      }
      return len - 0.4;
    },
    3 };
  return { sphere, donut };
}

void SourceStudy(std::FILE* csv, std::FILE* md, int repeats)
{
  std::fprintf(md,
    "\n## vtkParametricSurfaceSource: resolution against position and normal error\n\n"
    "| surface | U x V | triangles | time ms | max distance at centroids | max shading-normal "
    "error (deg) | mean facet-normal error (deg) |\n|---|---|---|---|---|---|---|\n");
  for (const Closed& surface : ClosedForms())
  {
    for (int v : { 4, 8, 16, 32, 64, 128, 256 })
    {
      const int u = surface.Aspect * v;
      vtkNew<vtkParametricSurfaceSource> source;
      source->SetParametricFunction(surface.Function());
      source->SetUResolution(u);
      source->SetVResolution(v);
      const double ms = TimeUpdates(source, repeats);
      vtkPolyData* mesh = source->GetOutput();
      vtkDataArray* normals = mesh->GetPointData()->GetNormals();
      Stats distance, shading, facet;
      vtkNew<vtkIdList> ids;
      for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
      {
        mesh->GetCellPoints(cell, ids);
        if (ids->GetNumberOfIds() != 3)
        {
          continue;
        }
        double p[3][3], c[3] = { 0, 0, 0 }, m[3] = { 0, 0, 0 };
        for (int k = 0; k < 3; ++k)
        {
          mesh->GetPoint(ids->GetId(k), p[k]);
          const double* n = normals->GetTuple3(ids->GetId(k));
          for (int j = 0; j < 3; ++j)
          {
            c[j] += p[k][j] / 3.0;
            m[j] += n[j];
          }
        }
        double truth[3];
        distance.Add(std::abs(surface.Distance(c, truth)));
        shading.Add(AngleDegrees(m, truth));
        double e1[3], e2[3], f[3];
        vtkMath::Subtract(p[1], p[0], e1);
        vtkMath::Subtract(p[2], p[0], e2);
        vtkMath::Cross(e1, e2, f);
        if (vtkMath::Norm(f) > 1e-12)
        {
          facet.Add(AngleDegrees(f, truth));
        }
      }
      std::fprintf(md, "| %s | %dx%d | %lld | %.2f | %.2e | %.3f | %.3f |\n", surface.Name.c_str(),
        u, v, static_cast<long long>(mesh->GetNumberOfCells()), ms, distance.Max, shading.Max,
        facet.Mean());
      std::fprintf(csv,
        "source,%s,default flags,%dx%d,%.3f,max_centroid_distance,%.4e,"
        "max_shading_normal_deg,%.4f,mean_facet_normal_deg,%.4f\n",
        surface.Name.c_str(), u, v, ms, distance.Max, shading.Max, facet.Mean());
    }
  }
}

// ---- Displacement ---------------------------------------------------------------------------

// Smooth on the sphere, poles included: sin(pi t)^8 sin(8 pi s) is a polynomial in the
// Cartesian coordinates near each pole, and cos(6 pi t) is even in the polar angle.
double SphereHeight(double s, double t)
{
  return 0.5 + 0.3 * std::pow(std::sin(Pi * t), 8) * std::sin(8 * Pi * s) +
    0.2 * std::cos(6 * Pi * t);
}

constexpr double DisplacementScale = 0.15;

// The displaced sphere P(s,t) = (1 + Scale (h - 0.5)) n(s,t), in the source's parameterisation.
void DisplacedSphere(double s, double t, double p[3])
{
  const double alpha = Pi * (1 - t), theta = 2 * Pi * s;
  const double n[3] = { std::sin(alpha) * std::cos(theta), std::cos(alpha),
    -std::sin(alpha) * std::sin(theta) };
  const double r = 1.0 + DisplacementScale * (SphereHeight(s, t) - 0.5);
  for (int k = 0; k < 3; ++k)
  {
    p[k] = r * n[k];
  }
}

void DisplacedNormal(double s, double t, double n[3])
{
  const double e = 1e-6;
  double a[3], b[3], c[3], d[3], du[3], dv[3], p[3];
  DisplacedSphere(s + e, t, a);
  DisplacedSphere(s - e, t, b);
  DisplacedSphere(s, t + e, c);
  DisplacedSphere(s, t - e, d);
  vtkMath::Subtract(a, b, du);
  vtkMath::Subtract(c, d, dv);
  vtkMath::Cross(du, dv, n);
  DisplacedSphere(s, t, p);
  if (vtkMath::Dot(n, p) < 0)
  {
    vtkMath::MultiplyScalar(n, -1.0);
  }
  vtkMath::Normalize(n);
}

void DisplacementStudy(std::FILE* csv, std::FILE* md, int repeats)
{
  std::fprintf(md,
    "\n## vtkDisplacementMapFilter: NormalMode against normal error\n\n"
    "Unit sphere, Scale %.2f, Midlevel 0.5, a smooth analytic height field in a 1024x512 float "
    "image (cubic interpolation). Vertex normals against the displaced surface's own normal, "
    "vertices within 0.02 of a pole in t left out (the parameterisation is singular there).\n\n"
    "| NormalMode | U x V | time ms | mean error (deg) | max error (deg) "
    "|\n|---|---|---|---|---|\n",
    DisplacementScale);
  const int w = 1024, h = 512;
  vtkNew<vtkImageData> heights;
  heights->SetDimensions(w, h, 1);
  heights->AllocateScalars(VTK_FLOAT, 1);
  auto* hv = static_cast<float*>(heights->GetScalarPointer());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      hv[j * w + i] = static_cast<float>(SphereHeight((i + 0.5) / w, (j + 0.5) / h));
    }
  }
  struct Mode
  {
    const char* Name;
    int NormalMode;
    bool Derivatives;
  };
  const Mode modes[] = { { "None (undisplaced normals)", vtkDisplacementMapFilter::Input, false },
    { "Approximate", vtkDisplacementMapFilter::Approximate, false },
    { "Exact (dNdu, dNdv from the source)", vtkDisplacementMapFilter::Exact, true },
    { "Exact (fitted from neighbours)", vtkDisplacementMapFilter::Exact, false },
    { "Mesh", vtkDisplacementMapFilter::Mesh, false } };
  for (int v : { 32, 64, 128, 256 })
  {
    for (const Mode& mode : modes)
    {
      vtkNew<vtkParametricSurfaceSource> source;
      source->SetParametricFunction(vtkNew<vtkParametricSphere>());
      source->SetUResolution(2 * v);
      source->SetVResolution(v);
      source->SetGenerateDerivatives(mode.Derivatives);
      source->Update();
      vtkNew<vtkDisplacementMapFilter> displace;
      displace->SetInputConnection(source->GetOutputPort());
      displace->SetInputData(1, heights);
      displace->SetScaleFactor(DisplacementScale);
      displace->SetMidlevel(0.5);
      displace->SetWrapToRepeat();
      displace->SetInterpolationToCubic();
      displace->SetNormalMode(mode.NormalMode);
      const double ms = TimeUpdates(displace, repeats);
      vtkPolyData* out = displace->GetOutput();
      vtkDataArray* normals = out->GetPointData()->GetNormals();
      vtkDataArray* tcoords = out->GetPointData()->GetTCoords();
      Stats error;
      for (vtkIdType id = 0; normals && id < out->GetNumberOfPoints(); ++id)
      {
        const double* st = tcoords->GetTuple2(id);
        if (st[1] < 0.02 || st[1] > 0.98)
        {
          continue;
        }
        double truth[3];
        DisplacedNormal(st[0], st[1], truth);
        error.Add(AngleDegrees(normals->GetTuple3(id), truth));
      }
      std::fprintf(md, "| %s | %dx%d | %.2f | %.3f | %.3f |\n", mode.Name, 2 * v, v, ms,
        error.Mean(), error.Max);
      std::fprintf(csv,
        "displacement,sphere,\"%s\",%dx%d,%.3f,mean_normal_deg,%.4f,max_normal_deg,%.4f,,\n",
        mode.Name, 2 * v, v, ms, error.Mean(), error.Max);
    }
  }
}

// ---- Height map to normal map ---------------------------------------------------------------

// Periodic on the unit square, frequencies up to about 8.6 cycles per side.
double FlatHeight(double s, double t, double& hs, double& ht)
{
  const double a = 2 * Pi * 3 * s, b = 2 * Pi * 2 * t, c = 2 * Pi * (5 * s + 7 * t);
  hs = 0.25 * 2 * Pi * 3 * std::cos(a) * std::cos(b) + 0.1 * 2 * Pi * 5 * std::cos(c);
  ht = -0.25 * 2 * Pi * 2 * std::sin(a) * std::sin(b) + 0.1 * 2 * Pi * 7 * std::cos(c);
  return 0.5 + 0.25 * std::sin(a) * std::cos(b) + 0.1 * std::sin(c);
}

void NormalMapStudy(std::FILE* csv, std::FILE* md, int repeats)
{
  const double k = 0.05;
  std::fprintf(md,
    "\n## vtkHeightMapToNormalMap: Scheme against slope error\n\n"
    "BumpScale %.2f on a periodic analytic height field (slopes up to about 21 degrees), Wrap "
    "Repeat. The decoded normal at each texel centre against (-k dh/ds, -k dh/dt, 1).\n\n"
    "| Scheme | size | output | time ms | mean error (deg) | max error (deg) |\n"
    "|---|---|---|---|---|---|\n",
    k);
  const char* names[] = { "Forward", "Central", "Sobel", "Scharr" };
  for (int size : { 64, 256, 1024 })
  {
    vtkNew<vtkImageData> heights;
    heights->SetDimensions(size, size, 1);
    heights->AllocateScalars(VTK_FLOAT, 1);
    auto* hv = static_cast<float*>(heights->GetScalarPointer());
    std::vector<double> truth(3 * size * size);
    for (int j = 0; j < size; ++j)
    {
      for (int i = 0; i < size; ++i)
      {
        double hs, ht;
        hv[j * size + i] =
          static_cast<float>(FlatHeight((i + 0.5) / size, (j + 0.5) / size, hs, ht));
        double* n = &truth[3 * (j * size + i)];
        n[0] = -k * hs;
        n[1] = -k * ht;
        n[2] = 1.0;
      }
    }
    for (int type : { VTK_FLOAT, VTK_UNSIGNED_CHAR })
    {
      for (int scheme = vtkHeightMapToNormalMap::Forward; scheme <= vtkHeightMapToNormalMap::Scharr;
           ++scheme)
      {
        vtkNew<vtkHeightMapToNormalMap> maps;
        maps->SetInputData(heights);
        maps->SetBumpScale(k);
        maps->SetDifferenceScheme(scheme);
        maps->SetWrapToRepeat();
        maps->SetOutputScalarType(type);
        const double ms = TimeUpdates(maps, repeats);
        vtkDataArray* rgb = maps->GetOutput()->GetPointData()->GetScalars();
        const double unit = type == VTK_FLOAT ? 1.0 : 255.0;
        Stats error;
        for (vtkIdType p = 0; p < rgb->GetNumberOfTuples(); ++p)
        {
          double n[3];
          for (int c = 0; c < 3; ++c)
          {
            n[c] = 2.0 * rgb->GetComponent(p, c) / unit - 1.0;
          }
          error.Add(AngleDegrees(n, &truth[3 * p]));
        }
        const char* output = type == VTK_FLOAT ? "float" : "uchar";
        std::fprintf(md, "| %s | %d | %s | %.2f | %.4f | %.4f |\n", names[scheme], size, output, ms,
          error.Mean(), error.Max);
        std::fprintf(csv,
          "normal map,periodic field,\"%s, %s\",%dx%d,%.3f,mean_normal_deg,%.5f,max_normal_deg,"
          "%.5f,,\n",
          names[scheme], output, size, size, ms, error.Mean(), error.Max);
      }
    }
  }
}
} // namespace

void RunFilterStudies(std::FILE* csv, std::FILE* md, int repeats)
{
  std::fprintf(csv,
    "study,subject,setting,resolution,time_ms_median,error1,value1,error2,"
    "value2,error3,value3\n");
  const int timed = std::max(repeats, 5);
  SourceStudy(csv, md, timed);
  DisplacementStudy(csv, md, timed);
  NormalMapStudy(csv, md, timed);
  std::fprintf(md, "\nTimes: median of %d executions each.\n", timed);
}
} // namespace SurfaceDetailStudy
