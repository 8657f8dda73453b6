// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkHeightMapToNormalMap against independent truths: analytic normals of z = k*h(s,t)
// (convergence order per scheme), a hand-worked 4x4 example of the seed's Forward formula,
// hand-picked neighbours at every border for every wrap mode, vtkImageGradient as a second
// implementation of central differences, and the failure modes of bad input.

#include "vtkHeightMapToNormalMap.h"
#include "vtkSurfaceDetailConventions.h"

#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkImageGradient.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSMPTools.h>
#include <vtkSOADataArrayTemplate.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnsignedShortArray.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <type_traits>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

// Counts errors and warnings and keeps the last message of each, so that tests can assert
// that a bad input was reported (and how often) without matching stderr.
class MessageCounter : public vtkCommand
{
public:
  static MessageCounter* New() { return new MessageCounter; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const char* text = static_cast<const char*>(data);
    if (event == vtkCommand::ErrorEvent)
    {
      ++this->Errors;
      this->AllErrors += text ? text : "";
    }
    else if (event == vtkCommand::WarningEvent)
    {
      ++this->Warnings;
      this->LastWarning = text ? text : "";
    }
  }
  void Watch(vtkObject* o)
  {
    o->AddObserver(vtkCommand::ErrorEvent, this);
    o->AddObserver(vtkCommand::WarningEvent, this);
  }
  int Errors = 0;
  int Warnings = 0;
  std::string AllErrors, LastWarning;
};

// An image of w x h texels holding f at the texel centres ((i+0.5)/w, (j+0.5)/h).
template <typename ArrayT>
vtkSmartPointer<vtkImageData> Sample(int w, int h, const std::function<double(double, double)>& f)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<ArrayT> a;
  a->SetName("height");
  a->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      a->SetValue(static_cast<vtkIdType>(j) * w + i,
        static_cast<typename ArrayT::ValueType>(
          f(vtkSurfaceDetail::TexelCentre(i, w), vtkSurfaceDetail::TexelCentre(j, h))));
    }
  }
  image->GetPointData()->SetScalars(a);
  return image;
}

// An image from a table given row by row, top row (largest t) first, as it reads on paper.
vtkSmartPointer<vtkImageData> FromRows(int w, int h, const std::vector<double>& topFirst)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      a->SetValue(static_cast<vtkIdType>(j) * w + i,
        static_cast<float>(topFirst[static_cast<size_t>(h - 1 - j) * w + i]));
    }
  }
  image->GetPointData()->SetScalars(a);
  return image;
}

struct Settings
{
  int Scheme = vtkHeightMapToNormalMap::Central;
  double Strength = 1.0;
  int Wrap = vtkHeightMapToNormalMap::Repeat;
  bool GreenUp = true;
  int Type = VTK_FLOAT;
  bool Relief = false;
  int Component = 0;
};

vtkSmartPointer<vtkImageData> MakeMap(vtkImageData* input, const Settings& s)
{
  vtkNew<vtkHeightMapToNormalMap> filter;
  filter->SetInputData(input);
  filter->SetDifferenceScheme(s.Scheme);
  filter->SetBumpScale(s.Strength);
  filter->SetWrap(s.Wrap);
  filter->SetGreenUp(s.GreenUp);
  filter->SetOutputScalarType(s.Type);
  filter->SetOutputRelief(s.Relief);
  filter->SetHeightComponent(s.Component);
  filter->Update();
  vtkSmartPointer<vtkImageData> out = filter->GetOutput();
  return out;
}

// The decoded unit normal at texel (i,j) of a map of any output type.
void NormalAt(vtkImageData* map, int i, int j, double n[3])
{
  vtkDataArray* a = map->GetPointData()->GetScalars();
  const int w = map->GetDimensions()[0];
  const double top = a->GetDataType() == VTK_FLOAT ? 1.0 : a->GetDataTypeMax();
  double rgb[3];
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = a->GetComponent(static_cast<vtkIdType>(j) * w + i, c) / top;
  }
  vtkSurfaceDetail::DecodeNormal(rgb, true, n);
}

// The angle between two unit vectors, accurate for tiny angles too.
double AngleBetween(const double a[3], const double b[3])
{
  double c[3];
  vtkSurfaceDetail::Cross(a, b, c);
  return std::atan2(std::sqrt(vtkSurfaceDetail::Dot(c, c)), vtkSurfaceDetail::Dot(a, b));
}

void AnalyticNormal(double k, double hs, double ht, double n[3])
{
  n[0] = -k * hs;
  n[1] = -k * ht;
  n[2] = 1.0;
  vtkSurfaceDetail::Normalize(n);
}

struct HeightFunction
{
  const char* Name;
  std::function<double(double, double)> H;
  std::function<void(double, double, double&, double&)> Gradient;
  double Strength;
  bool Smooth;
};

std::vector<HeightFunction> AnalyticFunctions()
{
  std::vector<HeightFunction> fs;
  fs.push_back({ "sines",
    [](double s, double t) { return 0.5 + 0.25 * std::sin(2 * Pi * s) * std::cos(4 * Pi * t); },
    [](double s, double t, double& hs, double& ht)
    {
      hs = 0.25 * 2 * Pi * std::cos(2 * Pi * s) * std::cos(4 * Pi * t);
      ht = -0.25 * 4 * Pi * std::sin(2 * Pi * s) * std::sin(4 * Pi * t);
    },
    0.3, true });
  // sigma = 0.1: at the borders the bump is below 4e-6, so Repeat wraps it smoothly enough.
  fs.push_back({ "gaussian",
    [](double s, double t)
    { return std::exp(-((s - 0.5) * (s - 0.5) + (t - 0.5) * (t - 0.5)) / 0.02); },
    [](double s, double t, double& hs, double& ht)
    {
      const double g = std::exp(-((s - 0.5) * (s - 0.5) + (t - 0.5) * (t - 0.5)) / 0.02);
      hs = -g * (s - 0.5) / 0.01;
      ht = -g * (t - 0.5) / 0.01;
    },
    0.15, true });
  // A cone of radius 0.35: kinks at the apex and along the rim, where no scheme converges.
  fs.push_back({ "cone",
    [](double s, double t) { return std::max(0.0, 1.0 - std::hypot(s - 0.5, t - 0.5) / 0.35); },
    [](double s, double t, double& hs, double& ht)
    {
      const double r = std::hypot(s - 0.5, t - 0.5);
      hs = ht = 0.0;
      if (r < 0.35 && r > 0.0)
      {
        hs = -(s - 0.5) / (r * 0.35);
        ht = -(t - 0.5) / (r * 0.35);
      }
    },
    0.3, false });
  return fs;
}

const char* SchemeName(int scheme)
{
  static const char* names[] = { "Forward", "Central", "Sobel", "Scharr" };
  return names[scheme];
}

struct ErrorStats
{
  double Mean = 0.0, Max = 0.0; // degrees
};

ErrorStats MeasureError(const HeightFunction& f, int size, int scheme)
{
  auto image = Sample<vtkDoubleArray>(size, size, f.H);
  Settings s;
  s.Scheme = scheme;
  s.Strength = f.Strength;
  auto map = MakeMap(image, s);
  ErrorStats e;
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const double u = vtkSurfaceDetail::TexelCentre(i, size);
      const double v = vtkSurfaceDetail::TexelCentre(j, size);
      double hs, ht, truth[3], got[3];
      f.Gradient(u, v, hs, ht);
      AnalyticNormal(f.Strength, hs, ht, truth);
      NormalAt(map, i, j, got);
      const double deg = AngleBetween(truth, got) * 180.0 / Pi;
      e.Mean += deg;
      e.Max = std::max(e.Max, deg);
    }
  }
  e.Mean /= static_cast<double>(size) * size;
  return e;
}
} // namespace

