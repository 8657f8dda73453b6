// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Relief mapping's depth correction, after vtkSurfaceDetailReliefFS.glsl: the window depth
// of the hit instead of the mesh's, written to gl_FragDepth by the mapper: the fragment
// moved along the view ray to the hit, projected.
uniform mat4 sdVCDCMatrix;
float sdReliefFragDepth(vec3 posVC)
{
  if (sdReliefRayLength == 0.0)
  {
    return gl_FragCoord.z;
  }
  vec3 V = sdCameraParallel != 0 ? vec3(0.0, 0.0, 1.0) : normalize(-posVC);
  vec4 clip = sdVCDCMatrix * vec4(posVC - sdReliefRayLength * V, 1.0);
  return clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
}
