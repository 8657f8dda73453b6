// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The image pipelines of TestPluginImages.py made with the C++ classes directly (no proxies,
// one process), each output written as <folder>/<name>.vti: the references the plugin's
// outputs must equal. The brick height map read by the OpenImageIO reader ("reader"), its
// normal map and relief map ("normal", "relief"), and a baked normal and height map of a
// displaced torus onto the plain one ("baked-normal", "baked-height").
#include "vtkDisplacementMapFilter.h"
#include "vtkHeightMapToConeMap.h"
#include "vtkHeightMapToNormalMap.h"
#include "vtkNormalMapBaker.h"
#include "vtkOIIOImageReader.h"
#include "vtkParametricDonut.h"
#include "vtkParametricSurfaceSource.h"

#include <vtkAlgorithm.h>
#include <vtkDataObject.h>
#include <vtkNew.h>
#include <vtkXMLImageDataWriter.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
bool Write(vtkAlgorithm* producer, int port, const std::string& folder, const char* name)
{
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputConnection(producer->GetOutputPort(port));
  writer->SetFileName((folder + "/" + name + ".vti").c_str());
  writer->SetDataModeToAscii();
  return writer->Write() == 1;
}
}

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cout << "usage: PluginReferenceImages <brick_height.png> <output folder>\n";
    return argc == 2 ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  const std::string folder = argv[2];
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(argv[1]);
  vtkNew<vtkHeightMapToNormalMap> normal;
  normal->SetInputConnection(reader->GetOutputPort());
  normal->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "OIIOImage");
  normal->SetBumpScale(0.05);
  vtkNew<vtkHeightMapToNormalMap> relief;
  relief->SetInputConnection(reader->GetOutputPort());
  relief->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "OIIOImage");
  relief->SetBumpScale(0.05);
  relief->OutputReliefOn();
  vtkNew<vtkHeightMapToConeMap> cones;
  cones->SetInputConnection(reader->GetOutputPort());
  cones->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "OIIOImage");

  vtkNew<vtkParametricDonut> donut;
  vtkNew<vtkParametricSurfaceSource> coarse;
  coarse->SetParametricFunction(donut);
  coarse->SetUResolution(48);
  coarse->SetVResolution(24);
  coarse->GenerateTangentsOn();
  vtkNew<vtkParametricSurfaceSource> fine;
  fine->SetParametricFunction(donut);
  fine->SetUResolution(256);
  fine->SetVResolution(128);
  vtkNew<vtkDisplacementMapFilter> displaced;
  displaced->SetInputConnection(fine->GetOutputPort());
  displaced->SetSourceConnection(reader->GetOutputPort());
  displaced->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "OIIOImage");
  displaced->SetScaleFactor(0.02);
  displaced->SetMidlevel(0.5);
  vtkNew<vtkNormalMapBaker> baker;
  baker->SetInputConnection(coarse->GetOutputPort());
  baker->SetSourceConnection(displaced->GetOutputPort());
  baker->SetTextureSize(128, 64);
  baker->BakeHeightOn();

  const bool written = Write(reader, 0, folder, "reader") && Write(normal, 0, folder, "normal") &&
    Write(relief, 0, folder, "relief") && Write(cones, 0, folder, "cones") &&
    Write(baker, 0, folder, "baked-normal") &&
    Write(baker, 1, folder, "baked-height");
  return written ? EXIT_SUCCESS : EXIT_FAILURE;
}
