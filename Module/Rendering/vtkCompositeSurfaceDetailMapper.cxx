// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkCompositeSurfaceDetailMapper.h"

#include "vtkActor.h"
#include "vtk_glew.h" // Before the helper header: VTK 9.1's uses GLenum without it
// clang-format off
#include "vtkCompositeMapperHelper2.h"
// clang-format on
#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSurfaceDetailMapper.h"
#include "vtkSurfaceDetailShading.h"

#include <string>
#include <vector>

/**
 * The helper that draws one batch of blocks (those with the same attributes) with the
 * shading of vtkSurfaceDetailMapper.
 */
class vtkSurfaceDetailCompositeHelper : public vtkCompositeMapperHelper2
{
public:
  static vtkSurfaceDetailCompositeHelper* New();
  vtkTypeMacro(vtkSurfaceDetailCompositeHelper, vtkCompositeMapperHelper2);

protected:
  vtkSurfaceDetailCompositeHelper() = default;
  ~vtkSurfaceDetailCompositeHelper() override = default;

  vtkSurfaceDetailMapper* Detail()
  {
    return static_cast<vtkCompositeSurfaceDetailMapper*>(this->Parent)->GetDetail();
  }

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override
  {
    std::vector<vtkPolyData*> blocks;
    for (const auto& block : this->Data)
    {
      blocks.push_back(block.first);
    }
    // Users observe the composite mapper, not its helpers.
    this->Shading.SetReporter(this->Parent);
    this->Shading.Resolve(this->Detail(), blocks, act);
    // The batch's buffers are built again when the attributes the shading reads change.
    const std::string arrays =
      this->Shading.GetTangentArray() + '\n' + this->Shading.GetHandednessArray();
    if (arrays != this->UploadedArrays)
    {
      this->UploadedArrays = arrays;
      this->Modified();
    }
    this->Shading.BindMaps(ren);
    this->Superclass::RenderPieceStart(ren, act);
  }

  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::RenderPieceFinish(ren, act);
    this->Shading.UnbindMaps(ren);
  }

  // The superclass uploads texture coordinates only for the actor's textures, and neither
  // it nor VTK's batching uploads mapped arrays; each block's are appended here, where the
  // superclass appended the block's points (not where it reused another block's).
  void AppendOneBufferObject(vtkRenderer* ren, vtkActor* act, vtkCompositeMapperHelperData* hdata,
    vtkIdType& vertexOffset, std::vector<unsigned char>& colors,
    std::vector<float>& normals) override
  {
    this->Superclass::AppendOneBufferObject(ren, act, hdata, vertexOffset, colors, normals);
    vtkPolyData* block = hdata->Data;
    if (!block->GetPoints() || this->Shading.GetActiveTechnique() == vtkSurfaceDetailMapper::Plain)
    {
      return;
    }
    const vtkIdType end = vertexOffset + block->GetNumberOfPoints();
    vtkPointData* pd = block->GetPointData();
    this->AppendPointArray("tcoord", pd->GetTCoords(), end);
    this->AppendPointArray(vtkSurfaceDetailShading::TangentAttribute,
      pd->GetArray(this->Shading.GetTangentArray().c_str()), end);
    this->AppendPointArray(vtkSurfaceDetailShading::HandednessAttribute,
      pd->GetArray(this->Shading.GetHandednessArray().c_str()), end);
  }

  // Appends @a array to @a attribute unless that attribute already reaches vertex @a end.
  void AppendPointArray(const char* attribute, vtkDataArray* array, vtkIdType end)
  {
    vtkIdType offset = 0;
    vtkIdType total = 0;
    if (array && !this->VBOs->ArrayExists(attribute, array, offset, total) && total < end)
    {
      this->VBOs->AppendDataArray(attribute, array, VTK_FLOAT);
    }
  }

  bool AppliesTo(vtkOpenGLHelper* cellBO, vtkActor* act)
  {
    if (!cellBO)
    {
      return false;
    }
    const bool triangles = cellBO == &this->Primitives[PrimitiveTris] ||
      cellBO == &this->Primitives[PrimitiveTriStrips];
    const bool normals = this->VBOs->GetNumberOfComponents("normalMC") == 3;
    const bool tcoords = this->VBOs->GetNumberOfComponents("tcoord") == 2;
    auto info = this->PrimitiveInfo.find(cellBO);
    const int lightComplexity =
      info != this->PrimitiveInfo.end() ? info->second.LastLightComplexity : 0;
    return this->Shading.AppliesTo(triangles, normals, tcoords, lightComplexity, act);
  }

  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
    const std::string key = this->AppliesTo(&cellBO, act) ? this->Shading.ShaderKey() : "";
    std::string& built = this->BuiltShaderKeys[&cellBO];
    if (built != key)
    {
      built = key;
      rebuild = true;
    }
    return rebuild;
  }

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    if (this->AppliesTo(this->LastBoundBO, act))
    {
      this->Shading.AddTags(shaders);
    }
    this->Superclass::ReplaceShaderValues(shaders, ren, act);
  }

  void ReplaceShaderNormal(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::ReplaceShaderNormal(shaders, ren, act);
    if (this->AppliesTo(this->LastBoundBO, act))
    {
      this->Shading.ReplaceNormal(shaders);
    }
  }

  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::ReplaceShaderLight(shaders, ren, act);
    if (this->AppliesTo(this->LastBoundBO, act))
    {
      this->Shading.ReplaceLight(shaders);
    }
  }

  void ReplaceShaderTCoord(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::ReplaceShaderTCoord(shaders, ren, act);
    if (this->AppliesTo(this->LastBoundBO, act))
    {
      this->Shading.ReplaceTCoord(shaders);
    }
  }

  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
    if (cellBO.Program && this->AppliesTo(&cellBO, act))
    {
      this->Shading.SetUniforms(cellBO.Program, ren, act, this->VBOs);
    }
  }

  void ReleaseGraphicsResources(vtkWindow* win) override
  {
    this->Shading.ReleaseGraphicsResources(win);
    this->BuiltShaderKeys.clear();
    this->Superclass::ReleaseGraphicsResources(win);
  }

