// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Uses SurfaceDetail::IO and SurfaceDetail::Filters from an installed package: writes an
// OpenEXR image with vtkOIIOImageWriter, reads it back through vtkImageReader2Factory
// (which must hand out vtkOIIOImageReader, registered through vtk_module_autoinit in
// CMakeLists.txt, without a call here), samples it with the wrap convention
// of SurfaceDetail::Filters, and checks every value; then turns a flat height map into a
// normal map with vtkHeightMapToNormalMap (a compiled Filters class), which must be +z.

#include <vtkDataArray.h>
#include <vtkHeightMapToNormalMap.h>
#include <vtkImageData.h>
#include <vtkImageReader2.h>
#include <vtkImageReader2Factory.h>
#include <vtkNew.h>
#include <vtkOIIOImageReader.h>
#include <vtkOIIOImageWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkSurfaceDetailConventions.h>

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: downstream <scratch-folder>\n";
    return 2;
  }
  const std::string path = std::string(argv[1]) + "/downstream.exr";

  constexpr int width = 5, height = 3;
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      image->SetScalarComponentFromFloat(i, j, 0, 0, 10.0f * j + i);
    }
  }
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::cerr << "writing " << path << " failed\n";
    return 1;
  }

  vtkSmartPointer<vtkImageReader2> reader;
  reader.TakeReference(vtkImageReader2Factory::CreateImageReader2(path.c_str()));
  if (!vtkOIIOImageReader::SafeDownCast(reader))
  {
    std::cerr << "vtkImageReader2Factory did not return vtkOIIOImageReader for " << path << "\n";
    return 1;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* back = reader->GetOutput();

  int wrong = 0;
  for (int j = 0; j < height; ++j)
  {
    for (int i = -width; i < 2 * width; ++i)
    {
      // Texel i of a repeating texture is texel WrapIndex(i) of the image.
      const int wrapped = vtkSurfaceDetail::WrapIndex(i, width, vtkSurfaceDetail::Repeat);
      const float expected = 10.0f * j + ((i % width) + width) % width;
      wrong += back->GetScalarComponentAsFloat(wrapped, j, 0, 0) != expected;
    }
  }
  std::cout << "downstream: read " << back->GetNumberOfPoints() << " texels back from " << path
            << ", " << wrong << " wrong\n";

  // A flat surface's normal is +z, stored as 0.5*n + 0.5 = (0.5, 0.5, 1).
  vtkNew<vtkImageData> flat;
  flat->SetDimensions(8, 8, 1);
  flat->AllocateScalars(VTK_FLOAT, 1);
  flat->GetPointData()->GetScalars()->Fill(0.5);
  vtkNew<vtkHeightMapToNormalMap> normals;
  normals->SetInputData(flat);
  normals->SetOutputScalarTypeToFloat();
  normals->Update();
  vtkImageData* map = normals->GetOutput();
  const bool flatIsUp = map->GetNumberOfPoints() == 64 &&
    map->GetScalarComponentAsDouble(3, 4, 0, 0) == 0.5 &&
    map->GetScalarComponentAsDouble(3, 4, 0, 1) == 0.5 &&
    map->GetScalarComponentAsDouble(3, 4, 0, 2) == 1.0;
  std::cout << "downstream: the normal map of a flat height map is " << (flatIsUp ? "+z" : "WRONG")
            << "\n";
  return wrong == 0 && back->GetNumberOfPoints() == width * height && flatIsUp ? 0 : 1;
}
