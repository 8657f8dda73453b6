// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The procedural brick wall the image tests share: a height field (bricks at height 1,
// mortar joints at 0, a smooth bevel between) and a colour texture of the same layout, 4
// courses of 2 bricks per texture square, every other course offset by half a brick.
#ifndef BrickTextures_h
#define BrickTextures_h

#include <vtkImageData.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <algorithm>
#include <cmath>

namespace BrickTextures
{
struct Layout
{
  int Size = 256;        // texels per side of the texture square
  double Mortar = 0.008; // half width of a joint, texture units
  double Bevel = 0.02;   // width of the rise from joint to brick, texture units
};

// Distance (texture units) from (s,t) to the nearest brick edge, and the brick's index.
inline double EdgeDistance(double s, double t, int& brick)
{
  const double rows = 4.0, perRow = 2.0;
  const double row = std::floor(t * rows);
  const double tr = t * rows - row;
  const double shifted = (s + (static_cast<int>(row) % 2 ? 0.5 / perRow : 0.0)) * perRow;
  const double col = std::floor(shifted);
  const double sc = shifted - col;
  brick = static_cast<int>(row) * 7 + static_cast<int>(col) % static_cast<int>(perRow);
  const double dx = std::min(sc, 1.0 - sc) / perRow;
  const double dy = std::min(tr, 1.0 - tr) / rows;
  return std::min(dx, dy);
}

inline double Height(const Layout& layout, double s, double t)
{
  int brick;
  const double d = EdgeDistance(s, t, brick);
  const double x = std::min(1.0, std::max(0.0, (d - layout.Mortar) / layout.Bevel));
  return x * x * (3 - 2 * x);
}

inline vtkSmartPointer<vtkImageData> MakeImage(const Layout& layout, int type, int comps)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(layout.Size, layout.Size, 1);
  image->AllocateScalars(type, comps);
  return image;
}

// Heights at texel centres (Documentation/Conventions.md: texel i covers [i, i+1)/Size), float.
inline vtkSmartPointer<vtkImageData> Heights(const Layout& layout = Layout())
{
  auto image = MakeImage(layout, VTK_FLOAT, 1);
  auto* h = static_cast<float*>(image->GetScalarPointer());
  const int n = layout.Size;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      h[j * n + i] = static_cast<float>(Height(layout, (i + 0.5) / n, (j + 0.5) / n));
    }
  }
  return image;
}

// Bricks of slightly different reds, light grey mortar, unsigned char RGB.
inline vtkSmartPointer<vtkImageData> Colours(const Layout& layout = Layout())
{
  auto image = MakeImage(layout, VTK_UNSIGNED_CHAR, 3);
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer());
  const int n = layout.Size;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double s = (i + 0.5) / n, t = (j + 0.5) / n;
      int brick;
      EdgeDistance(s, t, brick);
      const double h = Height(layout, s, t);
      const double shade = 0.85 + 0.15 * std::sin(brick * 2.3);
      const double brickRGB[3] = { 0.70 * shade, 0.30 * shade, 0.20 * shade };
      const double mortarRGB[3] = { 0.80, 0.78, 0.72 };
      for (int c = 0; c < 3; ++c)
      {
        const double v = h * brickRGB[c] + (1 - h) * mortarRGB[c];
        rgb[3 * (j * n + i) + c] = static_cast<unsigned char>(255 * v + 0.5);
      }
    }
  }
  return image;
}
} // namespace BrickTextures

#endif
