#include "vtkDisplacementMapFilter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkParametricSurfaceSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStaticCellLinksTemplate.h"
#include "vtkStaticPointLocator.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkSurfaceDetailCells.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailGhosts.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkDisplacementMapFilter);

namespace
{
using namespace vtkSurfaceDetail;

// Each point's polygons: vtkStaticCellLinks with 32-bit ids where they fit (half the memory,
// which the fits and Mesh normals read all of), else 64-bit ones.
struct PointPolygons
{
  vtkStaticCellLinksTemplate<int> Small;
  vtkStaticCellLinksTemplate<vtkIdType> Large;
  bool UseSmall = true;

  // Serial: each point's polygons in one fixed order, so that sums over them do not depend on
  // the threads.
  void Build(vtkIdType numPts, vtkIdType numCells, vtkCellArray* cells)
  {
    this->UseSmall = std::max(numCells, cells->GetNumberOfConnectivityIds()) < VTK_INT_MAX;
    if (this->UseSmall)
    {
      this->Small.SerialBuildLinks(numPts, numCells, cells);
    }
    else
    {
      this->Large.SerialBuildLinks(numPts, numCells, cells);
    }
  }

  vtkIdType Count(vtkIdType i)
  {
    return this->UseSmall ? this->Small.GetNcells(i) : this->Large.GetNcells(i);
  }

  vtkIdType Cell(vtkIdType i, vtkIdType k)
  {
    return this->UseSmall ? this->Small.GetCells(i)[k] : this->Large.GetCells(i)[k];
  }
};
using GroupList = std::vector<std::pair<vtkIdType, vtkIdType>>; // (representative, member)

//------------------------------------------------------------------------------
// Arrays

// A new float or double array of @a n tuples.
vtkSmartPointer<vtkDataArray> NewArray(int type, const char* name, int nc, vtkIdType n)
{
  auto a = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
  a->SetName(name);
  a->SetNumberOfComponents(nc);
  a->SetNumberOfTuples(n);
  return a;
}

// The polygons as raw offsets and connectivity. vtkCellArray may hold 32-bit ids; those are
// copied to 64 bits once, so that every pass reads one layout.
struct Polygons
{
  vtkSmartPointer<vtkCellArray> Cells;
  const vtkIdType* Offsets = nullptr;
  const vtkIdType* Conn = nullptr;
  vtkIdType Count = 0;

  explicit Polygons(vtkCellArray* polys)
    : Cells(polys)
  {
    static_assert(sizeof(vtkIdType) == sizeof(vtkTypeInt64), "64-bit vtkIdType expected");
    if (!polys->IsStorage64Bit())
    {
      this->Cells = vtkSmartPointer<vtkCellArray>::New();
      this->Cells->DeepCopy(polys);
      this->Cells->ConvertTo64BitStorage();
    }
    this->Offsets =
      reinterpret_cast<const vtkIdType*>(this->Cells->GetOffsetsArray64()->GetPointer(0));
    this->Conn =
      reinterpret_cast<const vtkIdType*>(this->Cells->GetConnectivityArray64()->GetPointer(0));
    this->Count = this->Cells->GetNumberOfCells();
  }
};

//------------------------------------------------------------------------------
// Sampling the height map

// Keeps huge coordinates from overflowing the texel index; 2 is a period of every wrap.
double TameCoordinate(double s, int wrap)
{
  if (std::abs(s) < 1e6)
  {
    return s;
  }
  return wrap == ClampToEdge ? std::min(std::max(s, -1.0), 2.0) : std::fmod(s, 2.0);
}

// Catmull-Rom weights and their derivatives for the fraction f in [0,1).
void CatmullRom(double f, double w[4], double dw[4])
{
  const double f2 = f * f, f3 = f2 * f;
  w[0] = 0.5 * (-f3 + 2.0 * f2 - f);
  w[1] = 0.5 * (3.0 * f3 - 5.0 * f2 + 2.0);
  w[2] = 0.5 * (-3.0 * f3 + 4.0 * f2 + f);
  w[3] = 0.5 * (f3 - f2);
  dw[0] = 0.5 * (-3.0 * f2 + 4.0 * f - 1.0);
  dw[1] = 0.5 * (9.0 * f2 - 10.0 * f);
  dw[2] = 0.5 * (-9.0 * f2 + 8.0 * f + 1.0);
  dw[3] = 0.5 * (3.0 * f2 - 2.0 * f);
}

// The height map as a texture of scalar type T: one component, normalised, non-finite
// values read as the midlevel (so that they do not move the surface) and reported in
// @a SawNonFinite (so that only a map with such values is counted, for the warning).
template <typename T>
struct HeightMap
{
  const T* Data;
  int W, H, NC, Comp, Wrap, Interpolation;
  double Norm, Mid;
  std::atomic<bool>* SawNonFinite;

  double Texel(int i, int j) const
  {
    // The wrap's integer division only outside the map.
    i = static_cast<unsigned>(i) < static_cast<unsigned>(this->W)
      ? i
      : WrapIndex(i, this->W, this->Wrap);
    j = static_cast<unsigned>(j) < static_cast<unsigned>(this->H)
      ? j
      : WrapIndex(j, this->H, this->Wrap);
    const double v =
      this->Norm * this->Data[(static_cast<vtkIdType>(j) * this->W + i) * this->NC + this->Comp];
    if (std::isfinite(v))
    {
      return v;
    }
    this->SawNonFinite->store(true, std::memory_order_relaxed);
    return this->Mid;
  }

  // The interpolant h(s,t) and its analytic derivatives in s and t.
  void Sample(double s, double t, double& h, double& hs, double& ht) const
  {
    s = TameCoordinate(s, this->Wrap);
    t = TameCoordinate(t, this->Wrap);
    if (this->Interpolation == vtkDisplacementMapFilter::Nearest)
    {
      const double x = std::floor(s * this->W), y = std::floor(t * this->H);
      h = this->Texel(
        std::isfinite(x) ? static_cast<int>(x) : 0, std::isfinite(y) ? static_cast<int>(y) : 0);
      hs = ht = 0.0;
      return;
    }
    int i0, j0;
    double fx, fy;
    LinearTexels(s, this->W, i0, fx);
    LinearTexels(t, this->H, j0, fy);
    // Both are separable: weights (and their derivatives) over texels i0 - 1 .. i0 + 2, of
    // which Linear uses the middle two.
    double wx[4], dwx[4], wy[4], dwy[4];
    const bool linear = this->Interpolation == vtkDisplacementMapFilter::Linear;
    if (linear)
    {
      const double lx[4] = { 0.0, 1.0 - fx, fx, 0.0 }, ly[4] = { 0.0, 1.0 - fy, fy, 0.0 };
      const double slope[4] = { 0.0, -1.0, 1.0, 0.0 };
      std::copy_n(lx, 4, wx);
      std::copy_n(ly, 4, wy);
      std::copy_n(slope, 4, dwx);
      std::copy_n(slope, 4, dwy);
    }
    else
    {
      CatmullRom(fx, wx, dwx);
      CatmullRom(fy, wy, dwy);
    }
    const int first = linear ? 1 : 0, last = linear ? 3 : 4;
    h = hs = ht = 0.0;
    for (int l = first; l < last; ++l)
    {
      double row = 0.0, drow = 0.0;
      for (int k = first; k < last; ++k)
      {
        const double v = this->Texel(i0 - 1 + k, j0 - 1 + l);
        row += wx[k] * v;
        drow += dwx[k] * v;
      }
      h += wy[l] * row;
      hs += wy[l] * drow;
      ht += dwy[l] * row;
    }
    hs *= this->W;
    ht *= this->H;
  }
};

// The number of non-finite values in component @a comp of the @a n texels of @a data.
template <typename T>
vtkIdType CountNonFinite(const T* data, vtkIdType n, int nc, int comp)
{
  std::atomic<vtkIdType> total(0);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkIdType count = 0;
      for (vtkIdType k = begin; k < end; ++k)
      {
        count += !std::isfinite(static_cast<double>(data[k * nc + comp]));
      }
      total += count;
    });
  return total;
}

