// SurfaceDetail tangent frame (the convention of Module/Filters/vtkSurfaceDetailConventions.h):
// T is made orthogonal to the mesh normal N, B = w*cross(N,T), and a tangent-space normal n
// is n.x*T + n.y*B + n.z*N in the mesh's own coordinates. That vector is a normal, so it
// goes to view coordinates with normalMatrix (the inverse transpose of the model-view
// matrix), which is linear: the vertex shader sends normalMatrix*T and normalMatrix*B,
// divided by |normalMatrix*N| so that they keep their size relative to the normalised N
// VTK interpolates. This stays right under non-uniform actor scaling.
vec3 sdTangentToView(vec3 nTS, vec3 N, vec3 tangentVC, vec3 bitangentVC)
{
  return normalize(nTS.x * tangentVC + nTS.y * bitangentVC + nTS.z * N);
}
