// Normal mapping: the tangent-space normal from the normal map, decoded by sdDecodeNormal
// (vtkSurfaceDetailNormalCoding.glsl, the twin of the conventions header), green up unless
// sdGreenUp is 0; the strength scales the tangential part, as vtkProperty's NormalScale does.
uniform sampler2D sdNormalMap;
uniform float sdNormalStrength;
uniform int sdGreenUp;

vec3 sdNormalMapTS(vec2 tc)
{
  vec3 n = sdDecodeNormal(texture(sdNormalMap, tc).rgb, sdGreenUp != 0);
  n.xy *= sdNormalStrength;
  float len = length(n);
  return len > 1e-12 ? n / len : vec3(0.0, 0.0, 1.0);
}
