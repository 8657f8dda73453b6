// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSurfaceDetailMapper
 * @brief   Polydata mapper that shades surface detail: normal, bump, parallax and relief mapping.
 *
 * vtkSurfaceDetailMapper is a vtkOpenGLPolyDataMapper that perturbs the shading normal
 * (and, for parallax and relief, the texture coordinate) per fragment, so that a coarse mesh shows
 * the detail of a normal map or a height map without moving any geometry.
 * Everything else is VTK's own: the actor's ambient, diffuse, specular colours and
 * specular power, the headlight, light kits, positional and spot lights, actor transforms
 * and cameras. The detail is applied by computing the perturbed normal in view coordinates
 * and handing it to VTK's lighting code in place of the interpolated one.
 *
 * Techniques (SetTechnique):
 * - Plain: exactly the plain mapper (no shader changes, no extra textures or attributes).
 * - NormalMapping: tangent-space normal map (SetNormalMap; RGB = 0.5*n + 0.5, green up
 *   by default, see GreenUp) with NormalScale scaling its tangential part. Needs point
 *   normals, 2-component texture coordinates and point tangents (the TANGENTS attribute)
 *   with their handedness beside them ("TangentHandedness", w = +-1, as
 *   vtkSurfaceDetailTangents stores it; without it w = +1, as VTK takes it). Unlike
 *   vtkProperty::SetNormalTexture, mirrored texture coordinates (w = -1) shade correctly.
 *   When the tangents were replaced or the handedness dropped by a filter that does not
 *   know it, the mapper warns once (vtkSurfaceDetailTangents::GetHandednessProblem).
 * - BumpMapping: the normal of the surface z = BumpScale*h(s,t) over the unit texture
 *   square, h the first channel of SetHeightMap, by forward or central
 *   differences at the height map's own texel size. With TangentFree on, the tangent frame
 *   comes from screen-space derivatives (Mikkelsen 2010) and no tangent array is needed.
 * - ParallaxMapping: parallax mapping with offset limiting (Welsh 2004): the texture
 *   coordinate of every texture, the actor's colour texture included, moves to where the
 *   view ray meets the height field lying DepthScale*(1 - h) below the mesh (DepthScale in
 *   the mesh's own units). Shading then uses the normal map if one is set (needs tangents),
 *   otherwise the height map's bumps (tangent free, BumpScale).
 * - ReliefMapping: relief mapping (Policarpo, Oliveira & Comba 2005): the eye ray is
 *   marched through a box DepthScale deep under the mesh, a linear search
 *   (LinearSearchSteps) to the first point under the height field, then a binary search
 *   (BinarySearchSteps); colour, normal and lighting are taken at the hit, so bricks
 *   hide the mortar behind them. The depth comes from a relief map (SetReliefMap: RGBA,
 *   the normal in RGB, depth = 1 - h in A, as vtkHeightMapToNormalMap makes with
 *   OutputRelief; needs tangents) or from the height map, shaded then with the normal
 *   map if one is set (needs tangents) or else with the normal of the relief surface
 *   itself, from the height gradient and DepthScale (no tangents). The relief with
 *   DepthScale d is the surface vtkDisplacementMapFilter makes with ScaleFactor d and
 *   Midlevel 1. The march uses each fragment's own dP/ds, dP/dt (screen-space
 *   derivatives), so depth is in object units on curved and stretched meshes alike.
 *   SelfShadowing traces from the hit toward every light that shades it (headlight,
 *   light kits, positional and spot lights). DepthCorrection writes the hit's depth, so
 *   the relief meets other geometry where the displaced surface would. The linear steps
 *   follow the view (AdaptiveSteps: one per texel the ray crosses, between a few and
 *   LinearSearchSteps), and where the whole depth is less than about a pixel on screen
 *   the relief fades to plain normal mapping and no search runs. Silhouettes stay those
 *   of the mesh. With a cone map (SetConeMap, from vtkHeightMapToConeMap) the search is by
 *   cone stepping instead: steps as long as each texel's cone allows (relaxed cones, which
 *   no ray leaves from under the surface, or conservative, empty ones), one read each, then
 *   secant steps; it finds the hits the linear search finds (and ridges of a texel that it
 *   steps over) in fewer reads, and the more texels a ray crosses, the fewer.
 *
 * Bad input (a technique that needs a texture, texture coordinates, normals or tangents the
 * input lacks, a normal map with fewer than 3 components or of a type other than unsigned
 * char or float with direct scalars, a height map of a signed integer type) is reported
 * once with vtkErrorMacro, and the actor is rendered as with Technique Plain until fixed.
 *
 * Shader code exists only for what is switched on. The program is rebuilt when the set of
 * shader features changes (technique, TangentFree, which maps are read, SelfShadowing,
 * DepthCorrection), never per frame; strengths, scales, step counts, GreenUp and the maps
 * themselves are uniforms and textures. Changing NormalScale, GreenUp, BumpScale,
 * DepthScale, LinearSearchSteps, BinarySearchSteps or AdaptiveSteps modifies the
 * mapper (GetMTime, and a ModifiedEvent for observers) but neither rebuilds the shader nor
 * re-uploads the vertex buffers: the next render just sets the new uniform. GetMTime also
 * includes the normal, height and relief maps' textures. The height map is
 * uploaded as a float texture holding h and its finite differences (DifferenceScheme), so bump
 * mapping reads one texel per fragment.
 *
 * Triplanar mapping (TriplanarOn) needs no texture coordinates and no tangents: the actor's
 * colour texture, the normal map (NormalMapping) and the height map (BumpMapping) are
 * projected along the three axes of the object's coordinates (or the world's,
 * TriplanarSpace), TriplanarScale texture squares per unit, and the three blended by the
 * normal with weights |n_i|^TriplanarSharpness (normalised; a weight under 1/256 is dropped
 * and its projection not read). Each face is mapped as seen from outside it, the right way
 * round, the faces along negative axes too, and each projection's normal-map frame is
 * reoriented to the surface normal, so a bump looks the same on every face and an axis-aligned
 * box shows on each face exactly what planar texture coordinates would give. The rules (which
 * axis runs along s and t, their signs) are vtkSurfaceDetail::TriplanarProject in
 * vtkSurfaceDetailConventions.h. Parallax and relief mapping need texture coordinates and are
 * refused with triplanar mapping. Textures should repeat (vtkTexture::RepeatOn).
 *
 * Flat interpolation, lighting off or a non-surface representation draw as the plain
 * mapper does (flat interpolation is reported, as it is likely a mistake).
 *
 * @sa vtkOpenGLPolyDataMapper vtkProperty::SetNormalTexture vtkHeightMapToNormalMap
 */

