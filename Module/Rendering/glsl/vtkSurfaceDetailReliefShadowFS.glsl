// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Relief mapping's self-shadowing (Policarpo, Oliveira & Comba 2005), after
// vtkSurfaceDetailReliefFS.glsl, whose march leaves the hit and the frame in its globals.
// The mapper passes each of VTK's per-light diffuse terms through sdShadowed.

// Depth (as a fraction of DepthScale) over which an occluder fades a light out: soft
// enough that shadow edges do not alias, hard enough to read as Policarpo and Oliveira's shadows.
const float sdShadowSoftness = 0.04;
// Occlusion (same units) that casts no shadow: the view search's steps may pass a corner
// of the height field that the denser or offset shadow steps then graze (shadow acne).
const float sdShadowBias = 0.02;
float sdLightVisibility = 1.0; // of the light being shaded (specular uses it too)

// How much of a light reaches the hit (1 lit, 0 in the relief's shadow): the ray toward
// the light (L, unit, view coordinates) is followed up to the top of the box from the last
// point of the view ray above the height field (so that the search's own tolerance under
// the surface is not taken for a shadow); any height above it on the way shades the hit.
// Lights behind the mesh's tangent plane cannot reach into the box.
float sdReliefShadow(vec3 L)
{
  if (sdReliefFade <= 0.0)
  {
    return 1.0;
  }
  vec3 ray = sdReliefToBox(L);
  if (!(ray.z > 0.0))
  {
    return 1.0 - sdReliefFade;
  }
  float up = max(ray.z, sdMinRayCosine);
  vec2 delta = ray.xy * (sdReliefAboveDepth * sdReliefDepthVC / up);
  int steps = sdReliefSteps(delta);
  float occlusion = 0.0;
  for (int i = 1; i < steps; ++i)
  {
    float f = float(i) / float(steps);
    float rayDepth = sdReliefAboveDepth * (1.0 - f);
    occlusion = max(occlusion, rayDepth - sdReliefDepthAt(sdReliefAboveTC + f * delta));
  }
  float lit = 1.0 - clamp((occlusion - sdShadowBias) / sdShadowSoftness, 0.0, 1.0);
  return mix(1.0, lit, sdReliefFade);
}

// VTK's diffuse term for one light, with its visibility; the light's specular term reads
// sdLightVisibility. Lights the detail normal faces away from are not traced.
float sdShadowed(float df, vec3 L)
{
  sdLightVisibility = df > 0.0 ? sdReliefShadow(normalize(L)) : 1.0;
  return df * sdLightVisibility;
}
