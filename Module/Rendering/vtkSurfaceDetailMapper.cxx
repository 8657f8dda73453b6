// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSurfaceDetailMapper.h"

#include "vtkActor.h"
#include "vtkCommand.h"
#include "vtkDataObject.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSurfaceDetailShading.h"
#include "vtkTexture.h"

#include <algorithm>

vtkStandardNewMacro(vtkSurfaceDetailMapper);
vtkCxxSetObjectMacro(vtkSurfaceDetailMapper, NormalMap, vtkTexture);
vtkCxxSetObjectMacro(vtkSurfaceDetailMapper, HeightMap, vtkTexture);
vtkCxxSetObjectMacro(vtkSurfaceDetailMapper, ReliefMap, vtkTexture);
vtkCxxSetObjectMacro(vtkSurfaceDetailMapper, ConeMap, vtkTexture);

//------------------------------------------------------------------------------
vtkSurfaceDetailMapper::vtkSurfaceDetailMapper()
  : Shading(new vtkSurfaceDetailShading(this))
{
}

//------------------------------------------------------------------------------
vtkSurfaceDetailMapper::~vtkSurfaceDetailMapper()
{
  this->SetNormalMap(nullptr);
  this->SetHeightMap(nullptr);
  this->SetReliefMap(nullptr);
  this->SetConeMap(nullptr);
}

//------------------------------------------------------------------------------
template <typename T>
void vtkSurfaceDetailMapper::SetUniformSetting(T& member, T value)
{
  if (member != value)
  {
    member = value;
    // What Modified() does, but on the time that GetMTime leaves out while the superclass
    // decides whether to rebuild: observers hear of the change, the shader stays.
    this->UniformTime.Modified();
    this->InvokeEvent(vtkCommand::ModifiedEvent, nullptr);
  }
}

void vtkSurfaceDetailMapper::SetNormalScale(double scale)
{
  this->SetUniformSetting(this->NormalScale, scale);
}

void vtkSurfaceDetailMapper::SetGreenUp(bool greenUp)
{
  this->SetUniformSetting(this->GreenUp, greenUp);
}

void vtkSurfaceDetailMapper::SetBumpScale(double scale)
{
  this->SetUniformSetting(this->BumpScale, scale);
}

void vtkSurfaceDetailMapper::SetTriplanarScale(double scale)
{
  this->SetUniformSetting(this->TriplanarScale, scale);
}

void vtkSurfaceDetailMapper::SetTriplanarSharpness(double sharpness)
{
  this->SetUniformSetting(this->TriplanarSharpness, std::max(sharpness, 1.0));
}

void vtkSurfaceDetailMapper::SetDepthScale(double depth)
{
  this->SetUniformSetting(this->DepthScale, std::max(depth, 0.0));
}

void vtkSurfaceDetailMapper::SetLinearSearchSteps(int steps)
{
  this->SetUniformSetting(this->LinearSearchSteps, std::min(std::max(steps, 1), 256));
}

void vtkSurfaceDetailMapper::SetBinarySearchSteps(int steps)
{
  this->SetUniformSetting(this->BinarySearchSteps, std::min(std::max(steps, 0), 32));
}

void vtkSurfaceDetailMapper::SetAdaptiveSteps(bool adaptive)
{
  this->SetUniformSetting(this->AdaptiveSteps, adaptive);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkSurfaceDetailMapper::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->IgnoreUniformTime)
  {
    return mtime;
  }
  // The maps' own changes reach the picture through their textures and uploads, not through
  // the shader, so they too are left out of the rebuild decision.
  mtime = std::max(mtime, this->UniformTime.GetMTime());
  for (vtkTexture* map : { this->NormalMap, this->HeightMap, this->ReliefMap, this->ConeMap })
  {
    if (map)
    {
      mtime = std::max(mtime, map->GetMTime());
    }
  }
  return mtime;
}