#ifndef vtkSurfaceDetailMapper_h
#define vtkSurfaceDetailMapper_h

#include "SurfaceDetailRenderingModule.h" // For export macro
#include "vtkOpenGLPolyDataMapper.h"

#include <map>    // For the per-primitive shader keys
#include <memory> // For the shading
#include <string> // For the shader keys

class vtkSurfaceDetailShading;
class vtkTexture;

class SURFACEDETAILRENDERING_EXPORT vtkSurfaceDetailMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkSurfaceDetailMapper* New();
  vtkTypeMacro(vtkSurfaceDetailMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum TechniqueType
  {
    Plain = 0,
    NormalMapping,
    BumpMapping,
    ParallaxMapping,
    ReliefMapping
  };

  enum DifferenceSchemeType
  {
    Forward = 0,
    Central
  };

  ///@{
  /**
   * The surface-detail technique. Default Plain.
   */
  vtkSetClampMacro(Technique, int, Plain, ReliefMapping);
  vtkGetMacro(Technique, int);
  void SetTechniqueToPlain() { this->SetTechnique(Plain); }
  void SetTechniqueToNormalMapping() { this->SetTechnique(NormalMapping); }
  void SetTechniqueToBumpMapping() { this->SetTechnique(BumpMapping); }
  void SetTechniqueToParallaxMapping() { this->SetTechnique(ParallaxMapping); }
  void SetTechniqueToReliefMapping() { this->SetTechnique(ReliefMapping); }
  const char* GetTechniqueAsString();
  ///@}

  ///@{
  /**
   * Tangent-space normal map (3 or 4 components, RGB = 0.5*n + 0.5). Default none.
   * Use nearest or linear filtering as you like; unsigned char and float images work
   * (float images need vtkTexture::SetColorModeToDirectScalars, values in [0,1]); other
   * types are reported as errors (vtkOpenGLTexture would map them through a lookup table).
   */
  virtual void SetNormalMap(vtkTexture*);
  vtkGetObjectMacro(NormalMap, vtkTexture);
  ///@}

  ///@{
  /**
   * Height map (component HeightComponent of its image's scalars; unsigned char and unsigned
   * short are read as [0,1], float and double as they are, other types are refused: the
   * rule of vtkSurfaceDetail::HeightMapScale, shared with vtkDisplacementMapFilter and
   * vtkHeightMapToNormalMap). It is uploaded as a 32-bit float texture with the vtkTexture's
   * wrap mode and interpolation (Interpolate on: linear); with ClampToBorder the height
   * outside is that component of the texture's border colour. Default none.
   */
  virtual void SetHeightMap(vtkTexture*);
  vtkGetObjectMacro(HeightMap, vtkTexture);
  ///@}

  ///@{
  /**
   * The component of the height map's scalars that holds the height, as
   * vtkDisplacementMapFilter's and vtkHeightMapToNormalMap's HeightComponent (e.g. 3 for the
   * alpha of an RGBA image). Default 0.
   */
  vtkSetClampMacro(HeightComponent, int, 0, 3);
  vtkGetMacro(HeightComponent, int);
  ///@}

  ///@{
  /**
   * Scale of the normal map's tangential part (1 = as stored, 0 = flat). Default 1.
   */
  void SetNormalScale(double scale);
  vtkGetMacro(NormalScale, double);
  ///@}

  ///@{
  /**
   * Whether the normal map's green channel points along +t (OpenGL, Blender) or -t
   * (DirectX). Default true.
   */
  void SetGreenUp(bool greenUp);
  vtkGetMacro(GreenUp, bool);
  vtkBooleanMacro(GreenUp, bool);
  ///@}

  ///@{
  /**
   * Bump height k: the bumps are those of z = k*h(s,t) over the unit texture square.
   * Negative values sink the bumps. Default 1.
   */
  void SetBumpScale(double scale);
  vtkGetMacro(BumpScale, double);
  ///@}

  ///@{
  /**
   * Finite differences for the height gradient: Forward (the classic Cg code's, one texel
   * ahead) or Central (one texel either side, second-order accurate). Default Central, as
   * vtkHeightMapToNormalMap's.
   */
  vtkSetClampMacro(DifferenceScheme, int, Forward, Central);
  vtkGetMacro(DifferenceScheme, int);
  void SetDifferenceSchemeToForward() { this->SetDifferenceScheme(Forward); }
  void SetDifferenceSchemeToCentral() { this->SetDifferenceScheme(Central); }
  ///@}

  ///@{
  /**
   * Bump mapping without a tangent array: the frame comes from screen-space derivatives
   * (Mikkelsen 2010). Default false (use the point tangents).
   */
  vtkSetMacro(TangentFree, bool);
  vtkGetMacro(TangentFree, bool);
  vtkBooleanMacro(TangentFree, bool);
  ///@}

  enum TriplanarSpaceType
  {
    ObjectSpace = 0,
    WorldSpace
  };

  ///@{
  /**
   * Triplanar mapping: the colour texture, normal map and height map projected along the
   * axes instead of read at texture coordinates (see the class description). Default false.
   */
  vtkSetMacro(Triplanar, bool);
  vtkGetMacro(Triplanar, bool);
  vtkBooleanMacro(Triplanar, bool);
  ///@}

  ///@{
  /**
   * The axes triplanar mapping projects along: the mesh's own coordinates (ObjectSpace, the
   * default: the texture moves with the actor) or the world's (WorldSpace: the texture stays
   * where it is in the world while the actor moves through it).
   */
  vtkSetClampMacro(TriplanarSpace, int, ObjectSpace, WorldSpace);
  vtkGetMacro(TriplanarSpace, int);
  void SetTriplanarSpaceToObjectSpace() { this->SetTriplanarSpace(ObjectSpace); }
  void SetTriplanarSpaceToWorldSpace() { this->SetTriplanarSpace(WorldSpace); }
  ///@}

  ///@{
  /**
   * Texture squares per unit of the triplanar space (texture coordinate = scale *
   * coordinate). Default 1.
   */
  void SetTriplanarScale(double scale);
  vtkGetMacro(TriplanarScale, double);
  ///@}

  ///@{
  /**
   * The exponent of the triplanar blend weights |n_i|^sharpness, at least 1: higher gives
   * narrower transitions between the projections. Default 4.
   */
  void SetTriplanarSharpness(double sharpness);
  vtkGetMacro(TriplanarSharpness, double);
  ///@}

  ///@{
  /**
   * Depth of the height field for parallax and relief mapping, in the mesh's own (object)
   * units: height 1 is the mesh, height 0 lies DepthScale below it. Default 0.05.
   */
  void SetDepthScale(double depth);
  vtkGetMacro(DepthScale, double);
  ///@}

  ///@{
  /**
   * Relief map for ReliefMapping: RGBA, RGB the tangent-space normal (as SetNormalMap),
   * A the depth 1 - h (0 = top, 1 = deepest), unsigned char or float with direct scalars.
   * When set, it replaces the normal and height maps for relief mapping. Default none.
   */
  virtual void SetReliefMap(vtkTexture*);
  vtkGetObjectMacro(ReliefMap, vtkTexture);
  ///@}

  ///@{
  /**
   * Cone map for ReliefMapping: when set, the view ray's linear search becomes cone stepping.
   * Its input is vtkHeightMapToConeMap's output for the heights the relief's depth comes
   * from (same size; its Wrap as the texture's: Repeat or ClampToEdge), relaxed or
   * conservative. The mapper packs it with the relief's depth into one 8-bit texture read
   * with linear filtering, whatever the texture's interpolation: each texel's apex and cone
   * ratio are the least over it and its eight neighbours, rounded to the safe side, so that a
   * blend is never a wider cone than the texel's own. Default none.
   */
  virtual void SetConeMap(vtkTexture*);
  vtkGetObjectMacro(ConeMap, vtkTexture);
  ///@}

  ///@{
  /**
   * Most steps of the relief's linear search (and of each shadow search); with
   * AdaptiveSteps off, the number of steps always taken. With a cone map, the most cone
   * steps. Clamped to [1, 256]. Default 32.
   */
  void SetLinearSearchSteps(int steps);
  vtkGetMacro(LinearSearchSteps, int);
  ///@}

  ///@{
  /**
   * Steps of the relief's binary search, each halving the depth bracket (with a cone map,
   * the most secant steps refining it). Clamped to [0, 32]. Default 8.
   */
  void SetBinarySearchSteps(int steps);
  vtkGetMacro(BinarySearchSteps, int);
  ///@}

  ///@{
  /**
   * Linear steps adapted to the view: one per texel the ray crosses in the depth map,
   * at least a few (head-on) and at most LinearSearchSteps (grazing). Default true.
   */
  void SetAdaptiveSteps(bool adaptive);
  vtkGetMacro(AdaptiveSteps, bool);
  vtkBooleanMacro(AdaptiveSteps, bool);
  ///@}

  ///@{
  /**
   * Relief mapping: whether the relief shades itself (a search from the hit toward each
   * light). Default false.
   */
  vtkSetMacro(SelfShadowing, bool);
  vtkGetMacro(SelfShadowing, bool);
  vtkBooleanMacro(SelfShadowing, bool);
  ///@}

  ///@{
  /**
   * Relief mapping: write the depth of the hit (gl_FragDepth) instead of the mesh's, so
   * the relief meets other geometry where the displaced surface would. It turns off the
   * GPU's early depth test for this actor. On a closed surface, turn on back-face culling
   * (vtkProperty::BackfaceCullingOn): near the silhouette a hit can lie deeper than the
   * surface's far side, whose inside would then show through. Default false.
   */
  vtkSetMacro(DepthCorrection, bool);
  vtkGetMacro(DepthCorrection, bool);
  vtkBooleanMacro(DepthCorrection, bool);
  ///@}

  /**
   * The technique used in the last render: the requested one, or Plain when the input
   * could not support it (see the class documentation).
   */
  int GetActiveTechnique();

  /**
   * Copies the technique, the maps and every setting, then the superclass's state.
   */
  void ShallowCopy(vtkAbstractMapper* m) override;

  /**
   * Includes the uniform-only settings (NormalScale, GreenUp, BumpScale, DepthScale and
   * the relief's step settings),
   * which are kept out of the time the shader and vertex-buffer rebuild checks compare:
   * changing them re-renders with new uniforms, not a new program or new buffers.
   */
  vtkMTimeType GetMTime() override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* win) override;

