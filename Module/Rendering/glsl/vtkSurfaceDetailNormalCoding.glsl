// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Normal-map coding shared by SurfaceDetail's shaders. This is the GLSL twin of
// EncodeNormal/DecodeNormal in Module/Filters/vtkSurfaceDetailConventions.h: change one,
// change the other. A normal map stores 0.5*n + 0.5 per component in tangent space,
// green up (+Y = +t, OpenGL) unless greenUp is false (DirectX, -Y). Integer textures are
// read by the sampler as value/max, which is the colour these functions expect.

vec3 sdEncodeNormal(vec3 n, bool greenUp)
{
  return 0.5 * vec3(n.x, greenUp ? n.y : -n.y, n.z) + 0.5;
}

// Quantisation leaves the decoded vector slightly off unit length: renormalise, and fall
// back to the unperturbed normal (0,0,1) for a degenerate colour.
vec3 sdDecodeNormal(vec3 rgb, bool greenUp)
{
  vec3 n = 2.0 * rgb - 1.0;
  n.y = greenUp ? n.y : -n.y;
  float len2 = dot(n, n);
  return len2 > 0.0 ? n * inversesqrt(len2) : vec3(0.0, 0.0, 1.0);
}