// Mean and max angular error against the analytic normal, per scheme and size; the smooth
// functions must converge at the schemes' orders (error ratio per halving of the texel).
TEST(TestHeightMapToNormalMap, ConvergesAtSchemeOrder)
{
  const int sizes[] = { 32, 64, 128, 256 };
  std::ostringstream table;
  table << "| function | scheme | size | mean error (deg) | max error (deg) | mean ratio |\n"
        << "|---|---|---:|---:|---:|---:|\n";
  for (const HeightFunction& f : AnalyticFunctions())
  {
    for (int scheme = 0; scheme < 4; ++scheme)
    {
      ErrorStats previous;
      for (int size : sizes)
      {
        const ErrorStats e = MeasureError(f, size, scheme);
        table << "| " << f.Name << " | " << SchemeName(scheme) << " | " << size << " | "
              << std::setprecision(3) << std::scientific << e.Mean << " | " << e.Max << " | ";
        if (previous.Mean > 0.0)
        {
          const double meanRatio = previous.Mean / e.Mean;
          const double maxRatio = previous.Max / e.Max;
          table << std::fixed << std::setprecision(2) << meanRatio;
          if (f.Smooth && scheme == vtkHeightMapToNormalMap::Forward)
          {
            EXPECT_GT(meanRatio, 1.8) << f.Name << " " << size;
            EXPECT_LT(meanRatio, 2.2) << f.Name << " " << size;
            EXPECT_GT(maxRatio, 1.8) << f.Name << " " << size;
            EXPECT_LT(maxRatio, 2.2) << f.Name << " " << size;
          }
          else if (f.Smooth)
          {
            EXPECT_GT(meanRatio, 3.5) << f.Name << " " << SchemeName(scheme) << " " << size;
            EXPECT_LT(meanRatio, 4.5) << f.Name << " " << SchemeName(scheme) << " " << size;
            EXPECT_GT(maxRatio, 3.5) << f.Name << " " << SchemeName(scheme) << " " << size;
          }
          else
          {
            // The kinks: the texels whose stencil straddles one keep an O(1) error, and
            // they are a fraction O(1/size) of the image, so the mean falls at first order
            // at best and the maximum does not fall.
            EXPECT_GT(meanRatio, 1.5) << f.Name << " " << SchemeName(scheme) << " " << size;
            EXPECT_LT(maxRatio, 1.5) << f.Name << " " << SchemeName(scheme) << " " << size;
          }
        }
        table << " |\n";
        previous = e;
      }
    }
  }
  std::cout << table.str();
}

// Strength means the normal map of z = k*h over the unit square: a plane h = a*s + b*t
// gives n = normalize(-k*a, -k*b, 1) in the interior for every scheme, whatever the size.
TEST(TestHeightMapToNormalMap, PlaneIsExactAtEverySizeAndScheme)
{
  const double a = 0.3, b = -0.1, k = 2.5;
  double truth[3];
  AnalyticNormal(k, a, b, truth);
  for (int size : { 5, 8, 64, 203 })
  {
    auto image =
      Sample<vtkDoubleArray>(size, size + 3, [&](double s, double t) { return a * s + b * t; });
    for (int scheme = 0; scheme < 4; ++scheme)
    {
      Settings s;
      s.Scheme = scheme;
      s.Strength = k;
      auto map = MakeMap(image, s);
      for (int j = 1; j < size + 1; ++j)
      {
        for (int i = 1; i < size - 1; ++i)
        {
          double got[3];
          NormalAt(map, i, j, got);
          EXPECT_LT(AngleBetween(truth, got), 1e-6)
            << SchemeName(scheme) << " size " << size << " at " << i << "," << j;
        }
      }
    }
  }
}

// The seed's Cg code, ddx = w*(tex2D(d, u + 1/w) - tex2D(d, u)) (and ddy alike), on a 4x4
// float height map with Repeat, worked by hand. Heights (top row t = 3 first):
//
//   t=3:  0.5     0.5     0.5     0.5
//   t=2:  1.0     0.5     0.5     0.5
//   t=1:  0.5     0.5     0.5     0.5
//   t=0:  0.5     0.5     0.3125  0.5          (0.3125 = 0.5 - 3/16)
//
// w = h = 4, k = 1; all differences and products are exact in float.
//   (1,0): ddx = 4*(0.3125 - 0.5) = -0.75, ddy = 4*(0.5 - 0.5) = 0
//   (2,0): ddx = 4*(0.5 - 0.3125) = 0.75,  ddy = 4*(0.5 - 0.3125) = 0.75
//   (2,3): ddy wraps to row 0: 4*(0.3125 - 0.5) = -0.75, ddx = 0
//   (0,1): ddy = 4*(1.0 - 0.5) = 2,        ddx = 0
//   (0,2): ddx = 4*(0.5 - 1.0) = -2,       ddy = 4*(0.5 - 1.0) = -2
//   (3,2): ddx wraps to column 0: 4*(1.0 - 0.5) = 2, ddy = 0
//   every other texel: ddx = ddy = 0.
// n = (-ddx, -ddy, 1) normalised as Cg's normalize does, v * (1/|v|), stored as 0.5*n + 0.5,
// all in float:
//   (1,0): (0.75, 0, 1)/1.25 = (3/5, 0, 4/5)      (2,3): (0, 0.75, 1)/1.25 = (0, 3/5, 4/5)
//   (0,2): (2, 2, 1)/3 = (2/3, 2/3, 1/3)          (0,1): (0, -2, 1)/sqrt(5)
//   (2,0): (-0.75, -0.75, 1)/sqrt(2.125)          (3,2): (-2, 0, 1)/sqrt(5)
TEST(TestHeightMapToNormalMap, ForwardIsTheSeedsFormulaToTheBit)
{
  auto image = FromRows(4, 4,
    { 0.5, 0.5, 0.5, 0.5, //
      1.0, 0.5, 0.5, 0.5, //
      0.5, 0.5, 0.5, 0.5, //
      0.5, 0.5, 0.3125, 0.5 });
  // {i, j, ddx, ddy} from the hand working above; every other texel has ddx = ddy = 0.
  struct Texel
  {
    int I, J;
    float Ddx, Ddy;
  };
  const std::vector<Texel> slopes = { { 1, 0, -0.75f, 0.0f }, { 2, 0, 0.75f, 0.75f },
    { 2, 3, 0.0f, -0.75f }, { 0, 1, 0.0f, 2.0f }, { 0, 2, -2.0f, -2.0f }, { 3, 2, 2.0f, 0.0f } };
  auto normal = [&](int i, int j, float n[3])
  {
    float ddx = 0.0f, ddy = 0.0f;
    for (const Texel& t : slopes)
    {
      if (t.I == i && t.J == j)
      {
        ddx = t.Ddx;
        ddy = t.Ddy;
      }
    }
    const float inv = 1.0f / std::sqrt(ddx * ddx + ddy * ddy + 1.0f);
    n[0] = -ddx * inv;
    n[1] = -ddy * inv;
    n[2] = inv;
  };
  // The worked fractions, to float precision: the table above is what the arithmetic gives.
  float n[3];
  normal(1, 0, n);
  EXPECT_FLOAT_EQ(n[0], 3.0f / 5.0f);
  EXPECT_FLOAT_EQ(n[2], 4.0f / 5.0f);
  normal(0, 2, n);
  EXPECT_FLOAT_EQ(n[1], 2.0f / 3.0f);
  EXPECT_FLOAT_EQ(n[2], 1.0f / 3.0f);
  normal(0, 1, n);
  EXPECT_FLOAT_EQ(n[1], -2.0f / std::sqrt(5.0f));
  Settings s;
  s.Scheme = vtkHeightMapToNormalMap::Forward;
  auto map = MakeMap(image, s);
  auto* out = vtkFloatArray::SafeDownCast(map->GetPointData()->GetScalars());
  ASSERT_NE(out, nullptr);
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      normal(i, j, n);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ(out->GetTypedComponent(j * 4 + i, c), 0.5f * n[c] + 0.5f)
          << "texel " << i << "," << j << " component " << c;
      }
    }
  }
}

