// Normal mapping: the tangent-space normal from the normal map, decoded by sdDecodeNormal
// (vtkSurfaceDetailNormalCoding.glsl, the twin of the conventions header), green up unless
// sdGreenUp is 0; the strength scales the tangential part, as vtkProperty's NormalScale
// does. The result is left unnormalised: sdTangentToView normalises once, at the end.
uniform sampler2D sdNormalMap;
uniform float sdNormalStrength;
uniform int sdGreenUp;

vec3 sdNormalMapTS(vec2 tc)
{
  vec3 n = sdDecodeNormal(texture(sdNormalMap, tc).rgb, sdGreenUp != 0);
  return vec3(sdNormalStrength * n.xy, n.z);
}
