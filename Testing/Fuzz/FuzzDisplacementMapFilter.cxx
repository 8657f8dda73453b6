// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: vtkDisplacementMapFilter on small arbitrary meshes (FuzzInput.h) and
// height maps, in every mode.
#include "FuzzInput.h"

#include <vtkDisplacementMapFilter.h>
#include <vtkImageData.h>
#include <vtkObject.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  vtkObject::GlobalWarningDisplayOff();
  FuzzInput in(data, size);
  vtkNew<vtkDisplacementMapFilter> filter;
  filter->SetWrap(in.Count(0, 2));
  filter->SetInterpolation(in.Count(0, 2));
  filter->SetNormalMode(in.Count(0, 3));
  filter->SetMergeSeams(in.Byte() % 2);
  filter->SetScaleFactor(in.Float());
  filter->SetMidlevel(in.Float());
  vtkNew<vtkImageData> heights;
  heights->SetDimensions(in.Count(1, 8), in.Count(1, 8), 1);
  heights->AllocateScalars(VTK_FLOAT, 1);
  auto* h = static_cast<float*>(heights->GetScalarPointer());
  for (vtkIdType k = 0; k < heights->GetNumberOfPoints(); ++k)
  {
    h[k] = in.Float();
  }
  vtkSmartPointer<vtkPolyData> mesh = FuzzMesh(in);
  filter->SetInputData(0, mesh);
  filter->SetInputData(1, heights);
  filter->Update();
  return 0;
}
