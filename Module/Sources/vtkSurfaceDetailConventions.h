// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSurfaceDetailConventions.h
 * @brief  The conventions shared by every SurfaceDetail filter and shader, in one place.
 *
 * SurfaceDetail's CPU filters (displacement, height map to normal map, baking) and its
 * shaders must agree to the texel on how a texture is sampled and how a tangent frame and
 * a normal are encoded, or a map baked on the CPU shows seams on the GPU. These inline
 * functions are that agreement. On the GPU side (Module/Rendering): texel centres, wrap
 * modes and linear filtering are OpenGL's own sampling, set up with the same wrap value
 * by vtkSurfaceDetailMapper.cxx (UploadHeightMap, which also uses WrapIndex);
 * glsl/vtkSurfaceDetailTangentFrameFS.glsl applies the tangent frame and
 * glsl/vtkSurfaceDetailNormalCoding.glsl is the twin of EncodeNormal/DecodeNormal.
 *
 * - Texture coordinates (s,t) have their origin bottom-left; row 0 of a vtkImageData is
 *   t = 0; texel (i,j) has its centre at ((i+0.5)/W, (j+0.5)/H).
 * - Wrap modes have vtkTexture's values and OpenGL's meaning (GL 4.5 spec, 8.14.2).
 * - Linear filtering is OpenGL's: x = s*W - 0.5, blend texels floor(x) and floor(x)+1.
 * - Tangent frame: T = normalize(dP/ds minus its part along N), w = sign(dot(cross(N,T),
 *   dP/dt)) (+1 when that is zero), B = w*cross(N,T).
 * - Normal maps store 0.5*n + 0.5 per component; green up (+Y = +t) by default.
 * - Integer normal maps round to nearest (flat is (128,128,255) in 8 bits); decoding
 *   renormalises (EncodeNormal/DecodeNormal; GLSL twin vtkSurfaceDetailNormalCoding.glsl).
 * - Triplanar projection (TriplanarWeights, TriplanarProject, TriplanarNormal; GLSL twin
 *   glsl/vtkSurfaceDetailTriplanarFS.glsl): three planar projections along the axes, each
 *   seen from outside the face it maps, blended by the normal.
 */

#ifndef vtkSurfaceDetailConventions_h
#define vtkSurfaceDetailConventions_h

#include "vtkType.h" // For the scalar type constants

#include <algorithm>
#include <cmath>

namespace vtkSurfaceDetail
{

/// Texture wrap modes, numbered as vtkTexture::Wrap so that one value serves both.
enum WrapMode
{
  ClampToEdge = 0,
  Repeat = 1,
  MirroredRepeat = 2,
  ClampToBorder = 3 ///< outside the image, a border value (vtkTexture's border colour)
};

/// The name of a wrap mode, for PrintSelf and Get...AsString methods.
inline const char* WrapModeName(int mode)
{
  switch (mode)
  {
    case ClampToEdge:
      return "ClampToEdge";
    case MirroredRepeat:
      return "MirroredRepeat";
    case ClampToBorder:
      return "ClampToBorder";
    default:
      return "Repeat";
  }
}

/**
 * The texel index that texel @a i of a texture @a n texels wide reads under @a mode, or -1
 * under ClampToBorder when @a i lies outside (the border value is read there).
 * Precondition: n >= 1 (callers reject empty images first; n = 0 would divide by zero).
 */
inline int WrapIndex(int i, int n, int mode)
{
  switch (mode)
  {
    case Repeat:
    {
      const int m = i % n;
      return m < 0 ? m + n : m;
    }
    case MirroredRepeat:
    {
      int m = i % (2 * n);
      if (m < 0)
      {
        m += 2 * n;
      }
      return m < n ? m : 2 * n - 1 - m;
    }
    case ClampToBorder:
      return i >= 0 && i < n ? i : -1;
    default:
      return std::min(std::max(i, 0), n - 1);
  }
}

/// Texture coordinate of the centre of texel @a i in a texture @a n texels wide.
inline double TexelCentre(int i, int n)
{
  return (i + 0.5) / n;
}

/**
 * Split texture coordinate @a s into the two texels that linear filtering blends and the
 * weight of the second: value = (1 - frac)*texel[i0] + frac*texel[i0 + 1]. The indices are
 * not wrapped yet. Non-finite @a s gives texel 0 with weight 0.
 */
inline void LinearTexels(double s, int n, int& i0, double& frac)
{
  const double x = s * n - 0.5;
  if (!std::isfinite(x))
  {
    i0 = 0;
    frac = 0.0;
    return;
  }
  const double f = std::floor(x);
  i0 = static_cast<int>(f);
  frac = x - f;
}

/// Encodes a unit-vector component in [-1,1] as a colour in [0,1].
inline double EncodeUnit(double c)
{
  return 0.5 * c + 0.5;
}

/// Decodes a colour in [0,1] back to a vector component in [-1,1].
inline double DecodeUnit(double c)
{
  return 2.0 * c - 1.0;
}

/**
 * Encodes unit normal @a n as a colour in [0,1]^3 (0.5*n + 0.5 per component). Green-up
 * (OpenGL, +Y = +t) stores n as it is; green-down (DirectX) stores -n.y.
 * glsl/vtkSurfaceDetailNormalCoding.glsl (Rendering) is the GLSL twin of this pair.
 */
inline void EncodeNormal(const double n[3], bool greenUp, double rgb[3])
{
  rgb[0] = EncodeUnit(n[0]);
  rgb[1] = EncodeUnit(greenUp ? n[1] : -n[1]);
  rgb[2] = EncodeUnit(n[2]);
}

/**
 * Decodes colour @a rgb in [0,1]^3 (integer maps divided by their type's maximum first)
 * back to a unit normal in the green-up convention. Quantisation leaves the decoded vector
 * slightly off unit length, so it is renormalised; a degenerate colour gives (0,0,1).
 */
inline void DecodeNormal(const double rgb[3], bool greenUp, double n[3])
{
  n[0] = DecodeUnit(rgb[0]);
  n[1] = greenUp ? DecodeUnit(rgb[1]) : -DecodeUnit(rgb[1]);
  n[2] = DecodeUnit(rgb[2]);
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 0.0) || !std::isfinite(len))
  {
    n[0] = 0.0;
    n[1] = 0.0;
    n[2] = 1.0;
    return;
  }
  n[0] /= len;
  n[1] /= len;
  n[2] /= len;
}

