// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The pipeline of TestPluginPieces.py made with the C++ classes directly (no proxies, one
// process), written to the file given: the reference the plugin's output must equal.
#include "vtkDisplacementMapFilter.h"
#include "vtkMikkTSpaceTangents.h"
#include "vtkParametricDonut.h"
#include "vtkParametricSurfaceSource.h"

#include <vtkDataObject.h>
#include <vtkNew.h>
#include <vtkRTAnalyticSource.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cout << "usage: PluginReferenceSurface <output.vtp>\n";
    return argc == 2 ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  vtkNew<vtkParametricDonut> donut;
  vtkNew<vtkParametricSurfaceSource> surface;
  surface->SetParametricFunction(donut);
  surface->SetUResolution(60);
  surface->SetVResolution(31);
  surface->GenerateTangentsOn();
  vtkNew<vtkRTAnalyticSource> heights; // ParaView's Wavelet
  heights->SetWholeExtent(0, 63, 0, 31, 0, 0);
  vtkNew<vtkDisplacementMapFilter> displaced;
  displaced->SetInputConnection(surface->GetOutputPort());
  displaced->SetSourceConnection(heights->GetOutputPort());
  displaced->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "RTData");
  displaced->SetScaleFactor(0.002);
  displaced->SetMidlevel(100.0);
  vtkNew<vtkMikkTSpaceTangents> tangents;
  tangents->SetInputConnection(displaced->GetOutputPort());
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(tangents->GetOutputPort());
  writer->SetFileName(argv[1]);
  writer->SetDataModeToAscii();
  return writer->Write() == 1 ? EXIT_SUCCESS : EXIT_FAILURE;
}