// Every wrap mode at every border, against neighbours picked by hand (Central, 5x4).
// Heights (top row t = 3 first), multiples of 1/8 so that the inputs are exact:
//   t=3:  0.125 0.250 0.375 0.500 0.875
//   t=2:  0.750 0.000 0.625 0.250 0.125
//   t=1:  0.500 0.375 1.000 0.000 0.250
//   t=0:  0.000 0.625 0.125 0.875 0.375
TEST(TestHeightMapToNormalMap, WrapModesReadTheRightNeighbours)
{
  const double H[4][5] = { // H[j][i], j = 0 is the bottom row
    { 0.000, 0.625, 0.125, 0.875, 0.375 }, { 0.500, 0.375, 1.000, 0.000, 0.250 },
    { 0.750, 0.000, 0.625, 0.250, 0.125 }, { 0.125, 0.250, 0.375, 0.500, 0.875 }
  };
  auto image = FromRows(5, 4,
    { 0.125, 0.250, 0.375, 0.500, 0.875, 0.750, 0.000, 0.625, 0.250, 0.125, //
      0.500, 0.375, 1.000, 0.000, 0.250, 0.000, 0.625, 0.125, 0.875, 0.375 });
  struct Case
  {
    int Wrap, I, J;
    double Left, Right, Down, Up; // the neighbours the stencil must read
  };
  const std::vector<Case> cases = {
    // Repeat: the far side of the image.
    { vtkHeightMapToNormalMap::Repeat, 0, 1, H[1][4], H[1][1], H[0][0], H[2][0] },
    { vtkHeightMapToNormalMap::Repeat, 4, 2, H[2][3], H[2][0], H[1][4], H[3][4] },
    { vtkHeightMapToNormalMap::Repeat, 2, 0, H[0][1], H[0][3], H[3][2], H[1][2] },
    { vtkHeightMapToNormalMap::Repeat, 2, 3, H[3][1], H[3][3], H[2][2], H[0][2] },
    { vtkHeightMapToNormalMap::Repeat, 0, 0, H[0][4], H[0][1], H[3][0], H[1][0] },
    { vtkHeightMapToNormalMap::Repeat, 4, 3, H[3][3], H[3][0], H[2][4], H[0][4] },
    // ClampToEdge: the border texel itself.
    { vtkHeightMapToNormalMap::ClampToEdge, 0, 1, H[1][0], H[1][1], H[0][0], H[2][0] },
    { vtkHeightMapToNormalMap::ClampToEdge, 4, 2, H[2][3], H[2][4], H[1][4], H[3][4] },
    { vtkHeightMapToNormalMap::ClampToEdge, 2, 0, H[0][1], H[0][3], H[0][2], H[1][2] },
    { vtkHeightMapToNormalMap::ClampToEdge, 2, 3, H[3][1], H[3][3], H[2][2], H[3][2] },
    { vtkHeightMapToNormalMap::ClampToEdge, 0, 0, H[0][0], H[0][1], H[0][0], H[1][0] },
    // MirroredRepeat: texel -1 mirrors to texel 0 and texel W to W-1, the same as
    // ClampToEdge for a one-texel stencil.
    { vtkHeightMapToNormalMap::MirroredRepeat, 0, 1, H[1][0], H[1][1], H[0][0], H[2][0] },
    { vtkHeightMapToNormalMap::MirroredRepeat, 4, 2, H[2][3], H[2][4], H[1][4], H[3][4] },
    { vtkHeightMapToNormalMap::MirroredRepeat, 2, 0, H[0][1], H[0][3], H[0][2], H[1][2] },
    { vtkHeightMapToNormalMap::MirroredRepeat, 4, 3, H[3][3], H[3][4], H[2][4], H[3][4] },
  };
  for (const Case& c : cases)
  {
    Settings s;
    s.Wrap = c.Wrap;
    auto map = MakeMap(image, s);
    double truth[3], got[3];
    AnalyticNormal(1.0, 5.0 * (c.Right - c.Left) / 2.0, 4.0 * (c.Up - c.Down) / 2.0, truth);
    NormalAt(map, c.I, c.J, got);
    EXPECT_LT(AngleBetween(truth, got), 1e-6) << "wrap " << c.Wrap << " at " << c.I << "," << c.J;
  }
  // Forward reads only right and up: at the top-right corner they wrap or clamp.
  Settings s;
  s.Scheme = vtkHeightMapToNormalMap::Forward;
  for (int wrap : { vtkHeightMapToNormalMap::Repeat, vtkHeightMapToNormalMap::ClampToEdge })
  {
    s.Wrap = wrap;
    auto map = MakeMap(image, s);
    const bool repeat = wrap == vtkHeightMapToNormalMap::Repeat;
    double truth[3], got[3];
    AnalyticNormal(1.0, 5.0 * ((repeat ? H[3][0] : H[3][4]) - H[3][4]),
      4.0 * ((repeat ? H[0][4] : H[3][4]) - H[3][4]), truth);
    NormalAt(map, 4, 3, got);
    EXPECT_LT(AngleBetween(truth, got), 1e-6) << "Forward, wrap " << wrap;
  }
}

// vtkImageGradient (central differences, boundary texels duplicated) with spacing 1/W, 1/H
// is a second implementation of Central + ClampToEdge: the normals agree everywhere.
TEST(TestHeightMapToNormalMap, CentralClampAgreesWithVtkImageGradient)
{
  const int w = 37, h = 23;
  const double k = 0.2;
  auto image = Sample<vtkFloatArray>(
    w, h, [](double s, double t) { return 0.5 + 0.3 * std::sin(7 * s + 2 * t) * t; });
  image->SetSpacing(1.0 / w, 1.0 / h, 1.0);
  vtkNew<vtkImageGradient> gradient;
  gradient->SetInputData(image);
  gradient->SetDimensionality(2);
  gradient->HandleBoundariesOn();
  gradient->Update();
  vtkDataArray* g = gradient->GetOutput()->GetPointData()->GetScalars();

  Settings s;
  s.Wrap = vtkHeightMapToNormalMap::ClampToEdge;
  s.Strength = k;
  auto map = MakeMap(image, s);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      double truth[3], got[3];
      const vtkIdType id = j * w + i;
      AnalyticNormal(k, g->GetComponent(id, 0), g->GetComponent(id, 1), truth);
      NormalAt(map, i, j, got);
      EXPECT_LT(AngleBetween(truth, got), 1e-6) << i << "," << j;
    }
  }
}

