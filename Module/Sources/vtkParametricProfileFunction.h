// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParametricProfileFunction
 * @brief   Base of the parametric surfaces built on a vtkBezierProfile.
 *
 * vtkParametricRevolution turns a profile about an axis and vtkParametricExtrusion sweeps one
 * along an axis; both own a profile, include its modification time in theirs, and evaluate
 * it once per row (or column) of the grid through EvaluateProfile(), which reports a missing
 * or invalid profile as an error. Subclasses choose the default profile and the surface.
 *
 * @sa vtkBezierProfile vtkParametricRevolution vtkParametricExtrusion
 */

#ifndef vtkParametricProfileFunction_h
#define vtkParametricProfileFunction_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkParametricSeparableFunction.h"
#include "vtkSmartPointer.h" // For the profile member

class vtkBezierProfile;

class SURFACEDETAILSOURCES_EXPORT vtkParametricProfileFunction
  : public vtkParametricSeparableFunction
{
public:
  vtkTypeMacro(vtkParametricProfileFunction, vtkParametricSeparableFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The profile. Each subclass sets its default; must not be null when evaluated. */
  void SetProfile(vtkBezierProfile* profile);
  vtkBezierProfile* GetProfile();
  ///@}

  /** Includes the profile's modification time. */
  vtkMTimeType GetMTime() override;

protected:
  vtkParametricProfileFunction();
  ~vtkParametricProfileFunction() override;

  /**
   * The profile's point, first and second derivative at @a t in terms[0..1], terms[2..3]
   * and terms[4..5]. A
   * missing or invalid profile is reported as an error (naming @a surface) and gives zeros.
   */
  void EvaluateProfile(double t, double terms[6], const char* surface);

  vtkSmartPointer<vtkBezierProfile> Profile;

private:
  vtkParametricProfileFunction(const vtkParametricProfileFunction&) = delete;
  void operator=(const vtkParametricProfileFunction&) = delete;
};

#endif
