// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: vtkHeightMapToNormalMap on small images of arbitrary floats (NaN and
// infinities included) with arbitrary parameters.
#include "FuzzInput.h"

#include <vtkHeightMapToNormalMap.h>
#include <vtkImageData.h>
#include <vtkObject.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  vtkObject::GlobalWarningDisplayOff();
  FuzzInput in(data, size);
  vtkNew<vtkHeightMapToNormalMap> filter;
  filter->SetDifferenceScheme(in.Count(0, 3));
  filter->SetWrap(in.Count(0, 2));
  filter->SetGreenUp(in.Byte() % 2);
  filter->SetOutputRelief(in.Byte() % 2);
  const int types[3] = { VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT, VTK_FLOAT };
  filter->SetOutputScalarType(types[in.Count(0, 2)]);
  filter->SetBumpScale(in.Float());
  vtkNew<vtkImageData> image;
  image->SetDimensions(in.Count(1, 16), in.Count(1, 16), 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* h = static_cast<float*>(image->GetScalarPointer());
  for (vtkIdType k = 0; k < image->GetNumberOfPoints(); ++k)
  {
    h[k] = in.Float();
  }
  filter->SetInputData(image);
  filter->Update();
  return 0;
}