// uchar and ushort maps decode to within one quantisation step of the exact normal, and
// round to nearest: a flat map is (128, 128, 255), not the truncated (127, 127, 255).
TEST(TestHeightMapToNormalMap, IntegerEncodingsRoundTripWithinOneStep)
{
  const HeightFunction f = AnalyticFunctions()[0];
  auto image = Sample<vtkDoubleArray>(64, 48, f.H);
  Settings s;
  s.Strength = f.Strength;
  s.Type = VTK_FLOAT;
  auto exact = MakeMap(image, s);
  auto* e = vtkFloatArray::SafeDownCast(exact->GetPointData()->GetScalars());
  ASSERT_NE(e, nullptr);
  for (int type : { VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT })
  {
    s.Type = type;
    auto map = MakeMap(image, s);
    vtkDataArray* q = map->GetPointData()->GetScalars();
    ASSERT_EQ(q->GetDataType(), type);
    const double top = type == VTK_UNSIGNED_CHAR ? 255.0 : 65535.0;
    double worst = 0.0;
    for (vtkIdType id = 0; id < q->GetNumberOfTuples(); ++id)
    {
      for (int c = 0; c < 3; ++c)
      {
        // Rounding to nearest: within half a step of the exact colour.
        const double err = std::abs(q->GetComponent(id, c) / top - e->GetTypedComponent(id, c));
        worst = std::max(worst, err);
        EXPECT_LE(err, 0.5 / top + 1e-7) << "type " << type << " texel " << id << " c " << c;
      }
      // Decoded (and renormalised), each component is within one step 2/top of the normal.
      double rgb[3], n[3], exactRgb[3], exactN[3];
      for (int c = 0; c < 3; ++c)
      {
        rgb[c] = q->GetComponent(id, c) / top;
        exactRgb[c] = e->GetTypedComponent(id, c);
      }
      vtkSurfaceDetail::DecodeNormal(rgb, true, n);
      vtkSurfaceDetail::DecodeNormal(exactRgb, true, exactN);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_LE(std::abs(n[c] - exactN[c]), 2.0 / top) << "type " << type << " id " << id;
      }
    }
    // Truncation would show as errors near a whole step.
    EXPECT_GT(worst, 0.4 / top);
  }
  auto flat = Sample<vtkFloatArray>(3, 3, [](double, double) { return 0.25; });
  s.Type = VTK_UNSIGNED_CHAR;
  auto map = MakeMap(flat, s);
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(map->GetPointData()->GetScalars());
  ASSERT_NE(rgb, nullptr);
  EXPECT_EQ(rgb->GetTypedComponent(4, 0), 128);
  EXPECT_EQ(rgb->GetTypedComponent(4, 1), 128);
  EXPECT_EQ(rgb->GetTypedComponent(4, 2), 255);
}

// EncodeNormal/DecodeNormal (shared with the GLSL twin) invert each other, in both green
// conventions, and DecodeNormal never returns a non-unit or NaN vector.
TEST(TestHeightMapToNormalMap, ConventionsEncodeDecodeInvert)
{
  const double n[3] = { 0.48, -0.6, 0.64 };
  for (bool greenUp : { true, false })
  {
    double rgb[3], back[3];
    vtkSurfaceDetail::EncodeNormal(n, greenUp, rgb);
    EXPECT_DOUBLE_EQ(rgb[1], greenUp ? 0.2 : 0.8);
    vtkSurfaceDetail::DecodeNormal(rgb, greenUp, back);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(back[c], n[c], 1e-15);
    }
  }
  const double grey[3] = { 0.5, 0.5, 0.5 };
  double z[3];
  vtkSurfaceDetail::DecodeNormal(grey, true, z);
  EXPECT_EQ(z[2], 1.0);
}

// GreenUp off flips only G; on a raised bump, with GreenUp, the right flank (h_s < 0) is
// red (n_x > 0) and the top flank (h_t < 0) green (n_y > 0), as OpenGL's convention reads.
TEST(TestHeightMapToNormalMap, GreenUpFlipsOnlyGreen)
{
  const HeightFunction bump = AnalyticFunctions()[1];
  auto image = Sample<vtkFloatArray>(41, 41, bump.H); // texel 20 is the bump's top
  Settings s;
  s.Scheme = vtkHeightMapToNormalMap::Sobel;
  auto up = MakeMap(image, s);
  s.GreenUp = false;
  auto down = MakeMap(image, s);
  auto* a = vtkFloatArray::SafeDownCast(up->GetPointData()->GetScalars());
  auto* b = vtkFloatArray::SafeDownCast(down->GetPointData()->GetScalars());
  for (vtkIdType id = 0; id < a->GetNumberOfTuples(); ++id)
  {
    EXPECT_EQ(a->GetTypedComponent(id, 0), b->GetTypedComponent(id, 0));
    EXPECT_NEAR(a->GetTypedComponent(id, 1), 1.0f - b->GetTypedComponent(id, 1), 1e-7);
    EXPECT_EQ(a->GetTypedComponent(id, 2), b->GetTypedComponent(id, 2));
  }
  const int centre = 20 * 41 + 20;
  const int right = 20 * 41 + 26, left = 20 * 41 + 14, top = 26 * 41 + 20, bottom = 14 * 41 + 20;
  EXPECT_GT(a->GetTypedComponent(right, 0), 0.6f);
  EXPECT_LT(a->GetTypedComponent(left, 0), 0.4f);
  EXPECT_GT(a->GetTypedComponent(top, 1), 0.6f);
  EXPECT_LT(a->GetTypedComponent(bottom, 1), 0.4f);
  EXPECT_LT(b->GetTypedComponent(top, 1), 0.4f);
  EXPECT_NEAR(a->GetTypedComponent(right, 1), 0.5f, 0.05f);
  EXPECT_GT(a->GetTypedComponent(centre, 2), 0.9999f);
}

// OutputRelief adds A = depth = 1 - height: integer heights by their type's range, float
// heights as given and clamped to [0,1] with one warning counting the clamped texels.
TEST(TestHeightMapToNormalMap, ReliefAlphaIsDepth)
{
  auto bytes = Sample<vtkUnsignedCharArray>(
    16, 16, [](double s, double t) { return std::floor(255.0 * s * t); });
  Settings s;
  s.Relief = true;
  s.Type = VTK_UNSIGNED_CHAR;
  auto map = MakeMap(bytes, s);
  auto* rgba = vtkUnsignedCharArray::SafeDownCast(map->GetPointData()->GetScalars());
  ASSERT_NE(rgba, nullptr);
  ASSERT_EQ(rgba->GetNumberOfComponents(), 4);
  EXPECT_STREQ(rgba->GetName(), "ReliefMap");
  auto* in = vtkUnsignedCharArray::SafeDownCast(bytes->GetPointData()->GetScalars());
  for (vtkIdType id = 0; id < rgba->GetNumberOfTuples(); ++id)
  {
    EXPECT_EQ(rgba->GetTypedComponent(id, 3), 255 - in->GetValue(id));
  }

  // 16 bits: depth (255 - v)/255 is exactly 257*(255 - v)/65535.
  s.Type = VTK_UNSIGNED_SHORT;
  auto map16 = MakeMap(bytes, s);
  auto* rgba16 = vtkUnsignedShortArray::SafeDownCast(map16->GetPointData()->GetScalars());
  ASSERT_NE(rgba16, nullptr);
  for (vtkIdType id = 0; id < rgba16->GetNumberOfTuples(); ++id)
  {
    EXPECT_EQ(rgba16->GetTypedComponent(id, 3), 257 * (255 - in->GetValue(id)));
    for (int c = 0; c < 3; ++c)
    {
      // The same normal as the 8-bit map, to within the 8-bit map's half step.
      EXPECT_NEAR(rgba16->GetTypedComponent(id, c) / 65535.0,
        rgba->GetTypedComponent(id, c) / 255.0, 0.5 / 255 + 1e-6);
    }
  }

  auto floats = FromRows(3, 1, { 0.25, 1.5, -0.5 });
  vtkNew<vtkHeightMapToNormalMap> filter;
  vtkNew<MessageCounter> messages;
  messages->Watch(filter);
  filter->SetInputData(floats);
  filter->SetOutputScalarTypeToFloat();
  filter->OutputReliefOn();
  filter->Update();
  auto* a = vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetScalars());
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->GetTypedComponent(0, 3), 0.75f);
  EXPECT_EQ(a->GetTypedComponent(1, 3), 0.0f);
  EXPECT_EQ(a->GetTypedComponent(2, 3), 1.0f);
  EXPECT_EQ(messages->Warnings, 1);
  EXPECT_NE(messages->LastWarning.find("2 height(s) lie outside [0,1]"), std::string::npos)
    << messages->LastWarning;
}