//------------------------------------------------------------------------------
// Per-point helpers

// NaN becomes 0 and infinity the largest double.
double Finite(double x)
{
  if (std::isnan(x))
  {
    return 0.0;
  }
  return std::min(
    std::max(x, -std::numeric_limits<double>::max()), std::numeric_limits<double>::max());
}

// The passes work on blocks of points held as arrays per coordinate ("lanes"): each step is a
// short loop over the block without branches, which the compiler can vectorise and the processor
// overlaps from point to point (one point's square roots and divisions are a long chain).
constexpr int Block = 64;
using Lanes = double[Block];

// Whether a length is positive and finite.
inline bool Usable(double length)
{
  return length > 0.0 && length <= std::numeric_limits<double>::max();
}

// Scales each vector @a v to unit length where its length (@a length) is Usable, and leaves it
// as it is elsewhere.
void UnitLanes(int count, Lanes v[3], Lanes length)
{
  for (int k = 0; k < count; ++k)
  {
    const double len = std::sqrt(v[0][k] * v[0][k] + v[1][k] * v[1][k] + v[2][k] * v[2][k]);
    const double inv = 1.0 / (Usable(len) ? len : 1.0);
    v[0][k] *= inv;
    v[1][k] *= inv;
    v[2][k] *= inv;
    length[k] = len;
  }
}

// A position as R: beyond float's range the largest float of its sign, never infinity.
template <typename R>
R ToPosition(double v)
{
  constexpr double big = std::numeric_limits<R>::max();
  return static_cast<R>(std::min(std::max(v, -big), big));
}

// The point derivatives of a block: P_s, P_t and (Exact) n_s, n_t as lanes, and the unit input
// normal n.
struct BlockDerivatives
{
  Lanes N[3], Ps[3], Pt[3], Ns[3], Nt[3];
};

// Everything the passes read and write, as raw arrays of R (float or double).
template <typename R>
struct Context
{
  vtkIdType NumPoints = 0;
  const R* Points = nullptr;
  const R* Normals = nullptr;
  const R* TCoords = nullptr;
  int TCoordsNC = 2;
  const R* DPdu = nullptr; // with DPdv, or null
  const R* DPdv = nullptr;
  const R* DNdu = nullptr; // with DNdv, used in Exact mode only, or null
  const R* DNdv = nullptr;
  const R* Tangents = nullptr; // null in None mode
  int TangentsNC = 4;
  double DerivativeScale[2] = { 1.0, 1.0 }; // dP/ds = dPdu * [0], dP/dt = dPdv * [1]
  int NormalMode = vtkDisplacementMapFilter::Exact;
  double Scale = 1.0;
  double Midlevel = 0.0;
  const Polygons* Polys = nullptr;
  PointPolygons* PointLinks = nullptr; // where the fits or Mesh normals read them
  // Exact's fits: each point's unit input normal (zero where it has no direction), 3 per point;
  // each point is a neighbour in a dozen fits.
  const double* UnitNormals = nullptr;
  R* OutPoints = nullptr;
  R* OutNormals = nullptr;  // null in None mode
  R* OutTangents = nullptr; // null without input tangents or in None mode

  void Get3(const R* a, vtkIdType i, double v[3]) const
  {
    v[0] = a[3 * i];
    v[1] = a[3 * i + 1];
    v[2] = a[3 * i + 2];
  }

  // The unit input normals of the points @a ids, zero where one has no direction.
  void InputNormals(const vtkIdType* ids, int count, Lanes n[3]) const
  {
    for (int k = 0; k < count; ++k)
    {
      for (int j = 0; j < 3; ++j)
      {
        n[j][k] = this->Normals[3 * ids[k] + j];
      }
    }
    Lanes length;
    UnitLanes(count, n, length);
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < count; ++k)
      {
        n[j][k] = Usable(length[k]) ? n[j][k] : 0.0;
      }
    }
  }

  void WritePoint(vtkIdType i, const double offset[3]) const
  {
    for (int k = 0; k < 3; ++k)
    {
      const double p = this->Points[3 * i + k];
      // Adding +0 would turn -0 into +0: no displacement leaves the bits alone.
      this->OutPoints[3 * i + k] =
        offset[k] == 0.0 ? this->Points[3 * i + k] : ToPosition<R>(Finite(p + offset[k]));
    }
  }

  // Normalises the directions @a m of the points @a ids and writes them as their normals (the
  // unit input normal @a n where a direction is degenerate, +z where that is zero too), then
  // their tangents re-orthogonalised to them with the handedness kept.
  void WriteNormalsAndTangents(const vtkIdType* ids, int count, const Lanes n[3], Lanes m[3]) const
  {
    Lanes length;
    UnitLanes(count, m, length);
    for (int k = 0; k < count; ++k)
    {
      const bool ok = Usable(length[k]);
      const bool none = n[0][k] == 0.0 && n[1][k] == 0.0 && n[2][k] == 0.0;
      m[0][k] = ok ? m[0][k] : n[0][k];
      m[1][k] = ok ? m[1][k] : n[1][k];
      m[2][k] = ok ? m[2][k] : (none ? 1.0 : n[2][k]);
    }
    for (int k = 0; k < count; ++k)
    {
      for (int j = 0; j < 3; ++j)
      {
        this->OutNormals[3 * ids[k] + j] = static_cast<R>(m[j][k]);
      }
    }
    if (this->OutTangents)
    {
      this->WriteTangents(ids, count, m);
    }
  }

  void WriteTangents(const vtkIdType* ids, int count, const Lanes m[3]) const
  {
    const int nc = this->TangentsNC;
    Lanes t[4];
    for (int k = 0; k < count; ++k)
    {
      for (int j = 0; j < nc; ++j)
      {
        t[j][k] = this->Tangents[nc * ids[k] + j];
      }
    }
    for (int k = 0; k < count; ++k)
    {
      const double along = m[0][k] * t[0][k] + m[1][k] * t[1][k] + m[2][k] * t[2][k];
      for (int j = 0; j < 3; ++j)
      {
        t[j][k] -= along * m[j][k];
      }
    }
    Lanes length;
    UnitLanes(count, t, length);
    for (int k = 0; k < count; ++k)
    {
      if (!Usable(length[k]))
      {
        // No direction left across the normal: any unit vector orthogonal to it.
        const double mk[3] = { m[0][k], m[1][k], m[2][k] }, zero[3] = { 0.0, 0.0, 0.0 };
        double frame[4];
        MakeTangentFrame(mk, zero, zero, frame);
        for (int j = 0; j < 3; ++j)
        {
          t[j][k] = frame[j];
        }
      }
      for (int j = 0; j < nc; ++j)
      {
        this->OutTangents[nc * ids[k] + j] = static_cast<R>(t[j][k]);
      }
    }
  }

  // The least-squares fit of the derivatives in (s,t) at point @a i of the points (P_s, P_t,
  // @a wantP) and of the unit normals (n_s, n_t, @a wantN): it minimises
  // sum |f_j - f_i - f_s ds - f_t dt|^2 over the neighbours j in the point's polygons, each
  // counted once per polygon it shares with the point. On a regular grid this is a central
  // difference. Where the texture coordinates around the point do not span two directions, or
  // (P) a neighbour sits at the point with other texture coordinates (a pole: p(s,t) is
  // singular there), the derivatives are 0 and the normal falls back on the input's.
  void Fit(vtkIdType i, bool wantP, bool wantN, BlockDerivatives& b, int k) const
  {
    const R* tc = this->TCoords;
    const vtkIdType tnc = this->TCoordsNC;
    const double s = tc[tnc * i], t = tc[tnc * i + 1];
    double p[3];
    this->Get3(this->Points, i, p);
    const double* n = wantN ? this->UnitNormals + 3 * i : nullptr;
    double ss = 0.0, st = 0.0, tt = 0.0, bp[6] = {}, bn[6] = {};
    double nearest = std::numeric_limits<double>::max(), farthest = 0.0;
    const vtkIdType numCells = this->PointLinks->Count(i);
    for (vtkIdType c = 0; c < numCells; ++c)
    {
      const vtkIdType cell = this->PointLinks->Cell(i, c);
      for (vtkIdType k = this->Polys->Offsets[cell]; k < this->Polys->Offsets[cell + 1]; ++k)
      {
        const vtkIdType j = this->Polys->Conn[k];
        if (j == i)
        {
          continue;
        }
        const double ds = tc[tnc * j] - s, dt = tc[tnc * j + 1] - t;
        ss += ds * ds;
        st += ds * dt;
        tt += dt * dt;
        if (wantP)
        {
          double d[3];
          this->Get3(this->Points, j, d);
          for (int q = 0; q < 3; ++q)
          {
            d[q] -= p[q];
            bp[q] += ds * d[q];
            bp[3 + q] += dt * d[q];
          }
          const double d2 = Dot(d, d);
          nearest = std::min(nearest, d2);
          farthest = std::max(farthest, d2);
        }
        if (wantN)
        {
          const double* nj = this->UnitNormals + 3 * j;
          double d[3];
          for (int q = 0; q < 3; ++q)
          {
            d[q] = nj[q] - n[q];
            bn[q] += ds * d[q];
            bn[3 + q] += dt * d[q];
          }
        }
      }
    }
    const double det = ss * tt - st * st;
    const bool spans = det > 1e-12 * (ss + tt) * (ss + tt);
    const bool distinct = spans && !(nearest <= 1e-16 * farthest);
    for (int q = 0; q < 3; ++q)
    {
      if (wantP)
      {
        b.Ps[q][k] = distinct ? (tt * bp[q] - st * bp[3 + q]) / det : 0.0;
        b.Pt[q][k] = distinct ? (ss * bp[3 + q] - st * bp[q]) / det : 0.0;
      }
      if (wantN)
      {
        b.Ns[q][k] = spans ? (tt * bn[q] - st * bn[3 + q]) / det : 0.0;
        b.Nt[q][k] = spans ? (ss * bn[3 + q] - st * bn[q]) / det : 0.0;
      }
    }
  }

  // P_s, P_t and (Exact) n_s, n_t of the points [first, first + count): from dPdu/dPdv (and
  // dNdu/dNdv) scaled by the texture coordinates' affine fit, else fitted from the neighbours.
  void Derivatives(vtkIdType first, int count, bool exact, BlockDerivatives& b) const
  {
    auto scaled = [&](const R* du, const R* dv, Lanes s[3], Lanes t[3])
    {
      for (int k = 0; k < count; ++k)
      {
        for (int q = 0; q < 3; ++q)
        {
          s[q][k] = du[3 * (first + k) + q] * this->DerivativeScale[0];
          t[q][k] = dv[3 * (first + k) + q] * this->DerivativeScale[1];
        }
      }
    };
    if (this->DPdu)
    {
      scaled(this->DPdu, this->DPdv, b.Ps, b.Pt);
    }
    if (exact && this->DNdu)
    {
      scaled(this->DNdu, this->DNdv, b.Ns, b.Nt);
    }
    const bool wantP = !this->DPdu, wantN = exact && !this->DNdu;
    for (int k = 0; (wantP || wantN) && k < count; ++k)
    {
      this->Fit(first + k, wantP, wantN, b, k);
    }
  }
};

