// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Meshes for the vtkMikkTSpaceTangents tests and benchmark, and the bridge to the
 * reference MikkTSpace (the npm package "mikktspace", run by node on an unindexed
 * triangle list). Everything is single precision, as the reference reads it, so that both
 * sides see exactly the same numbers.
 */
#ifndef MikkTSpaceTestMeshes_h
#define MikkTSpaceTestMeshes_h

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#ifdef _WIN32
#include <process.h> // _getpid
#else
#include <unistd.h> // getpid
#endif

namespace mikktest
{
constexpr double Pi = 3.14159265358979323846;

struct Sample
{
  std::array<double, 3> P, N;
  std::array<double, 2> T;
};

// An empty float array named @a name with @a components components: the meshes' "Normals"
// (3) and "TCoords" (2).
inline vtkSmartPointer<vtkFloatArray> NewFloatArray(const char* name, int components)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  return a;
}

inline std::array<double, 3> Normalized(std::array<double, 3> v)
{
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / l, v[1] / l, v[2] / l };
}

inline std::array<double, 3> CrossD(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

/// A surface of the given points and polygons, with point normals and texture coordinates.
inline vtkSmartPointer<vtkPolyData> MakeSurface(
  vtkPoints* points, vtkCellArray* polys, vtkDataArray* normals, vtkDataArray* tcoords)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  pd->GetPointData()->SetNormals(normals);
  pd->GetPointData()->SetTCoords(tcoords);
  return pd;
}

/**
 * A (nu+1) x (nv+1) grid of points from @a f(u, v) on [0,1]^2, two triangles per cell,
 * counter-clockwise in (u, v). Points on a periodic seam are separate points (a texture
 * seam), as in any UV-mapped mesh.
 */
inline vtkSmartPointer<vtkPolyData> MakeGrid(
  int nu, int nv, const std::function<Sample(double, double)>& f, bool quads = false)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  auto normals = NewFloatArray("Normals", 3);
  auto tcoords = NewFloatArray("TCoords", 2);
  for (int j = 0; j <= nv; ++j)
  {
    for (int i = 0; i <= nu; ++i)
    {
      const Sample s = f(static_cast<double>(i) / nu, static_cast<double>(j) / nv);
      points->InsertNextPoint(s.P.data());
      normals->InsertNextTuple(s.N.data());
      tcoords->InsertNextTuple(s.T.data());
    }
  }
  vtkNew<vtkCellArray> polys;
  auto id = [nu](int i, int j) { return static_cast<vtkIdType>(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const vtkIdType a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (quads)
      {
        const vtkIdType q[4] = { a, b, c, d };
        polys->InsertNextCell(4, q);
      }
      else
      {
        const vtkIdType t1[3] = { a, b, c }, t2[3] = { a, c, d };
        polys->InsertNextCell(3, t1);
        polys->InsertNextCell(3, t2);
      }
    }
  }
  return MakeSurface(points, polys, normals, tcoords);
}

/// A flat square with skewed, non-uniform texture coordinates.
inline vtkSmartPointer<vtkPolyData> MakePlane(int n)
{
  return MakeGrid(n, n,
    [](double u, double v)
    {
      return Sample{ { 2 * u - 1, 2 * v - 1, 0.0 }, { 0.0, 0.0, 1.0 },
        { u + 0.3 * v * v, v - 0.2 * u + 0.1 * std::sin(3 * u) } };
    });
}

/// Unit sphere, u around z, v from the south pole (v = 0) to the north pole (v = 1).
inline Sample SpherePoint(double u, double v)
{
  const double th = 2 * Pi * u, al = Pi * (1 - v);
  const std::array<double, 3> p{ std::cos(th) * std::sin(al), std::sin(th) * std::sin(al),
    std::cos(al) };
  return Sample{ p, p, { u, v } };
}

/**
 * UV sphere with poles, as modelling tools make it: rings of separate points on the seam
 * u = 0/1; at the south pole one point per segment (texture u at the segment's middle), at
 * the north pole a single point shared by the whole fan.
 */
