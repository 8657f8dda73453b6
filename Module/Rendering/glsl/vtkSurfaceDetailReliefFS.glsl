// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Relief mapping (Policarpo, Oliveira & Comba 2005). The mesh is the top of a
// box DepthScale deep (object units, Documentation/Conventions.md); depth d in [0,1] is SD_RELIEF_DEPTH(tc)
// (the relief map's alpha, or 1 - h of the height map, defined by the mapper). The eye ray
// is marched through the box in (s, t, depth) coordinates by one of two searches, the linear
// and binary search or cone stepping (sdReliefSearch, in the file that follows this one).
// The colour, the normal and the light visibility are all taken at the hit.
//
// The box's frame at a fragment is (dP/ds, dP/dt, N): the surface's own texture
// derivatives from screen-space derivatives, so depth and parallax keep object units
// wherever the texture is stretched, on curved meshes as on planes, and no tangent array
// is needed for the march itself. Every texture read inside the loops is at the level of
// detail of the fragment's own texture coordinate (textureLod), worked out from its
// derivatives before any branch, so mipmapped maps are read at the right level and never
// through derivatives taken in a branch (and one level costs less than a gradient per read).
uniform float sdDepthScale;
uniform int sdCameraParallel;
uniform int sdLinearSearchSteps;
uniform int sdBinarySearchSteps;
uniform int sdAdaptiveSteps;

// Fewest linear steps of the adaptive search: head-on the ray crosses no texel sideways,
// but a few steps keep the first bracket the binary search refines inside one slab.
const float sdMinLinearSteps = 2.0;
// Smallest cosine between the view ray and the tangent plane that the march accepts: a
// ray closer to the plane is marched as at this angle, which keeps the texture offset
// finite at the silhouette.
const float sdMinRayCosine = 0.03;

vec2 sdReliefGradX;    // d(tc)/dx of the fragment
vec2 sdReliefGradY;    // d(tc)/dy
float sdReliefLod;     // the depth map's level of detail there, for every read
vec3 sdReliefDualS;    // with sdReliefDualT: the dual basis of (dP/ds, dP/dt) in the
vec3 sdReliefDualT;    // tangent plane, so that a vector's (ds, dt) are dot products
vec2 sdReliefTexels;   // the depth map's size
vec3 sdReliefDPds;     // dP/ds in view coordinates
vec3 sdReliefDPdt;     // dP/dt
vec3 sdReliefN;        // unit mesh normal of the front face
float sdReliefDepthVC; // DepthScale in view units along N
float sdReliefFade;    // 1: full relief; 0: plain normal mapping (relief below a pixel)
vec2 sdReliefHitTC;    // texture coordinate of the hit
float sdReliefHitDepth;   // its depth, a fraction of DepthScale
vec2 sdReliefAboveTC;  // the last point of the view ray found above the height field,
float sdReliefAboveDepth; // where shadow rays start: the hit itself may lie just under it
float sdReliefRayLength;  // view-space distance from the fragment to the hit

float sdReliefDepthAt(vec2 tc)
{
  return SD_RELIEF_DEPTH(tc);
}

// A view-space vector in the box's coordinates: (ds, dt, depth along N in view units).
vec3 sdReliefToBox(vec3 v)
{
  return vec3(dot(sdReliefDualS, v), dot(sdReliefDualT, v), dot(sdReliefN, v));
}

// Linear steps for a texture-space path: one per texel crossed, between the adaptive
// minimum and LinearSearchSteps; LinearSearchSteps always when adaptive steps are off.
int sdReliefSteps(vec2 path)
{
  float most = float(max(sdLinearSearchSteps, 1));
  if (sdAdaptiveSteps == 0)
  {
    return int(most);
  }
  float texels = length(path * sdReliefTexels);
  return int(clamp(ceil(texels), min(sdMinLinearSteps, most), most));
}

// The search for the hit, by the linear and binary search (vtkSurfaceDetailReliefLinearFS.glsl)
// or by cone stepping (vtkSurfaceDetailReliefConeFS.glsl), whichever follows: the depth fraction
// where the ray tc + d*delta first goes under the height field. aboveTC, aboveDepth: where
// shadow rays start, a point the search found above the field, next to the hit. reach: the
// texels or pixels (the more) that one unit of depth spans along the ray.
float sdReliefSearch(vec2 tc, vec2 delta, float reach, out vec2 aboveTC, out float aboveDepth);