// Unsigned integer heights are fractions of their type's range: uchar v and ushort v give
// the normals of the float heights v/255 and v/65535.
TEST(TestHeightMapToNormalMap, UnsignedIntegerHeightsAreFractionsOfTheirRange)
{
  auto f = [](double s, double t) { return std::floor(200.0 * s * s + 50.0 * t); };
  auto asFloat = [&](double scale)
  { return Sample<vtkDoubleArray>(20, 15, [&](double s, double t) { return f(s, t) * scale; }); };
  struct Case
  {
    vtkSmartPointer<vtkImageData> Integer, Reference;
  };
  const std::vector<Case> cases = {
    { Sample<vtkUnsignedCharArray>(20, 15, f), asFloat(1.0 / 255.0) },
    { Sample<vtkUnsignedShortArray>(20, 15, f), asFloat(1.0 / 65535.0) },
  };
  for (const Case& c : cases)
  {
    Settings s;
    s.Relief = true;
    auto a = MakeMap(c.Integer, s);
    auto b = MakeMap(c.Reference, s);
    auto* x = vtkFloatArray::SafeDownCast(a->GetPointData()->GetScalars());
    auto* y = vtkFloatArray::SafeDownCast(b->GetPointData()->GetScalars());
    ASSERT_EQ(x->GetNumberOfValues(), y->GetNumberOfValues());
    for (vtkIdType v = 0; v < x->GetNumberOfValues(); ++v)
    {
      EXPECT_NEAR(x->GetValue(v), y->GetValue(v), 1e-5) << c.Integer->GetScalarTypeAsString();
    }
  }
}

// The height can live in any channel: an RGBA image with the heights in alpha gives, with
// HeightComponent 3, the map that the alpha channel alone gives; a channel the image does
// not have is an error.
TEST(TestHeightMapToNormalMap, HeightComponentChoosesTheChannel)
{
  auto f = [](double s, double t) { return std::floor(200.0 * s * s + 50.0 * t); };
  auto alone = Sample<vtkUnsignedCharArray>(20, 15, f);
  auto rgba = vtkSmartPointer<vtkImageData>::New();
  rgba->SetDimensions(20, 15, 1);
  rgba->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  vtkDataArray* in = alone->GetPointData()->GetScalars();
  vtkDataArray* all = rgba->GetPointData()->GetScalars();
  for (vtkIdType k = 0; k < all->GetNumberOfTuples(); ++k)
  {
    const double noise = (k * 37) % 251;
    all->SetTuple4(k, noise, 255 - noise, noise / 2, in->GetComponent(k, 0));
  }
  Settings s;
  s.Type = VTK_FLOAT;
  auto want = MakeMap(alone, s);
  s.Component = 3;
  auto got = MakeMap(rgba, s);
  vtkDataArray* a = want->GetPointData()->GetScalars();
  vtkDataArray* b = got->GetPointData()->GetScalars();
  ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues());
  EXPECT_EQ(std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0),
              a->GetNumberOfValues() * a->GetDataTypeSize()),
    0);

  vtkNew<vtkHeightMapToNormalMap> filter;
  vtkNew<MessageCounter> messages;
  messages->Watch(filter);
  messages->Watch(filter->GetExecutive());
  filter->SetInputData(alone);
  filter->SetHeightComponent(1);
  filter->Update();
  EXPECT_GE(messages->Errors, 1);
  EXPECT_NE(messages->AllErrors.find("HeightComponent 1"), std::string::npos)
    << messages->AllErrors;
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}

// ClampToBorder reads BorderHeight outside the image, as OpenGL reads a texture's border
// colour: the map of an N x N image equals the inside of the map of that image framed by a
// one-texel ring of the border height (read with ClampToEdge, which never reaches past the
// ring), with the bump scale that keeps the texel spacing, k N / (N + 2). Integer heights
// take the border in normalised units.
TEST(TestHeightMapToNormalMap, ClampToBorderReadsTheBorderHeight)
{
  constexpr int n = 12;
  auto f = [](double s, double t)
  { return std::floor(120.0 + 90.0 * std::sin(7 * s + 4 * t * t)); };
  auto framed = [&](auto array, double ring)
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(n + 2, n + 2, 1);
    array->SetNumberOfTuples((n + 2) * (n + 2));
    for (int j = 0; j < n + 2; ++j)
    {
      for (int i = 0; i < n + 2; ++i)
      {
        const bool inside = i > 0 && i <= n && j > 0 && j <= n;
        array->SetTuple1(j * (n + 2) + i, inside ? f((i - 0.5) / n, (j - 0.5) / n) : ring);
      }
    }
    image->GetPointData()->SetScalars(array);
    return image;
  };
  struct Case
  {
    vtkSmartPointer<vtkImageData> Image, Framed;
    double Border; // in heights, after normalisation
  };
  auto floats = Sample<vtkFloatArray>(n, n, f);
  auto bytes = Sample<vtkUnsignedCharArray>(n, n, f);
  const std::vector<Case> cases = {
    { floats, framed(vtkSmartPointer<vtkFloatArray>::New(), 30.0), 30.0 },
    { bytes, framed(vtkSmartPointer<vtkUnsignedCharArray>::New(), 51.0), 51.0 / 255.0 },
  };
  for (const Case& c : cases)
  {
    for (int scheme = vtkHeightMapToNormalMap::Forward; scheme <= vtkHeightMapToNormalMap::Scharr;
         ++scheme)
    {
      vtkNew<vtkHeightMapToNormalMap> filter;
      filter->SetInputData(c.Image);
      filter->SetDifferenceScheme(scheme);
      filter->SetWrapToClampToBorder();
      filter->SetBorderHeight(c.Border);
      filter->SetBumpScale(0.01);
      filter->SetOutputScalarTypeToFloat();
      filter->Update();
      Settings s;
      s.Scheme = scheme;
      s.Wrap = vtkHeightMapToNormalMap::ClampToEdge;
      s.Strength = 0.01 * n / (n + 2.0);
      auto want = MakeMap(c.Framed, s);
      double worst = 0.0;
      for (int j = 0; j < n; ++j)
      {
        for (int i = 0; i < n; ++i)
        {
          double a[3], b[3];
          NormalAt(filter->GetOutput(), i, j, a);
          NormalAt(want, i + 1, j + 1, b);
          worst = std::max(worst, AngleBetween(a, b));
        }
      }
      EXPECT_LT(worst, 1e-4) << SchemeName(scheme) << " " << c.Image->GetScalarTypeAsString();
      // The border is really read: another border height gives other edge normals.
      filter->SetBorderHeight(c.Border * 2.0);
      filter->Update();
      double a[3], b[3];
      NormalAt(filter->GetOutput(), n - 1, n / 2, a); // every scheme reads the texel after it
      NormalAt(want, n, n / 2 + 1, b);
      EXPECT_GT(AngleBetween(a, b), 1e-3) << SchemeName(scheme);
    }
  }
}

// One rule for every reader of height maps (vtkSurfaceDetail::HeightMapScale): signed and
// wide integers are refused here as vtkDisplacementMapFilter and vtkSurfaceDetailMapper
// refuse them, with the same advice, and the output is empty.
TEST(TestHeightMapToNormalMap, OtherHeightTypesAreRefusedAsByEveryReader)
{
  for (int type : { VTK_SIGNED_CHAR, VTK_SHORT, VTK_INT, VTK_UNSIGNED_INT, VTK_LONG_LONG })
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(4, 4, 1);
    image->AllocateScalars(type, 1);
    image->GetPointData()->GetScalars()->Fill(3);
    vtkNew<vtkHeightMapToNormalMap> filter;
    vtkNew<MessageCounter> messages;
    messages->Watch(filter);
    messages->Watch(filter->GetExecutive());
    filter->SetInputData(image);
    filter->Update();
    EXPECT_GE(messages->Errors, 1) << vtkImageScalarTypeNameMacro(type);
    EXPECT_NE(messages->AllErrors.find(vtkSurfaceDetail::HeightMapTypeAdvice()), std::string::npos)
      << messages->AllErrors;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
    double scale;
    EXPECT_FALSE(vtkSurfaceDetail::HeightMapScale(type, scale));
  }
}

