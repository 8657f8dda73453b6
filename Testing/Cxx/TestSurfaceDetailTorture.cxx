// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Randomised torture of every source and filter over extreme parameters and hostile input.
// Each case must end in one of two ways: a clear error (an ErrorEvent) and an empty output,
// or an output that is sound: finite points, unit normals, orthonormal tangent frames with
// w = +-1, and the inputs untouched. The cases are drawn from a seeded generator; the seed is
// printed with every failure, and SURFACEDETAIL_TORTURE_SEED=<n> replays one run.

#include "TangentFrameTestHelpers.h"
#include <vtkBezierProfile.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDisplacementMapFilter.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkImageData.h>
#include <vtkMikkTSpaceTangents.h>
#include <vtkNew.h>
#include <vtkParametricCylinder.h>
#include <vtkParametricDonut.h>
#include <vtkParametricExtrusion.h>
#include <vtkParametricRectangle.h>
#include <vtkParametricRevolution.h>
#include <vtkParametricSphere.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
std::uint64_t Seed()
{
  const char* text = std::getenv("SURFACEDETAIL_TORTURE_SEED");
  return text ? std::strtoull(text, nullptr, 10) : 20261128u;
}

// Counts the ErrorEvents of one algorithm, and keeps them and its executive's report of the
// failure off the console.
struct ErrorCount
{
  int Errors = 0;
  vtkNew<vtkCallbackCommand> Callback;
  explicit ErrorCount(vtkAlgorithm* algorithm)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long, void* self, void*)
      { ++static_cast<ErrorCount*>(self)->Errors; });
    algorithm->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    vtkNew<vtkCallbackCommand> quiet;
    algorithm->AddObserver(vtkCommand::WarningEvent, quiet);
    algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, quiet);
  }
};

// A magnitude spread over 1e-12 .. 1e12, either sign when asked.
double Extreme(std::mt19937_64& random, bool signedValue = false)
{
  std::uniform_real_distribution<double> exponent(-12.0, 12.0);
  double value = std::pow(10.0, exponent(random));
  if (signedValue && (random() & 1))
  {
    value = -value;
  }
  return value;
}

// A raw, byte-for-byte snapshot of a data array, to show that an input was not touched.
std::vector<unsigned char> Bytes(vtkDataArray* array)
{
  if (!array)
  {
    return {};
  }
  const auto* p = static_cast<const unsigned char*>(array->GetVoidPointer(0));
  return std::vector<unsigned char>(p, p + array->GetNumberOfValues() * array->GetDataTypeSize());
}

// The soundness of a surface with point normals and (optionally) tangent frames.
// Returns a description of the first defect, or an empty string.
std::string Defect(vtkPolyData* out)
{
  vtkPoints* points = out->GetPoints();
  if (!points)
  {
    return out->GetNumberOfCells() ? "cells without points" : "";
  }
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  auto tangents = TangentFrame(out);
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    double p[3];
    points->GetPoint(id, p);
    if (!std::isfinite(p[0] + p[1] + p[2]))
    {
      return "point " + std::to_string(id) + " is not finite";
    }
    double n[3] = { 0, 0, 1 };
    if (normals)
    {
      normals->GetTuple(id, n);
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (!(std::abs(length - 1.0) < 1e-5))
      {
        return "normal " + std::to_string(id) + " has length " + std::to_string(length);
      }
    }
    if (tangents && tangents->GetNumberOfComponents() == 4)
    {
      double t[4];
      tangents->GetTuple(id, t);
      const double length = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
      const double along = t[0] * n[0] + t[1] * n[1] + t[2] * n[2];
      if (!(std::abs(length - 1.0) < 1e-5) || !(std::abs(along) < 1e-4) ||
        !(t[3] == 1.0 || t[3] == -1.0))
      {
        return "tangent " + std::to_string(id) + " is not a unit vector orthogonal to the " +
          "normal with w = +-1";
      }
    }
  }
  for (int a = 0; a < out->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = out->GetPointData()->GetArray(a);
    for (vtkIdType v = 0; array && v < array->GetNumberOfValues(); ++v)
    {
      if (!std::isfinite(array->GetVariantValue(v).ToDouble()))
      {
        return std::string("array ") + (array->GetName() ? array->GetName() : "?") +
          " holds a non-finite value";
      }
    }
  }
  return "";
}

// Either an error and an empty output, or a sound one.
void ExpectErrorOrSound(int errors, vtkPolyData* out, const std::string& what)
{
  if (errors > 0)
  {
    EXPECT_EQ(out->GetNumberOfPoints(), 0) << what << ": an error, but the output is not empty";
    EXPECT_EQ(out->GetNumberOfCells(), 0) << what << ": an error, but the output has cells";
    return;
  }
  const std::string defect = Defect(out);
  EXPECT_TRUE(defect.empty()) << what << ": " << defect;
}

