// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Relief mapping's search by cone stepping, after vtkSurfaceDetailReliefFS.glsl, in place of
// the linear and binary search when the mapper has a cone map (vtkHeightMapToConeMap). For
// every texel the map holds the apex depth a, the highest point of the relief over the
// texel's footprint, and the ratio r (texture units of radius per unit of depth) of a cone
// opening upward from any apex there that holds no surface.
// - Above a, the march steps to the farther of two places it cannot pass the surface before:
//   the side of that cone (Dummer's conservative cone step) and the nearer of depth a and the
//   footprint's edge (the surface lies at a or deeper over the whole footprint).
// - At or under a, it reads the depth itself, where the ray crosses the footprint's middle (a
//   one-texel ridge peaks there, not at the edges); still above, it goes on to the next
//   footprint, whose cone it skips while the surface is within a texel's descent of the ray.
// - Under the surface, the bracket from the last point above is closed by secant steps, until
//   the bracket or the gap is below a fraction of a texel and of a pixel.
// Each step reads at most one cone and one depth.
uniform sampler2D sdConeMap;

// Gap (field depth minus ray depth, in units of depth) under which a secant step is taken as
// the hit, in texels or pixels of the whole depth's reach.
const float sdConeGapTolerance = 0.125;
// How far past a footprint's edge a step lands, in texels: the next point reads the next
// texel's cone, never the same one again.
const float sdConeEdgeNudge = 1.0 / 256.0;

// The cone of the texel whose footprint holds tc (the map is sampled nearest, with its wrap).
vec2 sdReliefConeAt(vec2 tc)
{
  return textureLod(sdConeMap, tc, 0.0).rg;
}

float sdReliefSearch(vec2 tc, vec2 delta, float reach, out vec2 aboveTC, out float aboveDepth)
{
  vec2 texels = vec2(textureSize(sdConeMap, 0));
  vec2 dir = delta * texels; // texels per unit of depth
  float run = length(delta); // texture units per unit of depth
  vec2 towardSide = step(0.0, dir);
  vec2 perTexel = 1.0 / max(abs(dir), vec2(1e-30)); // depth to cross one texel, per axis
  float nudge = sdConeEdgeNudge * min(perTexel.x, perTexel.y);

  float d = 0.0;
  float lo = 0.0;     // the last depth known above the surface
  float gapLo = -1.0; // its gap when read (> 0), -1 when known only from a cone
  float hi = 1.0;
  float gapHi = 0.0;
  bool under = false;
  bool near = false; // the last depth read found the surface within a texel's descent
  float texelDescent = min(perTexel.x, perTexel.y);
  bool alongS = abs(dir.x) >= abs(dir.y); // the ray's main direction across the texels
  for (int i = 0; i < sdLinearSearchSteps; ++i)
  {
    vec2 p = tc + d * delta;
    vec2 x = p * texels;
    vec2 f = x - floor(x);
    // The bottom of the box is under every surface: no cone can take the ray further.
    vec2 cone = d < 1.0 && !near ? sdReliefConeAt(p) : vec2(d, 0.0);
    vec2 toSide = mix(f, 1.0 - f, towardSide) * perTexel;
    float leave = d + min(toSide.x, toSide.y) + nudge; // where the ray leaves the footprint
    if (d < cone.x)
    {
      // Above the whole footprint: safe up to the cone's side, or the footprint's edge or a.
      lo = d;
      gapLo = -1.0;
      float coneStep = cone.y * (cone.x - d) / (run + cone.y);
      d = min(max(d + coneStep, min(cone.x, leave)), 1.0);
      if (d < cone.x)
      {
        continue;
      }
    }
    // At or under the footprint's highest point: the surface may be here. It is read where the
    // ray crosses the footprint's middle (or here, past it), where a one-texel ridge peaks.
    float toMiddle = alongS ? (0.5 - f.x) * sign(dir.x) * perTexel.x
                            : (0.5 - f.y) * sign(dir.y) * perTexel.y;
    d = toMiddle > 0.0 && d + toMiddle < min(leave, 1.0) ? d + toMiddle : d;
    float gap = sdReliefDepthAt(tc + d * delta) - d;
    if (gap <= 0.0)
    {
      hi = d;
      gapHi = gap;
      under = true;
      break;
    }
    lo = d;
    gapLo = gap;
    near = gap < texelDescent;
    d = min(leave, 1.0);
  }
  if (!under)
  {
    // Out of steps above the surface: the bottom of the box closes the bracket.
    hi = 1.0;
    gapHi = sdReliefDepthAt(tc + delta) - 1.0;
  }
  // Secant steps, exact at once where the relief is planar along the ray; a step after two
  // that moved the same end halves the bracket instead, so that both ends close in. A lower
  // end exactly on the field (a flat top, the bottom) is the hit.
  float side = 0.0; // which end the last step moved: +1 lo, -1 hi
  bool halve = false;
  for (int i = 0; i < sdBinarySearchSteps && gapHi < 0.0 && (hi - lo) * reach > 0.25; ++i)
  {
    // Halved too while the upper end's gap was never read (a point a cone proved above).
    float x = halve || gapLo <= 0.0 ? 0.5 * (lo + hi) : lo + (hi - lo) * gapLo / (gapLo - gapHi);
    float gap = sdReliefDepthAt(tc + x * delta) - x;
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
  float hit = gapLo > 0.0 && span > 0.0 ? lo + (hi - lo) * gapLo / span : (gapHi == 0.0 ? hi : lo);
  // Shadow rays start on the view ray a quarter of a texel or pixel before the hit, where the
  // linear and binary search would leave its last point above, or at the last point found
  // above if that is nearer: lo itself can be as far back as the footprint's highest point.
  aboveDepth = max(lo, hit - 0.25 / reach);
  aboveTC = tc + aboveDepth * delta;
  return hit;
}
