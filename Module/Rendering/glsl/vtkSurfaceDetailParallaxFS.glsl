// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Parallax mapping with offset limiting (Welsh 2004). The height map's first channel is the
// height h; the surface seen at a fragment lies DepthScale*(1 - h) below the mesh along its
// normal (Documentation/Conventions.md: depth in object units, the top of the relief is the mesh itself). The
// texture coordinate moves by that depth times the tangential part of the view vector,
// without the 1/(V.N) that makes plain parallax swim at grazing angles. The texture frame
// (dP/ds, dP/dt) comes from screen-space derivatives, so no tangent array is needed.
uniform float sdDepthScale;
uniform int sdCameraParallel;

vec2 sdParallaxTCoord(vec2 tc, vec3 posVC, vec3 N, float depthUnitVC)
{
  vec3 sigmaS = dFdx(posVC);
  vec3 sigmaT = dFdy(posVC);
  vec2 tcdx = dFdx(tc);
  vec2 tcdy = dFdy(tc);
  float tcDet = tcdx.x * tcdy.y - tcdx.y * tcdy.x;
  float h = texture(sdHeightMap, tc).r;
  if (!(abs(tcDet) > 1e-30))
  {
    return tc;
  }
  vec3 dPds = (sigmaS * tcdy.y - sigmaT * tcdx.y) / tcDet;
  vec3 dPdt = (sigmaT * tcdx.x - sigmaS * tcdy.x) / tcDet;
  vec3 V = sdCameraParallel != 0 ? vec3(0.0, 0.0, 1.0) : normalize(-posVC);
  vec3 Vt = V - N * dot(N, V);
  mat3 frame = mat3(dPds, dPdt, N);
  if (!(abs(determinant(frame)) > 1e-30))
  {
    return tc;
  }
  // depthUnitVC is how far below the surface, along N in view units, one object unit of
  // depth along the mesh's normal lies, under any actor scale (skewing ones included).
  float depthVC = sdDepthScale * (1.0 - h) * depthUnitVC;
  vec3 shift = inverse(frame) * Vt;
  return tc - depthVC * shift.xy;
}
