// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Relief mapping's search by a linear search to the first sample under the height field, so
// that thin features are not stepped over, then a binary search; after
// vtkSurfaceDetailReliefFS.glsl, when no cone map is given.

// Binary steps that narrow one linear step of a ray spanning `reach` texels or pixels
// (whichever is more) to a quarter of one; BinarySearchSteps always when adaptive steps
// are off.
int sdReliefBinarySteps(float reach, int linearSteps)
{
  if (sdAdaptiveSteps == 0)
  {
    return sdBinarySearchSteps;
  }
  float needed = ceil(log2(max(4.0 * reach / float(linearSteps), 1.0)));
  return int(min(needed, float(sdBinarySearchSteps)));
}

// The depth fraction where the ray tc + d*delta first goes under the height field; above:
// the last depth the searches found the ray still above it. The bracket the searches leave
// is closed by the secant through the ray's heights over the field at its ends, exact
// where the field is planar there (a flat top comes out at depth 0, not half a bracket in).
float sdReliefIntersect(vec2 tc, vec2 delta, int steps, int binarySteps, out float above)
{
  float lo = 0.0;
  float hi = 1.0;
  float gapLo = sdReliefDepthAt(tc); // field depth minus ray depth: > 0 above the field
  float gapHi = 0.0;
  float stepSize = 1.0 / float(steps);
  for (int i = 1; i <= steps; ++i)
  {
    float d = float(i) * stepSize;
    float gap = sdReliefDepthAt(tc + d * delta) - d;
    if (gap <= 0.0)
    {
      hi = d;
      gapHi = gap;
      break;
    }
    lo = d;
    gapLo = gap;
  }
  for (int i = 0; i < binarySteps; ++i)
  {
    float mid = 0.5 * (lo + hi);
    float gap = sdReliefDepthAt(tc + mid * delta) - mid;
    if (gap <= 0.0)
    {
      hi = mid;
      gapHi = gap;
    }
    else
    {
      lo = mid;
      gapLo = gap;
    }
  }
  above = lo;
  float span = gapLo - gapHi;
  return span > 0.0 ? lo + (hi - lo) * gapLo / span : lo;
}

float sdReliefSearch(vec2 tc, vec2 delta, float reach, out vec2 aboveTC, out float aboveDepth)
{
  int steps = sdReliefSteps(delta);
  float d = sdReliefIntersect(tc, delta, steps, sdReliefBinarySteps(reach, steps), aboveDepth);
  aboveTC = tc + aboveDepth * delta;
  return d;
}
