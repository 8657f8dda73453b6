// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkDisplacementMapFilter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDisplacementDerivatives.h"
#include "vtkDisplacementNormals.h"
#include "vtkDisplacementPolygons.h"
#include "vtkDisplacementSampling.h"
#include "vtkDisplacementSeams.h"
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
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkSurfaceDetailCells.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailGhosts.h"
#include "vtkSurfaceDetailProgress.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkDisplacementMapFilter);

namespace
{
using namespace vtkDisplacement;
using vtkSurfaceDetail::Dot;

// How an execution ended.
enum class Outcome
{
  Done,
  BadPointIds, // a polygon names a point the input does not have
  Aborted      // AbortExecute was set while it ran
};

// A new float or double array of @a n tuples.
vtkSmartPointer<vtkDataArray> NewArray(int type, const char* name, int nc, vtkIdType n)
{
  auto a = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
  a->SetName(name);
  a->SetNumberOfComponents(nc);
  a->SetNumberOfTuples(n);
  return a;
}

// A position as R: beyond float's range the largest float of its sign, never infinity.
template <typename R>
R ToPosition(double v)
{
  constexpr double big = std::numeric_limits<R>::max();
  return static_cast<R>(std::min(std::max(v, -big), big));
}

// A 3-component point array named @a name, or null.
vtkDataArray* Vector(vtkPointData* pd, const char* name)
{
  vtkDataArray* a = pd->GetArray(name);
  return a && a->GetNumberOfComponents() == 3 ? a : nullptr;
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
// The pass over the points: each point moved, and in the analytic modes (Approximate, Exact)
// its normal and tangent, in one pass that writes each output once. Its pieces also serve the
// seams and Mesh normals.
template <typename R, typename Id>
struct Displacer
{
  const Surface<R>& In;
  const Output<R>& Out;
  const HeightSampler& Map;
  const Fits<R, Id>& FitSums;
  vtkSMPThreadLocal<std::vector<double>>& Scratch; // each thread's sums over polygons
  vtkSurfaceDetail::Progress& Progress;
  double ScaleFactor;
  double Midlevel;
  int Mode;
  bool Triplanar;
  double TriplanarScale;
  double TriplanarSharpness;

  // The heights and slopes of the block's points, in D, Ds, Dt (triplanar: D and the
  // gradient G).
  void Sample(PointBlock& b) const
  {
    if (this->Triplanar)
    {
      this->SampleTriplanar(b);
      return;
    }
    const int nc = this->In.TCoordsNC;
    const R* tc = this->In.TCoords;
    for (int k = 0; k < b.Count; ++k)
    {
      b.S[k] = tc[nc * b.Ids[k]];
      b.T[k] = tc[nc * b.Ids[k] + 1];
    }
    this->Map.Sample(b.Count, b.S, b.T, b.D, b.Ds, b.Dt);
  }

  // The height blended from the three projections of the height map (D), and its gradient
  // in the input's coordinates (Gx, Gy, Gz): each projection's slopes along its own axes, the
  // weights held constant.
  void SampleTriplanar(PointBlock& b) const
  {
    UnitNormals(this->In, b);
    // Per projection: the points' texture coordinates, weights and axis frames.
    double st[3][2][Block], w[3][Block], T[3][3][Block], B[3][3][Block];
    for (int k = 0; k < b.Count; ++k)
    {
      const R* q = this->In.Points + 3 * b.Ids[k];
      const double p[3] = { double(q[0]), double(q[1]), double(q[2]) };
      const double n[3] = { b.Nx[k], b.Ny[k], b.Nz[k] };
      double weights[3];
      vtkSurfaceDetail::TriplanarWeights(n, this->TriplanarSharpness, weights);
      for (int axis = 0; axis < 3; ++axis)
      {
        double coordinates[2], tangent[3], bitangent[3];
        vtkSurfaceDetail::TriplanarProject(
          axis, p, n, this->TriplanarScale, coordinates, tangent, bitangent);
        st[axis][0][k] = coordinates[0];
        st[axis][1][k] = coordinates[1];
        w[axis][k] = weights[axis];
        for (int c = 0; c < 3; ++c)
        {
          T[axis][c][k] = tangent[c];
          B[axis][c][k] = bitangent[c];
        }
      }
      b.D[k] = b.Gx[k] = b.Gy[k] = b.Gz[k] = 0.0;
    }
    Lanes h, hs, ht;
    for (int axis = 0; axis < 3; ++axis)
    {
      this->Map.Sample(b.Count, st[axis][0], st[axis][1], h, hs, ht);
      for (int k = 0; k < b.Count; ++k)
      {
        // s and t advance TriplanarScale per unit along T and B.
        const double c = w[axis][k] * this->TriplanarScale;
        b.D[k] += w[axis][k] * h[k];
        b.Gx[k] += c * (hs[k] * T[axis][0][k] + ht[k] * B[axis][0][k]);
        b.Gy[k] += c * (hs[k] * T[axis][1][k] + ht[k] * B[axis][1][k]);
        b.Gz[k] += c * (hs[k] * T[axis][2][k] + ht[k] * B[axis][2][k]);
      }
    }
  }

  // The heights in D, Ds, Dt made displacements d = ScaleFactor (h - Midlevel) and their slopes,
  // finite whatever the scale.
  void Displacements(PointBlock& b) const
  {
    const double scale = this->ScaleFactor, midlevel = this->Midlevel;
    for (int k = 0; k < b.Count; ++k)
    {
      b.D[k] = Finite(scale * (b.D[k] - midlevel));
      b.Ds[k] = Finite(scale * b.Ds[k]);
      b.Dt[k] = Finite(scale * b.Dt[k]);
      b.Gx[k] = Finite(scale * b.Gx[k]);
      b.Gy[k] = Finite(scale * b.Gy[k]);
      b.Gz[k] = Finite(scale * b.Gz[k]);
    }
  }

  // Triplanar Approximate normals: n minus the displacement's gradient along the surface.
  static void TriplanarNormals(PointBlock& b)
  {
    for (int k = 0; k < b.Count; ++k)
    {
      const double along = b.Gx[k] * b.Nx[k] + b.Gy[k] * b.Ny[k] + b.Gz[k] * b.Nz[k];
      b.Mx[k] = b.Nx[k] - (b.Gx[k] - along * b.Nx[k]);
      b.My[k] = b.Ny[k] - (b.Gy[k] - along * b.Ny[k]);
      b.Mz[k] = b.Nz[k] - (b.Gz[k] - along * b.Nz[k]);
    }
  }

  // Point @a i's own offset, d n (for the seams' mean).
  void Displacement(vtkIdType i, double offset[3]) const
  {
    PointBlock b;
    b.Span(i, 1);
    this->Sample(b);
    this->Displacements(b);
    UnitNormals(this->In, b);
    offset[0] = b.D[0] * b.Nx[0];
    offset[1] = b.D[0] * b.Ny[0];
    offset[2] = b.D[0] * b.Nz[0];
  }

  // Point @a i moved by @a offset. Adding +0 would turn -0 into +0: no displacement leaves the
  // bits alone.
  void WritePoint(vtkIdType i, const double offset[3]) const
  {
    for (int j = 0; j < 3; ++j)
    {
      const R p = this->In.Points[3 * i + j];
      this->Out.Points[3 * i + j] = offset[j] == 0.0 ? p : ToPosition<R>(Finite(p + offset[j]));
    }
  }

  // The seams' view of one point: its unit input normal, its normal so far, and its final
  // normal and tangent.
  void InputNormal(vtkIdType i, double n[3]) const
  {
    PointBlock b;
    b.Span(i, 1);
    UnitNormals(this->In, b);
    n[0] = b.Nx[0];
    n[1] = b.Ny[0];
    n[2] = b.Nz[0];
  }

  void OutputNormal(vtkIdType i, double m[3]) const { Load3(this->Out.Normals, i, 1.0, m); }

  void WriteNormalAndTangent(vtkIdType i, const double n[3], const double m[3]) const
  {
    PointBlock b;
    b.Span(i, 1);
    b.Nx[0] = n[0];
    b.Ny[0] = n[1];
    b.Nz[0] = n[2];
    b.Mx[0] = m[0];
    b.My[0] = m[1];
    b.Mz[0] = m[2];
    WriteNormalsAndTangents(this->In, this->Out, b);
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    switch (this->Mode)
    {
      case vtkDisplacementMapFilter::Exact:
        this->Displace<true, true>(begin, end);
        break;
      case vtkDisplacementMapFilter::Approximate:
        this->Displace<true, false>(begin, end);
        break;
      default:
        this->Displace<false, false>(begin, end);
        break;
    }
  }

  // The points [begin, end) moved, with (Analytic) their normals and tangents.
  template <bool Analytic, bool Exact>
  void Displace(vtkIdType begin, vtkIdType end) const
  {
    std::vector<double>& sums = this->Scratch.Local();
    if (Analytic && this->FitSums.Any())
    {
      this->FitSums.Make(begin, end, sums);
    }
    PointBlock b;
    for (vtkIdType first = begin; first < end && !this->Progress.Aborted(); first += Block)
    {
      b.Span(first, static_cast<int>(std::min<vtkIdType>(Block, end - first)));
      this->Sample(b);
      this->Displacements(b);
      UnitNormals(this->In, b);
      for (int k = 0; k < b.Count; ++k)
      {
        const double offset[3] = { b.D[k] * b.Nx[k], b.D[k] * b.Ny[k], b.D[k] * b.Nz[k] };
        this->WritePoint(b.Ids[k], offset);
      }
      if (Analytic && this->Triplanar)
      {
        TriplanarNormals(b);
        WriteNormalsAndTangents(this->In, this->Out, b);
      }
      else if (Analytic)
      {
        Derivatives(this->In, this->FitSums, sums, begin, Exact, b);
        Directions<Exact>(b);
        WriteNormalsAndTangents(this->In, this->Out, b);
      }
      this->Progress.Advance(b.Count);
    }
  }

  // Mesh normals, after every point has moved: the sums of the displaced polygons' normals,
  // made unit, with their tangents.
  void MeshNormals(
    const vtkDisplacement::MeshNormals<R, Id>& mesh, vtkIdType begin, vtkIdType end) const
  {
    if (this->Progress.Aborted())
    {
      return;
    }
    std::vector<double>& sums = this->Scratch.Local();
    mesh.Make(begin, end, sums);
    PointBlock b;
    for (vtkIdType first = begin; first < end; first += Block)
    {
      b.Span(first, static_cast<int>(std::min<vtkIdType>(Block, end - first)));
      UnitNormals(this->In, b);
      for (int k = 0; k < b.Count; ++k)
      {
        const double* m = &sums[3 * (b.Ids[k] - begin)];
        b.Mx[k] = m[0];
        b.My[k] = m[1];
        b.Mz[k] = m[2];
      }
      WriteNormalsAndTangents(this->In, this->Out, b);
      this->Progress.Advance(b.Count);
    }
  }
};

//------------------------------------------------------------------------------
// One execution, with every array read and written as R (float or double).
template <typename R>
class Execution
{
public:
  static constexpr int Type = std::is_same<R, float>::value ? VTK_FLOAT : VTK_DOUBLE;

  Execution(vtkDisplacementMapFilter* filter, vtkPolyData* input, vtkDataArray* tangents,
    bool derivatives, bool normalDerivatives)
    : Filter(filter)
    , Input(input)
    , InNormals(input->GetPointData()->GetNormals())
    , InTangents(tangents)
  {
    vtkPointData* pd = input->GetPointData();
    Surface<R>& in = this->In;
    in.NumPoints = input->GetNumberOfPoints();
    in.Points = this->Read(input->GetPoints()->GetData());
    in.Normals = this->Read(this->InNormals);
    if (!filter->GetTriplanar())
    {
      in.TCoords = this->Read(pd->GetTCoords());
      in.TCoordsNC = pd->GetTCoords()->GetNumberOfComponents();
    }
    if (derivatives)
    {
      in.DPdu = this->Read(Vector(pd, "dPdu"));
      in.DPdv = this->Read(Vector(pd, "dPdv"));
    }
    if (normalDerivatives)
    {
      in.DNdu = this->Read(Vector(pd, "dNdu"));
      in.DNdv = this->Read(Vector(pd, "dNdv"));
    }
    in.Tangents = this->Read(tangents);
  }

  // Displaces the input by the height map @a image, with the polygons as @a polys. Nothing is
  // read through a polygon that names a point the input does not have (BadPointIds).
  template <typename Id>
  Outcome Run(const Polygons<Id>& polys, vtkImageData* image, vtkDataArray* heights)
  {
    vtkDisplacementMapFilter* f = this->Filter;
    const int mode = f->GetNormalMode();
    const vtkIdType n = this->In.NumPoints;
    const CellRuns runs(polys);
    if (!runs.IdsWithin(n))
    {
      return Outcome::BadPointIds;
    }
    this->AllocateOutputs(mode);
    if (this->In.DPdu &&
      !DeclaredDerivativeScale(this->Input->GetPointData()->GetTCoords(), this->In))
    {
      EstimateDerivativeScale(polys, this->In);
    }
    const GroupList groups = f->GetMergeSeams() ? this->FindSeams(polys, runs) : GroupList();
    f->UpdateProgress(0.2);

    // Passes that sum over polygons own ranges of points of the runs' grain.
    const bool exact = mode == vtkDisplacementMapFilter::Exact;
    const bool triplanar = f->GetTriplanar();
    const bool analytic = !triplanar && (exact || mode == vtkDisplacementMapFilter::Approximate);
    const Fits<R, Id> fits{ this->In, polys, runs, analytic && !this->In.DPdu,
      exact && !this->In.DNdu };
    const vtkIdType grain = fits.Any() || mode == vtkDisplacementMapFilter::Mesh
      ? runs.Grain(n)
      : std::max<vtkIdType>(Block, n / 1024);
    const std::unique_ptr<HeightSampler> map =
      MakeHeightSampler(image, heights, f->GetHeightComponent(), f->GetWrap(),
        f->GetInterpolation(), f->GetMidlevel(), f->GetBorderHeight());
    vtkSMPThreadLocal<std::vector<double>> scratch;
    const bool mesh = mode == vtkDisplacementMapFilter::Mesh;
    vtkSurfaceDetail::Progress progress(f, 0.2, 0.95, mesh ? 2 * n : n);
    const Displacer<R, Id> pass{ this->In, this->Out, *map, fits, scratch, progress,
      f->GetScaleFactor(), f->GetMidlevel(), mode, triplanar, f->GetTriplanarScale(),
      f->GetTriplanarSharpness() };
    vtkSMPTools::For(0, n, grain, pass);
    MergeSeamPoints(pass, groups);
    if (mesh)
    {
      const vtkDisplacement::MeshNormals<R, Id> sums{ this->In, polys, runs, this->Out.Points };
      vtkSMPTools::For(
        0, n, grain, [&](vtkIdType begin, vtkIdType end) { pass.MeshNormals(sums, begin, end); });
    }
    if (progress.Aborted())
    {
      return Outcome::Aborted;
    }
    if (mode != vtkDisplacementMapFilter::Input)
    {
      MergeSeamNormals(pass, groups);
    }
    if (map->SawNonFinite())
    {
      vtkWarningWithObjectMacro(
        f, << CountNonFinite(heights, f->GetHeightComponent()) << " height value(s) in component "
           << f->GetHeightComponent()
           << " of the height map are NaN or infinite; they are treated as Midlevel ("
           << f->GetMidlevel() << ").");
    }
    return Outcome::Done;
  }

  // The input's structure and arrays, with the new points, normals and tangents.
  void Output(vtkPolyData* output) const
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
    if (this->OutTangents)
    {
      output->GetPointData()->SetTangents(this->OutTangents);
    }
  }

private:
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
    a = NewArray(Type, name, nc, this->In.NumPoints);
    return static_cast<R*>(a->GetVoidPointer(0));
  }

