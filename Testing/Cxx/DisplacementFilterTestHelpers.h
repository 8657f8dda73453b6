// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// What the tests of vtkDisplacementMapFilter share: an independent transcription of OpenGL's
// sampling rules, random images and probes, and small checks of outputs.
#ifndef DisplacementFilterTestHelpers_h
#define DisplacementFilterTestHelpers_h

#include "DisplacementTestSurfaces.h"
#include "RenumberedPointsTestHelpers.h"
#include "TangentFrameTestHelpers.h"

#include "vtkDisplacementMapFilter.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMath.h>
#include <vtkMinimalStandardRandomSequence.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkRTAnalyticSource.h>
#include <vtkSMPTools.h>
#include <vtkSphereSource.h>
#include <vtkTexture.h>
#include <vtkTrivialProducer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnsignedShortArray.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sys/mman.h> // mmap, a guard page after a connectivity array
#include <unistd.h>   // sysconf
#endif

using namespace DisplacementTest;

namespace
{
// Counts error and warning events and keeps the last message.
class Observer : public vtkCommand
{
public:
  static Observer* New() { return new Observer; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)++;
    this->Message += data ? static_cast<const char*>(data) : "";
  }
  int Errors = 0;
  int Warnings = 0;
  std::string Message; // all messages, in order
};

inline vtkSmartPointer<Observer> Watch(vtkAlgorithm* algorithm)
{
  auto obs = vtkSmartPointer<Observer>::New();
  algorithm->AddObserver(vtkCommand::ErrorEvent, obs);
  algorithm->AddObserver(vtkCommand::WarningEvent, obs);
  algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, obs);
  return obs;
}

inline vtkSmartPointer<vtkImageData> RandomImage(int W, int H, int seed)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(seed);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* data = static_cast<float*>(image->GetScalarPointer());
  for (int k = 0; k < W * H; ++k)
  {
    data[k] = static_cast<float>(random->GetNextValue());
  }
  return image;
}

// A flat patch z = 0 with one point per (s,t) sample, normal +z, dPdu = +x, dPdv = +y, so
// that the output z is the sampled height and the output normal the height's gradient.
inline vtkSmartPointer<vtkPolyData> Probes(const std::vector<std::array<double, 2>>& st)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals, tcoords, du, dv;
  normals->SetNumberOfComponents(3);
  tcoords->SetNumberOfComponents(2);
  du->SetName("dPdu");
  du->SetNumberOfComponents(3);
  dv->SetName("dPdv");
  dv->SetNumberOfComponents(3);
  for (const auto& x : st)
  {
    points->InsertNextPoint(x[0], x[1], 0.0);
    normals->InsertNextTuple3(0, 0, 1);
    tcoords->InsertNextTuple2(x[0], x[1]);
    du->InsertNextTuple3(1, 0, 0);
    dv->InsertNextTuple3(0, 1, 0);
  }
  poly->SetPoints(points);
  poly->GetPointData()->SetNormals(normals);
  poly->GetPointData()->SetTCoords(tcoords);
  poly->GetPointData()->AddArray(du);
  poly->GetPointData()->AddArray(dv);
  return poly;
}

// OpenGL 4.5 spec, 8.14.2 and table 8.20, written out again independently of the
// conventions header: the texel a wrap mode reads for integer coordinate i of size n.
inline int GLWrap(int i, int n, int mode)
{
  if (mode == vtkDisplacementMapFilter::Repeat)
  {
    return ((i % n) + n) % n;
  }
  if (mode == vtkDisplacementMapFilter::MirroredRepeat)
  {
    // mirror(a) = a for a >= 0, -(1 + a) otherwise; (n - 1) - mirror((i mod 2n) - n)
    const int a = (((i % (2 * n)) + 2 * n) % (2 * n)) - n;
    const int mirror = a >= 0 ? a : -(1 + a);
    return (n - 1) - mirror;
  }
  return i < 0 ? 0 : (i >= n ? n - 1 : i);
}

// ClampToBorder's border value (a texture's border colour), in heights.
constexpr double BorderValue = 0.37;

// The value OpenGL reads at integer texel coordinates (i, j): the wrapped texel, or under
// ClampToBorder the border outside the image (8.14.2: the border colour for texels outside).
inline double GLTexel(const float* img, int W, int H, int mode, int i, int j)
{
  if (mode == vtkDisplacementMapFilter::ClampToBorder)
  {
    return i < 0 || i >= W || j < 0 || j >= H ? BorderValue : img[j * W + i];
  }
  return img[GLWrap(j, H, mode) * W + GLWrap(i, W, mode)];
}

