// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkParametricSurfaceSource as a pipeline citizen: pieces add up to the serial surface,
// thread counts do not change a byte, bad input gives a clear error and an empty output,
// and sweeps over degenerate and extreme surfaces give finite unit frames (or an error).

#include "ParametricSurfaceTestHelpers.h"
#include "TangentFrameTestHelpers.h"

#include <vtkBezierProfile.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkFloatArray.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkParametricBohemianDome.h>
#include <vtkParametricBoy.h>
#include <vtkParametricCrossCap.h>
#include <vtkParametricCylinder.h>
#include <vtkParametricDini.h>
#include <vtkParametricDonut.h>
#include <vtkParametricEllipsoid.h>
#include <vtkParametricEnneper.h>
#include <vtkParametricExtrusion.h>
#include <vtkParametricFigure8Klein.h>
#include <vtkParametricKlein.h>
#include <vtkParametricMobius.h>
#include <vtkParametricPseudosphere.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricRevolution.h>
#include <vtkParametricRoman.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSpline.h>
#include <vtkParametricSuperEllipsoid.h>
#include <vtkParametricSuperToroid.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkParametricTorus.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace
{
vtkSmartPointer<vtkParametricSurfaceSource> MakeSource(vtkParametricFunction* f, int U, int V)
{
  auto source = vtkSmartPointer<vtkParametricSurfaceSource>::New();
  source->SetParametricFunction(f);
  source->SetUResolution(U);
  source->SetVResolution(V);
  source->GenerateNormalsOn();
  source->GenerateTextureCoordinatesOn();
  source->GenerateTangentsOn();
  source->GenerateDerivativesOn();
  return source;
}

// Every value finite; normals unit; tangents unit, orthogonal to the normal, w = +-1.
// Returns the number of bad points (and says why for the first).
int CountBadFrames(vtkPolyData* out, double unitTolerance = 1e-5)
{
  int bad = 0;
  vtkPointData* pd = out->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    for (vtkIdType v = 0; v < array->GetNumberOfValues(); ++v)
    {
      if (!std::isfinite(array->GetComponent(v / array->GetNumberOfComponents(),
            static_cast<int>(v % array->GetNumberOfComponents()))))
      {
        ADD_FAILURE() << array->GetName() << " is not finite at value " << v;
        return 1;
      }
    }
  }
  vtkDataArray* points = out->GetPoints()->GetData();
  for (vtkIdType v = 0; v < 3 * points->GetNumberOfTuples(); ++v)
  {
    if (!std::isfinite(points->GetComponent(v / 3, static_cast<int>(v % 3))))
    {
      ADD_FAILURE() << "point " << v / 3 << " is not finite";
      return 1;
    }
  }
  vtkDataArray* normals = pd->GetNormals();
  auto tangents = TangentFrame(out);
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    double n[3], t[4];
    normals->GetTuple(id, n);
    tangents->GetTuple(id, t);
    const double nn = std::sqrt(vtkMath::Dot(n, n));
    const double tt = std::sqrt(vtkMath::Dot(t, t));
    const double nt = vtkMath::Dot(n, t);
    if (std::abs(nn - 1) > unitTolerance || std::abs(tt - 1) > unitTolerance ||
      std::abs(nt) > unitTolerance || std::abs(t[3]) != 1.0)
    {
      if (bad == 0)
      {
        ADD_FAILURE() << "point " << id << ": |n| = " << nn << ", |t| = " << tt << ", n.t = " << nt
                      << ", w = " << t[3];
      }
      ++bad;
    }
  }
  return bad;
}

// Runs the source; either it succeeds with finite unit frames, or it reports an error and
// the output is empty. Returns true on success.
bool RunChecked(vtkParametricFunction* f, int U, int V, const std::string& what)
{
  SCOPED_TRACE(what);
  auto source = MakeSource(f, U, V);
  vtkNew<ParametricErrorObserver> observer;
  observer->Observe(source);
  source->Update();
  vtkPolyData* out = source->GetOutput();
  if (observer->ErrorCount > 0)
  {
    EXPECT_EQ(out->GetNumberOfPoints(), 0);
    EXPECT_EQ(out->GetNumberOfCells(), 0);
    EXPECT_FALSE(observer->Errors.empty());
    return false;
  }
  EXPECT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(U + 1) * (V + 1));
  EXPECT_EQ(out->GetNumberOfCells(), 2 * static_cast<vtkIdType>(U) * V);
  EXPECT_EQ(CountBadFrames(out), 0);
  return true;
}

// A grid point is identified by its texture coordinates, which are distinct for every
// (i, j) with the default texture transform.
using Key = std::pair<float, float>;
Key PointKey(vtkPolyData* pd, vtkIdType id)
{
  double tc[2];
  pd->GetPointData()->GetTCoords()->GetTuple(id, tc);
  return { static_cast<float>(tc[0]), static_cast<float>(tc[1]) };
}

// A triangle as serial point indices, rotated so that the smallest comes first (the
// winding is kept, so a flipped triangle does not match).
std::array<vtkIdType, 3> Canonical(vtkIdType a, vtkIdType b, vtkIdType c)
{
  if (b < a && b < c)
  {
    return { b, c, a };
  }
  if (c < a && c < b)
  {
    return { c, a, b };
  }
  return { a, b, c };
}