vtkSmartPointer<vtkParametricFunction> RandomFunction(std::mt19937_64& random, std::string& name)
{
  switch (random() % 6)
  {
    case 0:
    {
      auto f = vtkSmartPointer<vtkParametricSphere>::New();
      f->SetRadius(Extreme(random, true));
      name = "sphere";
      return f;
    }
    case 1:
    {
      auto f = vtkSmartPointer<vtkParametricCylinder>::New();
      f->SetRadius(Extreme(random, true));
      f->SetHeight(Extreme(random, true));
      name = "cylinder";
      return f;
    }
    case 2:
    {
      auto f = vtkSmartPointer<vtkParametricDonut>::New();
      f->SetRingRadius(Extreme(random, true));
      f->SetCrossSectionRadius(Extreme(random, true));
      name = "donut";
      return f;
    }
    case 3:
    {
      auto f = vtkSmartPointer<vtkParametricRectangle>::New();
      f->SetPoint1(Extreme(random, true), Extreme(random, true), 0);
      f->SetPoint2(0, Extreme(random, true), Extreme(random, true));
      name = "rectangle";
      return f;
    }
    default:
    {
      // A profile with repeated control points, cusps and extreme coordinates.
      vtkNew<vtkBezierProfile> profile;
      const int segments = 1 + static_cast<int>(random() % 3);
      double previous[2] = { Extreme(random), Extreme(random, true) };
      for (int k = 0; k <= 3 * segments; ++k)
      {
        if (random() % 3 == 0)
        {
          profile->AddControlPoint(previous[0], previous[1]); // repeated: a cusp
          continue;
        }
        previous[0] = Extreme(random);
        previous[1] = Extreme(random, true);
        profile->AddControlPoint(previous[0], previous[1]);
      }
      profile->SetArcLengthParameterization(random() & 1);
      if (random() & 1)
      {
        auto f = vtkSmartPointer<vtkParametricRevolution>::New();
        f->SetProfile(profile);
        name = "revolution";
        return f;
      }
      auto f = vtkSmartPointer<vtkParametricExtrusion>::New();
      f->SetProfile(profile);
      f->SetHeight(Extreme(random, true));
      name = "extrusion";
      return f;
    }
  }
}
} // namespace

TEST(SurfaceDetailTorture, ParametricSurfaceSource)
{
  const std::uint64_t seed = Seed();
  SCOPED_TRACE("SURFACEDETAIL_TORTURE_SEED=" + std::to_string(seed));
  std::mt19937_64 random(seed);
  for (int trial = 0; trial < 150; ++trial)
  {
    std::string name;
    vtkSmartPointer<vtkParametricFunction> function = RandomFunction(random, name);
    vtkNew<vtkParametricSurfaceSource> source;
    ErrorCount errors(source);
    function->AddObserver(vtkCommand::ErrorEvent, vtkNew<vtkCallbackCommand>().Get());
    source->SetParametricFunction(function);
    // Resolutions from 1 to 4096 along one side, small along the other, so a trial stays fast.
    const int big = 1 << (random() % 13);
    const int small = 1 + static_cast<int>(random() % 4);
    source->SetUResolution(random() & 1 ? big : small);
    source->SetVResolution(source->GetUResolution() == big ? small : big);
    source->SetGenerateTangents(random() & 1);
    source->SetGenerateDerivatives(random() & 1);
    source->SetTextureRepeat(Extreme(random, true), Extreme(random, true));
    source->SetOutputPointsPrecision(
      random() & 1 ? vtkAlgorithm::DOUBLE_PRECISION : vtkAlgorithm::SINGLE_PRECISION);
    source->Update();
    ExpectErrorOrSound(
      errors.Errors, source->GetOutput(), "trial " + std::to_string(trial) + " (" + name + ")");
  }
}

