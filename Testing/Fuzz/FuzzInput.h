// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Reads a fuzzer's bytes as the small values the targets need; past the end it gives zeros,
// so every input, however short, is a valid case.
#ifndef FuzzInput_h
#define FuzzInput_h

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

class FuzzInput
{
public:
  FuzzInput(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }

  std::uint8_t Byte() { return this->Offset < this->Size ? this->Data[this->Offset++] : 0; }

  // Any float, NaN and infinities included: the bytes as they are.
  float Float()
  {
    std::uint8_t bytes[4] = { this->Byte(), this->Byte(), this->Byte(), this->Byte() };
    float value;
    std::memcpy(&value, bytes, sizeof(value));
    return value;
  }

  // A small count in [lo, hi].
  int Count(int lo, int hi) { return lo + this->Byte() % (hi - lo + 1); }

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t Offset = 0;
};

// A small polygonal mesh with normals and texture coordinates: up to 16 points of arbitrary
// coordinates, up to 12 triangles and quads whose ids may lie outside the points (or be
// negative), so the filters' own checks are what stands between them and the arrays.
inline vtkSmartPointer<vtkPolyData> FuzzMesh(FuzzInput& in)
{
  const int numPoints = in.Count(1, 16);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> normals, tcoords;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  for (int k = 0; k < numPoints; ++k)
  {
    points->InsertNextPoint(in.Float(), in.Float(), in.Float());
    const float n[3] = { in.Float(), in.Float(), in.Float() };
    normals->InsertNextTypedTuple(n);
    const float t[2] = { in.Float(), in.Float() };
    tcoords->InsertNextTypedTuple(t);
  }
  vtkNew<vtkCellArray> polys;
  const int numCells = in.Count(0, 12);
  for (int c = 0; c < numCells; ++c)
  {
    const int size = in.Count(3, 4);
    vtkIdType ids[4];
    for (int k = 0; k < size; ++k)
    {
      ids[k] = static_cast<vtkIdType>(static_cast<std::int8_t>(in.Byte()));
    }
    polys->InsertNextCell(size, ids);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->SetTCoords(tcoords);
  return mesh;
}

#endif