inline double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline void Cross(const double a[3], const double b[3], double c[3])
{
  const double x = a[1] * b[2] - a[2] * b[1];
  const double y = a[2] * b[0] - a[0] * b[2];
  const double z = a[0] * b[1] - a[1] * b[0];
  c[0] = x;
  c[1] = y;
  c[2] = z;
}

/// Normalises @a v in place; returns its former length (0 leaves @a v unchanged).
inline double Normalize(double v[3])
{
  const double len = std::sqrt(Dot(v, v));
  if (len > 0.0 && std::isfinite(len))
  {
    v[0] /= len;
    v[1] /= len;
    v[2] /= len;
  }
  return len;
}

/**
 * Builds the tangent frame of Documentation/Conventions.md from unit normal @a n and the
 * derivatives
 * @a dPds, @a dPdt: @a t[0..2] = normalize(dPds - n*dot(n,dPds)), @a t[3] = handedness.
 * When dP/ds has no part across @a n, the tangent comes from dP/dt instead
 * (T = cross(B, N) with w = +1); when neither has, @a t is any unit vector orthogonal to
 * @a n with w = +1 and the function returns false so that the caller can supply a limit.
 */
inline bool MakeTangentFrame(
  const double n[3], const double dPds[3], const double dPdt[3], double t[4])
{
  // Relative threshold: a derivative that is almost parallel to the normal is noise.
  constexpr double relEps = 1e-12;
  const double ds = std::sqrt(Dot(dPds, dPds));
  double dn = Dot(n, dPds);
  double tp[3] = { dPds[0] - dn * n[0], dPds[1] - dn * n[1], dPds[2] - dn * n[2] };
  double len = Normalize(tp);
  if (len > relEps * ds && len > 0.0 && std::isfinite(len))
  {
    double nxt[3];
    Cross(n, tp, nxt);
    t[0] = tp[0];
    t[1] = tp[1];
    t[2] = tp[2];
    t[3] = Dot(nxt, dPdt) < 0.0 ? -1.0 : 1.0;
    return true;
  }
  const double dt = std::sqrt(Dot(dPdt, dPdt));
  dn = Dot(n, dPdt);
  double bp[3] = { dPdt[0] - dn * n[0], dPdt[1] - dn * n[1], dPdt[2] - dn * n[2] };
  len = Normalize(bp);
  if (len > relEps * dt && len > 0.0 && std::isfinite(len))
  {
    Cross(bp, n, t);
    t[3] = 1.0;
    return true;
  }
  // Any unit vector orthogonal to n: cross n with the axis it is least aligned with.
  const double ax = std::abs(n[0]), ay = std::abs(n[1]), az = std::abs(n[2]);
  double axis[3] = { 0.0, 0.0, 0.0 };
  axis[(ax <= ay && ax <= az) ? 0 : (ay <= az ? 1 : 2)] = 1.0;
  Cross(axis, n, t);
  if (Normalize(t) == 0.0)
  {
    t[0] = 1.0;
    t[1] = 0.0;
    t[2] = 0.0;
  }
  t[3] = 1.0;
  return false;
}

