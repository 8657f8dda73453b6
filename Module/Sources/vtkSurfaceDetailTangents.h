// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSurfaceDetailTangents
 * @brief   How SurfaceDetail stores a tangent frame in point data, so that VTK sees it.
 *
 * A tangent frame is the tangent T and the handedness w = +1 or -1 of the bitangent
 * B = w*cross(N, T) (Documentation/Conventions.md). VTK's tangent attribute has exactly
 * three components and VTK's own normal mapping (vtkProperty::SetNormalTexture) takes
 * B = cross(N, T), which is wrong where texture coordinates are mirrored. SurfaceDetail
 * therefore writes:
 *
 * - T as the point data's TANGENTS attribute: a 3-component float array named "Tangents",
 *   which VTK's normal mapping, ParaView, vtkTransformFilter and the attribute copy flags
 *   (CopyTangents) know;
 * - w as a 1-component float array "TangentHandedness" beside it;
 * - the key WITH_HANDEDNESS() = 1 in the tangent array's information, which says that the
 *   two arrays were written together. VTK copies array information along with the array,
 *   so the mark survives filters that interpolate or pass point data.
 *
 * A filter that replaces the tangents without knowing the handedness (vtkPolyDataTangents)
 * writes an array without the mark; one that drops arrays (vtkPassArrays) may remove the
 * handedness. Both leave a frame whose bitangent can be wrong, and the readers of
 * SurfaceDetail (vtkSurfaceDetailMapper, vtkNormalMapBaker, vtkDisplacementMapFilter) warn
 * once with GetHandednessProblem()'s text. Tangents without mark and without handedness,
 * as any VTK filter writes them, are read with w = +1, as VTK reads them.
 */

#ifndef vtkSurfaceDetailTangents_h
#define vtkSurfaceDetailTangents_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For GetHandednessProblem

class vtkDataArray;
class vtkInformationIntegerKey;
class vtkPointData;

class SURFACEDETAILSOURCES_EXPORT vtkSurfaceDetailTangents : public vtkObject
{
public:
  static vtkSurfaceDetailTangents* New();
  vtkTypeMacro(vtkSurfaceDetailTangents, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** "Tangents": the name SurfaceDetail gives its TANGENTS attribute. */
  static const char* GetTangentsArrayName() { return "Tangents"; }

  /** "TangentHandedness": the name of the handedness array (1 component, +1 or -1). */
  static const char* GetHandednessArrayName() { return "TangentHandedness"; }

  /** Set to 1 in a tangent array's information when a handedness array was written with it. */
  static vtkInformationIntegerKey* WITH_HANDEDNESS();

  /**
   * Makes @a tangents (3 components) the TANGENTS attribute of @a pd and @a handedness
   * (1 component) the array beside it, named and marked as above. Either may already be in
   * @a pd: after vtkTransformFilter with TransformAllInputVectors on (VTK 9.1 turns the
   * tangents only then, and leaves them a plain array without the mark), SetFrame(pd,
   * pd->GetArray("Tangents"), GetHandedness(pd)) makes them the frame again.
   */
  static void SetFrame(vtkPointData* pd, vtkDataArray* tangents, vtkDataArray* handedness);

  /**
   * Splits a 4-component frame (Tx, Ty, Tz, w) into the two float arrays of SetFrame and
   * stores them in @a pd. For frames computed four components at a time.
   */
  static void SetFrameFromXYZW(vtkPointData* pd, vtkDataArray* frame);

  /**
   * The handedness array of @a pd, or null when it has none that fits: 1 component and as
   * many tuples as the TANGENTS attribute.
   */
  static vtkDataArray* GetHandedness(vtkPointData* pd);

  /**
   * Empty when the tangents and handedness of @a pd belong together (or when @a pd has no
   * tangents); otherwise what went wrong and what to do, for a reader's warning.
   */
  static std::string GetHandednessProblem(vtkPointData* pd);

protected:
  vtkSurfaceDetailTangents() = default;
  ~vtkSurfaceDetailTangents() override = default;

private:
  vtkSurfaceDetailTangents(const vtkSurfaceDetailTangents&) = delete;
  void operator=(const vtkSurfaceDetailTangents&) = delete;
};

#endif