//------------------------------------------------------------------------------
const char* vtkSurfaceDetailMapper::GetTechniqueAsString()
{
  return vtkSurfaceDetailShading::TechniqueName(this->Technique);
}

//------------------------------------------------------------------------------
int vtkSurfaceDetailMapper::GetActiveTechnique()
{
  return this->Shading->GetActiveTechnique();
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailMapper::MapAttribute(
  const char* attribute, const std::string& array, std::string& mapped)
{
  if (array == mapped)
  {
    return;
  }
  if (array.empty())
  {
    this->RemoveVertexAttributeMapping(attribute);
  }
  else
  {
    this->MapDataArrayToVertexAttribute(
      attribute, array.c_str(), vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  }
  mapped = array;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkSurfaceDetailMapper::AppliesTo(vtkOpenGLHelper* cellBO, vtkActor* act)
{
  if (!cellBO)
  {
    return false;
  }
  const bool triangles =
    cellBO == &this->Primitives[PrimitiveTris] || cellBO == &this->Primitives[PrimitiveTriStrips];
  const bool normals = this->VBOs->GetNumberOfComponents("normalMC") == 3;
  const bool tcoords = this->VBOs->GetNumberOfComponents("tcoord") == 2;
  auto info = this->PrimitiveInfo.find(cellBO);
  const int lightComplexity =
    info != this->PrimitiveInfo.end() ? info->second.LastLightComplexity : 0;
  return this->Shading->AppliesTo(triangles, normals, tcoords, lightComplexity, act);
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  this->Shading->Resolve(this, { this->CurrentInput }, act);
  this->MapAttribute(vtkSurfaceDetailShading::TangentAttribute, this->Shading->GetTangentArray(),
    this->MappedTangentArray);
  this->MapAttribute(vtkSurfaceDetailShading::HandednessAttribute,
    this->Shading->GetHandednessArray(), this->MappedHandednessArray);
  this->Shading->BindMaps(ren);
  this->Superclass::RenderPieceStart(ren, act);
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceFinish(ren, act);
  this->Shading->UnbindMaps(ren);
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  for (vtkTexture* map : { this->NormalMap, this->HeightMap, this->ReliefMap, this->ConeMap })
  {
    if (map)
    {
      map->ReleaseGraphicsResources(win);
    }
  }
  this->Shading->ReleaseGraphicsResources(win);
  this->BuiltShaderKeys.clear();
  this->Superclass::ReleaseGraphicsResources(win);
}

//------------------------------------------------------------------------------
bool vtkSurfaceDetailMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->IgnoreUniformTime = true;
  bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  this->IgnoreUniformTime = false;
  const std::string key = this->AppliesTo(&cellBO, act) ? this->Shading->ShaderKey() : "";
  std::string& built = this->BuiltShaderKeys[&cellBO];
  if (built != key)
  {
    built = key;
    rebuild = true;
  }
  return rebuild;
}

//------------------------------------------------------------------------------
bool vtkSurfaceDetailMapper::GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  this->IgnoreUniformTime = true;
  const bool rebuild = this->Superclass::GetNeedToRebuildBufferObjects(ren, act);
  this->IgnoreUniformTime = false;
  return rebuild;
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  if (this->AppliesTo(this->LastBoundBO, act))
  {
    this->Shading->AddTags(shaders);
  }
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
}

void vtkSurfaceDetailMapper::ReplaceShaderNormal(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::ReplaceShaderNormal(shaders, ren, act);
  if (this->AppliesTo(this->LastBoundBO, act))
  {
    this->Shading->ReplaceNormal(shaders);
  }
}

void vtkSurfaceDetailMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::ReplaceShaderLight(shaders, ren, act);
  if (this->AppliesTo(this->LastBoundBO, act))
  {
    this->Shading->ReplaceLight(shaders);
  }
}

