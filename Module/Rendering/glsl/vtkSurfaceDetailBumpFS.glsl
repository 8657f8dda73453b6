// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Bump mapping (Blinn 1978) from a height map h(s,t). sdHeightMap holds (h, dh/ds, dh/dt)
// per texel, or only (dh/ds, dh/dt) for bump mapping, which needs no height (SD_GRADIENT,
// defined by the mapper, names the two channels), the derivatives by forward (the classic three-lookup Cg code) or central differences at the
// height map's own texel size 1/w, 1/h, made on upload (vtkSurfaceDetailMapper.cxx,
// UploadHeightMap): interpolating those differences gives exactly the difference of
// interpolated heights one texel apart, in one lookup instead of three. The gradient of
// k*h over the unit texture square gives the tangent-space normal of z = k*h(s,t),
// normalize(-k*dh/ds, -k*dh/dt, 1), the same map vtkHeightMapToNormalMap makes.
uniform sampler2D sdHeightMap;
uniform float sdBumpScale;

vec2 sdHeightGradient(vec2 tc)
{
  return sdBumpScale * texture(sdHeightMap, tc).SD_GRADIENT;
}

vec3 sdBumpTS(vec2 tc)
{
  return vec3(-sdHeightGradient(tc), 1.0); // normalised by sdTangentToView
}

// Tangent-free bump mapping (Mikkelsen 2010, "Bump mapping unparametrized surfaces on the
// GPU"): the surface gradient of the height field comes from screen-space derivatives of
// the position, so no tangent array is needed. The height's screen derivatives are taken by
// the chain rule from the texture-space gradient (smooth, unlike dFdx of the height itself),
// and the height is measured in units of the texture square's side in view coordinates, so
// that BumpScale means the same as with tangents.
vec3 sdBumpSurfaceGradient(vec3 N, vec3 posVC, vec2 tc, vec2 gradST)
{
  vec3 sigmaS = dFdx(posVC);
  vec3 sigmaT = dFdy(posVC);
  vec2 tcdx = dFdx(tc);
  vec2 tcdy = dFdy(tc);
  vec3 r1 = cross(sigmaT, N);
  vec3 r2 = cross(N, sigmaS);
  float det = dot(sigmaS, r1);
  float tcDet = tcdx.x * tcdy.y - tcdx.y * tcdy.x;
  if (!(abs(det) > 1e-30) || !(abs(tcDet) > 1e-30))
  {
    return N;
  }
  float side = sqrt(abs(det) / abs(tcDet));
  float dBs = side * dot(gradST, tcdx);
  float dBt = side * dot(gradST, tcdy);
  vec3 surfGrad = sign(det) * (dBs * r1 + dBt * r2);
  return normalize(abs(det) * N - surfGrad);
}