// 1xN, Nx1, 1x1 and odd sizes work; a single column has no slope along s in any wrap mode.
TEST(TestHeightMapToNormalMap, DegenerateAndOddSizes)
{
  const int sizes[][2] = { { 1, 1 }, { 1, 9 }, { 9, 1 }, { 3, 5 }, { 2, 2 } };
  for (const auto& size : sizes)
  {
    auto image = Sample<vtkFloatArray>(
      size[0], size[1], [](double s, double t) { return 0.3 * s + 0.6 * t * t; });
    for (int wrap = 0; wrap < 3; ++wrap)
    {
      for (int scheme = 0; scheme < 4; ++scheme)
      {
        Settings s;
        s.Wrap = wrap;
        s.Scheme = scheme;
        auto map = MakeMap(image, s);
        auto* a = vtkFloatArray::SafeDownCast(map->GetPointData()->GetScalars());
        ASSERT_NE(a, nullptr);
        ASSERT_EQ(a->GetNumberOfTuples(), size[0] * size[1]);
        for (vtkIdType id = 0; id < a->GetNumberOfTuples(); ++id)
        {
          for (int c = 0; c < 3; ++c)
          {
            ASSERT_TRUE(std::isfinite(a->GetTypedComponent(id, c)));
          }
          if (size[0] == 1)
          {
            EXPECT_EQ(a->GetTypedComponent(id, 0), 0.5f);
          }
          if (size[1] == 1)
          {
            EXPECT_EQ(a->GetTypedComponent(id, 1), 0.5f);
          }
        }
      }
    }
  }
  // A column of 9 under ClampToEdge: interior texels see t's slope 1.2*t exactly (Central
  // differences are exact on a quadratic), scaled by H = 9 texels per unit.
  auto column = Sample<vtkDoubleArray>(1, 9, [](double, double t) { return 0.6 * t * t; });
  Settings s;
  s.Wrap = vtkHeightMapToNormalMap::ClampToEdge;
  auto map = MakeMap(column, s);
  for (int j = 1; j < 8; ++j)
  {
    double truth[3], got[3];
    AnalyticNormal(1.0, 0.0, 1.2 * vtkSurfaceDetail::TexelCentre(j, 9), truth);
    NormalAt(map, 0, j, got);
    EXPECT_LT(AngleBetween(truth, got), 1e-6) << j;
  }
}

// One thread or two, the same bytes.
TEST(TestHeightMapToNormalMap, ThreadCountDoesNotChangeTheResult)
{
  auto image = Sample<vtkFloatArray>(
    301, 257, [](double s, double t) { return 0.5 + 0.4 * std::sin(40 * s * t) * s; });
  for (int scheme = 0; scheme < 4; ++scheme)
  {
    for (int type : { VTK_UNSIGNED_CHAR, VTK_FLOAT })
    {
      Settings s;
      s.Scheme = scheme;
      s.Type = type;
      s.Relief = true;
      s.Strength = 3.0;
      vtkSMPTools::Initialize(1);
      auto one = MakeMap(image, s);
      vtkSMPTools::Initialize(2);
      auto two = MakeMap(image, s);
      vtkDataArray* a = one->GetPointData()->GetScalars();
      vtkDataArray* b = two->GetPointData()->GetScalars();
      ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues());
      EXPECT_EQ(std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0),
                  a->GetNumberOfValues() * a->GetDataTypeSize()),
        0)
        << SchemeName(scheme) << " " << type;
    }
  }
  vtkSMPTools::Initialize();
}

// A request for part of the image computes just that part, equal to the same texels of the
// whole (the borders still wrap across the whole image).
TEST(TestHeightMapToNormalMap, SubExtentMatchesWhole)
{
  auto image = Sample<vtkFloatArray>(
    30, 20, [](double s, double t) { return 0.5 + 0.4 * std::sin(9 * s + 5 * t * t); });
  vtkNew<vtkHeightMapToNormalMap> filter;
  filter->SetInputData(image);
  filter->SetDifferenceSchemeToScharr();
  filter->Update();
  vtkImageData* whole = filter->GetOutput();
  // A second filter: the first would not re-execute for an extent it already holds.
  vtkNew<vtkHeightMapToNormalMap> partial;
  partial->SetInputData(image);
  partial->SetDifferenceSchemeToScharr();
  const int part[6] = { 0, 6, 15, 19, 0, 0 };
  partial->UpdateExtent(part);
  vtkImageData* piece = partial->GetOutput();
  int got[6];
  piece->GetExtent(got);
  for (int a = 0; a < 6; ++a)
  {
    EXPECT_EQ(got[a], part[a]);
  }
  for (int j = part[2]; j <= part[3]; ++j)
  {
    for (int i = part[0]; i <= part[1]; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ(piece->GetScalarComponentAsDouble(i, j, 0, c),
          whole->GetScalarComponentAsDouble(i, j, 0, c))
          << i << "," << j;
      }
    }
  }
}

// NaN and infinite heights: one warning with the count, each replaced by the mean of its
// finite neighbours (so the map equals that of the hand-repaired heights), input untouched.
TEST(TestHeightMapToNormalMap, NonFiniteHeightsAreRepairedWithOneWarning)
{
  const double nan = std::nan(""), inf = HUGE_VAL;
  auto image = FromRows(4, 3,
    { 0.1, 0.2, 0.3, 0.4, //
      0.5, nan, 0.7, inf, //
      0.9, 1.0, 0.0, 0.2 });
  // Repeat: each is the mean of 2*h(x+d) - h(x+2d) over the directions d where both are
  // finite (rows and columns wrap; +-x are blocked by the other bad texel). (1,1):
  // up 2*0.2-1.0, down 2*1.0-0.2, up-right 2*0.3-0.2, up-left 2*0.1-0.2, down-right
  // 2*0.0-0.4, down-left 2*0.9-0.4. (3,1): up 2*0.4-0.2, down 2*0.2-0.4, up-right
  // 2*0.1-1.0, up-left 2*0.3-1.0, down-right 2*0.9-0.2, down-left 2*0.0-0.2.
  const double a = (-0.6 + 1.8 + 0.4 + 0.0 - 0.4 + 1.4) / 6;
  const double b = (0.6 + 0.0 - 0.8 - 0.4 + 1.6 - 0.2) / 6;
  auto repaired = FromRows(4, 3,
    { 0.1, 0.2, 0.3, 0.4, //
      0.5, a, 0.7, b,     //
      0.9, 1.0, 0.0, 0.2 });
  vtkNew<vtkHeightMapToNormalMap> filter;
  vtkNew<MessageCounter> messages;
  messages->Watch(filter);
  filter->SetInputData(image);
  filter->SetOutputScalarTypeToFloat();
  filter->Update();
  EXPECT_EQ(messages->Warnings, 1);
  EXPECT_EQ(messages->Errors, 0);
  EXPECT_NE(messages->LastWarning.find("2 height(s) are NaN or infinite"), std::string::npos)
    << messages->LastWarning;
  auto* got = vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetScalars());
  ASSERT_NE(got, nullptr);
  Settings s;
  auto truth = MakeMap(repaired, s);
  auto* want = vtkFloatArray::SafeDownCast(truth->GetPointData()->GetScalars());
  for (vtkIdType v = 0; v < got->GetNumberOfValues(); ++v)
  {
    ASSERT_TRUE(std::isfinite(got->GetValue(v))) << v;
    EXPECT_NEAR(got->GetValue(v), want->GetValue(v), 1e-6) << v;
  }
  EXPECT_TRUE(std::isnan(image->GetScalarComponentAsDouble(1, 1, 0, 0)));

  // Nothing finite at all: a flat map, still no NaN.
  auto hopeless = FromRows(2, 2, { nan, inf, -inf, nan });
  filter->SetInputData(hopeless);
  filter->Update();
  got = vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetScalars());
  for (vtkIdType t = 0; t < 4; ++t)
  {
    EXPECT_EQ(got->GetTypedComponent(t, 0), 0.5f);
    EXPECT_EQ(got->GetTypedComponent(t, 1), 0.5f);
    EXPECT_EQ(got->GetTypedComponent(t, 2), 1.0f);
  }
  EXPECT_EQ(messages->Warnings, 2);

  // Slopes too steep for a float: the map saturates but never holds NaN.
  filter->SetInputData(FromRows(2, 1, { 0.0, 1.0 }));
  filter->SetBumpScale(1e300);
  filter->Update();
  got = vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetScalars());
  for (vtkIdType v = 0; v < got->GetNumberOfValues(); ++v)
  {
    EXPECT_TRUE(std::isfinite(got->GetValue(v)));
  }
}