  void AllocateOutputs(int mode)
  {
    this->Out.Points = this->Write(this->OutPoints, "Points", 3);
    if (mode != vtkDisplacementMapFilter::Input)
    {
      this->Out.Normals = this->Write(this->OutNormals, this->InNormals->GetName(), 3);
    }
    if (this->InTangents)
    {
      this->Out.Tangents = this->Write(this->OutTangents, this->InTangents->GetName(), 3);
      // The mark of vtkSurfaceDetailTangents (and any other) stays with the tangents.
      this->OutTangents->CopyInformation(this->InTangents->GetInformation());
    }
  }

  // The seam groups among the boundary points, within SeamTolerance of the bounding-box
  // diagonal.
  template <typename Id>
  GroupList FindSeams(const Polygons<Id>& polys, const CellRuns& runs) const
  {
    const std::vector<vtkIdType> candidates = SeamCandidates(polys, runs, this->In.NumPoints);
    if (candidates.size() < 2)
    {
      return GroupList();
    }
    const double* b = this->Input->GetPoints()->GetBounds();
    const double diagonal = std::hypot(std::hypot(b[1] - b[0], b[3] - b[2]), b[5] - b[4]);
    const double tol = this->Filter->GetSeamTolerance() * diagonal;
    return CoincidentGroups(this->In.Points, candidates, std::isfinite(tol) ? tol : 0.0);
  }