bool SameArrays(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetDataType() != b->GetDataType() ||
    a->GetNumberOfValues() != b->GetNumberOfValues())
  {
    return false;
  }
  return std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0),
           static_cast<size_t>(a->GetNumberOfValues()) * a->GetDataTypeSize()) == 0;
}
} // namespace

TEST(ParametricSurfaceSource, PiecesTogetherAreTheSerialSurface)
{
  vtkNew<vtkParametricTorus> torus;
  const int U = 13, V = 11;
  auto serialSource = MakeSource(torus, U, V);
  serialSource->Update();
  vtkPolyData* serial = serialSource->GetOutput();
  std::map<Key, vtkIdType> index;
  for (vtkIdType id = 0; id < serial->GetNumberOfPoints(); ++id)
  {
    index[PointKey(serial, id)] = id;
  }
  ASSERT_EQ(static_cast<vtkIdType>(index.size()), serial->GetNumberOfPoints());
  std::multiset<std::array<vtkIdType, 3>> serialCells;
  vtkIdType npts;
  const vtkIdType* pts;
  for (vtkIdType c = 0; c < serial->GetNumberOfCells(); ++c)
  {
    serial->GetPolys()->GetCellAtId(c, npts, pts);
    serialCells.insert(Canonical(pts[0], pts[1], pts[2]));
  }

  for (int numPieces : { 1, 2, 3, 4, 7, V, V + 5 })
  {
    SCOPED_TRACE("pieces: " + std::to_string(numPieces));
    std::multiset<std::array<vtkIdType, 3>> union_;
    int nonEmpty = 0;
    for (int piece = 0; piece < numPieces; ++piece)
    {
      auto source = MakeSource(torus, U, V);
      source->UpdatePiece(piece, numPieces, 0);
      vtkPolyData* out = source->GetOutput();
      nonEmpty += out->GetNumberOfCells() > 0;
      std::vector<vtkIdType> toSerial(out->GetNumberOfPoints());
      for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
      {
        auto it = index.find(PointKey(out, id));
        ASSERT_NE(it, index.end());
        toSerial[id] = it->second;
        // Every array of a piece's point is bit-identical to the serial one.
        for (const char* name :
          { "Normals", "TCoords", "Tangents", "TangentHandedness", "dPdu", "dPdv" })
        {
          vtkDataArray* a = out->GetPointData()->GetArray(name);
          vtkDataArray* b = serial->GetPointData()->GetArray(name);
          for (int k = 0; k < a->GetNumberOfComponents(); ++k)
          {
            ASSERT_EQ(a->GetComponent(id, k), b->GetComponent(it->second, k)) << name;
          }
        }
        for (int k = 0; k < 3; ++k)
        {
          ASSERT_EQ(out->GetPoints()->GetData()->GetComponent(id, k),
            serial->GetPoints()->GetData()->GetComponent(it->second, k));
        }
      }
      for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
      {
        out->GetPolys()->GetCellAtId(c, npts, pts);
        union_.insert(Canonical(toSerial[pts[0]], toSerial[pts[1]], toSerial[pts[2]]));
      }
    }
    EXPECT_EQ(union_, serialCells); // no cell missing, none twice, same winding
    EXPECT_EQ(nonEmpty, std::min(numPieces, V));
  }
}

