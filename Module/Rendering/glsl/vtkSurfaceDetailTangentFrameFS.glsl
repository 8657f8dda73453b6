// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// SurfaceDetail tangent frame (the convention of Module/Filters/vtkSurfaceDetailConventions.h):
// T is made orthogonal to the mesh normal N, B = w*cross(N,T), and a tangent-space normal n
// is n.x*T + n.y*B + n.z*N in the mesh's own coordinates. That vector is a normal, so it
// goes to view coordinates with normalMatrix (the inverse transpose of the model-view
// matrix), which is linear: the vertex shader sends normalMatrix*T and normalMatrix*B,
// divided by |normalMatrix*N| so that they keep their size relative to the normalised N
// VTK interpolates. This stays right under non-uniform actor scaling. A zero combination
// (a degenerate normal-map colour, 0.5 grey) leaves the mesh normal, as sdDecodeNormal's
// fallback (0,0,1) does.
vec3 sdTangentToView(vec3 nTS, vec3 N, vec3 tangentVC, vec3 bitangentVC)
{
  vec3 n = nTS.x * tangentVC + nTS.y * bitangentVC + nTS.z * N;
  float len2 = dot(n, n);
  return len2 > 0.0 ? n * inversesqrt(len2) : N;
}