inline double GLLinear(const float* img, int W, int H, int mode, double s, double t)
{
  const double u = s * W, v = t * H;
  const int i0 = static_cast<int>(std::floor(u - 0.5)), j0 = static_cast<int>(std::floor(v - 0.5));
  const double a = (u - 0.5) - std::floor(u - 0.5), b = (v - 0.5) - std::floor(v - 0.5);
  auto T = [&](int i, int j) { return GLTexel(img, W, H, mode, i, j); };
  return (1 - a) * (1 - b) * T(i0, j0) + a * (1 - b) * T(i0 + 1, j0) + (1 - a) * b * T(i0, j0 + 1) +
    a * b * T(i0 + 1, j0 + 1);
}

// @a count texture coordinates drawn from @a random in [-2.3, 3.1]^2: outside [0,1] too, where
// the wrap modes differ.
inline std::vector<std::array<double, 2>> RandomCoordinates(
  vtkMinimalStandardRandomSequence* random, int count)
{
  std::vector<std::array<double, 2>> st;
  for (int k = 0; k < count; ++k)
  {
    const double s = random->GetNextRangeValue(-2.3, 3.1);
    const double t = random->GetNextRangeValue(-2.3, 3.1);
    st.push_back({ s, t });
  }
  return st;
}

inline double GLNearest(const float* img, int W, int H, int mode, double s, double t)
{
  const int i = static_cast<int>(std::floor(s * W)), j = static_cast<int>(std::floor(t * H));
  return GLTexel(img, W, H, mode, i, j);
}

inline vtkSmartPointer<vtkPolyData> Displace(vtkPolyData* mesh, vtkImageData* image, int mode,
  double scale = 0.1, double mid = 0.5, int interp = vtkDisplacementMapFilter::Linear,
  int wrap = vtkDisplacementMapFilter::Repeat)
{
  vtkNew<vtkDisplacementMapFilter> f;
  f->SetInputData(0, mesh);
  f->SetInputData(1, image);
  f->SetNormalMode(mode);
  f->SetScaleFactor(scale);
  f->SetMidlevel(mid);
  f->SetInterpolation(interp);
  f->SetWrap(wrap);
  f->SetBorderHeight(BorderValue); // read under ClampToBorder only
  f->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(f->GetOutput());
  return out;
}

// Points, normals and (where there are) tangents all finite.
inline bool AllFinite(vtkPolyData* out)
{
  auto tangents = TangentFrame(out);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3], n[3], t[4] = { 0.0, 0.0, 0.0, 0.0 };
    out->GetPoint(i, p);
    out->GetPointData()->GetNormals()->GetTuple(i, n);
    if (tangents)
    {
      tangents->GetTuple(i, t);
    }
    for (int k = 0; k < 3; ++k)
    {
      if (!std::isfinite(p[k]) || !std::isfinite(n[k]) || !std::isfinite(t[k]))
      {
        return false;
      }
    }
    if (!std::isfinite(t[3]))
    {
      return false;
    }
  }
  return true;
}

inline bool SameBits(vtkDataArray* a, vtkDataArray* b)
{
  if (a->GetDataType() != b->GetDataType() || a->GetNumberOfValues() != b->GetNumberOfValues())
  {
    return false;
  }
  return std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0),
           a->GetNumberOfValues() * a->GetDataTypeSize()) == 0;
}

const int AllModes[4] = { vtkDisplacementMapFilter::Input, vtkDisplacementMapFilter::Approximate,
  vtkDisplacementMapFilter::Exact, vtkDisplacementMapFilter::Mesh };

// Adds spherical texture coordinates to vtkSphereSource's output, piece by piece.
class SphereTCoords : public vtkPolyDataAlgorithm
{
public:
  static SphereTCoords* New();
  vtkTypeMacro(SphereTCoords, vtkPolyDataAlgorithm);

protected:
  int RequestData(vtkInformation*, vtkInformationVector** in, vtkInformationVector* out) override
  {
    vtkPolyData* input = vtkPolyData::GetData(in[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(out, 0);
    output->ShallowCopy(input);
    vtkNew<vtkDoubleArray> tc;
    tc->SetNumberOfComponents(2);
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      double p[3];
      input->GetPoint(i, p);
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      tc->InsertNextTuple2(std::atan2(p[1], p[0]) / (2 * Pi) + 0.5, std::acos(p[2] / r) / Pi);
    }
    output->GetPointData()->SetTCoords(tc);
    return 1;
  }
};
vtkStandardNewMacro(SphereTCoords);
// Outputs equal to the bit: points, normals and tangents (when there are any).
inline bool SameOutput(vtkPolyData* a, vtkPolyData* b)
{
  auto ta = TangentFrame(a);
  auto tb = TangentFrame(b);
  return SameBits(a->GetPoints()->GetData(), b->GetPoints()->GetData()) &&
    SameBits(a->GetPointData()->GetNormals(), b->GetPointData()->GetNormals()) &&
    ((!ta && !tb) || (ta && tb && SameBits(ta, tb)));
}

} // namespace

#endif
