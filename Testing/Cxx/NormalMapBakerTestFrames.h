// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Meshes and frames for the tests and the benchmark of vtkNormalMapBaker: the detailed mesh
// (a DisplacementTestSurfaces.h surface displaced by vtkDisplacementMapFilter), and the frame of
// a coarse MakeMesh grid at any texture coordinate, rebuilt from the mesh's own arrays the way
// vtkSurfaceDetailMapper's shaders rebuild it: what a baked texel must be decoded with, and
// where its ray starts.

#ifndef NormalMapBakerTestFrames_h
#define NormalMapBakerTestFrames_h

#include "DisplacementTestSurfaces.h"
#include "TangentFrameTestHelpers.h"

#include "vtkDisplacementMapFilter.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>

namespace DisplacementTest
{
// The coarse mesh's frame at texture coordinate (s,t) of a MakeMesh grid of U x V quads, each
// split as (a, b, d), (a, d, c): position, unit normal, and the interpolated per-vertex
// tangent and bitangent (T without its part along the vertex normal, B = w cross(N, T)).
struct Frame
{
  Vec P, N, T, B;
};

inline Frame CoarseFrame(vtkPolyData* mesh, int U, int V, double s, double t)
{
  const int i = std::min(static_cast<int>(s * U), U - 1),
            j = std::min(static_cast<int>(t * V), V - 1);
  const double fu = s * U - i, fv = t * V - j;
  const vtkIdType a = static_cast<vtkIdType>(j) * (U + 1) + i, b = a + 1, c = a + U + 1, d = c + 1;
  vtkIdType ids[3];
  double w[3];
  if (fu >= fv)
  {
    ids[0] = a, ids[1] = b, ids[2] = d;
    w[0] = 1 - fu, w[1] = fu - fv, w[2] = fv;
  }
  else
  {
    ids[0] = a, ids[1] = d, ids[2] = c;
    w[0] = 1 - fv, w[1] = fu, w[2] = fv - fu;
  }
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  auto tangents = TangentFrame(mesh);
  Frame f{ { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  for (int k = 0; k < 3; ++k)
  {
    Vec p, n, tw;
    mesh->GetPoint(ids[k], p.data());
    normals->GetTuple(ids[k], n.data());
    n = Unit(n);
    double t4[4];
    tangents->GetTuple(ids[k], t4);
    tw = Unit(Add({ t4[0], t4[1], t4[2] }, n, -DotV({ t4[0], t4[1], t4[2] }, n)));
    Vec bt = CrossV(n, tw);
    if (t4[3] < 0)
    {
      bt = { -bt[0], -bt[1], -bt[2] };
    }
    f.P = Add(f.P, p, w[k]);
    f.N = Add(f.N, n, w[k]);
    f.T = Add(f.T, tw, w[k]);
    f.B = Add(f.B, bt, w[k]);
  }
  f.N = Unit(f.N);
  return f;
}

// The surface displaced by vtkDisplacementMapFilter (Exact normals from dNdu/dNdv).
inline vtkSmartPointer<vtkPolyData> Detailed(const Surface& s, int U, int V)
{
  vtkSmartPointer<vtkPolyData> mesh = MakeMesh(s, U, V, true, false, true);
  vtkSmartPointer<vtkImageData> heights = MakeHeightImage(s.Height, 1024, 1024);
  vtkNew<vtkDisplacementMapFilter> displace;
  displace->SetInputData(0, mesh);
  displace->SetInputData(1, heights);
  displace->SetScaleFactor(s.Scale);
  displace->SetMidlevel(s.Midlevel);
  displace->SetInterpolationToCubic();
  displace->SetWrapToRepeat();
  displace->SetNormalModeToExact();
  displace->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(displace->GetOutput());
  return out;
}

} // namespace DisplacementTest

#endif
