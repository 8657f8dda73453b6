// Normal map decode: RGB = 0.5*n + 0.5 in tangent space (DecodeUnit in
// vtkSurfaceDetailConventions.h), green up unless sdGreenSign = -1; the strength scales the
// tangential part, as vtkProperty's NormalScale does.
uniform sampler2D sdNormalMap;
uniform float sdNormalStrength;
uniform float sdGreenSign;

vec3 sdNormalMapTS(vec2 tc)
{
  vec3 n = texture(sdNormalMap, tc).xyz * 2.0 - 1.0;
  n.y *= sdGreenSign;
  n.xy *= sdNormalStrength;
  float len = length(n);
  return len > 1e-12 ? n / len : vec3(0.0, 0.0, 1.0);
}
