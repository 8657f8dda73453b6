// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkHeightMapToConeMap
 * @brief   The cone map of a height map, for relief mapping by cone stepping.
 *
 * The relief of a height map h is the surface at depth 1 - h under the top of a box (depth 0
 * at the top, 1 at the bottom, in units of the relief's depth, as vtkHeightMapToNormalMap's
 * relief maps and vtkSurfaceDetailMapper's DepthScale have it), drawn by OpenGL's bilinear
 * interpolation between texel centres. For every texel the cone map stores, as a 2-component
 * float image named "ConeMap":
 * - component 0, the apex depth a: the depth of the highest point of the surface over the
 *   texel's footprint (the square of one texel around its centre);
 * - component 1, the cone ratio r, texture-coordinate units of radius per unit of depth, of the
 *   cone opening upward from (x, a) for any point x of the footprint. A march above a whose ray
 *   starts on the cone's axis may step to the cone's side at once, wherever in the texel it
 *   stands. Two kinds (ConeType):
 *   - Relaxed (default; Policarpo and Oliveira 2007): the cone may hold surface, but no ray
 *     in it goes from under the surface back above it, so a step to its side crosses the
 *     surface at most once: if the step ends under the surface, the hit lies between its ends
 *     and a search between them finds it.
 *   - Conservative (Dummer 2006): the cone holds no point of the surface, so a step to its
 *     side never reaches it.
 * Where nothing above a limits it, the ratio is MaxConeRatio. vtkSurfaceDetailMapper::SetConeMap
 * takes it for relief mapping by cone stepping, of either kind.
 *
 * How the conservative ratio is bounded, cell by cell (a cell is the square between four texel
 * centres, on which the surface is bilinear): a point y of cell Q is at least g from the
 * footprint (g the gap between the footprint and Q) and at most (a - Q's highest corner) above
 * the apex, and since the surface is at depth a or lower on the footprint and rises no faster
 * than the steepest slope G of the cells around the way there, also at most G times its
 * distance above it; so y cannot limit the ratio below max(g / (a - highest corner), 1 / G).
 * The ratio is the least of these over the cells above the apex: narrower than the widest cone
 * the exact surface allows (TestHeightMapToConeMap states by how much), never wider. It is found
 * by a best-first branch and bound over a pyramid of each block of cells' highest corner (the
 * block nearest in bound first, until no block left can narrow the cone), not by testing every
 * texel against every other; each texel's search is independent, so the result does not depend
 * on the number of threads (vtkSMPTools). The work grows with how wide the cones are: flat,
 * wide-open maps cost the most.
 *
 * The relaxed ratio: a ray that comes back above the surface leaves it where the surface falls
 * away along the ray, past the highest point of its way so far, which was above the ray; just
 * past that crest lies a point q, almost as high, where the depth rises along the way from the
 * ray's start x. So the cone is never left from below if its ratio is at most |q - x| / (a -
 * depth at q) for every point q that faces away from a point x of the footprint in that sense,
 * and that is also the widest such cone: the conservative bound, over those points only. The
 * same branch and bound finds it from below, leaving out the blocks, cells and parts of cells (down to a
 * sixteenth of a texel) where interval arithmetic on the depth's derivatives shows that no
 * point faces away from the footprint. Relaxed cones are at least as wide as conservative ones
 * (several times as wide beside steep walls) and take two to four times as long to make.
 *
 * Distances are in texture coordinates (s, t), the texture square being 1 x 1 whatever its
 * texels, and wrap with Wrap: Repeat (default: tiling maps) or ClampToEdge (the edge texels
 * continue). Heights are read as vtkHeightMapToNormalMap reads them (HeightComponent of the
 * point scalars or of the array chosen with SetInputArrayToProcess; unsigned integer types as
 * fractions of their range; vtkSurfaceDetail::HeightMapScale) and clamped to [0, 1].
 *
 * @sa vtkHeightMapToNormalMap vtkSurfaceDetailMapper
 */

#ifndef vtkHeightMapToConeMap_h
#define vtkHeightMapToConeMap_h

#include "SurfaceDetailFiltersModule.h" // For export macro
#include "vtkImageAlgorithm.h"
#include "vtkSurfaceDetailConventions.h" // For the wrap mode values

class SURFACEDETAILFILTERS_EXPORT vtkHeightMapToConeMap : public vtkImageAlgorithm
{
public:
  static vtkHeightMapToConeMap* New();
  vtkTypeMacro(vtkHeightMapToConeMap, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The channel of the height array that holds the height. Default 0.
   */
  vtkSetClampMacro(HeightComponent, int, 0, VTK_INT_MAX);
  vtkGetMacro(HeightComponent, int);
  ///@}

  ///@{
  /**
   * How the surface continues past the texture's edges: Repeat (default) or ClampToEdge
   * (vtkTexture's values). MirroredRepeat and ClampToBorder are refused.
   */
  vtkSetClampMacro(Wrap, int, vtkSurfaceDetail::ClampToEdge, vtkSurfaceDetail::ClampToBorder);
  vtkGetMacro(Wrap, int);
  void SetWrapToRepeat() { this->SetWrap(vtkSurfaceDetail::Repeat); }
  void SetWrapToClampToEdge() { this->SetWrap(vtkSurfaceDetail::ClampToEdge); }
  ///@}

  enum ConeTypes
  {
    Conservative = 0,
    Relaxed = 1
  };

  ///@{
  /**
   * Which cones: Relaxed (default), cones in which no ray comes back out of the surface, or
   * Conservative, cones that hold no surface (see above).
   */
  vtkSetClampMacro(ConeType, int, Conservative, Relaxed);
  vtkGetMacro(ConeType, int);
  void SetConeTypeToConservative() { this->SetConeType(Conservative); }
  void SetConeTypeToRelaxed() { this->SetConeType(Relaxed); }
  const char* GetConeTypeAsString();
  ///@}

  ///@{
  /**
   * The widest cone stored, in texture-coordinate units per unit of depth, where nothing
   * above a texel limits it. Default 1.
   */
  vtkSetClampMacro(MaxConeRatio, double, 1e-6, 1e6);
  vtkGetMacro(MaxConeRatio, double);
  ///@}

protected:
  vtkHeightMapToConeMap();
  ~vtkHeightMapToConeMap() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int HeightComponent = 0;
  int Wrap = vtkSurfaceDetail::Repeat;
  int ConeType = Relaxed;
  double MaxConeRatio = 1.0;

private:
  vtkHeightMapToConeMap(const vtkHeightMapToConeMap&) = delete;
  void operator=(const vtkHeightMapToConeMap&) = delete;
};

#endif
