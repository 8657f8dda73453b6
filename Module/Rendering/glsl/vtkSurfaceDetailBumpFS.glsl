// Bump mapping (Blinn 1978) from a height texture h(s,t) (first channel). The gradient of
// k*h over the unit texture square comes from finite differences at the texture's own texel
// size (1/w, 1/h), forward as in seed 000's Cg code or central when
// SD_CENTRAL_DIFFERENCES is defined; the tangent-space normal of z = k*h(s,t) is then
// normalize(-k*dh/ds, -k*dh/dt, 1), the same map vtkHeightMapToNormalMap makes.
uniform sampler2D sdHeightMap;
uniform vec2 sdHeightTexelSize;
uniform float sdBumpScale;

vec2 sdHeightGradient(vec2 tc)
{
  vec2 d = sdHeightTexelSize;
#ifdef SD_CENTRAL_DIFFERENCES
  float dhds = texture(sdHeightMap, tc + vec2(d.x, 0.0)).r - texture(sdHeightMap, tc - vec2(d.x, 0.0)).r;
  float dhdt = texture(sdHeightMap, tc + vec2(0.0, d.y)).r - texture(sdHeightMap, tc - vec2(0.0, d.y)).r;
  return sdBumpScale * vec2(dhds, dhdt) / (2.0 * d);
#else
  float h0 = texture(sdHeightMap, tc).r;
  float dhds = texture(sdHeightMap, tc + vec2(d.x, 0.0)).r - h0;
  float dhdt = texture(sdHeightMap, tc + vec2(0.0, d.y)).r - h0;
  return sdBumpScale * vec2(dhds, dhdt) / d;
#endif
}

vec3 sdBumpTS(vec2 tc)
{
  return normalize(vec3(-sdHeightGradient(tc), 1.0));
}

// Tangent-free bump mapping (Mikkelsen 2010, "Bump mapping unparametrized surfaces on the
// GPU"): the surface gradient of the height field comes from screen-space derivatives of
// the position, so no tangent array is needed. The height's screen derivatives are taken by
// the chain rule from the texture-space gradient (smooth, unlike dFdx of the height itself),
// and the height is measured in units of the texture square's side in view coordinates, so
// that BumpScale means the same as with tangents.
vec3 sdBumpSurfaceGradient(vec3 N, vec3 posVC, vec2 tc, vec2 gradST)
{
  vec3 sigmaS = dFdx(posVC);
  vec3 sigmaT = dFdy(posVC);
  vec2 tcdx = dFdx(tc);
  vec2 tcdy = dFdy(tc);
  vec3 r1 = cross(sigmaT, N);
  vec3 r2 = cross(N, sigmaS);
  float det = dot(sigmaS, r1);
  float tcDet = tcdx.x * tcdy.y - tcdx.y * tcdy.x;
  if (!(abs(det) > 1e-30) || !(abs(tcDet) > 1e-30))
  {
    return N;
  }
  float side = sqrt(abs(det) / abs(tcDet));
  float dBs = side * dot(gradST, tcdx);
  float dBt = side * dot(gradST, tcdy);
  vec3 surfGrad = sign(det) * (dBs * r1 + dBt * r2);
  return normalize(abs(det) * N - surfGrad);
}