inline vtkSmartPointer<vtkPolyData> MakeUVSphere(int nu, int nv)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  auto normals = NewFloatArray("Normals", 3);
  auto tcoords = NewFloatArray("TCoords", 2);
  auto add = [&](const Sample& s)
  {
    points->InsertNextPoint(s.P.data());
    normals->InsertNextTuple(s.N.data());
    tcoords->InsertNextTuple(s.T.data());
    return points->GetNumberOfPoints() - 1;
  };
  // rings j = 1 .. nv-1, each nu+1 points
  std::vector<vtkIdType> ring((nv + 1) * (nu + 1), -1);
  for (int j = 1; j < nv; ++j)
  {
    for (int i = 0; i <= nu; ++i)
    {
      ring[j * (nu + 1) + i] =
        add(SpherePoint(static_cast<double>(i) / nu, static_cast<double>(j) / nv));
    }
  }
  vtkNew<vtkCellArray> polys;
  for (int i = 0; i < nu; ++i)
  {
    Sample s = SpherePoint(0.0, 0.0);
    s.T = { (i + 0.5) / nu, 0.0 };
    const vtkIdType pole = add(s);
    const vtkIdType t[3] = { pole, ring[(nu + 1) + i + 1], ring[(nu + 1) + i] };
    polys->InsertNextCell(3, t);
  }
  Sample north = SpherePoint(0.0, 1.0);
  north.T = { 0.5, 1.0 };
  const vtkIdType northPole = add(north);
  for (int j = 1; j < nv - 1; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const vtkIdType a = ring[j * (nu + 1) + i], b = ring[j * (nu + 1) + i + 1];
      const vtkIdType c = ring[(j + 1) * (nu + 1) + i + 1], d = ring[(j + 1) * (nu + 1) + i];
      const vtkIdType t1[3] = { a, b, c }, t2[3] = { a, c, d };
      polys->InsertNextCell(3, t1);
      polys->InsertNextCell(3, t2);
    }
  }
  for (int i = 0; i < nu; ++i)
  {
    const vtkIdType t[3] = { ring[(nv - 1) * (nu + 1) + i], ring[(nv - 1) * (nu + 1) + i + 1],
      northPole };
    polys->InsertNextCell(3, t);
  }
  return MakeSurface(points, polys, normals, tcoords);
}

/// Torus (ring radius 1, tube 0.35), seams in both directions, texture repeated twice in u.
inline vtkSmartPointer<vtkPolyData> MakeTorus(int nu, int nv)
{
  return MakeGrid(nu, nv,
    [](double u, double v)
    {
      const double a = 2 * Pi * u, b = 2 * Pi * v, R = 1.0, r = 0.35;
      const std::array<double, 3> p{ (R + r * std::cos(b)) * std::cos(a),
        (R + r * std::cos(b)) * std::sin(a), r * std::sin(b) };
      const std::array<double, 3> pu{ -(R + r * std::cos(b)) * std::sin(a),
        (R + r * std::cos(b)) * std::cos(a), 0.0 };
      const std::array<double, 3> pv{ -r * std::sin(b) * std::cos(a),
        -r * std::sin(b) * std::sin(a), r * std::cos(b) };
      return Sample{ p, Normalized(CrossD(pu, pv)), { 2 * u, v } };
    });
}

/**
 * A bumpy sheet whose texture is mirrored about x = 0 (s = |x|): the left half is a
 * mirrored copy of the right half's texture, sharing the points on the mirror line.
 */
inline vtkSmartPointer<vtkPolyData> MakeMirroredSheet(int n)
{
  return MakeGrid(2 * n, n,
    [](double u, double v)
    {
      const double x = 2 * u - 1, y = v;
      const double z = 0.15 * std::sin(2 * x + 1) * std::cos(3 * y);
      const double zx = 0.3 * std::cos(2 * x + 1) * std::cos(3 * y);
      const double zy = -0.45 * std::sin(2 * x + 1) * std::sin(3 * y);
      return Sample{ { x, y, z }, Normalized({ -zx, -zy, 1.0 }), { std::abs(x), y } };
    });
}

/// An open cylinder of radius 1 with its texture seam at u = 0/1 (separate points).
inline vtkSmartPointer<vtkPolyData> MakeSeamCylinder(int nu, int nv)
{
  return MakeGrid(nu, nv,
    [](double u, double v)
    {
      const double a = 2 * Pi * u;
      return Sample{ { std::cos(a), std::sin(a), 2 * v }, { std::cos(a), std::sin(a), 0.0 },
        { u, 0.5 * v } };
    });
}