// Heights at the ends of their type's range: one difference overflows to +inf, another to
// -inf, and a stencil adding them (or Strength 0 times inf) must not make NaN. Strength 0
// is the plain truth to compare with: a flat map.
TEST(TestHeightMapToNormalMap, ExtremeHeightsNeverGiveNaN)
{
  auto check = [](auto* array, double big)
  {
    const int w = 5, h = 4;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(w, h, 1);
    array->SetNumberOfTuples(w * h);
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        // A checkerboard and a stripe mixed, so that the stencil's terms overflow both ways.
        array->SetValue(j * w + i, ((i + j) % 2 == 0) != (i % 3 == 0) ? big : -big);
      }
    }
    image->GetPointData()->SetScalars(array);
    for (double strength : { 1.0, 0.0, -3.0 })
    {
      for (int scheme = vtkHeightMapToNormalMap::Forward; scheme <= vtkHeightMapToNormalMap::Scharr;
           ++scheme)
      {
        for (int wrap = vtkHeightMapToNormalMap::ClampToEdge;
             wrap <= vtkHeightMapToNormalMap::MirroredRepeat; ++wrap)
        {
          Settings s;
          s.Scheme = scheme;
          s.Wrap = wrap;
          s.Strength = strength;
          auto map = MakeMap(image, s);
          auto* got = vtkFloatArray::SafeDownCast(map->GetPointData()->GetScalars());
          ASSERT_NE(got, nullptr);
          for (vtkIdType t = 0; t < got->GetNumberOfTuples(); ++t)
          {
            for (int c = 0; c < 3; ++c)
            {
              const float v = got->GetTypedComponent(t, c);
              ASSERT_TRUE(std::isfinite(v))
                << array->GetDataTypeAsString() << " " << SchemeName(scheme) << " wrap " << wrap
                << " strength " << strength << " texel " << t;
              if (strength == 0.0)
              {
                EXPECT_EQ(v, c == 2 ? 1.0f : 0.5f) << SchemeName(scheme) << " texel " << t;
              }
            }
          }
        }
      }
    }
  };
  vtkNew<vtkFloatArray> f;
  check(f.Get(), std::numeric_limits<float>::max());
  vtkNew<vtkDoubleArray> d;
  check(d.Get(), std::numeric_limits<double>::max());
}

// A hole in a plane is filled with the plane itself (the fill continues the slope), so the
// map equals the hole-free plane's, in the interior and, with ClampToEdge or
// MirroredRepeat, along a border too.
TEST(TestHeightMapToNormalMap, HolesInAPlaneAreFilledWithThePlane)
{
  const int w = 48, h = 40;
  auto plane = [](double s, double t) { return 0.3 + 0.2 * s + 0.1 * t; };
  for (int wrap = vtkHeightMapToNormalMap::ClampToEdge;
       wrap <= vtkHeightMapToNormalMap::MirroredRepeat; ++wrap)
  {
    auto whole = Sample<vtkFloatArray>(w, h, plane);
    auto holed = Sample<vtkFloatArray>(w, h, plane);
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        const bool disc = (i - 20) * (i - 20) + (j - 18) * (j - 18) <= 64;
        const bool strip = i <= 2 && j >= 5 && j <= 30;
        if (disc || (strip && wrap != vtkHeightMapToNormalMap::Repeat))
        {
          holed->SetScalarComponentFromDouble(i, j, 0, 0, std::nan(""));
        }
      }
    }
    Settings s;
    s.Wrap = wrap;
    s.Scheme = vtkHeightMapToNormalMap::Sobel;
    auto want = MakeMap(whole, s);
    auto got = MakeMap(holed, s);
    auto* x = vtkFloatArray::SafeDownCast(got->GetPointData()->GetScalars());
    auto* y = vtkFloatArray::SafeDownCast(want->GetPointData()->GetScalars());
    for (vtkIdType v = 0; v < x->GetNumberOfValues(); ++v)
    {
      EXPECT_NEAR(x->GetValue(v), y->GetValue(v), 1e-5) << "wrap " << wrap << " value " << v;
    }
  }
}

// Under ClampToEdge a corner's neighbours clamp onto one another: each texel counts once.
// 2x2 with (0,0) missing: no direction has two distinct finite texels, so the fill is the
// plain mean of (1,0), (0,1), (1,1).
TEST(TestHeightMapToNormalMap, ClampedNeighboursCountOnce)
{
  Settings s;
  s.Wrap = vtkHeightMapToNormalMap::ClampToEdge;
  auto got = MakeMap(FromRows(2, 2, { 0.2, 0.7, std::nan(""), 0.3 }), s);
  auto want = MakeMap(FromRows(2, 2, { 0.2, 0.7, (0.3 + 0.2 + 0.7) / 3, 0.3 }), s);
  auto* x = vtkFloatArray::SafeDownCast(got->GetPointData()->GetScalars());
  auto* y = vtkFloatArray::SafeDownCast(want->GetPointData()->GetScalars());
  for (vtkIdType v = 0; v < x->GetNumberOfValues(); ++v)
  {
    EXPECT_NEAR(x->GetValue(v), y->GetValue(v), 1e-6) << v;
  }
}

// Stress: one finite texel in 1024^2 fills the whole image with its height (a flat map).
// The fill is linear in the texel count (0.14 s here); the earlier repeated sweep took 7 s
// and grew with the image's width times its texel count.
TEST(TestHeightMapToNormalMap, OneFiniteTexelFillsAMegapixelQuickly)
{
  const int n = 1024;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, 1);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(n * n);
  a->Fill(std::numeric_limits<float>::quiet_NaN());
  a->SetValue(777 * n + 123, 0.25f);
  image->GetPointData()->SetScalars(a);
  vtkNew<vtkHeightMapToNormalMap> filter;
  vtkNew<MessageCounter> messages;
  messages->Watch(filter);
  filter->SetInputData(image);
  filter->SetOutputScalarTypeToFloat();
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  std::cout << "1024^2 with one finite texel: "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s\n";
  EXPECT_EQ(messages->Warnings, 1);
  auto* got = vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetScalars());
  ASSERT_NE(got, nullptr);
  ASSERT_EQ(got->GetNumberOfTuples(), static_cast<vtkIdType>(n) * n);
  for (vtkIdType t = 0; t < got->GetNumberOfTuples(); ++t)
  {
    ASSERT_EQ(got->GetTypedComponent(t, 0), 0.5f) << t;
    ASSERT_EQ(got->GetTypedComponent(t, 1), 0.5f) << t;
    ASSERT_EQ(got->GetTypedComponent(t, 2), 1.0f) << t;
  }
}

