// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Triplanar mapping, the twin of TriplanarWeights, TriplanarProject and TriplanarNormal in
// vtkSurfaceDetailConventions.h: three planar projections along the axes of the triplanar
// space (the object's or the world's), each face seen from outside it, blended by the
// normal. A projection whose weight is under 1/256 is not read. Textures are read with the
// derivatives of their coordinates taken before any branch, so mipmaps stay right where
// neighbouring fragments read different projections.
// SD_TRIPLANAR_COLOR, SD_TRIPLANAR_NORMAL_MAP and SD_TRIPLANAR_BUMP say what is read.
in vec3 sdTriplanarPositionVSOutput;
in vec3 sdTriplanarNormalVSOutput;
uniform float sdTriplanarScale;
uniform float sdTriplanarSharpness;

vec3 sdTriplanarWeights(vec3 n)
{
  vec3 w = pow(abs(n), vec3(sdTriplanarSharpness));
  w /= max(w.x + w.y + w.z, 1e-30);
  w *= step(vec3(1.0 / 256.0), w);
  return w / (w.x + w.y + w.z);
}

// Texture coordinates of projection axis (0, 1, 2) for sign sigma of the normal along it.
vec2 sdTriplanarST(int axis, float sigma, vec3 p)
{
  vec2 st = axis == 0 ? vec2(sigma * p.y, p.z)
                      : (axis == 1 ? vec2(-sigma * p.x, p.z) : vec2(sigma * p.x, p.y));
  return sdTriplanarScale * st;
}

vec3 sdTriplanarTangent(int axis, float sigma)
{
  return axis == 0 ? vec3(0.0, sigma, 0.0)
                   : (axis == 1 ? vec3(-sigma, 0.0, 0.0) : vec3(sigma, 0.0, 0.0));
}

// A tangent-space normal of one projection, in triplanar space, its frame reoriented to the
// surface normal n (unit).
vec3 sdTriplanarReorient(vec3 nTS, vec3 n, vec3 tangent)
{
  vec3 T = tangent - n * dot(n, tangent);
  float len = length(T);
  T = len > 0.0 ? T / len : vec3(0.0);
  return nTS.x * T + nTS.y * cross(n, T) + nTS.z * n;
}

#ifdef SD_TRIPLANAR_COLOR
uniform sampler2D sdTriplanarColorTexture;
#endif
vec4 sdTriplanarColor = vec4(1.0);   // the projected colour texture
vec3 sdTriplanarDetail = vec3(0.0);  // the detail normal in triplanar space (not unit)

// Reads every projection whose weight counts, once, for all that is on: the colour into
// sdTriplanarColor, the normal-map or bump normal, reoriented, into sdTriplanarDetail.
void sdTriplanarSample(vec3 p, vec3 n)
{
  vec3 w = sdTriplanarWeights(n);
  vec3 sigma = vec3(n.x < 0.0 ? -1.0 : 1.0, n.y < 0.0 ? -1.0 : 1.0, n.z < 0.0 ? -1.0 : 1.0);
#ifdef SD_TRIPLANAR_COLOR
  sdTriplanarColor = vec4(0.0);
#endif
  for (int axis = 0; axis < 3; ++axis)
  {
    vec2 st = sdTriplanarST(axis, sigma[axis], p);
    vec2 dx = dFdx(st);
    vec2 dy = dFdy(st);
    if (w[axis] > 0.0)
    {
#ifdef SD_TRIPLANAR_COLOR
      sdTriplanarColor += w[axis] * textureGrad(sdTriplanarColorTexture, st, dx, dy);
#endif
#if defined(SD_TRIPLANAR_NORMAL_MAP) || defined(SD_TRIPLANAR_BUMP)
#ifdef SD_TRIPLANAR_NORMAL_MAP
      vec3 nTS = sdNormalMapDecodeTS(textureGrad(sdNormalMap, st, dx, dy).rgb);
#else
      vec3 nTS = sdBumpTS(st);
#endif
      vec3 nA = sdTriplanarReorient(nTS, n, sdTriplanarTangent(axis, sigma[axis]));
      float len2 = dot(nA, nA);
      sdTriplanarDetail += w[axis] * (len2 > 0.0 ? nA * inversesqrt(len2) : n);
#endif
    }
  }
}
