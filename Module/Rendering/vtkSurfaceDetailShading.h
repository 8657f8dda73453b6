// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSurfaceDetailShading
 * @brief   The shading of vtkSurfaceDetailMapper, for any vtkOpenGLPolyDataMapper that draws.
 *
 * Private to the module. Both mappers that shade surface detail draw through one of these:
 * vtkSurfaceDetailMapper for a vtkPolyData, and each helper of
 * vtkCompositeSurfaceDetailMapper for the blocks of a composite dataset. It reads the settings
 * of a vtkSurfaceDetailMapper, works out what the input and textures allow, writes the shader
 * code and sets the uniforms; the mapper that owns it calls it from its own overrides, after
 * VTK's, and tells it what only a mapper can see (the primitive being drawn, the uploaded
 * attributes, the light complexity).
 */

#ifndef vtkSurfaceDetailShading_h
#define vtkSurfaceDetailShading_h

#include "vtkShader.h"       // For vtkShader::Type
#include "vtkSmartPointer.h" // For the height texture
#include "vtkType.h"         // For vtkMTimeType

#include <map>    // For the shader sources
#include <string> // For the shader key and array names
#include <vector> // For the blocks

class vtkActor;
class vtkObject;
class vtkOpenGLVertexBufferObjectGroup;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProgram;
class vtkSurfaceDetailMapper;
class vtkTexture;
class vtkTextureObject;
class vtkWindow;

class vtkSurfaceDetailShading
{
public:
  // Errors and warnings are reported as @a reporter's.
  explicit vtkSurfaceDetailShading(vtkObject* reporter);
  ~vtkSurfaceDetailShading();
  vtkSurfaceDetailShading(const vtkSurfaceDetailShading&) = delete;
  vtkSurfaceDetailShading& operator=(const vtkSurfaceDetailShading&) = delete;

  static const char* TechniqueName(int technique);
  void SetReporter(vtkObject* reporter) { this->Reporter = reporter; }

  // The vertex attributes the shaders read the tangent and its handedness from.
  static const char* const TangentAttribute;
  static const char* const HandednessAttribute;

  /**
   * Works out what @a blocks (every one must allow it) and the textures of @a detail allow
   * for @a act, reports a problem once, and remembers @a detail until the next call.
   */
  void Resolve(vtkSurfaceDetailMapper* detail, const std::vector<vtkPolyData*>& blocks,
    vtkActor* act);
  int GetActiveTechnique() const { return this->ActiveTechnique; }
  // The point arrays read as TangentAttribute and HandednessAttribute ("" when none is read).
  const std::string& GetTangentArray() const { return this->TangentArray; }
  const std::string& GetHandednessArray() const { return this->HandednessArray; }

  /**
   * Whether a primitive gets the detail: @a triangles (polygons or strips), drawn with point
   * normals uploaded, and 2-component texture coordinates unless mapped triplanar, and lit
   * (@a lightComplexity above 0).
   */
  bool AppliesTo(bool triangles, bool normalsUploaded, bool tcoordsUploaded, int lightComplexity,
    vtkActor* act) const;
  // The shader features in use: a program is rebuilt when it changes.
  std::string ShaderKey() const;

  ///@{
  /**
   * Shader edits for a primitive the detail applies to: AddTags before VTK's replacements,
   * the others each after VTK's own replacement of the same name.
   */
  void AddTags(std::map<vtkShader::Type, vtkShader*>& shaders) const;
  void ReplaceNormal(std::map<vtkShader::Type, vtkShader*>& shaders) const;
  void ReplaceLight(std::map<vtkShader::Type, vtkShader*>& shaders) const;
  void ReplaceTCoord(std::map<vtkShader::Type, vtkShader*>& shaders) const;
  ///@}
  void SetUniforms(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act,
    vtkOpenGLVertexBufferObjectGroup* vbos) const;

  // Binds the maps for the piece being drawn (uploading the height map when it changed).
  void BindMaps(vtkRenderer* ren);
  void UnbindMaps(vtkRenderer* ren);
  void ReleaseGraphicsResources(vtkWindow* win);

private:
  // Uploads the height map's channel and its finite differences as a 32-bit float texture
  // (integer types scaled to [0,1]): vtkOpenGLTexture would store float images in 8 bits,
  // too coarse for differences.
  void UploadHeightMap(vtkRenderer* ren);
  // Uploads the cone map with the relief's depth beside it, as 32-bit floats.
  void UploadConeMap(vtkRenderer* ren);
  // The height map's channel per texel, scaled to [0,1] as its type is read; non-finite
  // heights (counted in @a nonFinite) are read as 0.
  std::vector<double> Heights(vtkIdType& nonFinite) const;
  // The relief's depth per texel, as the shader reads it.
  std::vector<float> ReliefDepths() const;
  // Passes each of VTK's per-light diffuse terms through the relief's shadow search.
  void AddReliefShadows(std::string& fs) const;
  void SetTriplanarUniforms(
    vtkShaderProgram* program, vtkActor* act, vtkOpenGLVertexBufferObjectGroup* vbos) const;
  // The problem that keeps @a technique from @a block, "" if none.
  std::string Problem(int technique, vtkPolyData* block, vtkActor* act) const;

  vtkObject* Reporter;
  vtkSurfaceDetailMapper* Detail = nullptr;
  int ActiveTechnique = 0;
  bool ActiveUsesTangents = false;
  bool ActiveUsesHandedness = false;
  bool ActiveUsesNormalMap = false;
  bool ActiveUsesHeightMap = false;
  bool ActiveUsesReliefMap = false;
  bool ActiveUsesConeMap = false;
  bool ActiveTriplanar = false;
  bool ActiveTriplanarColor = false;
  std::string TangentArray;
  std::string HandednessArray;
  std::string ReportedProblem;
  std::string ReportedHandednessProblem;
  vtkSmartPointer<vtkTextureObject> HeightTexture;
  vtkMTimeType HeightUploadStamp = 0;
  int HeightUploadDifferenceScheme = -1;
  int HeightUploadComponents = 0;
  int HeightUploadComponent = 0;
  vtkSmartPointer<vtkTextureObject> ConeTexture;
  vtkMTimeType ConeUploadStamp = 0;
  const vtkTexture* ConeUploadDepth = nullptr; // the map its depths came from
};

#endif
// VTK-HeaderTest-Exclude: vtkSurfaceDetailShading.h