// Bad input is reported, the filter fails and its output is empty.
TEST(TestHeightMapToNormalMap, BadInputIsAnError)
{
  struct Case
  {
    const char* What;
    vtkSmartPointer<vtkImageData> Image;
    double Strength;
    const char* Expect;
  };
  auto noScalars = vtkSmartPointer<vtkImageData>::New();
  noScalars->SetDimensions(4, 4, 1);
  auto volume = vtkSmartPointer<vtkImageData>::New();
  volume->SetDimensions(4, 4, 2);
  volume->AllocateScalars(VTK_FLOAT, 1);
  auto empty = vtkSmartPointer<vtkImageData>::New();
  auto good = Sample<vtkFloatArray>(4, 4, [](double s, double) { return s; });
  const std::vector<Case> cases = {
    { "no scalars", noScalars, 1.0, "no point scalars" },
    { "3-D", volume, 1.0, "3-D image" },
    { "empty", empty, 1.0, "empty" },
    { "NaN strength", good, std::nan(""), "BumpScale" },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkHeightMapToNormalMap> filter;
    vtkNew<MessageCounter> messages;
    messages->Watch(filter);
    messages->Watch(filter->GetExecutive());
    filter->SetInputData(c.Image);
    filter->SetBumpScale(c.Strength);
    filter->Update();
    EXPECT_GE(messages->Errors, 1) << c.What;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << c.What;
    EXPECT_EQ(filter->GetOutput()->GetPointData()->GetNumberOfArrays(), 0) << c.What;
    EXPECT_NE(messages->AllErrors.find(c.Expect), std::string::npos)
      << c.What << ": " << messages->AllErrors;
  }
  vtkNew<vtkHeightMapToNormalMap> filter;
  vtkNew<MessageCounter> messages;
  messages->Watch(filter);
  filter->SetOutputScalarType(VTK_DOUBLE);
  EXPECT_EQ(messages->Errors, 1);
  EXPECT_EQ(filter->GetOutputScalarType(), VTK_UNSIGNED_CHAR);
}

TEST(TestHeightMapToNormalMap, SettersAndPrintSelf)
{
  vtkNew<vtkHeightMapToNormalMap> filter;
  EXPECT_EQ(filter->GetDifferenceScheme(), vtkHeightMapToNormalMap::Central);
  EXPECT_EQ(filter->GetWrap(), vtkHeightMapToNormalMap::Repeat);
  EXPECT_TRUE(filter->GetGreenUp());
  EXPECT_FALSE(filter->GetOutputRelief());
  filter->SetDifferenceSchemeToForward();
  EXPECT_EQ(filter->GetDifferenceScheme(), vtkHeightMapToNormalMap::Forward);
  filter->SetDifferenceSchemeToSobel();
  EXPECT_EQ(filter->GetDifferenceScheme(), vtkHeightMapToNormalMap::Sobel);
  filter->SetDifferenceSchemeToScharr();
  EXPECT_STREQ(filter->GetDifferenceSchemeAsString(), "Scharr");
  filter->SetWrapToMirroredRepeat();
  EXPECT_STREQ(filter->GetWrapAsString(), "MirroredRepeat");
  filter->SetWrapToClampToEdge();
  EXPECT_EQ(filter->GetWrap(), vtkHeightMapToNormalMap::ClampToEdge);
  filter->SetOutputScalarTypeToUnsignedShort();
  EXPECT_EQ(filter->GetOutputScalarType(), VTK_UNSIGNED_SHORT);
  filter->GreenUpOff();
  filter->OutputReliefOn();
  filter->SetBumpScale(2.5);
  std::ostringstream os;
  filter->Print(os);
  const std::string text = os.str();
  for (const char* expect : { "DifferenceScheme: Scharr", "BumpScale: 2.5", "Wrap: ClampToEdge",
         "GreenUp: Off", "OutputScalarType: unsigned short", "OutputRelief: On" })
  {
    EXPECT_NE(text.find(expect), std::string::npos) << expect << "\n" << text;
  }
}

// The map lies where the heights lie: origin, spacing and extent come from the input.
TEST(TestHeightMapToNormalMap, OutputKeepsTheInputGeometry)
{
  auto image = Sample<vtkFloatArray>(6, 5, [](double s, double t) { return s * t; });
  image->SetOrigin(1.0, 2.0, 0.0);
  image->SetSpacing(0.5, 0.25, 1.0);
  auto map = MakeMap(image, Settings());
  double origin[3], spacing[3];
  map->GetOrigin(origin);
  map->GetSpacing(spacing);
  int dims[3];
  map->GetDimensions(dims);
  EXPECT_EQ(origin[0], 1.0);
  EXPECT_EQ(origin[1], 2.0);
  EXPECT_EQ(spacing[0], 0.5);
  EXPECT_EQ(spacing[1], 0.25);
  EXPECT_EQ(dims[0], 6);
  EXPECT_EQ(dims[1], 5);
  EXPECT_EQ(dims[2], 1);
  EXPECT_STREQ(map->GetPointData()->GetScalars()->GetName(), "NormalMap");
}

// A second run reuses the map's memory only when nobody else holds the previous map: a map
// kept by the caller is never overwritten by the next execution.
TEST(TestHeightMapToNormalMap, KeptOutputIsNotOverwritten)
{
  auto first = Sample<vtkFloatArray>(8, 8, [](double s, double) { return s; });
  auto second = Sample<vtkFloatArray>(8, 8, [](double, double t) { return t; });
  vtkNew<vtkHeightMapToNormalMap> filter;
  filter->SetInputData(first);
  filter->SetOutputScalarTypeToFloat();
  filter->Update();
  vtkSmartPointer<vtkDataArray> kept = filter->GetOutput()->GetPointData()->GetScalars();
  const double red = kept->GetComponent(9, 0);
  EXPECT_LT(red, 0.5); // h = s rises to the right: the normal leans left
  filter->SetInputData(second);
  filter->Update();
  EXPECT_NE(filter->GetOutput()->GetPointData()->GetScalars(), kept.Get());
  EXPECT_EQ(kept->GetComponent(9, 0), red);
  EXPECT_EQ(filter->GetOutput()->GetPointData()->GetScalars()->GetComponent(9, 0), 0.5);
}

// Only the first component is the height, whatever the array's layout: an interleaved
// two-component array and a struct-of-arrays one give the map of their first component.
TEST(TestHeightMapToNormalMap, OnlyTheFirstComponentIsRead)
{
  auto f = [](double s, double t) { return 0.5 + 0.3 * std::sin(6 * s) * std::cos(5 * t); };
  auto single = Sample<vtkFloatArray>(17, 11, f);
  vtkDataArray* h = single->GetPointData()->GetScalars();

  auto interleaved = vtkSmartPointer<vtkImageData>::New();
  interleaved->SetDimensions(17, 11, 1);
  vtkNew<vtkFloatArray> two;
  two->SetNumberOfComponents(2);
  two->SetNumberOfTuples(h->GetNumberOfTuples());
  auto soa = vtkSmartPointer<vtkImageData>::New();
  soa->SetDimensions(17, 11, 1);
  vtkNew<vtkSOADataArrayTemplate<float>> planar;
  planar->SetNumberOfComponents(2);
  planar->SetNumberOfTuples(h->GetNumberOfTuples());
  for (vtkIdType id = 0; id < h->GetNumberOfTuples(); ++id)
  {
    two->SetTypedComponent(id, 0, static_cast<float>(h->GetComponent(id, 0)));
    two->SetTypedComponent(id, 1, static_cast<float>((id * 7919) % 13));
    planar->SetTypedComponent(id, 0, static_cast<float>(h->GetComponent(id, 0)));
    planar->SetTypedComponent(id, 1, -static_cast<float>(id));
  }
  interleaved->GetPointData()->SetScalars(two);
  soa->GetPointData()->SetScalars(planar);

  Settings s;
  s.Scheme = vtkHeightMapToNormalMap::Scharr;
  s.Relief = true;
  auto want = MakeMap(single, s);
  for (vtkImageData* image : { interleaved.Get(), soa.Get() })
  {
    auto got = MakeMap(image, s);
    vtkDataArray* a = got->GetPointData()->GetScalars();
    vtkDataArray* b = want->GetPointData()->GetScalars();
    ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues());
    for (vtkIdType v = 0; v < a->GetNumberOfValues(); ++v)
    {
      EXPECT_EQ(a->GetVariantValue(v).ToFloat(), b->GetVariantValue(v).ToFloat()) << v;
    }
  }
}