void vtkSurfaceDetailMapper::ReplaceShaderTCoord(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::ReplaceShaderTCoord(shaders, ren, act);
  if (this->AppliesTo(this->LastBoundBO, act))
  {
    this->Shading->ReplaceTCoord(shaders);
  }
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  if (cellBO.Program && this->AppliesTo(&cellBO, act))
  {
    this->Shading->SetUniforms(cellBO.Program, ren, act, this->VBOs);
  }
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailMapper::ShallowCopy(vtkAbstractMapper* m)
{
  if (auto* other = vtkSurfaceDetailMapper::SafeDownCast(m))
  {
    this->SetTechnique(other->GetTechnique());
    this->SetNormalMap(other->GetNormalMap());
    this->SetHeightMap(other->GetHeightMap());
    this->SetNormalScale(other->GetNormalScale());
    this->SetGreenUp(other->GetGreenUp());
    this->SetBumpScale(other->GetBumpScale());
    this->SetDifferenceScheme(other->GetDifferenceScheme());
    this->SetHeightComponent(other->GetHeightComponent());
    this->SetTangentFree(other->GetTangentFree());
    this->SetTriplanar(other->GetTriplanar());
    this->SetTriplanarSpace(other->GetTriplanarSpace());
    this->SetTriplanarScale(other->GetTriplanarScale());
    this->SetTriplanarSharpness(other->GetTriplanarSharpness());
    this->SetDepthScale(other->GetDepthScale());
    this->SetReliefMap(other->GetReliefMap());
    this->SetConeMap(other->GetConeMap());
    this->SetLinearSearchSteps(other->GetLinearSearchSteps());
    this->SetBinarySearchSteps(other->GetBinarySearchSteps());
    this->SetAdaptiveSteps(other->GetAdaptiveSteps());
    this->SetSelfShadowing(other->GetSelfShadowing());
    this->SetDepthCorrection(other->GetDepthCorrection());
  }
  this->Superclass::ShallowCopy(m);
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Technique: " << vtkSurfaceDetailShading::TechniqueName(this->Technique) << "\n";
  os << indent << "ActiveTechnique: " << vtkSurfaceDetailShading::TechniqueName(this->GetActiveTechnique()) << "\n";
  os << indent << "NormalMap: " << this->NormalMap << "\n";
  os << indent << "HeightMap: " << this->HeightMap << "\n";
  os << indent << "NormalScale: " << this->NormalScale << "\n";
  os << indent << "GreenUp: " << (this->GreenUp ? "On" : "Off") << "\n";
  os << indent << "BumpScale: " << this->BumpScale << "\n";
  os << indent
     << "DifferenceScheme: " << (this->DifferenceScheme == Central ? "Central" : "Forward") << "\n";
  os << indent << "HeightComponent: " << this->HeightComponent << "\n";
  os << indent << "TangentFree: " << (this->TangentFree ? "On" : "Off") << "\n";
  os << indent << "Triplanar: " << (this->Triplanar ? "On" : "Off") << "\n";
  os << indent << "TriplanarSpace: "
     << (this->TriplanarSpace == WorldSpace ? "WorldSpace" : "ObjectSpace") << "\n";
  os << indent << "TriplanarScale: " << this->TriplanarScale << "\n";
  os << indent << "TriplanarSharpness: " << this->TriplanarSharpness << "\n";
  os << indent << "DepthScale: " << this->DepthScale << "\n";
  os << indent << "ReliefMap: " << this->ReliefMap << "\n";
  os << indent << "ConeMap: " << this->ConeMap << "\n";
  os << indent << "LinearSearchSteps: " << this->LinearSearchSteps << "\n";
  os << indent << "BinarySearchSteps: " << this->BinarySearchSteps << "\n";
  os << indent << "AdaptiveSteps: " << (this->AdaptiveSteps ? "On" : "Off") << "\n";
  os << indent << "SelfShadowing: " << (this->SelfShadowing ? "On" : "Off") << "\n";
  os << indent << "DepthCorrection: " << (this->DepthCorrection ? "On" : "Off") << "\n";
}