// Ghost levels: each piece gets g more rows of cells on each side, marked DUPLICATECELL, whose
// points are the serial surface's own (across the v seam of a joined function, the far end's
// points, at t = 1 next to the first piece's t = 0); every serial point is owned (not marked
// DUPLICATEPOINT) by exactly one piece, and the pieces' own cells are the serial cells once.
TEST(ParametricSurfaceSource, GhostLevelsAddMarkedNeighbourRows)
{
  vtkNew<vtkParametricDonut> donut; // joined in v
  vtkNew<vtkParametricSphere> sphere;
  const int U = 8, V = 12, numPieces = 3;
  for (vtkParametricFunction* f :
    { static_cast<vtkParametricFunction*>(donut), static_cast<vtkParametricFunction*>(sphere) })
  {
    auto serialSource = MakeSource(f, U, V);
    serialSource->Update();
    vtkPolyData* serial = serialSource->GetOutput();
    std::map<Key, vtkIdType> index;
    for (vtkIdType id = 0; id < serial->GetNumberOfPoints(); ++id)
    {
      index[PointKey(serial, id)] = id;
    }
    std::multiset<std::array<vtkIdType, 3>> serialCells;
    vtkIdType npts;
    const vtkIdType* pts;
    for (vtkIdType c = 0; c < serial->GetNumberOfCells(); ++c)
    {
      serial->GetPolys()->GetCellAtId(c, npts, pts);
      serialCells.insert(Canonical(pts[0], pts[1], pts[2]));
    }
    for (int ghostLevels : { 1, 2 })
    {
      SCOPED_TRACE(
        std::string(f->GetClassName()) + ", ghost levels " + std::to_string(ghostLevels));
      std::vector<int> owners(serial->GetNumberOfPoints(), 0);
      std::multiset<std::array<vtkIdType, 3>> ownCells;
      for (int piece = 0; piece < numPieces; ++piece)
      {
        auto source = MakeSource(f, U, V);
        source->UpdatePiece(piece, numPieces, ghostLevels);
        vtkPolyData* out = source->GetOutput();
        vtkUnsignedCharArray* pointGhosts = out->GetPointGhostArray();
        vtkUnsignedCharArray* cellGhosts = out->GetCellGhostArray();
        ASSERT_NE(pointGhosts, nullptr);
        ASSERT_NE(cellGhosts, nullptr);
        std::vector<vtkIdType> toSerial(out->GetNumberOfPoints());
        bool farEnd = false;
        for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
        {
          auto it = index.find(PointKey(out, id));
          ASSERT_NE(it, index.end());
          toSerial[id] = it->second;
          for (int k = 0; k < 3; ++k)
          {
            ASSERT_EQ(out->GetPoints()->GetData()->GetComponent(id, k),
              serial->GetPoints()->GetData()->GetComponent(it->second, k));
          }
          const bool ghost = pointGhosts->GetValue(id) & vtkDataSetAttributes::DUPLICATEPOINT;
          owners[it->second] += ghost ? 0 : 1;
          farEnd = farEnd || (piece == 0 && it->first.second == 1.0f);
        }
        // The joined donut's first piece reaches across its v seam to the far end's points.
        EXPECT_EQ(farEnd, f == donut.Get() && piece == 0);
        vtkIdType ghostCells = 0;
        for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
        {
          out->GetPolys()->GetCellAtId(c, npts, pts);
          const auto cell = Canonical(toSerial[pts[0]], toSerial[pts[1]], toSerial[pts[2]]);
          ASSERT_EQ(serialCells.count(cell), 1u);
          if (cellGhosts->GetValue(c) & vtkDataSetAttributes::DUPLICATECELL)
          {
            ++ghostCells;
          }
          else
          {
            ownCells.insert(cell);
          }
        }
        // g rows of 2U triangles on each side; the sphere's first and last pieces end at a pole.
        const bool end = piece == 0 || piece == numPieces - 1;
        const int sides = f == donut.Get() || !end ? 2 : 1;
        EXPECT_EQ(ghostCells, sides * ghostLevels * 2 * U);
      }
      EXPECT_EQ(std::count(owners.begin(), owners.end(), 1), serial->GetNumberOfPoints());
      EXPECT_EQ(ownCells, serialCells);
    }
  }
  // Without ghost levels nothing is marked (a piece is as vtkSphereSource makes one).
  auto source = MakeSource(donut, U, V);
  source->UpdatePiece(1, numPieces, 0);
  EXPECT_EQ(source->GetOutput()->GetPointGhostArray(), nullptr);
  EXPECT_EQ(source->GetOutput()->GetCellGhostArray(), nullptr);
}

TEST(ParametricSurfaceSource, ThreadCountDoesNotChangeTheResult)
{
  vtkNew<vtkParametricRevolution> vase;
  vase->GetProfile()->ArcLengthParameterizationOn();
  std::vector<vtkSmartPointer<vtkPolyData>> results;
  for (int threads : { 1, 2 })
  {
    vtkSMPTools::Initialize(threads);
    EXPECT_EQ(vtkSMPTools::GetEstimatedNumberOfThreads(), threads);
    auto source = MakeSource(vase, 300, 200); // many more points than one grain of work
    source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    source->Update();
    results.emplace_back(source->GetOutput());
  }
  vtkSMPTools::Initialize(0);
  vtkPolyData* a = results[0];
  vtkPolyData* b = results[1];
  EXPECT_TRUE(SameArrays(a->GetPoints()->GetData(), b->GetPoints()->GetData()));
  for (const char* name : { "Normals", "TCoords", "Tangents", "TangentHandedness", "dPdu", "dPdv" })
  {
    EXPECT_TRUE(SameArrays(a->GetPointData()->GetArray(name), b->GetPointData()->GetArray(name)))
      << name;
  }
  EXPECT_TRUE(
    SameArrays(a->GetPolys()->GetConnectivityArray(), b->GetPolys()->GetConnectivityArray()));
  EXPECT_TRUE(SameArrays(a->GetPolys()->GetOffsetsArray(), b->GetPolys()->GetOffsetsArray()));
}