/// Every triangle on its own three points (a "triangle soup" with smooth normals).
inline vtkSmartPointer<vtkPolyData> Unweld(vtkPolyData* in)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkIdList> ids;
  vtkNew<vtkCellArray> polys;
  vtkIdType n = 0;
  for (vtkIdType c = 0; c < in->GetNumberOfCells(); ++c)
  {
    in->GetCellPoints(c, ids);
    polys->InsertNextCell(static_cast<int>(ids->GetNumberOfIds()));
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      polys->InsertCellPoint(n++);
    }
  }
  vtkNew<vtkIdList> src;
  for (vtkIdType c = 0; c < in->GetNumberOfCells(); ++c)
  {
    in->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      src->InsertNextId(ids->GetId(k));
    }
  }
  points->SetNumberOfPoints(n);
  in->GetPoints()->GetData()->GetTuples(src, points->GetData());
  out->SetPoints(points);
  out->SetPolys(polys);
  out->GetPointData()->CopyAllocate(in->GetPointData(), n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    out->GetPointData()->CopyData(in->GetPointData(), src->GetId(i), i);
  }
  return out;
}

/// Corners of an unindexed triangle list, as the reference reads them.
struct Corners
{
  std::vector<float> P, N, T;
  size_t Size() const { return this->P.size() / 3; }
  void Add(vtkPolyData* pd, vtkIdType pt)
  {
    double p[3], n[3], t[2];
    pd->GetPoint(pt, p);
    pd->GetPointData()->GetNormals()->GetTuple(pt, n);
    pd->GetPointData()->GetTCoords()->GetTuple(pt, t);
    this->P.insert(this->P.end(), { float(p[0]), float(p[1]), float(p[2]) });
    this->N.insert(this->N.end(), { float(n[0]), float(n[1]), float(n[2]) });
    this->T.insert(this->T.end(), { float(t[0]), float(t[1]) });
  }
};

/**
 * Runs the reference on @a corners; returns 4 floats per corner, or an empty vector if
 * node or the package failed (the caller must fail the test then).
 */
inline std::vector<float> ReferenceTangents(
  const Corners& corners, const std::string& tag, int repetitions = 0)
{
  // The process id keeps apart the same test's runs that ctest may start at once (its
  // -avx2 and -baseline registrations).
#ifdef _WIN32
  const std::string base =
    std::string(MIKKTSPACE_WORK_DIR) + "/" + tag + "-" + std::to_string(_getpid());
#else
  const std::string base =
    std::string(MIKKTSPACE_WORK_DIR) + "/" + tag + "-" + std::to_string(getpid());
#endif
  const std::string in = base + ".in.bin";
  const std::string out = base + ".out.bin";
  {
    std::ofstream f(in, std::ios::binary);
    const std::uint32_t n = static_cast<std::uint32_t>(corners.Size());
    f.write(reinterpret_cast<const char*>(&n), sizeof(n));
    f.write(reinterpret_cast<const char*>(corners.P.data()), corners.P.size() * sizeof(float));
    f.write(reinterpret_cast<const char*>(corners.N.data()), corners.N.size() * sizeof(float));
    f.write(reinterpret_cast<const char*>(corners.T.data()), corners.T.size() * sizeof(float));
  }
  std::remove(out.c_str());
  const std::string cmd = std::string("\"") + MIKKTSPACE_NODE + "\" \"" + MIKKTSPACE_SCRIPT +
    "\" \"" + MIKKTSPACE_NPM_DIR + "\" \"" + in + "\" \"" + out + "\" " +
    std::to_string(repetitions);
  if (std::system(cmd.c_str()) != 0)
  {
    return {};
  }
  std::vector<float> result(4 * corners.Size());
  std::ifstream f(out, std::ios::binary);
  f.read(reinterpret_cast<char*>(result.data()), result.size() * sizeof(float));
  const bool complete = static_cast<size_t>(f.gcount()) == result.size() * sizeof(float);
  f.close();
  std::remove(in.c_str());
  std::remove(out.c_str());
  if (!complete)
  {
    return {};
  }
  return result;
}
} // namespace mikktest

#endif