// The directions @a m of the displaced normals of a block, from the displacement @a d and its
// derivatives @a ds, @a dt: the seed's formula (Approximate), or (Exact) the cross product of
// the displaced surface's derivatives. P_s and P_t count only across n (n defines the tangent
// plane), so that a map without slope gives back n itself, and the result is oriented by
// n . (P_s x P_t), whatever the orientation of the parameterisation. Where P_s x P_t vanishes
// (a singular point of the parameterisation) the input normal is kept.
void Directions(int count, bool exact, BlockDerivatives& b, const Lanes d, const Lanes ds,
  const Lanes dt, Lanes m[3])
{
  const Lanes* n = b.N;
  Lanes* const across[4] = { b.Ps, b.Pt, b.Ns, b.Nt };
  for (int a = 0; a < (exact ? 4 : 2); ++a)
  {
    Lanes* v = across[a];
    for (int k = 0; k < count; ++k)
    {
      const double along = n[0][k] * v[0][k] + n[1][k] * v[1][k] + n[2][k] * v[2][k];
      for (int j = 0; j < 3; ++j)
      {
        v[j][k] -= along * n[j][k];
      }
    }
  }
  // The sign of n . (P_s x P_t), 0 where that vanishes (the input normal is kept there).
  Lanes area, sign;
  for (int k = 0; k < count; ++k)
  {
    const double ps[3] = { b.Ps[0][k], b.Ps[1][k], b.Ps[2][k] };
    const double pt[3] = { b.Pt[0][k], b.Pt[1][k], b.Pt[2][k] };
    const double nk[3] = { n[0][k], n[1][k], n[2][k] };
    double base[3];
    Cross(ps, pt, base);
    area[k] = Dot(nk, base);
    const double size = std::sqrt(Dot(ps, ps) * Dot(pt, pt));
    const bool degenerate = !(std::abs(area[k]) > 1e-10 * size) || !std::isfinite(area[k]);
    sign[k] = degenerate ? 0.0 : (area[k] < 0.0 ? -1.0 : 1.0);
  }
  if (exact)
  {
    for (int k = 0; k < count; ++k)
    {
      double qs[3], qt[3];
      for (int j = 0; j < 3; ++j)
      {
        qs[j] = Finite(b.Ps[j][k] + ds[k] * n[j][k] + d[k] * b.Ns[j][k]);
        qt[j] = Finite(b.Pt[j][k] + dt[k] * n[j][k] + d[k] * b.Nt[j][k]);
      }
      // Only the direction matters: each vector divided by its largest component keeps the
      // cross product finite.
      const double ls = std::max(std::max(std::abs(qs[0]), std::abs(qs[1])), std::abs(qs[2]));
      const double lt = std::max(std::max(std::abs(qt[0]), std::abs(qt[1])), std::abs(qt[2]));
      const double is = 1.0 / (ls > 0.0 ? ls : 1.0), it = 1.0 / (lt > 0.0 ? lt : 1.0);
      for (int j = 0; j < 3; ++j)
      {
        qs[j] *= is;
        qt[j] *= it;
      }
      double mk[3];
      Cross(qs, qt, mk);
      for (int j = 0; j < 3; ++j)
      {
        m[j][k] = mk[j];
      }
    }
  }
  else
  {
    for (int k = 0; k < count; ++k)
    {
      // (n . (P_s x P_t)) n + d_s (n x P_t) - d_t (n x P_s), divided by its largest
      // coefficient so that huge slopes stay finite.
      const double ps[3] = { b.Ps[0][k], b.Ps[1][k], b.Ps[2][k] };
      const double pt[3] = { b.Pt[0][k], b.Pt[1][k], b.Pt[2][k] };
      const double nk[3] = { n[0][k], n[1][k], n[2][k] };
      double nxPs[3], nxPt[3];
      Cross(nk, ps, nxPs);
      Cross(nk, pt, nxPt);
      const double largest =
        std::max(std::max(std::max(std::abs(area[k]), std::abs(ds[k])), std::abs(dt[k])), 1e-300);
      const double inv = 1.0 / largest;
      for (int j = 0; j < 3; ++j)
      {
        m[j][k] = area[k] * inv * nk[j] + ds[k] * inv * nxPt[j] - dt[k] * inv * nxPs[j];
      }
    }
  }
  for (int j = 0; j < 3; ++j)
  {
    for (int k = 0; k < count; ++k)
    {
      m[j][k] = sign[k] == 0.0 ? n[j][k] : sign[k] * m[j][k];
    }
  }
}

