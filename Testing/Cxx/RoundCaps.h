// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// A height map of a 4 x 4 grid of round caps (hemispheres squashed to height 1) on a flat floor
// at height 0: the open floor gives relief's cone maps their widest cones.
#ifndef RoundCaps_h
#define RoundCaps_h

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <cmath>

inline vtkSmartPointer<vtkImageData> RoundCaps(int size)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* h = static_cast<float*>(image->GetScalarPointer());
  const double cell = size / 4.0, radius = 0.4 * cell;
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const double x = std::fmod(i + 0.5, cell) - 0.5 * cell;
      const double y = std::fmod(j + 0.5, cell) - 0.5 * cell;
      const double r2 = (x * x + y * y) / (radius * radius);
      h[j * size + i] = static_cast<float>(r2 < 1 ? std::sqrt(1 - r2) : 0.0);
    }
  }
  return image;
}

#endif
