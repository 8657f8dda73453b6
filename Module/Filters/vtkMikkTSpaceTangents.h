/**
 * @class   vtkMikkTSpaceTangents
 * @brief   tangent frames for any polygonal surface, compatible with MikkTSpace
 *
 * Normal maps are only right when the renderer rebuilds the tangent frame the baker used,
 * and the content tools (Blender, Substance, xNormal, Unity, glTF) bake against MikkTSpace
 * (M. S. Mikkelsen, "Simulation of wrinkled surfaces revisited", 2008, and the reference
 * implementation's description in mikktspace.h). This filter computes that frame:
 *
 * - per triangle, the directions of dP/ds and dP/dt from positions and texture
 *   coordinates, and the triangle's orientation in texture space (the sign of its signed
 *   texture area);
 * - at each vertex (vertices with identical position, normal and texture coordinates are
 *   one vertex, whether or not they share a point id), the triangles around it that are
 *   connected across edges and have the same orientation form a group; their directions,
 *   projected onto the vertex normal's tangent plane, are averaged with the corner angle
 *   as weight;
 * - the tangent is that average, w = +1 for orientation-preserving groups and -1 for
 *   mirrored ones (so B = w cross(N, T) as in vtkSurfaceDetailConventions.h).
 *
 * Quads are split along the shorter texture-space diagonal (the shorter position-space
 * one on a tie) and their two triangles are forced to one orientation, as MikkTSpace does;
 * the output keeps them as quads. Larger polygons and triangle strips are triangulated;
 * their triangles carry the cell data of the cell they came from. Vertices, lines and
 * polygons with fewer than three points pass through.
 *
 * The output is the input surface with a 4-component float point array "Tangents"
 * (xyz, w). VTK 9.1's point data takes only 3-component tangent attributes, so it is a
 * named array (GetPointData()->GetArray("Tangents")), as vtkParametricSurfaceSource's.
 * A point whose corners get different frames (a mirrored texture shell, or faces around
 * it that MikkTSpace does not join) is split: the first frame keeps the point, every
 * other frame gets a new point appended after the input's points, with all point data
 * copied, and the polygons are renumbered. Points whose texture coordinates differ across
 * a seam are separate points in the input already and stay so.
 *
 * Differences from the reference implementation, all on input it handles badly:
 * normals are normalised before use (the reference assumes unit normals); corners for
 * which the reference returns a zero vector or its (1, 0, 0) placeholder (no usable
 * texture derivatives around them, non-finite coordinates) get that placeholder made
 * orthogonal to the normal, or any unit vector orthogonal to it, so the output is always
 * finite and unit length. Missing normals are computed with vtkPolyDataNormals (no
 * splitting, no reordering), with a warning.
 *
 * Arithmetic is in double precision. Where the reference's single precision cancels a
 * sliver's dP/ds or dP/dt to zero (a texture edge along a position edge shorter than the
 * rounding of the others), the filter also treats it as zero, rather than as a direction
 * made of rounding noise. The result does not depend on the number of threads.
 *
 * Most meshes take a fast path: triangles only, float or double arrays, the default
 * AngularThreshold, and every vertex one connected fan of one texture orientation (no
 * mirror seam through it, no pole of more than 32 triangles, no degenerate triangle).
 * There each point has one frame, computed in one parallel pass per point, with the
 * triangles' directions kept in single precision and a polynomial angle (frames within
 * 1e-5 degrees of the general algorithm's). Other meshes take the general algorithm.
 * In the AVX2 and AVX-512 builds, whether a closed fan is one run is shown by its angles
 * and by sums of a 64-bit hash of its neighbours' ids: a mesh whose ids were chosen to make
 * those sums collide (by chance about 2^-64 per fan) could get one frame at a vertex where
 * MikkTSpace gives two.
 *
 * @sa vtkPolyDataTangents vtkPolyDataNormals
 */

#ifndef vtkMikkTSpaceTangents_h
#define vtkMikkTSpaceTangents_h

#include "SurfaceDetailFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkPointData;

class SURFACEDETAILFILTERS_EXPORT vtkMikkTSpaceTangents : public vtkPolyDataAlgorithm
{
public:
  static vtkMikkTSpaceTangents* New();
  vtkTypeMacro(vtkMikkTSpaceTangents, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * MikkTSpace's angular threshold in degrees (genTangSpace's fAngularThreshold): within
   * a group, triangles whose projected tangent or bitangent directions differ by this
   * angle or more are given separate frames. The default, 180, is what every tool uses
   * (genTangSpaceDefault) and never separates a group. Range [0, 180].
   */
  vtkSetClampMacro(AngularThreshold, double, 0.0, 180.0);
  vtkGetMacro(AngularThreshold, double);
  ///@}

protected:
  vtkMikkTSpaceTangents() = default;
  ~vtkMikkTSpaceTangents() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// The checks of the input that make the filter stop with an error.
  bool CheckInput(vtkPolyData* input, vtkPolyData* output);
  /// The input's point data in @a inPD, with normals from vtkPolyDataNormals if it has none.
  bool PrepareNormals(vtkPolyData* input, vtkPointData* inPD);

  double AngularThreshold = 180.0;

private:
  vtkMikkTSpaceTangents(const vtkMikkTSpaceTangents&) = delete;
  void operator=(const vtkMikkTSpaceTangents&) = delete;
};

#endif