TEST(ParametricSurfaceSource, BadInputIsAClearError)
{
  vtkNew<ParametricErrorObserver> observer;
  auto expectError = [&observer](vtkParametricSurfaceSource* source, const char* phrase)
  {
    observer->Clear();
    source->Modified();
    source->Update();
    EXPECT_EQ(observer->ErrorCount, 1) << phrase;
    EXPECT_NE(observer->Errors.find(phrase), std::string::npos) << observer->Errors;
    EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_EQ(source->GetOutput()->GetPointData()->GetNumberOfArrays(), 0);
  };

  vtkNew<vtkParametricSphere> sphere;
  vtkNew<vtkParametricSurfaceSource> source;
  observer->Observe(source);
  expectError(source, "SetParametricFunction");

  source->SetParametricFunction(sphere);
  // Resolutions below 1 are clamped when set, as VTK's sources clamp theirs.
  source->SetUResolution(0);
  source->SetVResolution(-3);
  EXPECT_EQ(source->GetUResolution(), 1);
  EXPECT_EQ(source->GetVResolution(), 1);
  // Point and triangle counts beyond what the output's arrays can index (their bytes
  // would overflow 64 bits): an error naming the products, before any memory is asked for.
  source->SetUResolution(VTK_INT_MAX);
  source->SetVResolution(VTK_INT_MAX);
  expectError(source, "= 4611686018427387904 points"); // 2^31 x 2^31
  expectError(source, "= 9223372028264841218 triangles");
  source->SetUResolution(VTK_INT_MAX - 1);
  source->SetVResolution((1 << 29) - 1);
  expectError(source, "= 1152921504069976064 points"); // (2^31 - 1) x 2^29: 24 bytes each
  source->SetUResolution(8);
  source->SetVResolution(4);

  source->GenerateTangentsOn();
  source->SetTextureRepeat(0, 1);
  expectError(source, "non-zero repeat");
  source->SetTextureRepeat(1, 1);

  // A non-finite texture transform would put NaN into the texture coordinates (and the
  // tangents): an error whenever either is asked for, not only with tangents.
  for (bool tangents : { true, false })
  {
    source->SetGenerateTangents(tangents);
    source->SetTextureOffset(vtkMath::Nan(), 0);
    expectError(source, "TextureOffset");
    source->SetTextureOffset(0, vtkMath::Inf());
    expectError(source, "TextureOffset");
    source->SetTextureOffset(0, 0);
    source->SetTextureRepeat(vtkMath::Nan(), 1);
    expectError(source, "TextureRepeat");
    source->SetTextureRepeat(1, -vtkMath::Inf());
    expectError(source, "TextureRepeat");
    source->SetTextureRepeat(1, 1);
  }
  source->SetTextureRepeat(1e39, 1); // finite, but not as a float texture coordinate
  expectError(source, "float range");
  source->SetTextureRepeat(1, 1);
  // Neither texture coordinates nor tangents: the transform is not used, so not an error.
  source->GenerateTextureCoordinatesOff();
  source->SetTextureOffset(vtkMath::Nan(), 0);
  observer->Clear();
  source->Update();
  EXPECT_EQ(observer->ErrorCount, 0);
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 9 * 5);
  source->SetTextureOffset(0, 0);
  source->GenerateTextureCoordinatesOn();
  source->GenerateTangentsOn();

  vtkNew<vtkParametricSpline> curve; // a curve, not a surface
  source->SetParametricFunction(curve);
  expectError(source, "dimension");

  vtkNew<vtkParametricTorus> torus;
  torus->SetMaximumU(torus->GetMinimumU());
  source->SetParametricFunction(torus);
  expectError(source, "domain");

  sphere->SetRadius(vtkMath::Nan());
  source->SetParametricFunction(sphere);
  expectError(source, "non-finite");
  sphere->SetRadius(1e308); // finite points, overflowing derivatives
  expectError(source, "non-finite");

  vtkNew<vtkParametricRevolution> vase;
  vase->GetProfile()->AddControlPoint(3, 3); // 11 points: not 3k+1
  source->SetParametricFunction(vase);
  expectError(source, "3k+1");
  vase->SetProfile(nullptr);
  expectError(source, "no profile");

  vtkNew<vtkParametricExtrusion> pillar;
  pillar->GetProfile()->SetControlPoint(2, vtkMath::Inf(), 0);
  source->SetParametricFunction(pillar);
  expectError(source, "non-finite control point");

  // After an error, good input works again.
  observer->Clear();
  sphere->SetRadius(2);
  source->SetParametricFunction(sphere);
  source->Update();
  EXPECT_EQ(observer->ErrorCount, 0);
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 9 * 5);
}

TEST(ParametricSurfaceSource, StressOurSurfaces)
{
  const std::array<std::array<int, 2>, 6> resolutions = { { { 1, 1 }, { 2, 2 }, { 3, 3 }, { 1, 3 },
    { 2048, 3 }, { 3, 2048 } } };
  const double scales[] = { 1e-12, 1e-6, 1, 1e6, 1e12 };
  for (const auto& r : resolutions)
  {
    const std::string res = std::to_string(r[0]) + "x" + std::to_string(r[1]);
    for (double s : scales)
    {
      const std::string at = res + " scale " + std::to_string(s);
      vtkNew<vtkParametricSphere> sphere;
      sphere->SetRadius(s);
      EXPECT_TRUE(RunChecked(sphere, r[0], r[1], "sphere " + at));

      vtkNew<vtkParametricCylinder> cylinder;
      cylinder->SetRadius(s);
      cylinder->SetHeight(3 * s);
      EXPECT_TRUE(RunChecked(cylinder, r[0], r[1], "cylinder " + at));

      vtkNew<vtkParametricDonut> donut;
      donut->SetRingRadius(s);
      donut->SetCrossSectionRadius(s); // horn torus: touches the axis at v = 1/2
      EXPECT_TRUE(RunChecked(donut, r[0], r[1], "horn donut " + at));

      vtkNew<vtkParametricRectangle> rect;
      rect->SetOrigin(-s, 0, 0);
      rect->SetPoint1(s, 0, s);
      rect->SetPoint2(-s, s, 0);
      EXPECT_TRUE(RunChecked(rect, r[0], r[1], "rectangle " + at));

      vtkNew<vtkParametricRevolution> vase;
      vtkNew<vtkParametricExtrusion> pillar;
      for (vtkBezierProfile* profile : { vase->GetProfile(), pillar->GetProfile() })
      {
        for (int i = 0; i < profile->GetNumberOfControlPoints(); ++i)
        {
          double p[2];
          profile->GetControlPoint(i, p);
          profile->SetControlPoint(i, s * p[0], s * p[1]);
        }
      }
      pillar->SetHeight(2 * s);
      EXPECT_TRUE(RunChecked(vase, r[0], r[1], "vase " + at));
      EXPECT_TRUE(RunChecked(pillar, r[0], r[1], "pillar " + at));
    }
  }
}