//------------------------------------------------------------------------------
// The passes

// Pass 1: each point moved, and the analytic normals (Approximate, Exact) with their tangents.
template <typename R, typename T>
struct DisplacePoints
{
  const Context<R>& C;
  const HeightMap<T>& Map;

  // The displacements d of the points @a ids and their derivatives in (s,t); @a n gets their
  // unit input normals (zero where one has none). One function for pass 1 and the seams' mean.
  void Displacements(const vtkIdType* ids, int count, Lanes n[3], Lanes d, Lanes ds, Lanes dt) const
  {
    const Context<R>& c = this->C;
    c.InputNormals(ids, count, n);
    for (int k = 0; k < count; ++k)
    {
      const R* st = c.TCoords + c.TCoordsNC * ids[k];
      this->Map.Sample(st[0], st[1], d[k], ds[k], dt[k]);
    }
    for (int k = 0; k < count; ++k)
    {
      d[k] = Finite(c.Scale * (d[k] - c.Midlevel));
      ds[k] = Finite(c.Scale * ds[k]);
      dt[k] = Finite(c.Scale * dt[k]);
    }
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    const Context<R>& c = this->C;
    const bool exact = c.NormalMode == vtkDisplacementMapFilter::Exact;
    const bool analytic = exact || c.NormalMode == vtkDisplacementMapFilter::Approximate;
    vtkIdType ids[Block];
    BlockDerivatives b;
    Lanes d, ds, dt, m[3];
    for (vtkIdType first = begin; first < end; first += Block)
    {
      const int count = static_cast<int>(std::min<vtkIdType>(Block, end - first));
      std::iota(ids, ids + count, first);
      this->Displacements(ids, count, b.N, d, ds, dt);
      for (int k = 0; k < count; ++k)
      {
        const double offset[3] = { d[k] * b.N[0][k], d[k] * b.N[1][k], d[k] * b.N[2][k] };
        c.WritePoint(ids[k], offset);
      }
      if (analytic)
      {
        c.Derivatives(first, count, exact, b);
        Directions(count, exact, b, d, ds, dt, m);
        c.WriteNormalsAndTangents(ids, count, b.N, m);
      }
    }
  }
};

// Mesh normals: each point's normal is the sum of the normals of its displaced polygons,
// area-weighted (a fan of cross products from corner 0) and each oriented as its input normals
// (the input polygon's normal against the sum of its points' input normals: @a Signs, found
// first for each polygon). The polygons are read through the links in their fixed order, so the
// bits never depend on the threads; a displaced polygon's normal is computed for each of its
// points, which needs no array of polygon normals.
template <typename R>
struct MeshNormals
{
  const Context<R>& C;
  signed char* Signs;

  static void FanSum(const R* pts, const vtkIdType* ids, vtkIdType n, double sum[3])
  {
    for (vtkIdType k = 1; k + 1 < n; ++k)
    {
      double a[3], b[3], x[3];
      for (int q = 0; q < 3; ++q)
      {
        a[q] = static_cast<double>(pts[3 * ids[k] + q]) - pts[3 * ids[0] + q];
        b[q] = static_cast<double>(pts[3 * ids[k + 1] + q]) - pts[3 * ids[0] + q];
      }
      Cross(a, b, x);
      for (int q = 0; q < 3; ++q)
      {
        sum[q] += x[q];
      }
    }
  }

  void FindSigns(vtkIdType begin, vtkIdType end) const
  {
    const Context<R>& c = this->C;
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      const vtkIdType* ids = c.Polys->Conn + c.Polys->Offsets[cell];
      const vtkIdType n = c.Polys->Offsets[cell + 1] - c.Polys->Offsets[cell];
      double input[3] = {}, normals[3] = {};
      FanSum(c.Points, ids, n, input);
      for (vtkIdType k = 0; k < n; ++k)
      {
        for (int q = 0; q < 3; ++q)
        {
          normals[q] += c.Normals[3 * ids[k] + q];
        }
      }
      this->Signs[cell] = Dot(input, normals) < 0.0 ? -1 : 1;
    }
  }

  void AddPolygon(vtkIdType cell, double sum[3]) const
  {
    const Context<R>& c = this->C;
    double moved[3] = {};
    FanSum(c.OutPoints, c.Polys->Conn + c.Polys->Offsets[cell],
      c.Polys->Offsets[cell + 1] - c.Polys->Offsets[cell], moved);
    for (int q = 0; q < 3; ++q)
    {
      sum[q] += this->Signs[cell] * moved[q];
    }
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    vtkIdType ids[Block];
    Lanes n[3], m[3];
    for (vtkIdType first = begin; first < end; first += Block)
    {
      const int count = static_cast<int>(std::min<vtkIdType>(Block, end - first));
      for (int k = 0; k < count; ++k)
      {
        ids[k] = first + k;
        double sum[3] = { 0.0, 0.0, 0.0 };
        for (vtkIdType c = 0; c < this->C.PointLinks->Count(ids[k]); ++c)
        {
          this->AddPolygon(this->C.PointLinks->Cell(ids[k], c), sum);
        }
        for (int q = 0; q < 3; ++q)
        {
          m[q][k] = sum[q];
        }
      }
      this->C.InputNormals(ids, count, n);
      this->C.WriteNormalsAndTangents(ids, count, n, m);
    }
  }
};

//------------------------------------------------------------------------------
// Seams

// Seam candidates: a texture seam cuts the mesh, so its duplicated points lie on the mesh's
// boundary. One sweep over the polygons' edges, no links: each corner adds the hash of its
// next point minus that of its previous one to its point's sum. Where every edge around a point
// is shared by two consistently oriented polygons (an interior point), the sums cancel exactly;
// a boundary edge leaves a non-zero sum. Inconsistent orientation or non-manifold edges only add
// candidates, which the position test then discards; points in no polygon are candidates too.
// Integer sums commute, so the result never depends on the order.
std::vector<vtkIdType> SeamCandidates(const Polygons& polys, vtkIdType numPts)
{
  // splitmix64's finaliser on 63 bits (a bijection), shifted up one bit: every hash and sum is
  // even, so the lowest bit is free to mark the points some polygon uses. A hash that mixes
  // well, not a near-additive one, is what keeps the sums of a point where several boundary
  // fans meet (a bowtie) from cancelling by chance.
  auto hash = [](vtkIdType id)
  {
    constexpr std::uint64_t low63 = ~std::uint64_t(0) >> 1;
    std::uint64_t z = (static_cast<std::uint64_t>(id) + 0x9E3779B97F4A7C15ULL) & low63;
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL) & low63;
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EBULL) & low63;
    return (z ^ (z >> 31)) << 1;
  };
  std::vector<std::uint64_t> sum(numPts, 0), corners;
  for (vtkIdType cell = 0; cell < polys.Count; ++cell)
  {
    const vtkIdType* ids = polys.Conn + polys.Offsets[cell];
    const vtkIdType n = polys.Offsets[cell + 1] - polys.Offsets[cell];
    corners.resize(std::max<size_t>(corners.size(), n));
    for (vtkIdType k = 0; k < n; ++k)
    {
      corners[k] = hash(ids[k]);
    }
    for (vtkIdType k = 0; k < n; ++k)
    {
      const std::uint64_t next = corners[k + 1 < n ? k + 1 : 0],
                          prev = corners[k > 0 ? k - 1 : n - 1];
      sum[ids[k]] = (sum[ids[k]] + next - prev) | 1;
    }
  }
  std::vector<vtkIdType> candidates;
  for (vtkIdType i = 0; i < numPts; ++i)
  {
    if (sum[i] != 1)
    {
      candidates.push_back(i);
    }
  }
  return candidates;
}