protected:
  vtkSurfaceDetailMapper();
  ~vtkSurfaceDetailMapper() override;

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderNormal(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderTCoord(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;

  int Technique = Plain;
  vtkTexture* NormalMap = nullptr;
  vtkTexture* HeightMap = nullptr;
  double NormalScale = 1.0;
  bool GreenUp = true;
  double BumpScale = 1.0;
  int DifferenceScheme = Central;
  int HeightComponent = 0;
  bool TangentFree = false;
  bool Triplanar = false;
  int TriplanarSpace = ObjectSpace;
  double TriplanarScale = 1.0;
  double TriplanarSharpness = 4.0;
  double DepthScale = 0.05;
  vtkTexture* ReliefMap = nullptr;
  vtkTexture* ConeMap = nullptr;
  int LinearSearchSteps = 32;
  int BinarySearchSteps = 8;
  bool AdaptiveSteps = true;
  bool SelfShadowing = false;
  bool DepthCorrection = false;

private:
  vtkSurfaceDetailMapper(const vtkSurfaceDetailMapper&) = delete;
  void operator=(const vtkSurfaceDetailMapper&) = delete;

  // Whether the primitive being built or drawn gets the detail shading.
  bool AppliesTo(vtkOpenGLHelper* cellBO, vtkActor* act);
  // Maps point array @a array (empty: none) to vertex attribute @a attribute, where it is not
  // mapped already (@a mapped remembers what is).
  void MapAttribute(const char* attribute, const std::string& array, std::string& mapped);

  // The shading itself, shared with vtkCompositeSurfaceDetailMapper's helpers.
  std::unique_ptr<vtkSurfaceDetailShading> Shading;
  std::string MappedTangentArray;
  std::string MappedHandednessArray;
  std::map<const vtkOpenGLHelper*, std::string> BuiltShaderKeys;
  // When a uniform-only setting last changed; GetMTime leaves it out while the superclass
  // decides whether to rebuild (IgnoreUniformTime).
  vtkTimeStamp UniformTime;
  bool IgnoreUniformTime = false;
  // Records a uniform-only change: a new MTime for observers and renders, no rebuild.
  template <typename T>
  void SetUniformSetting(T& member, T value);
};

#endif