TEST(SurfaceDetailTorture, HeightMapToNormalMap)
{
  const std::uint64_t seed = Seed() + 1;
  SCOPED_TRACE("SURFACEDETAIL_TORTURE_SEED base " + std::to_string(Seed()));
  std::mt19937_64 random(seed);
  const double specials[] = { std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
    std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), 0.0 };
  for (int trial = 0; trial < 150; ++trial)
  {
    const int w = 1 + static_cast<int>(random() % 33), h = 1 + static_cast<int>(random() % 33);
    vtkNew<vtkImageData> image;
    image->SetDimensions(w, h, 1);
    image->AllocateScalars(VTK_FLOAT, 1);
    auto* values = static_cast<float*>(image->GetScalarPointer());
    const int kind = static_cast<int>(random() % 4); // random, constant, specials, huge slopes
    for (int k = 0; k < w * h; ++k)
    {
      double v = kind == 1 ? 0.5 : Extreme(random, true);
      if (kind == 2 && random() % 4 == 0)
      {
        v = specials[random() % 6];
      }
      if (kind == 3)
      {
        v = (k % 2 ? 1 : -1) * std::numeric_limits<float>::max();
      }
      values[k] = static_cast<float>(v);
    }
    const std::vector<unsigned char> before = Bytes(image->GetPointData()->GetScalars());
    vtkNew<vtkHeightMapToNormalMap> filter;
    ErrorCount errors(filter);
    filter->SetInputData(image);
    filter->SetDifferenceScheme(static_cast<int>(random() % 4));
    filter->SetWrap(static_cast<int>(random() % 3));
    filter->SetBumpScale(Extreme(random, true));
    filter->SetOutputScalarType(random() % 3 == 0 ? VTK_FLOAT : VTK_UNSIGNED_CHAR);
    filter->SetOutputRelief(random() & 1);
    filter->Update();
    vtkImageData* out = filter->GetOutput();
    const std::string what = "trial " + std::to_string(trial);
    EXPECT_EQ(Bytes(image->GetPointData()->GetScalars()), before) << what << ": input changed";
    if (errors.Errors > 0)
    {
      EXPECT_EQ(out->GetNumberOfPoints(), 0) << what;
      continue;
    }
    vtkDataArray* normals = out->GetPointData()->GetScalars();
    ASSERT_NE(normals, nullptr) << what;
    for (vtkIdType t = 0; t < normals->GetNumberOfTuples(); ++t)
    {
      double n[4];
      normals->GetTuple(t, n);
      if (normals->GetDataType() == VTK_FLOAT)
      {
        // Float maps hold the same 0.5 n + 0.5 coding as the integer ones, unquantised.
        const double x = 2 * n[0] - 1, y = 2 * n[1] - 1, z = 2 * n[2] - 1;
        const double length = std::sqrt(x * x + y * y + z * z);
        EXPECT_NEAR(length, 1.0, 1e-5) << what << ", texel " << t;
      }
      for (int c = 0; c < normals->GetNumberOfComponents(); ++c)
      {
        ASSERT_TRUE(std::isfinite(n[c])) << what << ", texel " << t;
      }
    }
  }
}