private:
  vtkSurfaceDetailCompositeHelper(const vtkSurfaceDetailCompositeHelper&) = delete;
  void operator=(const vtkSurfaceDetailCompositeHelper&) = delete;

  vtkSurfaceDetailShading Shading{ this };
  std::string UploadedArrays;
  std::map<const vtkOpenGLHelper*, std::string> BuiltShaderKeys;
};

vtkStandardNewMacro(vtkSurfaceDetailCompositeHelper);
vtkStandardNewMacro(vtkCompositeSurfaceDetailMapper);

//------------------------------------------------------------------------------
vtkCompositeSurfaceDetailMapper::vtkCompositeSurfaceDetailMapper()
{
  this->Detail = vtkSurfaceDetailMapper::New();
}

//------------------------------------------------------------------------------
vtkCompositeSurfaceDetailMapper::~vtkCompositeSurfaceDetailMapper()
{
  this->Detail->UnRegister(this);
}

//------------------------------------------------------------------------------
void vtkCompositeSurfaceDetailMapper::SetDetail(vtkSurfaceDetailMapper* detail)
{
  if (detail && detail == this->Detail)
  {
    return;
  }
  vtkSurfaceDetailMapper* previous = this->Detail;
  if (detail)
  {
    detail->Register(this);
    this->Detail = detail;
  }
  else
  {
    this->Detail = vtkSurfaceDetailMapper::New();
  }
  previous->UnRegister(this);
  this->Modified();
}

//------------------------------------------------------------------------------
vtkCompositeMapperHelper2* vtkCompositeSurfaceDetailMapper::CreateHelper()
{
  return vtkSurfaceDetailCompositeHelper::New();
}

//------------------------------------------------------------------------------
void vtkCompositeSurfaceDetailMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Detail->ReleaseGraphicsResources(win);
  this->Superclass::ReleaseGraphicsResources(win);
}

//------------------------------------------------------------------------------
void vtkCompositeSurfaceDetailMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Detail:\n";
  this->Detail->PrintSelf(os, indent.GetNextIndent());
}