TEST(ParametricSurfaceSource, StressFullResolution2048)
{
  // 2049 x 2049 = 4.2M points with every array, poles and the arc-length profile included.
  vtkNew<vtkParametricSphere> sphere;
  EXPECT_TRUE(RunChecked(sphere, 2048, 2048, "sphere 2048x2048"));
  vtkNew<vtkParametricRevolution> vase;
  vase->GetProfile()->ArcLengthParameterizationOn();
  EXPECT_TRUE(RunChecked(vase, 2048, 2048, "arc-length vase 2048x2048"));
}

TEST(ParametricSurfaceSource, StressDegenerateShapes)
{
  // Zero sizes: no area at all. The frames are arbitrary but finite and unit, with a warning.
  vtkNew<vtkParametricSphere> point;
  point->SetRadius(0);
  vtkNew<vtkParametricCylinder> line;
  line->SetRadius(0);
  vtkNew<vtkParametricCylinder> ring;
  ring->SetHeight(0);
  vtkNew<vtkParametricDonut> circle;
  circle->SetCrossSectionRadius(0);
  vtkNew<vtkParametricDonut> tube; // spindle torus: R < r, self-intersecting, crosses axis
  tube->SetRingRadius(0.2);
  tube->SetCrossSectionRadius(1);
  vtkNew<vtkParametricRectangle> flat;
  flat->SetPoint2(flat->GetPoint1());
  for (vtkParametricFunction* f :
    std::initializer_list<vtkParametricFunction*>{ point, line, ring, circle, tube, flat })
  {
    for (int res : { 1, 2, 3, 17 })
    {
      auto source = MakeSource(f, res, res);
      vtkNew<ParametricErrorObserver> observer;
      observer->Observe(source);
      source->Update();
      SCOPED_TRACE(std::string(f->GetClassName()) + " " + std::to_string(res));
      EXPECT_EQ(observer->ErrorCount, 0);
      EXPECT_EQ(CountBadFrames(source->GetOutput()), 0);
      if (f == point.Get())
      {
        EXPECT_NE(observer->Warnings.find("no area"), std::string::npos);
      }
    }
  }

  // Profiles: coincident control points (the curve stops), a profile on the axis, a profile
  // crossing the axis, a fully collapsed profile; arc length on and off.
  const std::vector<std::vector<std::array<double, 2>>> profiles = {
    { { 0, 0 }, { 0, 0 }, { 1, 1 }, { 1, 2 } },   // stops at the start, on the axis
    { { 1, 0 }, { 2, 1 }, { 1, 2 }, { 1, 2 } },   // stops at the end
    { { 1, 0 }, { 1, 0 }, { 1, 0 }, { 0.5, 1 } }, // three coincident at the start
    { { 0, 0 }, { 0, 1 }, { 0, 2 }, { 0, 3 } },   // lies on the axis
    { { -1, 0 }, { 1, 1 }, { -1, 2 }, { 1, 3 } }, // crosses the axis twice
    { { 1, 1 }, { 1, 1 }, { 1, 1 }, { 1, 1 } },   // a single point
    { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 1, 1 }, { 1, 1 }, { 0, 1 }, { 0, 2 } }, // stop at join
  };
  for (size_t k = 0; k < profiles.size(); ++k)
  {
    for (bool arc : { false, true })
    {
      vtkNew<vtkParametricRevolution> revolution;
      vtkNew<vtkParametricExtrusion> extrusion;
      for (vtkBezierProfile* profile : { revolution->GetProfile(), extrusion->GetProfile() })
      {
        profile->RemoveAllControlPoints();
        for (const auto& p : profiles[k])
        {
          profile->AddControlPoint(p[0], p[1]);
        }
        profile->SetArcLengthParameterization(arc);
      }
      for (int res : { 1, 2, 3, 40 })
      {
        for (vtkParametricFunction* f :
          std::initializer_list<vtkParametricFunction*>{ revolution, extrusion })
        {
          auto source = MakeSource(f, res, res);
          vtkNew<ParametricErrorObserver> observer;
          observer->Observe(source);
          source->Update();
          SCOPED_TRACE(std::string(f->GetClassName()) + " profile " + std::to_string(k) +
            (arc ? " arc length" : "") + " res " + std::to_string(res));
          EXPECT_EQ(observer->ErrorCount, 0);
          EXPECT_EQ(CountBadFrames(source->GetOutput()), 0);
        }
      }
    }
  }
}