  vtkDisplacementMapFilter* Filter;
  vtkPolyData* Input;
  vtkDataArray* InNormals;
  vtkDataArray* InTangents; // null where none are made
  Surface<R> In;
  vtkDisplacement::Output<R> Out;
  std::vector<vtkSmartPointer<vtkDataArray>> Kept; // converted inputs, alive while read
  vtkSmartPointer<vtkDataArray> OutPoints, OutNormals, OutTangents;
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
  if (!this->MergeSeams && this->NormalMode == Input)
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
bool vtkDisplacementMapFilter::CheckHeightMap(vtkImageData* image, vtkDataArray* scalars)
{
  int dims[3];
  image->GetDimensions(dims);
  double norm;
  if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1 || image->GetNumberOfPoints() == 0 || !scalars ||
    scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    vtkErrorMacro("The height map on input port 1 is empty or lacks the height array (its point "
                  "scalars, or the array SetInputArrayToProcess(0, ...) names); give it at least "
                  "1x1 texels with one height each.");
    return false;
  }
  if (dims[2] != 1)
  {
    vtkErrorMacro("The height map is a " << dims[0] << "x" << dims[1] << "x" << dims[2]
                                         << " volume; it must be a 2-D image "
                                            "(extract a slice with vtkExtractVOI).");
    return false;
  }
  if (this->HeightComponent >= scalars->GetNumberOfComponents())
  {
    vtkErrorMacro("HeightComponent " << this->HeightComponent
                                     << " was asked for but the height map has "
                                     << scalars->GetNumberOfComponents() << " component(s).");
    return false;
  }
  if (!vtkSurfaceDetail::HeightMapScale(scalars->GetDataType(), norm))
  {
    vtkErrorMacro("The height map's scalars are "
      << scalars->GetDataTypeAsString() << ": " << vtkSurfaceDetail::HeightMapTypeAdvice() << ".");
    return false;
  }
  if (this->Wrap == ClampToBorder && !std::isfinite(this->BorderHeight))
  {
    vtkErrorMacro("BorderHeight is " << this->BorderHeight << ": set a finite value.");
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
  if (this->Triplanar && this->NormalMode == Exact)
  {
    vtkErrorMacro("Exact normals need texture coordinates (and the surface's derivatives in "
                  "them); with Triplanar sampling choose the Approximate or Mesh NormalMode.");
    return false;
  }
  if (!this->Triplanar && (!tcoords || tcoords->GetNumberOfComponents() < 2))
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
  // The polygons' ids are checked where they are first read (Execution::Run).
  if (!vtkSurfaceDetailCells::PointIdsInRange(input->GetStrips(), numPts))
  {
    this->ReportBadPointIds(numPts);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkDisplacementMapFilter::ReportBadPointIds(vtkIdType numPts)
{
  vtkErrorMacro("A polygon or triangle strip of the input names a point id outside [0, "
    << numPts << "); fix the connectivity (e.g. with vtkCleanPolyData) first.");
}

//------------------------------------------------------------------------------
vtkDataArray* vtkDisplacementMapFilter::InputTangents(vtkPolyData* input)
{
  // The TANGENTS attribute has 3 components (VTK enforces it); the handedness beside it
  // (vtkSurfaceDetailTangents) does not change when the tangents turn with the normals.
  return this->NormalMode != Input ? input->GetPointData()->GetTangents() : nullptr;
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
  vtkDataArray* heights = this->GetInputArrayToProcess(0, inputVector);
  if (!this->CheckSurface(input) || !this->CheckHeightMap(image, heights))
  {
    return 0;
  }
  if (this->ScaleFactor == 0.0 && this->NormalMode != Mesh)
  {
    // Nothing moves, so nothing changes: the input itself, bit for bit.
    if (!vtkSurfaceDetailCells::PointIdsInRange(input->GetPolys(), input->GetNumberOfPoints()))
    {
      this->ReportBadPointIds(input->GetNumberOfPoints());
      return 0;
    }
    output->ShallowCopy(input);
    vtkSurfaceDetailGhosts::RemoveUnrequested(outputVector->GetInformationObject(0), output);
    return 1;
  }
  // One precision for all: float when every array read is float (as VTK's sources make them),
  // else double. The work is done in double either way.
  vtkPointData* pd = input->GetPointData();
  // Triplanar sampling takes its slopes along the axes: no surface derivatives are read.
  const bool analytic =
    !this->Triplanar && (this->NormalMode == Approximate || this->NormalMode == Exact);
  vtkDataArray* dPdu = Vector(pd, "dPdu");
  vtkDataArray* dPdv = Vector(pd, "dPdv");
  const bool derivatives = analytic && dPdu && dPdv;
  // dNdu/dNdv are derivatives in the parameters of dPdu/dPdv: usable with them only.
  vtkDataArray* dNdu = Vector(pd, "dNdu");
  vtkDataArray* dNdv = Vector(pd, "dNdv");
  const bool normalDerivatives = derivatives && this->NormalMode == Exact && dNdu && dNdv;
  std::vector<vtkDataArray*> used = { input->GetPoints()->GetData(), pd->GetNormals(),
    this->Triplanar ? nullptr : pd->GetTCoords(), this->InputTangents(input) };
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
  Outcome outcome = Outcome::Done;
  auto run = [&](auto precision)
  {
    Execution<decltype(precision)> x(
      this, input, this->InputTangents(input), derivatives, normalDerivatives);
    WithPolygons(
      input->GetPolys(), [&](const auto& polys) { outcome = x.Run(polys, image, heights); });
    if (outcome == Outcome::Done)
    {
      x.Output(output);
    }
  };
  this->UpdateProgress(0.0);
  const bool single = this->OutputPointsPrecision == SINGLE_PRECISION ||
    (this->OutputPointsPrecision == DEFAULT_PRECISION && allFloat);
  if (single)
  {
    run(float());
  }
  else
  {
    run(double());
  }
  if (outcome == Outcome::BadPointIds)
  {
    this->ReportBadPointIds(input->GetNumberOfPoints());
    return 0;
  }
  if (outcome == Outcome::Aborted)
  {
    // Stopped by the user (AbortExecute): no error, and no half-made output.
    output->Initialize();
    return 1;
  }
  this->UpdateProgress(1.0);
  vtkSurfaceDetailGhosts::RemoveUnrequested(outputVector->GetInformationObject(0), output);
  return 1;
}

//------------------------------------------------------------------------------
void vtkDisplacementMapFilter::SetSourceData(vtkImageData* image)
{
  this->SetInputData(1, image);
}

//------------------------------------------------------------------------------
vtkDisplacementMapFilter::vtkDisplacementMapFilter()
{
  this->SetNumberOfInputPorts(2);
  // The heights: the height map's point scalars unless told otherwise.
  this->SetInputArrayToProcess(
    0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
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
    case Input:
      return "Input";
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
  os << indent << "ScaleFactor: " << this->ScaleFactor << "\n";
  os << indent << "Midlevel: " << this->Midlevel << "\n";
  os << indent << "HeightComponent: " << this->HeightComponent << "\n";
  os << indent << "Wrap: " << this->GetWrapAsString() << "\n";
  os << indent << "BorderHeight: " << this->BorderHeight << "\n";
  os << indent << "Interpolation: " << this->GetInterpolationAsString() << "\n";
  os << indent << "NormalMode: " << this->GetNormalModeAsString() << "\n";
  os << indent << "Triplanar: " << (this->Triplanar ? "On" : "Off") << "\n";
  os << indent << "TriplanarScale: " << this->TriplanarScale << "\n";
  os << indent << "TriplanarSharpness: " << this->TriplanarSharpness << "\n";
  os << indent << "MergeSeams: " << (this->MergeSeams ? "On" : "Off") << "\n";
  os << indent << "SeamTolerance: " << this->SeamTolerance << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