// Marches the view ray from the fragment; returns the texture coordinate every texture is
// then read at. N: the unit normal of the front face; depthUnitVC: view units per object
// unit of depth along N (see the mapper).
vec2 sdReliefTCoord(vec2 tc, vec3 posVC, vec3 N, float depthUnitVC)
{
  vec3 sigmaS = dFdx(posVC);
  vec3 sigmaT = dFdy(posVC);
  sdReliefGradX = dFdx(tc);
  sdReliefGradY = dFdy(tc);
  sdReliefN = N;
  // The isotropic level OpenGL would choose: log2 of the longer texel footprint.
  sdReliefTexels = vec2(textureSize(SD_RELIEF_SAMPLER, 0));
  vec2 footX = sdReliefGradX * sdReliefTexels;
  vec2 footY = sdReliefGradY * sdReliefTexels;
  sdReliefLod = max(0.5 * log2(max(dot(footX, footX), dot(footY, footY))), 0.0);
  sdReliefFade = 0.0;
  sdReliefHitTC = tc;
  sdReliefHitDepth = 0.0;
  sdReliefAboveTC = tc;
  sdReliefAboveDepth = 0.0;
  sdReliefRayLength = 0.0;
  sdReliefDepthVC = sdDepthScale * depthUnitVC;
  float tcDet = sdReliefGradX.x * sdReliefGradY.y - sdReliefGradX.y * sdReliefGradY.x;
  if (!(abs(tcDet) > 1e-30))
  {
    return tc;
  }
  // Screen-space derivatives give each triangle's flat dP/ds, dP/dt; their parts in the
  // tangent plane of the interpolated normal vary smoothly enough not to show the facets.
  sdReliefDPds = (sigmaS * sdReliefGradY.y - sigmaT * sdReliefGradX.y) / tcDet;
  sdReliefDPdt = (sigmaT * sdReliefGradX.x - sigmaS * sdReliefGradY.x) / tcDet;
  sdReliefDPds -= N * dot(N, sdReliefDPds);
  sdReliefDPdt -= N * dot(N, sdReliefDPdt);
  // (dP/ds, dP/dt, N) with N orthogonal to both: the inverse is N itself and, in the
  // plane, the inverse of the 2x2 Gram matrix of dP/ds, dP/dt.
  float gss = dot(sdReliefDPds, sdReliefDPds);
  float gst = dot(sdReliefDPds, sdReliefDPdt);
  float gtt = dot(sdReliefDPdt, sdReliefDPdt);
  float gram = gss * gtt - gst * gst;
  if (!(gram > 1e-30 * gss * gtt) || !(gram > 0.0))
  {
    return tc;
  }
  sdReliefDualS = (gtt * sdReliefDPds - gst * sdReliefDPdt) / gram;
  sdReliefDualT = (gss * sdReliefDPdt - gst * sdReliefDPds) / gram;

  // Fade to normal mapping where the whole depth spans less than a pixel: the pixel's
  // size across the view ray is that of the screen derivatives without their part along it.
  vec3 V = sdCameraParallel != 0 ? vec3(0.0, 0.0, 1.0) : normalize(-posVC);
  float pixel = max(length(sigmaS - V * dot(V, sigmaS)), length(sigmaT - V * dot(V, sigmaT)));
  sdReliefFade = gl_FrontFacing ? clamp(2.0 * sdReliefDepthVC / max(pixel, 1e-30) - 1.0, 0.0, 1.0) : 0.0;
  if (sdReliefFade <= 0.0)
  {
    return tc;
  }

  vec3 ray = sdReliefToBox(-V);
  float down = max(-ray.z, sdMinRayCosine);
  vec2 delta = ray.xy * (sdReliefDepthVC / down); // texture offset from the top to depth 1
  float reach = max(length(delta * sdReliefTexels), sdReliefDepthVC / max(pixel, 1e-30));
  float d = sdReliefSearch(tc, delta, reach, sdReliefAboveTC, sdReliefAboveDepth);
  sdReliefHitTC = tc + d * delta;
  sdReliefHitDepth = d;
  sdReliefRayLength = sdReliefFade * d * sdReliefDepthVC / down;
  return tc + sdReliefFade * d * delta;
}

// The normal of the relief itself, P + DepthScale*(h - 1)*N, at tc: from the height map's
// gradient (dh/ds, dh/dt) and the same frame the march used, so shading and depth describe
// one surface (the one vtkDisplacementMapFilter makes with ScaleFactor = DepthScale, Midlevel 1,
// up to the mesh's curvature over the depth).
vec3 sdReliefHeightNormal(vec2 tc, vec2 gradST)
{
  vec3 a = sdReliefDPds + (sdReliefDepthVC * gradST.x) * sdReliefN;
  vec3 b = sdReliefDPdt + (sdReliefDepthVC * gradST.y) * sdReliefN;
  vec3 n = cross(a, b);
  // Mirrored texture coordinates turn the parameter frame around, not the surface.
  float side = dot(cross(sdReliefDPds, sdReliefDPdt), sdReliefN) < 0.0 ? -1.0 : 1.0;
  float len2 = dot(n, n);
  return len2 > 0.0 ? side * n * inversesqrt(len2) : sdReliefN;
}