// The smallest n.(P - C)/|P - C| over the output, C(P) the centre the normal must face away
// from; @a maxAngle, if given, receives the largest angle between n and P - C.
template <typename Centre>
double MinOutwardness(vtkPolyData* out, Centre&& centre, double* maxAngle = nullptr)
{
  double smallest = vtkMath::Inf();
  double largestAngle = 0.0;
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    double p[3], n[3], c[3];
    out->GetPoint(id, p);
    out->GetPointData()->GetNormals()->GetTuple(id, n);
    centre(p, c);
    double d[3] = { p[0] - c[0], p[1] - c[1], p[2] - c[2] };
    vtkMath::Normalize(d);
    smallest = std::min(smallest, vtkMath::Dot(n, d));
    double side[3];
    vtkMath::Cross(n, d, side);
    largestAngle = std::max(largestAngle, std::atan2(vtkMath::Norm(side), vtkMath::Dot(n, d)));
  }
  if (maxAngle)
  {
    *maxAngle = largestAngle;
  }
  return smallest;
}

TEST(ParametricSurfaceSource, StressVTKFunctions)
{
  std::vector<vtkSmartPointer<vtkParametricFunction>> functions = {
    vtkSmartPointer<vtkParametricBohemianDome>::New(), vtkSmartPointer<vtkParametricBoy>::New(),
    vtkSmartPointer<vtkParametricCrossCap>::New(), vtkSmartPointer<vtkParametricDini>::New(),
    vtkSmartPointer<vtkParametricEllipsoid>::New(), vtkSmartPointer<vtkParametricEnneper>::New(),
    vtkSmartPointer<vtkParametricFigure8Klein>::New(), vtkSmartPointer<vtkParametricKlein>::New(),
    vtkSmartPointer<vtkParametricMobius>::New(), vtkSmartPointer<vtkParametricPseudosphere>::New(),
    vtkSmartPointer<vtkParametricRoman>::New(), vtkSmartPointer<vtkParametricSuperEllipsoid>::New(),
    vtkSmartPointer<vtkParametricSuperToroid>::New(), vtkSmartPointer<vtkParametricTorus>::New()
  };
  for (auto& f : functions)
  {
    for (int res : { 1, 2, 3, 64 })
    {
      EXPECT_TRUE(
        RunChecked(f, res, res, std::string(f->GetClassName()) + " " + std::to_string(res)));
    }
  }
}

TEST(ParametricSurfaceSource, VTKClosedSurfacesFaceOutward)
{
  auto run = [](vtkParametricFunction* f)
  {
    auto source = MakeSource(f, 48, 40);
    source->Update();
    return vtkSmartPointer<vtkPolyData>(source->GetOutput());
  };
  auto origin = [](const double*, double c[3]) { c[0] = c[1] = c[2] = 0.0; };
  // Tori about z: the normal faces away from the nearest point of the ring circle.
  auto ring = [](double radius)
  {
    return [radius](const double p[3], double c[3])
    {
      const double rho = std::hypot(p[0], p[1]);
      c[0] = radius * p[0] / rho;
      c[1] = radius * p[1] / rho;
      c[2] = 0.0;
    };
  };

  vtkNew<vtkParametricEllipsoid> ellipsoid;
  ellipsoid->SetXRadius(1);
  ellipsoid->SetYRadius(2);
  ellipsoid->SetZRadius(0.5);
  // A convex body around the origin: n.P > 0 everywhere, poles included.
  EXPECT_GT(MinOutwardness(run(ellipsoid), origin), 0.0);

  vtkNew<vtkParametricTorus> torus;
  EXPECT_GT(MinOutwardness(run(torus), ring(torus->GetRingRadius())), 1 - 1e-6);

  // The measure tells them apart: with ClockwiseOrdering on, VTK's torus faces inward.
  vtkNew<vtkParametricTorus> inward;
  inward->ClockwiseOrderingOn();
  EXPECT_LT(-MinOutwardness(run(inward),
              [&](const double p[3], double c[3])
              {
                // C mirrored through P turns n.(P - C) round: the largest n.(P - C), below
                // -1 + 1e-6, says every normal faces inward.
                ring(inward->GetRingRadius())(p, c);
                for (int k = 0; k < 3; ++k)
                {
                  c[k] = 2 * p[k] - c[k];
                }
              }),
    -1 + 1e-6);

  vtkNew<vtkParametricSuperToroid> superToroid; // N1 = N2 = 1: an ordinary torus
  superToroid->SetN1(1);
  superToroid->SetN2(1);
  EXPECT_GT(MinOutwardness(run(superToroid), ring(superToroid->GetRingRadius())), 1 - 1e-6);

  // SuperEllipsoid with N1 = N2 = 1 is the unit sphere and has no analytic derivatives (the
  // source differentiates its points): its normal must be the radial direction, poles too.
  vtkNew<vtkParametricSuperEllipsoid> superEllipsoid;
  superEllipsoid->SetN1(1);
  superEllipsoid->SetN2(1);
  double angle = 0.0;
  EXPECT_GT(MinOutwardness(run(superEllipsoid), origin, &angle), 1 - 1e-6);
  EXPECT_LT(angle, 1e-6); // the bound for double away from poles, met at poles too

  // Our closed surfaces, with the same measure.
  vtkNew<vtkParametricSphere> sphere;
  EXPECT_GT(MinOutwardness(run(sphere), origin, &angle), 1 - 1e-6);
  EXPECT_LT(angle, 1e-6);
  vtkNew<vtkParametricDonut> donut;
  EXPECT_GT(MinOutwardness(run(donut), ring(donut->GetRingRadius())), 1 - 1e-6);
}