/**
 * Whether scalars of VTK type @a type can be a height map, and the factor @a scale that
 * takes their values to heights: unsigned char and unsigned short are fractions of their
 * range (as 8- and 16-bit images are, and as OpenGL reads them), float and double are
 * heights as they are. Other types are refused: signed integers have no [0,1] reading (a
 * DEM in metres is heights as they are: make it float), and wider integers have no texture
 * format. Every SurfaceDetail reader of height maps (vtkHeightMapToNormalMap,
 * vtkDisplacementMapFilter, vtkSurfaceDetailMapper) applies this one rule, and says
 * HeightMapTypeAdvice() when it refuses.
 */
inline bool HeightMapScale(int type, double& scale)
{
  switch (type)
  {
    case VTK_UNSIGNED_CHAR:
      scale = 1.0 / 255.0;
      return true;
    case VTK_UNSIGNED_SHORT:
      scale = 1.0 / 65535.0;
      return true;
    case VTK_FLOAT:
    case VTK_DOUBLE:
      scale = 1.0;
      return true;
    default:
      scale = 0.0;
      return false;
  }
}

/**
 * What a refusal by HeightMapScale tells the user to do. vtkImageShiftScale to float keeps
 * negative values; a cast to an unsigned type would wrap them.
 */
inline const char* HeightMapTypeAdvice()
{
  return "height maps are unsigned char or unsigned short (fractions of their range), or float "
         "or double (heights as they are): convert other types with vtkImageShiftScale "
         "(SetOutputScalarTypeToFloat, with the shift and scale that give the heights you mean)";
}

/**
 * Triplanar blend weights of unit normal @a n: w_i = |n_i|^sharpness over their sum, then
 * every weight under 1/256 set to 0 and the rest renormalised, so that a projection that
 * would change an 8-bit colour by less than one level is not read at all. They sum to one.
 */
inline void TriplanarWeights(const double n[3], double sharpness, double w[3])
{
  double sum = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    w[i] = std::pow(std::abs(n[i]), sharpness);
    sum += w[i];
  }
  double kept = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    w[i] = sum > 0.0 ? w[i] / sum : 1.0 / 3.0;
    w[i] = w[i] < 1.0 / 256.0 ? 0.0 : w[i];
    kept += w[i];
  }
  for (int i = 0; i < 3; ++i)
  {
    w[i] /= kept;
  }
}

/**
 * The planar projection along axis @a axis (0 = x, 1 = y, 2 = z) of point @a p whose normal
 * is @a n: its texture coordinates (@a st, scaled by @a scale) and its tangent and bitangent
 * (unit axis vectors along +s and +t). Each face is mapped as seen from outside it, right way
 * round: T x B points out of the face, on the faces along negative axes too. With sigma the
 * sign of n along the axis (+1 where it is 0):
 *   x:  s =  sigma*y,  t = z,  T = (0, sigma, 0),  B = (0, 0, 1)
 *   y:  s = -sigma*x,  t = z,  T = (-sigma, 0, 0), B = (0, 0, 1)
 *   z:  s =  sigma*x,  t = y,  T = (sigma, 0, 0),  B = (0, 1, 0)
 */
inline void TriplanarProject(int axis, const double p[3], const double n[3], double scale,
  double st[2], double tangent[3], double bitangent[3])
{
  const double sigma = n[axis] < 0.0 ? -1.0 : 1.0;
  const int s = axis == 0 ? 1 : 0; // the axis s runs along
  const double sSign = axis == 1 ? -sigma : sigma;
  const int t = axis == 2 ? 1 : 2; // the axis t runs along
  st[0] = scale * sSign * p[s];
  st[1] = scale * p[t];
  for (int i = 0; i < 3; ++i)
  {
    tangent[i] = i == s ? sSign : 0.0;
    bitangent[i] = i == t ? 1.0 : 0.0;
  }
}

/**
 * A tangent-space normal @a nTS of projection frame (@a tangent, @a bitangent) on a surface
 * of unit normal @a n, as a vector in the projection's space: the frame is reoriented to the
 * surface (T made orthogonal to n, B = n x T), so that a bump looks the same on every face
 * and the flat normal (0,0,1) gives the surface normal. Not normalised; the detail normal
 * is the sum over the projections of weight times this normalised, itself normalised.
 */
inline void TriplanarNormal(const double nTS[3], const double n[3], const double tangent[3],
  double out[3])
{
  const double along = n[0] * tangent[0] + n[1] * tangent[1] + n[2] * tangent[2];
  double T[3] = { tangent[0] - along * n[0], tangent[1] - along * n[1], tangent[2] - along * n[2] };
  const double length = std::sqrt(T[0] * T[0] + T[1] * T[1] + T[2] * T[2]);
  for (double& c : T)
  {
    c = length > 0.0 ? c / length : 0.0;
  }
  const double B[3] = { n[1] * T[2] - n[2] * T[1], n[2] * T[0] - n[0] * T[2],
    n[0] * T[1] - n[1] * T[0] };
  for (int i = 0; i < 3; ++i)
  {
    out[i] = nTS[0] * T[i] + nTS[1] * B[i] + nTS[2] * n[i];
  }
}

} // namespace vtkSurfaceDetail

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailConventions.h