// Groups the points @a ids that lie within @a tol of one another (transitively), as
// (representative, member) pairs sorted, so that every sum over a group has one order. The
// representative is the group's first point; points that are not finite join no group.
template <typename R>
GroupList CoincidentGroups(const R* points, const std::vector<vtkIdType>& ids, double tol)
{
  vtkNew<vtkPoints> candidates;
  candidates->SetDataTypeToDouble();
  std::vector<vtkIdType> finite; // index into ids of each candidate
  for (size_t k = 0; k < ids.size(); ++k)
  {
    const double p[3] = { points[3 * ids[k]], points[3 * ids[k] + 1], points[3 * ids[k] + 2] };
    if (std::isfinite(p[0] + p[1] + p[2]))
    {
      candidates->InsertNextPoint(p);
      finite.push_back(static_cast<vtkIdType>(k));
    }
  }
  std::vector<vtkIdType> parent(finite.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](vtkIdType k)
  {
    while (parent[k] != k)
    {
      k = parent[k] = parent[parent[k]];
    }
    return k;
  };
  if (finite.size() > 1)
  {
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(candidates);
    vtkNew<vtkStaticPointLocator> locator;
    locator->SetDataSet(cloud);
    locator->BuildLocator();
    vtkNew<vtkIdList> near;
    for (vtkIdType k = 0; k < static_cast<vtkIdType>(finite.size()); ++k)
    {
      locator->FindPointsWithinRadius(tol, candidates->GetPoint(k), near);
      for (vtkIdType q = 0; q < near->GetNumberOfIds(); ++q)
      {
        const vtkIdType a = find(k), b = find(near->GetId(q));
        parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  GroupList groups;
  std::vector<char> inGroup(finite.size(), 0);
  for (size_t k = 0; k < finite.size(); ++k)
  {
    const vtkIdType r = find(static_cast<vtkIdType>(k));
    if (r != static_cast<vtkIdType>(k))
    {
      groups.emplace_back(ids[finite[r]], ids[finite[k]]);
      inGroup[r] = 1;
    }
  }
  for (size_t k = 0; k < finite.size(); ++k)
  {
    if (inGroup[k])
    {
      groups.emplace_back(ids[finite[k]], ids[finite[k]]);
    }
  }
  std::sort(groups.begin(), groups.end());
  return groups;
}

// Calls @a body(b, e) for each group [b, e) of @a groups.
template <typename F>
void ForEachGroup(const GroupList& groups, F&& body)
{
  for (size_t b = 0, e = 0; b < groups.size(); b = e)
  {
    while (e < groups.size() && groups[e].first == groups[b].first)
    {
      ++e;
    }
    body(b, e);
  }
}

// Calls @a body(ids, count) for the members of groups [b, e) in blocks.
template <typename F>
void ForEachBlock(const GroupList& groups, size_t b, size_t e, F&& body)
{
  vtkIdType ids[Block];
  for (size_t first = b; first < e; first += Block)
  {
    const int count = static_cast<int>(std::min<size_t>(Block, e - first));
    for (int k = 0; k < count; ++k)
    {
      ids[k] = groups[first + k].second;
    }
    body(ids, count, first - b);
  }
}

// One displacement per group: the mean of the members' own.
template <typename R, typename T>
void MergeSeamPoints(const DisplacePoints<R, T>& pass, const GroupList& groups)
{
  ForEachGroup(groups,
    [&](size_t b, size_t e)
    {
      double mean[3] = { 0.0, 0.0, 0.0 };
      ForEachBlock(groups, b, e,
        [&](const vtkIdType* ids, int count, size_t)
        {
          Lanes n[3], d, ds, dt;
          pass.Displacements(ids, count, n, d, ds, dt);
          for (int k = 0; k < count; ++k)
          {
            for (int j = 0; j < 3; ++j)
            {
              mean[j] += d[k] * n[j][k];
            }
          }
        });
      for (int j = 0; j < 3; ++j)
      {
        mean[j] /= static_cast<double>(e - b);
      }
      for (size_t g = b; g < e; ++g)
      {
        pass.C.WritePoint(groups[g].second, mean);
      }
    });
}

// One normal per group member: the sum of the members' that share its input normal (a hard
// edge keeps its two sides apart).
template <typename R>
void MergeSeamNormals(const Context<R>& c, const GroupList& groups)
{
  ForEachGroup(groups,
    [&](size_t b, size_t e)
    {
      std::vector<double> unit(3 * (e - b)), sums(3 * (e - b), 0.0);
      ForEachBlock(groups, b, e,
        [&](const vtkIdType* ids, int count, size_t at)
        {
          Lanes n[3];
          c.InputNormals(ids, count, n);
          for (int k = 0; k < count; ++k)
          {
            for (int j = 0; j < 3; ++j)
            {
              unit[3 * (at + k) + j] = n[j][k];
            }
          }
        });
      for (size_t g = 0; g < e - b; ++g)
      {
        for (size_t h = 0; h < e - b; ++h)
        {
          for (int j = 0; Dot(&unit[3 * g], &unit[3 * h]) > 1.0 - 1e-9 && j < 3; ++j)
          {
            sums[3 * g + j] += c.OutNormals[3 * groups[b + h].second + j];
          }
        }
      }
      ForEachBlock(groups, b, e,
        [&](const vtkIdType* ids, int count, size_t at)
        {
          Lanes n[3], m[3];
          for (int k = 0; k < count; ++k)
          {
            for (int j = 0; j < 3; ++j)
            {
              n[j][k] = unit[3 * (at + k) + j];
              m[j][k] = sums[3 * (at + k) + j];
            }
          }
          c.WriteNormalsAndTangents(ids, count, n, m);
        });
    });
}

//------------------------------------------------------------------------------
// dPdu and dPdv may be derivatives with respect to parameters (u,v) of which the texture
// coordinates are an axis-aligned affine function, s = o_s + r_s u, t = o_t + r_t v
// (vtkParametricSurfaceSource's TextureRepeat and TextureOffset). Estimates r_s and r_t by
// least squares over up to 4096 edges spread over the polygons: each edge's (du, dv) solves
// dP ~ dPdu du + dPdv dv, against its (ds, dt). Sets 1/r (so dP/ds = dPdu / r_s); exactly
// 1 when the fit is within its own error of it (0.1%, or twice the O(h^2) chord bias estimated
// from how far the derivatives turn along the edges: float positions and that bias would
// otherwise perturb the untransformed case) or cannot be made. Edges whose texture
// coordinates are not finite are left out.
template <typename R>
void EstimateDerivativeScale(Context<R>& c)
{
  const Polygons& polys = *c.Polys;
  double su = 0.0, uu = 0.0, tv = 0.0, vv = 0.0, biasU = 0.0, biasV = 0.0;
  const vtkIdType stride = std::max<vtkIdType>(1, polys.Count / 4096);
  for (vtkIdType cell = 0; cell < polys.Count; cell += stride)
  {
    if (polys.Offsets[cell + 1] - polys.Offsets[cell] < 2)
    {
      continue;
    }
    const vtkIdType i = polys.Conn[polys.Offsets[cell]], j = polys.Conn[polys.Offsets[cell] + 1];
    // The mean of the two ends' derivatives: exact for quadratic p, so the fit has no
    // first-order bias from the surface's curvature.
    double pi[3], pj[3], a[3], b[3], aj[3], bj[3], ta[3], tb[3];
    c.Get3(c.Points, i, pi);
    c.Get3(c.Points, j, pj);
    c.Get3(c.DPdu, i, a);
    c.Get3(c.DPdv, i, b);
    c.Get3(c.DPdu, j, aj);
    c.Get3(c.DPdv, j, bj);
    for (int k = 0; k < 3; ++k)
    {
      ta[k] = aj[k] - a[k];
      tb[k] = bj[k] - b[k];
      a[k] = 0.5 * (a[k] + aj[k]);
      b[k] = 0.5 * (b[k] + bj[k]);
    }
    const double dp[3] = { pj[0] - pi[0], pj[1] - pi[1], pj[2] - pi[2] };
    const double aa = Dot(a, a), ab = Dot(a, b), bb = Dot(b, b);
    const double det = aa * bb - ab * ab;
    if (!(det > 1e-12 * (aa + bb) * (aa + bb)))
    {
      continue;
    }
    double du = (bb * Dot(a, dp) - ab * Dot(b, dp)) / det;
    double dv = (aa * Dot(b, dp) - ab * Dot(a, dp)) / det;
    // The chord of an arc that turns its tangent by phi is tan(phi/2) / (phi/2) = 1 + phi^2/12
    // times the mean tangent's step, so (du, dv) comes out that much long: a bias of order h^2,
    // which the correction leaves at order h^4 (exact to that order for constant-speed curves
    // such as the parametric circles of a sphere or torus).
    double turn[3], step[3];
    for (int k = 0; k < 3; ++k)
    {
      turn[k] = ta[k] * du + tb[k] * dv;
      step[k] = a[k] * du + b[k] * dv;
    }
    const double step2 = Dot(step, step);
    double bias = 0.0;
    if (step2 > 0.0)
    {
      bias = Dot(turn, turn) / (12.0 * step2);
      du /= 1.0 + bias;
      dv /= 1.0 + bias;
    }
    const double ds = c.TCoords[c.TCoordsNC * j] - c.TCoords[c.TCoordsNC * i];
    const double dt = c.TCoords[c.TCoordsNC * j + 1] - c.TCoords[c.TCoordsNC * i + 1];
    if (!std::isfinite(ds * du + dt * dv + du * du + dv * dv))
    {
      continue;
    }
    su += ds * du;
    uu += du * du;
    tv += dt * dv;
    vv += dv * dv;
    biasU += bias * du * du;
    biasV += bias * dv * dv;
  }
  const double r[2] = { uu > 0.0 ? su / uu : 1.0, vv > 0.0 ? tv / vv : 1.0 };
  // Within the estimate's own error of 1, r is 1: the common case of texture coordinates that
  // are the parameters, whose derivatives are then used as given.
  const double tolerance[2] = { std::max(1e-3, uu > 0.0 ? 2.0 * biasU / uu : 0.0),
    std::max(1e-3, vv > 0.0 ? 2.0 * biasV / vv : 0.0) };
  for (int k = 0; k < 2; ++k)
  {
    const bool useful =
      std::isfinite(r[k]) && std::abs(r[k]) > 1e-12 && std::abs(r[k] - 1.0) > tolerance[k];
    c.DerivativeScale[k] = useful ? 1.0 / r[k] : 1.0;
  }
}

// The map from dPdu/dPdv's parameters to the texture coordinates as
// vtkParametricSurfaceSource declares it on them: exact, and the same in every piece, where
// an estimate depends on the polygons at hand. False where it is not declared or not usable.
template <typename R>
bool DeclaredDerivativeScale(vtkDataArray* tcoords, Context<R>& c)
{
  vtkInformationDoubleVectorKey* key = vtkParametricSurfaceSource::TEXTURE_TRANSFORM();
  vtkInformation* info = tcoords->HasInformation() ? tcoords->GetInformation() : nullptr;
  if (!info || !info->Has(key) || info->Length(key) != 4)
  {
    return false;
  }
  const double* transform = info->Get(key);
  const double repeat[2] = { transform[0], transform[2] };
  for (int k = 0; k < 2; ++k)
  {
    if (!std::isfinite(1.0 / repeat[k]) || repeat[k] == 0.0)
    {
      return false;
    }
  }
  c.DerivativeScale[0] = 1.0 / repeat[0];
  c.DerivativeScale[1] = 1.0 / repeat[1];
  return true;
}

// A 3-component point array named @a name, or null.
vtkDataArray* Vector(vtkPointData* pd, const char* name)
{
  vtkDataArray* a = pd->GetArray(name);
  return a && a->GetNumberOfComponents() == 3 ? a : nullptr;
}

// The height map's scalar type T for @a body(const T*), among those HeightMapScale accepts.
template <typename F>
void WithTexelType(vtkDataArray* scalars, F&& body)
{
  void* raw = scalars->GetVoidPointer(0);
  switch (scalars->GetDataType())
  {
    case VTK_UNSIGNED_CHAR:
      body(static_cast<const unsigned char*>(raw));
      break;
    case VTK_UNSIGNED_SHORT:
      body(static_cast<const unsigned short*>(raw));
      break;
    case VTK_FLOAT:
      body(static_cast<const float*>(raw));
      break;
    default:
      body(static_cast<const double*>(raw));
      break;
  }
}
// Whether normal mode @a mode fits derivatives to a point's neighbours (the surface's own
// derivatives are missing), and so reads its polygons.
bool FitsDerivatives(int mode, vtkPointData* pd)
{
  const bool derivatives = Vector(pd, "dPdu") && Vector(pd, "dPdv");
  return (mode == vtkDisplacementMapFilter::Approximate && !derivatives) ||
    (mode == vtkDisplacementMapFilter::Exact &&
      !(derivatives && Vector(pd, "dNdu") && Vector(pd, "dNdv")));
}

//------------------------------------------------------------------------------
// One execution, with every array read and written as R.
template <typename R>
struct Execution
{
  vtkDisplacementMapFilter* Filter;
  vtkPolyData* Input;
  vtkImageData* Image;
  vtkDataArray* InNormals;
  vtkDataArray* InTangents; // null where none are made
  Context<R> C;
  std::vector<vtkSmartPointer<vtkDataArray>> Kept; // converted inputs, alive while read
  std::unique_ptr<Polygons> Polys;
  PointPolygons PointLinks;
  std::unique_ptr<double[]> UnitNormals;
  GroupList Groups;
  vtkSmartPointer<vtkDataArray> OutPoints, OutNormals, OutTangents;

  Execution(vtkDisplacementMapFilter* filter, vtkPolyData* input, vtkImageData* image,
    vtkDataArray* tangents)
    : Filter(filter)
    , Input(input)
    , Image(image)
    , InNormals(input->GetPointData()->GetNormals())
    , InTangents(tangents)
  {
  }

  static constexpr int Type = std::is_same<R, float>::value ? VTK_FLOAT : VTK_DOUBLE;

  // The values of @a a (null: none) as raw memory of R: @a a's own when it is a plain array of
  // R, else those of a converted copy.
  const R* Read(vtkDataArray* a)
  {
    if (a && !(a->GetDataType() == Type && a->HasStandardMemoryLayout()))
    {
      this->Kept.push_back(NewArray(Type, a->GetName(), a->GetNumberOfComponents(), 0));
      this->Kept.back()->DeepCopy(a);
      a = this->Kept.back();
    }
    return a ? static_cast<const R*>(a->GetVoidPointer(0)) : nullptr;
  }

  R* Write(vtkSmartPointer<vtkDataArray>& a, const char* name, int nc)
  {
    a = NewArray(Type, name, nc, this->C.NumPoints);
    return static_cast<R*>(a->GetVoidPointer(0));
  }

  // Pass 1 and the seams' mean displacement, with the height map read as its own type.
  void Displace()
  {
    int dims[3];
    this->Image->GetDimensions(dims);
    vtkDataArray* scalars = this->Image->GetPointData()->GetScalars();
    const int nc = scalars->GetNumberOfComponents(), comp = this->Filter->GetComponent();
    double norm = 1.0;
    HeightMapScale(scalars->GetDataType(), norm);
    WithTexelType(scalars,
      [&](auto* data)
      {
        using T = std::remove_const_t<std::remove_pointer_t<decltype(data)>>;
        std::atomic<bool> sawNonFinite(false);
        const HeightMap<T> map{ data, dims[0], dims[1], nc, comp, this->Filter->GetWrap(),
          this->Filter->GetInterpolation(), norm, this->C.Midlevel, &sawNonFinite };
        DisplacePoints<R, T> pass{ this->C, map };
        vtkSMPTools::For(0, this->C.NumPoints, pass);
        MergeSeamPoints(pass, this->Groups);
        if (sawNonFinite)
        {
          vtkWarningWithObjectMacro(this->Filter,
            << CountNonFinite(data, static_cast<vtkIdType>(dims[0]) * dims[1], nc, comp)
            << " height value(s) in component " << comp
            << " of the height map are NaN or infinite; they are treated as Midlevel ("
            << this->C.Midlevel << ").");
        }
      });
  }

  // The seam groups among the boundary points, within SeamTolerance of the bounding-box
  // diagonal.
  void FindGroups()
  {
    const std::vector<vtkIdType> candidates = SeamCandidates(*this->Polys, this->C.NumPoints);
    if (candidates.size() > 1)
    {
      const double* b = this->Input->GetPoints()->GetBounds();
      const double diagonal = std::hypot(std::hypot(b[1] - b[0], b[3] - b[2]), b[5] - b[4]);
      const double tol = this->Filter->GetSeamTolerance() * diagonal;
      this->Groups = CoincidentGroups(this->C.Points, candidates, std::isfinite(tol) ? tol : 0.0);
    }
  }

  void SetUp(vtkDataArray* tcoords, vtkDataArray* dPdu, vtkDataArray* dPdv, vtkDataArray* dNdu,
    vtkDataArray* dNdv)
  {
    Context<R>& c = this->C;
    const int mode = this->Filter->GetNormalMode();
    const vtkIdType n = this->Input->GetNumberOfPoints();
    c.NumPoints = n;
    c.NormalMode = mode;
    c.Scale = this->Filter->GetScale();
    c.Midlevel = this->Filter->GetMidlevel();
    c.Points = this->Read(this->Input->GetPoints()->GetData());
    c.Normals = this->Read(this->InNormals);
    c.TCoords = this->Read(tcoords);
    c.TCoordsNC = tcoords->GetNumberOfComponents();
    c.DPdu = this->Read(dPdu);
    c.DPdv = this->Read(dPdv);
    c.DNdu = this->Read(dNdu);
    c.DNdv = this->Read(dNdv);
    c.Tangents = this->Read(this->InTangents);
    c.OutPoints = this->Write(this->OutPoints, "Points", 3);
    if (mode != vtkDisplacementMapFilter::None)
    {
      c.OutNormals = this->Write(this->OutNormals, this->InNormals->GetName(), 3);
    }
    if (this->InTangents)
    {
      c.TangentsNC = this->InTangents->GetNumberOfComponents();
      c.OutTangents = this->Write(this->OutTangents, this->InTangents->GetName(), c.TangentsNC);
    }
    this->Polys.reset(new Polygons(this->Input->GetPolys()));
    c.Polys = this->Polys.get();
    if (mode == vtkDisplacementMapFilter::Mesh ||
      FitsDerivatives(mode, this->Input->GetPointData()))
    {
      this->PointLinks.Build(n, this->Polys->Count, this->Polys->Cells);
      c.PointLinks = &this->PointLinks;
    }
    if (mode == vtkDisplacementMapFilter::Exact && !c.DNdu)
    {
      this->UnitNormals.reset(new double[3 * static_cast<size_t>(n)]);
      c.UnitNormals = this->UnitNormals.get();
      vtkSMPTools::For(0, n,
        [&](vtkIdType begin, vtkIdType end)
        {
          vtkIdType ids[Block];
          Lanes v[3];
          for (vtkIdType first = begin; first < end; first += Block)
          {
            const int count = static_cast<int>(std::min<vtkIdType>(Block, end - first));
            std::iota(ids, ids + count, first);
            c.InputNormals(ids, count, v);
            for (int k = 0; k < 3 * count; ++k)
            {
              this->UnitNormals[3 * first + k] = v[k % 3][k / 3];
            }
          }
        });
    }
    if (c.DPdu && !DeclaredDerivativeScale(tcoords, c))
    {
      EstimateDerivativeScale(c);
    }
    if (this->Filter->GetMergeSeams())
    {
      this->FindGroups();
    }
  }

  void Output(vtkPolyData* output)
  {
    output->CopyStructure(this->Input);
    output->SetPoints(vtkNew<vtkPoints>());
    output->GetPoints()->SetData(this->OutPoints);
    output->GetPointData()->PassData(this->Input->GetPointData());
    output->GetCellData()->PassData(this->Input->GetCellData());
    if (this->OutNormals)
    {
      output->GetPointData()->SetNormals(this->OutNormals);
    }
    // VTK 9.1's tangents attribute takes 3 components only: 4 go by name.
    if (this->OutTangents && this->OutTangents->GetNumberOfComponents() == 3)
    {
      output->GetPointData()->SetTangents(this->OutTangents);
    }
    else if (this->OutTangents)
    {
      output->GetPointData()->AddArray(this->OutTangents);
    }
  }
};

} // namespace

//------------------------------------------------------------------------------
int vtkDisplacementMapFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkDisplacementMapFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The surface streams piece by piece; every piece needs the whole height map. Seams, fits
  // and Mesh normals read a point's polygons, so a piece needs its neighbours' as ghosts.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkSurfaceDetailGhosts::RequestOneMoreLevel(inInfo, outInfo);
  if (!this->MergeSeams && this->NormalMode == None)
  {
    // Each point moves on its own: no neighbours needed.
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(),
      outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()));
  }
  vtkInformation* mapInfo = inputVector[1]->GetInformationObject(0);
  if (mapInfo && mapInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    mapInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    mapInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    mapInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    mapInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
      mapInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkDisplacementMapFilter::CheckHeightMap(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  double norm;
  if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1 || image->GetNumberOfPoints() == 0 || !scalars ||
    scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    vtkErrorMacro("The height map on input port 1 is empty or has no point scalars; give "
                  "it at least 1x1 texels with scalars.");
    return false;
  }
  if (dims[2] != 1)
  {
    vtkErrorMacro("The height map is a " << dims[0] << "x" << dims[1] << "x" << dims[2]
                                         << " volume; it must be a 2-D image "
                                            "(extract a slice with vtkExtractVOI).");
    return false;
  }
  if (this->Component >= scalars->GetNumberOfComponents())
  {
    vtkErrorMacro("Component " << this->Component << " was asked for but the height map has "
                               << scalars->GetNumberOfComponents() << " component(s).");
    return false;
  }
  if (!vtkSurfaceDetail::HeightMapScale(scalars->GetDataType(), norm))
  {
    vtkErrorMacro("The height map's scalars are " << scalars->GetDataTypeAsString()
                                                  << "; use unsigned char, unsigned short, "
                                                     "float or double (vtkImageCast).");
    return false;
  }
  if (dims[0] == 1 && dims[1] == 1)
  {
    // Valid (a 1x1 texture samples to its only texel), but seldom meant: say what it does.
    vtkWarningMacro("The height map is a single texel: a constant, so every point moves by the "
                    "same distance and the map gives the normals no slope.");
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkDisplacementMapFilter::CheckSurface(vtkPolyData* input)
{
  vtkPointData* pd = input->GetPointData();
  vtkDataArray* normals = pd->GetNormals();
  vtkDataArray* tcoords = pd->GetTCoords();
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The input has no 3-component point normals; displacement moves points "
                  "along them. Compute them with vtkPolyDataNormals (SplittingOff) or "
                  "generate the surface with vtkParametricSurfaceSource.");
    return false;
  }
  if (!tcoords || tcoords->GetNumberOfComponents() < 2)
  {
    vtkErrorMacro("The input has no point texture coordinates (2 or more components); "
                  "they locate each point in the height map. Generate them, e.g. with "
                  "vtkParametricSurfaceSource or vtkTextureMapToSphere.");
    return false;
  }
  const vtkIdType numPts = input->GetNumberOfPoints();
  for (vtkDataArray* a : { normals, tcoords, Vector(pd, "dPdu"), Vector(pd, "dPdv"),
         Vector(pd, "dNdu"), Vector(pd, "dNdv"), this->InputTangents(input) })
  {
    if (a && a->GetNumberOfTuples() < numPts)
    {
      vtkErrorMacro("The point array " << (a->GetName() ? a->GetName() : "(unnamed)") << " has "
                                       << a->GetNumberOfTuples() << " tuples for " << numPts
                                       << " points; give it one tuple per point.");
      return false;
    }
  }
  if ((this->NormalMode == Mesh || FitsDerivatives(this->NormalMode, pd)) &&
    input->GetNumberOfStrips() > 0)
  {
    vtkErrorMacro("The input has triangle strips; normal mode " << this->GetNormalModeAsString()
                                                                << " needs polygons. Run "
                                                                   "vtkTriangleFilter first.");
    return false;
  }
  if (!vtkSurfaceDetailCells::PointIdsInRange(input->GetPolys(), numPts) ||
    !vtkSurfaceDetailCells::PointIdsInRange(input->GetStrips(), numPts))
  {
    vtkErrorMacro("A polygon or triangle strip of the input names a point id outside [0, "
      << numPts << "); fix the connectivity (e.g. with vtkCleanPolyData) first.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkDisplacementMapFilter::InputTangents(vtkPolyData* input)
{
  // DESIGN.md's 4-component frame goes by its name "Tangents".
  vtkDataArray* t = input->GetPointData()->GetTangents();
  t = t ? t : input->GetPointData()->GetArray("Tangents");
  const bool usable = t && (t->GetNumberOfComponents() == 3 || t->GetNumberOfComponents() == 4);
  return this->NormalMode != None && usable ? t : nullptr;
}

//------------------------------------------------------------------------------
int vtkDisplacementMapFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkImageData* image = vtkImageData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("Input port 0 needs a vtkPolyData.");
    return 0;
  }
  if (!image)
  {
    vtkErrorMacro("Input port 1 needs the height map as a vtkImageData "
                  "(SetInputConnection(1, ...)).");
    return 0;
  }
  if (input->GetNumberOfPoints() == 0)
  {
    output->ShallowCopy(input);
    return 1;
  }
  if (!this->CheckSurface(input) || !this->CheckHeightMap(image))
  {
    return 0;
  }
  if (this->Scale == 0.0 && this->NormalMode != Mesh)
  {
    // Nothing moves, so nothing changes: the input itself, bit for bit.
    output->ShallowCopy(input);
    vtkSurfaceDetailGhosts::RemoveUnrequested(outputVector->GetInformationObject(0), output);
    return 1;
  }
  // One precision for all: float when every array read is float (as VTK's sources make them),
  // else double. The work is done in double either way.
  vtkPointData* pd = input->GetPointData();
  const bool analytic = this->NormalMode == Approximate || this->NormalMode == Exact;
  vtkDataArray* dPdu = Vector(pd, "dPdu");
  vtkDataArray* dPdv = Vector(pd, "dPdv");
  const bool derivatives = analytic && dPdu && dPdv;
  // dNdu/dNdv are derivatives in the parameters of dPdu/dPdv: usable with them only.
  vtkDataArray* dNdu = Vector(pd, "dNdu");
  vtkDataArray* dNdv = Vector(pd, "dNdv");
  const bool normalDerivatives = derivatives && this->NormalMode == Exact && dNdu && dNdv;
  std::vector<vtkDataArray*> used = { input->GetPoints()->GetData(), pd->GetNormals(),
    pd->GetTCoords(), this->InputTangents(input) };
  if (derivatives)
  {
    used.insert(used.end(), { dPdu, dPdv });
  }
  if (normalDerivatives)
  {
    used.insert(used.end(), { dNdu, dNdv });
  }
  const bool allFloat = std::all_of(
    used.begin(), used.end(), [](vtkDataArray* a) { return !a || a->GetDataType() == VTK_FLOAT; });
  auto run = [&](auto precision)
  {
    Execution<decltype(precision)> x(this, input, image, this->InputTangents(input));
    x.SetUp(pd->GetTCoords(), derivatives ? dPdu : nullptr, derivatives ? dPdv : nullptr,
      normalDerivatives ? dNdu : nullptr, normalDerivatives ? dNdv : nullptr);
    x.Displace();
    if (this->NormalMode == Mesh)
    {
      std::unique_ptr<signed char[]> signs(new signed char[x.Polys->Count]);
      const MeshNormals<decltype(precision)> mesh{ x.C, signs.get() };
      vtkSMPTools::For(
        0, x.Polys->Count, [&](vtkIdType begin, vtkIdType end) { mesh.FindSigns(begin, end); });
      vtkSMPTools::For(0, input->GetNumberOfPoints(), mesh);
    }
    if (this->NormalMode != None)
    {
      MergeSeamNormals(x.C, x.Groups);
    }
    x.Output(output);
  };
  if (allFloat)
  {
    run(float());
  }
  else
  {
    run(double());
  }
  vtkSurfaceDetailGhosts::RemoveUnrequested(outputVector->GetInformationObject(0), output);
  return 1;
}

//------------------------------------------------------------------------------
vtkDisplacementMapFilter::vtkDisplacementMapFilter()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
const char* vtkDisplacementMapFilter::GetWrapAsString()
{
  return vtkSurfaceDetail::WrapModeName(this->Wrap);
}

//------------------------------------------------------------------------------
const char* vtkDisplacementMapFilter::GetInterpolationAsString()
{
  switch (this->Interpolation)
  {
    case Nearest:
      return "Nearest";
    case Cubic:
      return "Cubic";
    default:
      return "Linear";
  }
}

//------------------------------------------------------------------------------
const char* vtkDisplacementMapFilter::GetNormalModeAsString()
{
  switch (this->NormalMode)
  {
    case None:
      return "None";
    case Approximate:
      return "Approximate";
    case Mesh:
      return "Mesh";
    default:
      return "Exact";
  }
}

//------------------------------------------------------------------------------
void vtkDisplacementMapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scale: " << this->Scale << "\n";
  os << indent << "Midlevel: " << this->Midlevel << "\n";
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "Wrap: " << this->GetWrapAsString() << "\n";
  os << indent << "Interpolation: " << this->GetInterpolationAsString() << "\n";
  os << indent << "NormalMode: " << this->GetNormalModeAsString() << "\n";
  os << indent << "MergeSeams: " << (this->MergeSeams ? "On" : "Off") << "\n";
  os << indent << "SeamTolerance: " << this->SeamTolerance << "\n";
}