namespace
{
// A user subclass that changes the shape through EvaluateTerms() alone (the customisation
// point of vtkParametricSeparableFunction): the surface stretched 3 times along y.
template <typename Base>
class StretchedY : public Base
{
public:
  static StretchedY* New()
  {
    auto* object = new StretchedY;
    object->InitializeObjectBase();
    return object;
  }
  void EvaluateTerms(
    const double* uTerms, const double* vTerms, double Pt[3], double Duvw[9]) override
  {
    this->Base::EvaluateTerms(uTerms, vTerms, Pt, Duvw);
    Pt[1] *= 3.0;
    Duvw[1] *= 3.0;
    Duvw[4] *= 3.0;
  }
  // The parent's closed-form second derivatives describe the unstretched shape.
  bool EvaluateSecondDerivatives(const double*, const double*, double*) override { return false; }
};

template <typename Base>
void ExpectSubclassShapeIsHonoured()
{
  vtkNew<Base> plain;
  vtkNew<StretchedY<Base>> stretched;
  // 70 x 9 cells: many grains of the source's threaded point loop.
  auto plainSource = MakeSource(plain, 70, 9);
  auto stretchedSource = MakeSource(stretched, 70, 9);
  for (auto* source : { plainSource.Get(), stretchedSource.Get() })
  {
    source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    source->Update();
  }
  vtkDataArray* a = plainSource->GetOutput()->GetPoints()->GetData();
  vtkDataArray* b = stretchedSource->GetOutput()->GetPoints()->GetData();
  vtkDataArray* da = plainSource->GetOutput()->GetPointData()->GetArray("dPdv");
  vtkDataArray* db = stretchedSource->GetOutput()->GetPointData()->GetArray("dPdv");
  ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
  int bad = 0;
  for (vtkIdType id = 0; id < a->GetNumberOfTuples(); ++id)
  {
    // Multiplying by 3 is exact up to rounding the same way in both: compare the bits.
    bad += b->GetComponent(id, 0) != a->GetComponent(id, 0) ||
      b->GetComponent(id, 1) != 3.0 * a->GetComponent(id, 1) ||
      b->GetComponent(id, 2) != a->GetComponent(id, 2) ||
      db->GetComponent(id, 1) != 3.0 * da->GetComponent(id, 1);
  }
  EXPECT_EQ(bad, 0) << plain->GetClassName();
  // And Evaluate() gives the same point as the source at a grid point.
  double uvw[3] = { 3.0 / 70.0, 4.0 / 9.0, 0.0 }, P[3], D[9];
  stretched->Evaluate(uvw, P, D);
  const vtkIdType id = 4 * 71 + 3;
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(b->GetComponent(id, c), P[c], 1e-12);
  }
}
} // namespace

TEST(ParametricSurfaceSource, SubclassOverridingEvaluateTermsIsHonoured)
{
  ExpectSubclassShapeIsHonoured<vtkParametricSphere>();
  ExpectSubclassShapeIsHonoured<vtkParametricDonut>();
  ExpectSubclassShapeIsHonoured<vtkParametricRevolution>();
}

namespace
{
vtkSmartPointer<vtkParametricSurfaceSource> BigFloatDonut(vtkParametricDonut* donut)
{
  // 1000 x 701 points and 1.4M triangles: many grains of every thread.
  auto source = MakeSource(donut, 999, 700);
  source->GenerateDerivativesOff();
  return source;
}

// The bytes of `count` tuples of `part` equal those of `whole` from tuple `first`.
bool SameTuples(vtkDataArray* part, vtkDataArray* whole, vtkIdType first)
{
  if (!part || !whole || part->GetDataType() != whole->GetDataType() ||
    part->GetNumberOfComponents() != whole->GetNumberOfComponents() ||
    first + part->GetNumberOfTuples() > whole->GetNumberOfTuples())
  {
    return false;
  }
  const std::size_t tupleBytes =
    static_cast<std::size_t>(part->GetNumberOfComponents()) * part->GetDataTypeSize();
  return std::memcmp(part->GetVoidPointer(0),
           static_cast<const char*>(whole->GetVoidPointer(0)) + first * tupleBytes,
           static_cast<std::size_t>(part->GetNumberOfTuples()) * tupleBytes) == 0;
}
} // namespace

