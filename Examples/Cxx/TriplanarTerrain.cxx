// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Terrain without texture coordinates: a flat grid of points displaced by a height map with
// vtkDisplacementMapFilter's triplanar sampling (the grid faces +z, so the map is projected
// from above), its normals from the displaced mesh. The rock is triplanar too: the marble
// colours and the same heights as a bump map, projected along the three axes, so the steep
// cliffs keep their grain instead of showing the map smeared down their faces, as a texture
// projected from above would.
#include "ExampleScene.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDisplacementMapFilter.h>
#include <vtkFloatArray.h>
#include <vtkOIIOImageReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkSurfaceDetailMapper.h>

int main(int argc, char* argv[])
{
  if (ExampleScene::PrintedUsage(argc, argv, "TriplanarTerrain",
        "Terrain displaced and textured by triplanar projection, without texture coordinates."))
  {
    return 0;
  }
  // A 256 x 256 quad grid over [-2, 2]^2 at z = 0, facing +z.
  constexpr int cells = 256;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> up;
  up->SetName("Normals");
  up->SetNumberOfComponents(3);
  for (int j = 0; j <= cells; ++j)
  {
    for (int i = 0; i <= cells; ++i)
    {
      points->InsertNextPoint(-2.0 + 4.0 * i / cells, -2.0 + 4.0 * j / cells, 0.0);
      up->InsertNextTuple3(0, 0, 1);
    }
  }
  vtkNew<vtkCellArray> quads;
  for (int j = 0; j < cells; ++j)
  {
    for (int i = 0; i < cells; ++i)
    {
      const vtkIdType a = j * (cells + 1) + i;
      const vtkIdType quad[4] = { a, a + 1, a + cells + 2, a + cells + 1 };
      quads->InsertNextCell(4, quad);
    }
  }
  vtkNew<vtkPolyData> grid;
  grid->SetPoints(points);
  grid->SetPolys(quads);
  grid->GetPointData()->SetNormals(up);

  vtkNew<vtkOIIOImageReader> heights;
  heights->SetFileName(SURFACEDETAIL_DATA_DIR "/noise_height.png");
  vtkNew<vtkDisplacementMapFilter> terrain;
  terrain->SetInputData(grid);
  terrain->SetSourceConnection(heights->GetOutputPort());
  terrain->SetWrapToRepeat();
  terrain->SetInterpolationToCubic();
  terrain->TriplanarOn();
  terrain->SetTriplanarScale(0.25); // the whole map across the grid
  terrain->SetScaleFactor(0.8);
  terrain->SetMidlevel(0.5);
  terrain->SetNormalModeToMesh();

  vtkNew<vtkTexture> bumps;
  bumps->SetInputConnection(heights->GetOutputPort());
  bumps->InterpolateOn();
  bumps->RepeatOn();
  vtkNew<vtkSurfaceDetailMapper> mapper;
  mapper->SetInputConnection(terrain->GetOutputPort());
  mapper->SetTechniqueToBumpMapping();
  mapper->SetHeightMap(bumps);
  mapper->SetBumpScale(0.15);
  mapper->TriplanarOn();
  mapper->SetTriplanarScale(1.5);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(ExampleScene::LoadTexture("marble.png"));
  actor->GetProperty()->SetAmbient(0.15);
  actor->GetProperty()->SetDiffuse(0.85);
  actor->RotateX(-90); // z up in the data, y up on the screen

  const double eye[3] = { 3.9, 3.1, 4.4 }, focus[3] = { 0, -0.2, 0 };
  auto window = ExampleScene::ViewActor(actor, eye, focus, 40.0);
  return ExampleScene::WritePicture(
    window, ExampleScene::OutputFolder(argc, argv), "TriplanarTerrain");
}
