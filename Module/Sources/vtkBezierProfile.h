// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBezierProfile
 * @brief   A composite cubic Bézier curve in 2-D with exact derivatives and arc length.
 *
 * The profile of the gallery's extrusion ("love pillar") and surface of revolution ("marble
 * vase"). 3k+1 control points define k cubic segments that share end points; the curve is
 * evaluated over one parameter t in [0,1] across all segments (segment i covers
 * [i/k, (i+1)/k]). Evaluate() returns the point and its exact first and second
 * derivatives with respect to t.
 *
 * With ArcLengthParameterization on, t is the fraction of the curve's length instead, so
 * that equal steps of t are equal distances along the curve and a texture is not stretched
 * where control points bunch up; the derivatives are then those of the arc-length curve
 * (|dP/dt| = GetLength() wherever the curve has a tangent). The length is integrated by
 * Gauss-Legendre quadrature and inverted by safeguarded Newton steps, to about machine
 * precision.
 *
 * Evaluate() may be called from several threads at once; the validity check and the length
 * table it needs are made once, under a lock, after each modification, so an evaluation costs
 * a Bézier evaluation (and with arc length, about one Newton step from an interpolated guess).
 *
 * @sa vtkParametricRevolution vtkParametricExtrusion
 */

#ifndef vtkBezierProfile_h
#define vtkBezierProfile_h

#include "SurfaceDetailSourcesModule.h" // For export macro
#include "vtkObject.h"

#include <array>  // For the control points
#include <atomic> // For the time the tables were built
#include <mutex>  // For building the tables once
#include <string> // For IsValid
#include <vector> // For the control points

class SURFACEDETAILSOURCES_EXPORT vtkBezierProfile : public vtkObject
{
public:
  static vtkBezierProfile* New();
  vtkTypeMacro(vtkBezierProfile, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Control points. A valid profile has 3k+1 points (k >= 1 segments); points 3i are on the
   * curve, the two between them shape segment i. Empty by default.
   */
  void AddControlPoint(double x, double y);
  void SetControlPoint(int index, double x, double y);
  void GetControlPoint(int index, double point[2]);
  void RemoveAllControlPoints();
  int GetNumberOfControlPoints();
  ///@}

  /** Number of cubic segments, or 0 when the control points do not make a valid curve. */
  int GetNumberOfSegments();

  /**
   * True when the profile can be evaluated: 3k+1 finite control points, k >= 1. Otherwise
   * @a reason (if given) says what is wrong.
   */
  bool IsValid(std::string* reason = nullptr);

  ///@{
  /**
   * When on, t is the fraction of the curve's length rather than the Bézier parameter
   * spread over the segments. Default off.
   */
  vtkSetMacro(ArcLengthParameterization, bool);
  vtkGetMacro(ArcLengthParameterization, bool);
  vtkBooleanMacro(ArcLengthParameterization, bool);
  ///@}

  /**
   * The point at @a t (clamped to [0,1]) and its first and second derivatives with respect
   * to t (either may be null). Returns false, and zeros, when the profile is not valid.
   */
  bool Evaluate(double t, double point[2], double d1[2], double d2[2]);

  /** Length of the whole curve (0 when invalid). */
  double GetLength();

  /** The default profiles of the gallery's scenes, replacing the current control points. */
  void SetToVase();
  void SetToHeart();

protected:
  vtkBezierProfile() = default;
  ~vtkBezierProfile() override = default;

  using Point = std::array<double, 2>;
  std::vector<Point> ControlPoints;
  bool ArcLengthParameterization = false;

private:
  vtkBezierProfile(const vtkBezierProfile&) = delete;
  void operator=(const vtkBezierProfile&) = delete;

  // Bézier parameter tau in [0,1] over all segments: point and derivatives.
  void EvaluateBezier(double tau, double p[2], double d1[2], double d2[2], double d3[2]) const;
  double Speed(double tau) const;
  double LengthBetween(double a, double b) const;
  double InverseLength(double length) const;
  // Validity and the length tables, rebuilt once (under a lock) after each modification.
  void Prepare();

  bool Valid = false;
  std::string InvalidReason;
  // At tau = i / (TableIntervalsPerSegment * k): cumulative length, and for the inversion
  // the speed and the curvature of the length (|s'| / 2s, infinite where the curve stops).
  std::vector<double> LengthTable;
  std::vector<double> SpeedTable;
  std::vector<double> NewtonFactor;
  std::atomic<vtkMTimeType> PreparedTime{ 0 };
  std::mutex PrepareMutex;
};

#endif