TEST(ParametricSurfaceSource, BigFloatOutputIsTheClosedFormAtAnySplit)
{
  vtkNew<vtkParametricDonut> donut;
  const double R = 1.2, r = 0.4;
  donut->SetRingRadius(R);
  donut->SetCrossSectionRadius(r);
  const int U = 999, V = 700;
  const vtkIdType rowLength = U + 1;

  std::vector<vtkSmartPointer<vtkPolyData>> wholes;
  for (int threads : { 1, 2 })
  {
    vtkSMPTools::Initialize(threads);
    auto source = BigFloatDonut(donut);
    source->Update();
    wholes.emplace_back(source->GetOutput());
  }
  vtkSMPTools::Initialize(0);
  vtkPolyData* whole = wholes[0];
  ASSERT_EQ(whole->GetNumberOfPoints(), rowLength * (V + 1));
  ASSERT_NE(vtkFloatArray::SafeDownCast(whole->GetPoints()->GetData()), nullptr);
  const char* names[] = { "Normals", "TCoords", "Tangents", "TangentHandedness" };

  // One thread or two: the same bytes.
  EXPECT_TRUE(SameArrays(whole->GetPoints()->GetData(), wholes[1]->GetPoints()->GetData()));
  for (const char* name : names)
  {
    EXPECT_TRUE(
      SameArrays(whole->GetPointData()->GetArray(name), wholes[1]->GetPointData()->GetArray(name)))
      << name;
  }
  vtkCellArray* cells = whole->GetPolys();
  EXPECT_TRUE(
    SameArrays(cells->GetConnectivityArray(), wholes[1]->GetPolys()->GetConnectivityArray()));
  EXPECT_TRUE(SameArrays(cells->GetOffsetsArray(), wholes[1]->GetPolys()->GetOffsetsArray()));

  // Positions, normals and texture coordinates against the donut's closed form, in double:
  // only the rounding to float separates them.
  auto* points = vtkFloatArray::SafeDownCast(whole->GetPoints()->GetData());
  auto* normals = vtkFloatArray::SafeDownCast(whole->GetPointData()->GetArray("Normals"));
  auto* tcoords = vtkFloatArray::SafeDownCast(whole->GetPointData()->GetArray("TCoords"));
  ASSERT_NE(normals, nullptr);
  ASSERT_NE(tcoords, nullptr);
  const double twoPi = 2.0 * vtkMath::Pi();
  const double pointTolerance = 4 * FLT_EPSILON * (R + r);
  const double unitTolerance = 4 * FLT_EPSILON;
  double worstPoint = 0, worstNormal = 0, worstTCoord = 0;
  for (int j = 0; j <= V; ++j)
  {
    const double v = static_cast<double>(j) / V;
    for (int i = 0; i <= U; ++i)
    {
      const double u = static_cast<double>(i) / U;
      const vtkIdType id = i + j * rowLength;
      const double ring = R + r * std::cos(twoPi * v);
      const double exact[3] = { ring * std::cos(twoPi * u), ring * std::sin(twoPi * u),
        r * std::sin(twoPi * v) };
      const double outward[3] = { std::cos(twoPi * v) * std::cos(twoPi * u),
        std::cos(twoPi * v) * std::sin(twoPi * u), std::sin(twoPi * v) };
      for (int c = 0; c < 3; ++c)
      {
        worstPoint = std::max(worstPoint, std::abs(points->GetValue(3 * id + c) - exact[c]));
        worstNormal = std::max(worstNormal, std::abs(normals->GetValue(3 * id + c) - outward[c]));
      }
      worstTCoord = std::max(worstTCoord, std::abs(tcoords->GetValue(2 * id) - u));
      worstTCoord = std::max(worstTCoord, std::abs(tcoords->GetValue(2 * id + 1) - v));
    }
  }
  EXPECT_LE(worstPoint, pointTolerance);
  EXPECT_LE(worstNormal, unitTolerance);
  EXPECT_LE(worstTCoord, unitTolerance);

  // Pieces: each is the whole's rows cellRow0..cellRow1 of points, byte for byte, and its
  // triangles are the whole's of those rows, shifted to the piece's first point. Pieces of
  // a third are still above the streaming threshold; pieces of an eighth (4 MB of point
  // arrays, 3 MB of connectivity) are written with ordinary stores.
  for (int numPieces : { 3, 8 })
  {
    for (int piece = 0; piece < numPieces; ++piece)
    {
      SCOPED_TRACE(std::to_string(numPieces) + " pieces, piece " + std::to_string(piece));
      auto source = BigFloatDonut(donut);
      source->UpdatePiece(piece, numPieces, 0);
      vtkPolyData* out = source->GetOutput();
      const vtkIdType row0 = piece * V / numPieces, row1 = (piece + 1) * V / numPieces;
      const vtkIdType first = row0 * rowLength;
      ASSERT_EQ(out->GetNumberOfPoints(), (row1 - row0 + 1) * rowLength);
      EXPECT_TRUE(SameTuples(out->GetPoints()->GetData(), whole->GetPoints()->GetData(), first));
      for (const char* name : names)
      {
        EXPECT_TRUE(SameTuples(
          out->GetPointData()->GetArray(name), whole->GetPointData()->GetArray(name), first))
          << name;
      }
      vtkDataArray* connectivity = out->GetPolys()->GetConnectivityArray();
      vtkDataArray* wholeConnectivity = cells->GetConnectivityArray();
      const vtkIdType firstValue = 6 * U * row0;
      ASSERT_EQ(connectivity->GetNumberOfValues(), 6 * U * (row1 - row0));
      int badIds = 0;
      for (vtkIdType k = 0; k < connectivity->GetNumberOfValues(); ++k)
      {
        badIds += connectivity->GetComponent(k, 0) + first !=
          wholeConnectivity->GetComponent(firstValue + k, 0);
      }
      EXPECT_EQ(badIds, 0);
    }
  }
}
