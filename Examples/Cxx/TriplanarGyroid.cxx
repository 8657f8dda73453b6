// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Triplanar mapping on an isosurface: the sheets |f| = 0.4 of the gyroid
// f = sin x cos y + sin y cos z + sin z cos x, made by vtkFlyingEdges3D, which gives normals
// but no texture coordinates and no tangents. vtkSurfaceDetailMapper projects the brick colours
// and a brick normal map along the three axes and blends them by the normal: bricks of one
// size everywhere, no seam to cut, nothing stretched where the surface turns.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkImageData.h>
#include <vtkOIIOImageReader.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkSurfaceDetailMapper.h>

#include <cmath>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "TriplanarGyroid",
        "Triplanar brick colours and normal map on a gyroid isosurface without texture "
        "coordinates."))
  {
    return 0;
  }
  // The field sampled on 64^3 points over [-4, 4]^3.
  constexpr int n = 64;
  constexpr double half = 4.0, step = 2 * half / (n - 1);
  vtkNew<vtkImageData> field;
  field->SetDimensions(n, n, n);
  field->SetOrigin(-half, -half, -half);
  field->SetSpacing(step, step, step);
  vtkNew<vtkFloatArray> values;
  values->SetName("Gyroid");
  values->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double x = -half + i * step, y = -half + j * step, z = -half + k * step;
        const double f = std::sin(x) * std::cos(y) + std::sin(y) * std::cos(z) +
          std::sin(z) * std::cos(x);
        values->SetValue((static_cast<vtkIdType>(k) * n + j) * n + i,
          static_cast<float>(std::abs(f)));
      }
    }
  }
  field->GetPointData()->SetScalars(values);
  vtkNew<vtkFlyingEdges3D> sheets;
  sheets->SetInputData(field);
  sheets->SetValue(0, 0.4);
  sheets->ComputeNormalsOn();

  vtkNew<vtkOIIOImageReader> heights;
  heights->SetFileName(SURFACEDETAIL_DATA_DIR "/brick_height.png");
  vtkNew<vtkHeightMapToNormalMap> normals;
  normals->SetInputConnection(heights->GetOutputPort());
  normals->SetBumpScale(0.04);
  vtkNew<vtkTexture> normalMap;
  normalMap->SetInputConnection(normals->GetOutputPort());
  normalMap->InterpolateOn();
  normalMap->RepeatOn();

  vtkNew<vtkSurfaceDetailMapper> mapper;
  mapper->SetInputConnection(sheets->GetOutputPort());
  mapper->ScalarVisibilityOff();
  mapper->SetTechniqueToNormalMapping();
  mapper->SetNormalMap(normalMap);
  mapper->TriplanarOn();
  mapper->SetTriplanarScale(0.5); // a texture square (eight courses of bricks) per 2 units
  mapper->SetTriplanarSharpness(6);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(ExampleScene::LoadTexture("brick_color.png"));
  actor->GetProperty()->SetSpecular(0.15);
  actor->GetProperty()->SetSpecularPower(20);

  const double eye[3] = { 11.4, 8.4, 15.0 }, focus[3] = { 0, 0, 0 };
  auto window = ExampleScene::ViewActor(actor, eye, focus, 38.0);
  return ExampleScene::WritePicture(
    window, ExampleScene::OutputFolder(argc, argv), "TriplanarGyroid");
}