namespace
{
// A small random triangle soup over a few points: ids out of range, repeated ids, coincident
// points, NaN and huge coordinates, texture coordinates that are constant, collinear, NaN.
vtkSmartPointer<vtkPolyData> RandomMesh(std::mt19937_64& random, bool& badIds)
{
  const int numPoints = 1 + static_cast<int>(random() % 12);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> normals, tcoords;
  normals->SetNumberOfComponents(3);
  normals->SetName("Normals");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetName("TCoords");
  const int style = static_cast<int>(random() % 4);
  for (int k = 0; k < numPoints; ++k)
  {
    double p[3] = { Extreme(random, true), Extreme(random, true), Extreme(random, true) };
    if (style == 1)
    {
      p[0] = p[1] = p[2] = 1.0; // all coincident
    }
    if (style == 2 && random() % 5 == 0)
    {
      p[random() % 3] = std::numeric_limits<double>::quiet_NaN();
    }
    points->InsertNextPoint(p);
    double n[3] = { Extreme(random, true), Extreme(random, true), Extreme(random, true) };
    // Unit normals, as VTK's filters make them, or now and then a zero one.
    const double scale =
      random() % 7 == 0 ? 0.0 : 1.0 / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& c : n)
    {
      c *= scale;
    }
    normals->InsertNextTuple(n);
    double t[2] = { std::fmod(Extreme(random, true), 4.0), std::fmod(Extreme(random, true), 4.0) };
    if (style == 3)
    {
      t[1] = t[0]; // collinear texture coordinates
    }
    if (style == 2 && random() % 5 == 0)
    {
      t[0] = std::numeric_limits<double>::infinity();
    }
    tcoords->InsertNextTuple(t);
  }
  vtkNew<vtkCellArray> polys;
  badIds = false;
  const int numCells = 1 + static_cast<int>(random() % 10);
  for (int c = 0; c < numCells; ++c)
  {
    const int size = random() % 6 == 0 ? 4 : 3;
    std::vector<vtkIdType> ids(size);
    for (vtkIdType& id : ids)
    {
      id = static_cast<vtkIdType>(random() % numPoints);
      if (random() % 40 == 0)
      {
        id = random() & 1 ? numPoints + static_cast<vtkIdType>(random() % 5) : -1;
        badIds = true;
      }
    }
    polys->InsertNextCell(size, ids.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->SetTCoords(tcoords);
  return mesh;
}

struct MeshBytes
{
  std::vector<unsigned char> Points, Normals, TCoords, Connectivity;
  explicit MeshBytes(vtkPolyData* mesh)
    : Points(Bytes(mesh->GetPoints()->GetData()))
    , Normals(Bytes(mesh->GetPointData()->GetNormals()))
    , TCoords(Bytes(mesh->GetPointData()->GetTCoords()))
    , Connectivity(Bytes(mesh->GetPolys()->GetConnectivityArray()))
  {
  }
  bool operator==(const MeshBytes& o) const
  {
    return this->Points == o.Points && this->Normals == o.Normals && this->TCoords == o.TCoords &&
      this->Connectivity == o.Connectivity;
  }
};

// Whether every point, normal and texture coordinate of the mesh is finite and every normal
// non-zero: only then is a sound output asked of the filters.
bool FiniteInput(vtkPolyData* mesh)
{
  for (vtkIdType id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    double p[3], n[3], t[2];
    mesh->GetPoint(id, p);
    mesh->GetPointData()->GetNormals()->GetTuple(id, n);
    mesh->GetPointData()->GetTCoords()->GetTuple(id, t);
    if (!std::isfinite(p[0] + p[1] + p[2] + n[0] + n[1] + n[2] + t[0] + t[1]) ||
      n[0] * n[0] + n[1] * n[1] + n[2] * n[2] == 0.0)
    {
      return false;
    }
  }
  return true;
}
} // namespace

TEST(SurfaceDetailTorture, MikkTSpaceTangents)
{
  SCOPED_TRACE("SURFACEDETAIL_TORTURE_SEED base " + std::to_string(Seed()));
  std::mt19937_64 random(Seed() + 2);
  for (int trial = 0; trial < 400; ++trial)
  {
    bool badIds = false;
    vtkSmartPointer<vtkPolyData> mesh = RandomMesh(random, badIds);
    const MeshBytes before(mesh);
    vtkNew<vtkMikkTSpaceTangents> filter;
    ErrorCount errors(filter);
    filter->SetInputData(mesh);
    filter->Update();
    const std::string what = "trial " + std::to_string(trial);
    EXPECT_TRUE(MeshBytes(mesh) == before) << what << ": input changed";
    if (badIds)
    {
      EXPECT_GT(errors.Errors, 0) << what << ": point ids out of range were not an error";
    }
    // Non-finite input may give non-finite output (NaN in, NaN out); it must not crash.
    if (errors.Errors > 0 || FiniteInput(mesh))
    {
      ExpectErrorOrSound(errors.Errors, filter->GetOutput(), what);
    }
  }
}

TEST(SurfaceDetailTorture, DisplacementMapFilter)
{
  SCOPED_TRACE("SURFACEDETAIL_TORTURE_SEED base " + std::to_string(Seed()));
  std::mt19937_64 random(Seed() + 3);
  for (int trial = 0; trial < 400; ++trial)
  {
    bool badIds = false;
    vtkSmartPointer<vtkPolyData> mesh = RandomMesh(random, badIds);
    const MeshBytes before(mesh);
    vtkNew<vtkImageData> heights;
    const int w = 1 + static_cast<int>(random() % 9), h = 1 + static_cast<int>(random() % 9);
    heights->SetDimensions(w, h, 1);
    heights->AllocateScalars(VTK_FLOAT, 1);
    auto* values = static_cast<float*>(heights->GetScalarPointer());
    for (int k = 0; k < w * h; ++k)
    {
      values[k] = random() % 10 == 0 ? std::numeric_limits<float>::quiet_NaN()
                                     : static_cast<float>(Extreme(random, true));
    }
    const std::vector<unsigned char> heightsBefore = Bytes(heights->GetPointData()->GetScalars());
    vtkNew<vtkDisplacementMapFilter> filter;
    ErrorCount errors(filter);
    filter->SetInputData(0, mesh);
    filter->SetInputData(1, heights);
    filter->SetScaleFactor(Extreme(random, true));
    filter->SetMidlevel(Extreme(random, true));
    filter->SetWrap(static_cast<int>(random() % 3));
    filter->SetInterpolation(static_cast<int>(random() % 3));
    filter->SetNormalMode(static_cast<int>(random() % 4));
    filter->Update();
    const std::string what = "trial " + std::to_string(trial);
    EXPECT_TRUE(MeshBytes(mesh) == before) << what << ": input changed";
    EXPECT_EQ(Bytes(heights->GetPointData()->GetScalars()), heightsBefore) << what;
    if (badIds)
    {
      EXPECT_GT(errors.Errors, 0) << what << ": point ids out of range were not an error";
    }
    // Non-finite input may give non-finite output (NaN in, NaN out); it must not crash.
    if (errors.Errors > 0 || FiniteInput(mesh))
    {
      ExpectErrorOrSound(errors.Errors, filter->GetOutput(), what);
    }
  }
}
