// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Tests read and write a tangent frame four components at a time, (Tx, Ty, Tz, w), as the
// conventions state it; vtkSurfaceDetailTangents stores it as the TANGENTS attribute and a
// handedness array. These two helpers convert.
#ifndef TangentFrameTestHelpers_h
#define TangentFrameTestHelpers_h

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSurfaceDetailTangents.h"

/// The frame of @a pd as (Tx, Ty, Tz, w) tuples of the tangents' value type (w = +1 without
/// handedness), or null when @a pd has no TANGENTS attribute.
inline vtkSmartPointer<vtkDataArray> TangentFrame(vtkPolyData* pd)
{
  vtkDataArray* t = pd->GetPointData()->GetTangents();
  if (!t)
  {
    return nullptr;
  }
  vtkDataArray* w = vtkSurfaceDetailTangents::GetHandedness(pd->GetPointData());
  auto frame = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(t->GetDataType()));
  frame->SetName("Frame");
  frame->SetNumberOfComponents(4);
  frame->SetNumberOfTuples(t->GetNumberOfTuples());
  for (vtkIdType i = 0; i < t->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      frame->SetComponent(i, c, t->GetComponent(i, c));
    }
    frame->SetComponent(i, 3, w ? w->GetComponent(i, 0) : 1.0);
  }
  return frame;
}

/// Stores the (Tx, Ty, Tz, w) tuples of @a frame in @a pd as vtkSurfaceDetailTangents does.
inline void SetTangentFrame(vtkPolyData* pd, vtkDataArray* frame)
{
  vtkSurfaceDetailTangents::SetFrameFromXYZW(pd->GetPointData(), frame);
}

#endif
