// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The pipeline of the DistributedSurface example, kept apart so that its test can build the
// same surface serially and compare it with what the ranks wrote.
//
// A donut (a torus, joined in u and v) with a procedural height map of bumps that
// repeat across both seams, displaced with Exact normals from the source's analytic
// derivatives; its tangent frames are re-orthogonalised to the new normals.

#ifndef DistributedSurfacePipeline_h
#define DistributedSurfacePipeline_h

#include <vtkDisplacementMapFilter.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkParametricDonut.h>
#include <vtkParametricSurfaceSource.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <cmath>

namespace DistributedSurface
{
// A W x H float height map in [0,1], periodic in s and t so that Repeat has no seam.
inline vtkSmartPointer<vtkImageData> MakeHeightMap(int w = 256, int h = 128)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> heights;
  heights->SetName("Height");
  heights->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  const double twoPi = 2.0 * 3.14159265358979323846;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const double s = (i + 0.5) / w, t = (j + 0.5) / h;
      const double bumps = std::sin(twoPi * 12.0 * s) * std::sin(twoPi * 6.0 * t);
      const double ridges = std::cos(twoPi * (3.0 * s + 2.0 * t));
      heights->SetValue(
        static_cast<vtkIdType>(j) * w + i, static_cast<float>(0.5 + 0.3 * bumps + 0.2 * ridges));
    }
  }
  image->GetPointData()->SetScalars(heights);
  return image;
}

// The surface's last filter; the caller asks it for a piece (UpdatePiece, or a writer).
struct Pipeline
{
  vtkNew<vtkParametricDonut> Donut;
  vtkNew<vtkParametricSurfaceSource> Source;
  vtkSmartPointer<vtkImageData> HeightMap = MakeHeightMap();
  vtkNew<vtkDisplacementMapFilter> Displace;

  explicit Pipeline(int resolution)
  {
    this->Donut->SetRingRadius(1.0);
    this->Donut->SetCrossSectionRadius(0.4);
    this->Source->SetParametricFunction(this->Donut);
    // Twice as many columns as rows: the ring is longer than the cross-section.
    this->Source->SetUResolution(2 * resolution);
    this->Source->SetVResolution(resolution);
    this->Source->GenerateTangentsOn();
    this->Source->GenerateDerivativesOn();
    this->Displace->SetInputConnection(0, this->Source->GetOutputPort());
    this->Displace->SetInputData(1, this->HeightMap);
    this->Displace->SetScaleFactor(0.08);
    this->Displace->SetMidlevel(0.5);
    this->Displace->SetInterpolationToCubic();
    this->Displace->SetNormalModeToExact();
  }
};
}

#endif
