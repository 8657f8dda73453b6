// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSurfaceDetailTangents.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArrayRange.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

vtkStandardNewMacro(vtkSurfaceDetailTangents);
vtkInformationKeyMacro(vtkSurfaceDetailTangents, WITH_HANDEDNESS, Integer);

namespace
{
// Copies (x, y, z, w) tuples into a 3-component and a 1-component float array.
struct SplitFrame
{
  template <typename FrameArray>
  void operator()(FrameArray* frame, float* xyz, float* w) const
  {
    const auto tuples = vtk::DataArrayTupleRange<4>(frame);
    vtkSMPTools::For(0, tuples.size(),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const auto t = tuples[i];
          xyz[3 * i] = static_cast<float>(t[0]);
          xyz[3 * i + 1] = static_cast<float>(t[1]);
          xyz[3 * i + 2] = static_cast<float>(t[2]);
          w[i] = static_cast<float>(t[3]);
        }
      });
  }
};
} // namespace

//------------------------------------------------------------------------------
void vtkSurfaceDetailTangents::SetFrame(
  vtkPointData* pd, vtkDataArray* tangents, vtkDataArray* handedness)
{
  // Held here: either may be the array of that name in @a pd already, which is removed so that
  // an input's arrays of these names do not survive beside the new frame.
  vtkSmartPointer<vtkDataArray> t = tangents, w = handedness;
  pd->RemoveArray(GetTangentsArrayName());
  pd->RemoveArray(GetHandednessArrayName());
  t->SetName(GetTangentsArrayName());
  w->SetName(GetHandednessArrayName());
  t->GetInformation()->Set(WITH_HANDEDNESS(), 1);
  pd->SetTangents(t);
  pd->AddArray(w);
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailTangents::SetFrameFromXYZW(vtkPointData* pd, vtkDataArray* frame)
{
  const vtkIdType n = frame->GetNumberOfTuples();
  vtkNew<vtkFloatArray> tangents, handedness;
  tangents->SetNumberOfComponents(3);
  tangents->SetNumberOfTuples(n);
  handedness->SetNumberOfTuples(n);
  SplitFrame split;
  if (!vtkArrayDispatch::Dispatch::Execute(
        frame, split, tangents->GetPointer(0), handedness->GetPointer(0)))
  {
    split(frame, tangents->GetPointer(0), handedness->GetPointer(0));
  }
  SetFrame(pd, tangents, handedness);
}

//------------------------------------------------------------------------------
vtkDataArray* vtkSurfaceDetailTangents::GetHandedness(vtkPointData* pd)
{
  // An array of another shape, or of another length than the tangents, is not their
  // handedness: readers index it by the tangents' point ids.
  vtkDataArray* w = pd ? pd->GetArray(GetHandednessArrayName()) : nullptr;
  vtkDataArray* t = pd ? pd->GetTangents() : nullptr;
  const bool matches = w && w->GetNumberOfComponents() == 1 &&
    (!t || t->GetNumberOfTuples() == w->GetNumberOfTuples());
  return matches ? w : nullptr;
}

//------------------------------------------------------------------------------
std::string vtkSurfaceDetailTangents::GetHandednessProblem(vtkPointData* pd)
{
  vtkDataArray* tangents = pd ? pd->GetTangents() : nullptr;
  if (!tangents)
  {
    return std::string();
  }
  const bool marked = tangents->GetInformation()->Has(WITH_HANDEDNESS()) &&
    tangents->GetInformation()->Get(WITH_HANDEDNESS()) != 0;
  const bool hasHandedness = GetHandedness(pd) != nullptr;
  if (marked && !hasHandedness)
  {
    return "The tangents were written with a \"TangentHandedness\" array that is gone or no "
           "longer matches them (a filter removed or changed it); the bitangents are taken as "
           "cross(N, T), which is wrong where the texture coordinates are mirrored. Keep that "
           "array, or make the tangents again (vtkMikkTSpaceTangents) after the filter.";
  }
  if (!marked && hasHandedness)
  {
    return "The tangents were replaced by a filter that writes no handedness (e.g. "
           "vtkPolyDataTangents); the \"TangentHandedness\" array beside them belongs to the "
           "earlier tangents and is used as it is. Make the tangents with "
           "vtkMikkTSpaceTangents instead, after the last filter that changes them.";
  }
  return std::string();
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailTangents::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TangentsArrayName: " << GetTangentsArrayName() << "\n";
  os << indent << "HandednessArrayName: " << GetHandednessArrayName() << "\n";
}
