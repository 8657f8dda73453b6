// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Normal mapping: the tangent-space normal from the normal map, decoded as sdDecodeNormal
// (vtkSurfaceDetailNormalCoding.glsl, the twin of the conventions header) does, the
// strength scaling the tangential part as vtkProperty's NormalScale does. sdNormalScaleXY
// is (strength, +-strength): its sign on y is the green-up convention (- for DirectX maps),
// so that no branch is taken per fragment. The decoded colour is not renormalised here:
// its length scales all three components alike and sdTangentToView normalises the
// combination, so doing it twice would change nothing but the frame time.
uniform sampler2D sdNormalMap;
uniform vec2 sdNormalScaleXY;

vec3 sdNormalMapDecodeTS(vec3 rgb)
{
  vec3 n = 2.0 * rgb - 1.0;
  return vec3(sdNormalScaleXY * n.xy, n.z);
}

vec3 sdNormalMapTS(vec2 tc)
{
  return sdNormalMapDecodeTS(texture(sdNormalMap, tc).rgb);
}
