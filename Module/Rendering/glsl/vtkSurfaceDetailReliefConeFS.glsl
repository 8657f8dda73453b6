// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Relief mapping's search by cone stepping, after vtkSurfaceDetailReliefFS.glsl, in place of
// the linear and binary search when the mapper has a cone map (vtkHeightMapToConeMap). The
// mapper uploads it beside the relief's depth: one linearly filtered read gives the depth where
// the ray is, an apex depth a no deeper than the highest point of the relief over the texel
// there, and a ratio r (texture units of radius per unit of depth) of a cone opening upward
// from any point of that texel at depth a that no ray leaves from under the surface (relaxed
// cones) or that holds no surface (conservative ones): a step to its side crosses the surface
// at most once, so a step that ends under it brackets the first hit. Each step is one read:
// - under the surface: the bracket from the last point above is closed by secant steps, until
//   the bracket or the gap is below a fraction of a texel and of a pixel;
// - above the surface: on to where the ray crosses the middle of a texel next (one-texel
//   ridges peak there, not at the edges), as a linear search of one step per texel would, or,
//   above a, to the cone's side if that is further (the cone step of Dummer and of Policarpo
//   and Oliveira); at least the rest of the ray over the steps left (LinearSearchSteps).
uniform sampler2D sdConeMap;

// Gap (field depth minus ray depth, in units of depth) under which a secant step is taken as
// the hit, in texels or pixels of the whole depth's reach.
const float sdConeGapTolerance = 0.125;
// The shortest step to a texel's middle, in texels: a ray on a middle goes on to the next.
const float sdConeEdgeNudge = 1.0 / 256.0;

// (depth, apex depth, cone ratio) at tc; the map holds the ratio's square root.
vec3 sdReliefConeAt(vec2 tc)
{
  vec3 c = textureLod(sdConeMap, tc, 0.0).rgb;
  return vec3(c.x, c.y, c.z * c.z);
}

float sdReliefSearch(vec2 tc, vec2 delta, float reach, out vec2 aboveTC, out float aboveDepth)
{
  vec2 texels = vec2(textureSize(sdConeMap, 0));
  vec2 dir = delta * texels; // texels per unit of depth
  float run = length(delta); // texture units per unit of depth
  vec2 perTexel = 1.0 / max(abs(dir), vec2(1e-30)); // depth to cross one texel, per axis
  float nudge = sdConeEdgeNudge * min(perTexel.x, perTexel.y);
  bool alongS = abs(dir.x) >= abs(dir.y); // the ray's main direction across the texels
  float texelDepth = alongS ? perTexel.x : perTexel.y;

  float d = 0.0;
  float lo = 0.0;     // the last depth found above the surface, and its gap there
  float gapLo = 0.0;
  float hi = 1.0;     // the first found under it
  float gapHi = 0.0;
  bool under = false;
  for (int i = 0; i < sdLinearSearchSteps; ++i)
  {
    vec2 p = tc + d * delta;
    vec3 cone = sdReliefConeAt(p);
    float gap = cone.x - d;
    if (gap <= 0.0)
    {
      hi = d;
      gapHi = gap;
      under = true;
      break;
    }
    lo = d;
    gapLo = gap;
    // At least on to where the ray crosses the middle of a texel next (one-texel ridges peak
    // there, not at the edges), as the linear search would step; further where the cone allows.
    float f = fract(alongS ? p.x * texels.x : p.y * texels.y);
    float toMiddle = (0.5 - f) * (alongS ? sign(dir.x) : sign(dir.y)) * texelDepth;
    toMiddle += toMiddle > nudge ? 0.0 : texelDepth;
    float coneStep = cone.z * max(cone.y - d, 0.0) / max(run + cone.z, 1e-30);
    // Never shorter than the rest of the ray over the steps left, so that a long ray reaches the
    // bottom spaced as the linear search would space it.
    float share = (1.0 - d) / float(sdLinearSearchSteps - i);
    d = min(d + max(max(toMiddle, coneStep), share), 1.0);
  }
  if (!under)
  {
    // Out of steps above the surface: the bottom of the box closes the bracket.
    hi = 1.0;
    gapHi = sdReliefConeAt(tc + delta).x - 1.0;
  }
  // Secant steps, exact at once where the relief is planar along the ray; a step after two
  // that moved the same end halves the bracket instead, so that both ends close in. A lower
  // end exactly on the field (a flat top, the bottom) is the hit.
  float side = 0.0; // which end the last step moved: +1 lo, -1 hi
  bool halve = false;
  for (int i = 0; i < sdBinarySearchSteps && gapHi < 0.0 && (hi - lo) * reach > 0.25; ++i)
  {
    float x = halve ? 0.5 * (lo + hi) : lo + (hi - lo) * gapLo / (gapLo - gapHi);
    float gap = sdReliefConeAt(tc + x * delta).x - x;
    float moved = gap <= 0.0 ? -1.0 : 1.0;
    halve = !halve && moved == side;
    side = moved;
    if (gap <= 0.0)
    {
      hi = x;
      gapHi = gap;
    }
    else
    {
      lo = x;
      gapLo = gap;
      if (gap * reach <= sdConeGapTolerance)
      {
        break;
      }
    }
  }
  float span = gapLo - gapHi;
  float hit = span > 0.0 ? lo + (hi - lo) * gapLo / span : hi;
  // Shadow rays start on the view ray a quarter of a texel or pixel before the hit, where the
  // linear and binary search would leave its last point above, or at the last point found
  // above if that is nearer.
  aboveDepth = max(lo, hit - 0.25 / reach);
  aboveTC = tc + aboveDepth * delta;
  return hit;
}
