// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: vtkMikkTSpaceTangents on small arbitrary meshes (FuzzInput.h).
#include "FuzzInput.h"

#include <vtkMikkTSpaceTangents.h>
#include <vtkObject.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  vtkObject::GlobalWarningDisplayOff();
  FuzzInput in(data, size);
  vtkSmartPointer<vtkPolyData> mesh = FuzzMesh(in);
  vtkNew<vtkMikkTSpaceTangents> filter;
  filter->SetAngularThreshold(in.Byte() % 2 ? 180.0 : in.Byte() * (180.0 / 255.0));
  filter->SetInputData(mesh);
  filter->Update();
  return 0;
}
