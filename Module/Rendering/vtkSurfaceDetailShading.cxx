// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSurfaceDetailShading.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLTexture.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSurfaceDetailMapper.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"

#include "vtkSurfaceDetailBumpFS.h"
#include "vtkSurfaceDetailConventions.h"
#include "vtkSurfaceDetailNormalCoding.h"
#include "vtkSurfaceDetailNormalMapFS.h"
#include "vtkSurfaceDetailParallaxFS.h"
#include "vtkSurfaceDetailReliefConeFS.h"
#include "vtkSurfaceDetailReliefDepthFS.h"
#include "vtkSurfaceDetailReliefFS.h"
#include "vtkSurfaceDetailReliefLinearFS.h"
#include "vtkSurfaceDetailReliefShadowFS.h"
#include "vtkSurfaceDetailTangentFrameFS.h"
#include "vtkSurfaceDetailTangents.h"
#include "vtkSurfaceDetailTriplanarFS.h"

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>

namespace
{
// Our tags sit just before VTK's, so VTK's tags stay where the superclass expects them.
const char* const DecTag = "//VTK::SurfaceDetail::Dec";
const char* const VSImplTag = "//VTK::SurfaceDetail::Impl";
const char* const TCoordImplTag = "//VTK::SurfaceDetail::TCoord::Impl";
const char* const NormalImplTag = "//VTK::SurfaceDetail::Normal::Impl";
const char* const TriplanarColorTag = "//VTK::SurfaceDetail::TriplanarColor::Impl";
// The techniques and schemes, by their mapper's names.
constexpr int Plain = vtkSurfaceDetailMapper::Plain;
constexpr int NormalMapping = vtkSurfaceDetailMapper::NormalMapping;
constexpr int BumpMapping = vtkSurfaceDetailMapper::BumpMapping;
constexpr int ParallaxMapping = vtkSurfaceDetailMapper::ParallaxMapping;
constexpr int ReliefMapping = vtkSurfaceDetailMapper::ReliefMapping;
constexpr int Central = vtkSurfaceDetailMapper::Central;

// The image behind a texture, brought up to date; nullptr if there is none. On a pipeline
// where nothing changed, UpdateWholeExtent only walks the pipeline MTimes and sends no
// request to any algorithm (HeightProducerUpdatedOnlyWhenChanged counts them), the same
// per-frame update vtkTexture::Render does; a check of our own would repeat that walk.
vtkImageData* TextureImage(vtkTexture* texture)
{
  if (!texture)
  {
    return nullptr;
  }
  if (vtkAlgorithm* producer = texture->GetInputAlgorithm())
  {
    producer->UpdateWholeExtent();
  }
  return texture->GetInput();
}

// vtkOpenGLTexture passes unsigned char colours through as they are and, with direct
// scalars, floats too; other types go through a lookup table or are read as 0-255.
bool NormalMapTypeReadable(vtkDataArray* scalars, vtkTexture* texture)
{
  const int type = scalars->GetDataType();
  return type == VTK_UNSIGNED_CHAR ||
    (type == VTK_FLOAT && texture->GetColorMode() == VTK_COLOR_MODE_DIRECT_SCALARS);
}

int TextureUnit(vtkTexture* texture)
{
  auto* glTexture = vtkOpenGLTexture::SafeDownCast(texture);
  return glTexture ? glTexture->GetTextureUnit() : -1;
}
}

// VTK 9.1 uploads float tangents as its own tangentMC but not double ones, so the
// mappers upload them themselves, by name, whatever their type.
const char* const vtkSurfaceDetailShading::TangentAttribute = "sdTangentMC";
const char* const vtkSurfaceDetailShading::HandednessAttribute = "sdHandednessMC";

//------------------------------------------------------------------------------
vtkSurfaceDetailShading::vtkSurfaceDetailShading(vtkObject* reporter)
  : Reporter(reporter)
{
}

vtkSurfaceDetailShading::~vtkSurfaceDetailShading() = default;

//------------------------------------------------------------------------------
const char* vtkSurfaceDetailShading::TechniqueName(int technique)
{
  switch (technique)
  {
    case Plain:
      return "Plain";
    case NormalMapping:
      return "NormalMapping";
    case BumpMapping:
      return "BumpMapping";
    case ParallaxMapping:
      return "ParallaxMapping";
    case ReliefMapping:
      return "ReliefMapping";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
namespace
{
// Why a cone map cannot guide the search through @a depthImage's relief, "" if it can: the
// cones describe one surface, so the map must be the cone map of the same texels.
std::string ConeMapProblem(
  vtkImageData* coneImage, vtkDataArray* coneScalars, vtkTexture* cone, vtkImageData* depthImage)
{
  std::ostringstream err;
  int coneDims[3] = { 0, 0, 0 };
  int depthDims[3] = { 0, 0, 0 };
  if (coneImage)
  {
    coneImage->GetDimensions(coneDims);
  }
  depthImage->GetDimensions(depthDims);
  const int wrap = cone->GetWrap();
  if (!coneScalars || coneScalars->GetNumberOfComponents() != 2 ||
    (coneScalars->GetDataType() != VTK_FLOAT && coneScalars->GetDataType() != VTK_DOUBLE))
  {
    err << "The cone map must be an image of 2-component floats (apex depth, cone ratio); this "
        << "one has " << (coneScalars ? coneScalars->GetNumberOfComponents() : 0) << " component(s)"
        << (coneScalars ? std::string(" of ") + coneScalars->GetDataTypeAsString() : "")
        << ". Make it with vtkHeightMapToConeMap.";
  }
  else if (coneDims[0] != depthDims[0] || coneDims[1] != depthDims[1])
  {
    err << "The cone map is " << coneDims[0] << " x " << coneDims[1] << " texels but the relief's "
        << "depth map is " << depthDims[0] << " x " << depthDims[1]
        << ": make it with vtkHeightMapToConeMap from the same heights.";
  }
  else if (wrap != vtkTexture::Repeat && wrap != vtkTexture::ClampToEdge)
  {
    err << "The cone map's texture wraps with mode " << wrap << "; cone maps are made for Repeat "
        << "or ClampToEdge (vtkHeightMapToConeMap::Wrap).";
  }
  return err.str();
}

// What a technique reads, with the maps that are set.
struct Needs
{
  bool ReliefMap, ConeMap, NormalMap, HeightMap, Tangents;
};

Needs NeedsOf(int technique, vtkSurfaceDetailMapper* detail)
{
  // Relief reads its relief map if it has one, else the height map (with the normal map if
  // one is set); parallax reads the height map and, if set, the normal map.
  Needs needs;
  needs.ReliefMap = technique == ReliefMapping && detail->GetReliefMap() != nullptr;
  const bool heightRelief = technique == ReliefMapping && !needs.ReliefMap;
  needs.ConeMap = technique == ReliefMapping && detail->GetConeMap() != nullptr;
  needs.NormalMap = technique == NormalMapping ||
    ((technique == ParallaxMapping || heightRelief) && detail->GetNormalMap() != nullptr);
  needs.HeightMap = technique == BumpMapping || technique == ParallaxMapping || heightRelief;
  // Triplanar mapping builds its frames from the axes.
  needs.Tangents = !detail->GetTriplanar() &&
    (needs.NormalMap || needs.ReliefMap || (technique == BumpMapping && !detail->GetTangentFree()));
  return needs;
}
}

//------------------------------------------------------------------------------
std::string vtkSurfaceDetailShading::Problem(int technique, vtkPolyData* block, vtkActor* act) const
{
  const Needs needs = NeedsOf(technique, this->Detail);
  const bool usesReliefMap = needs.ReliefMap;
  const bool usesNormalMap = needs.NormalMap;
  const bool usesHeightMap = needs.HeightMap;
  const bool usesTangents = needs.Tangents;
  vtkPointData* pd = block->GetPointData();
  vtkDataArray* tangents = pd->GetTangents();
  vtkDataArray* tcoords = pd->GetTCoords();
  vtkImageData* normalImage = usesNormalMap ? TextureImage(this->Detail->GetNormalMap()) : nullptr;
  vtkImageData* heightImage = usesHeightMap ? TextureImage(this->Detail->GetHeightMap()) : nullptr;
  vtkImageData* reliefImage = usesReliefMap ? TextureImage(this->Detail->GetReliefMap()) : nullptr;
  vtkDataArray* reliefScalars = reliefImage ? reliefImage->GetPointData()->GetScalars() : nullptr;
  vtkImageData* coneImage = needs.ConeMap ? TextureImage(this->Detail->GetConeMap()) : nullptr;
  vtkDataArray* coneScalars = coneImage ? coneImage->GetPointData()->GetScalars() : nullptr;
  std::ostringstream err;
  double heightScale = 1.0;
  const bool triplanar = this->Detail->GetTriplanar();
  const char* name = technique == Plain ? "Triplanar mapping" : TechniqueName(technique);
  if (triplanar && (technique == ParallaxMapping || technique == ReliefMapping))
  {
    err << name << " needs texture coordinates: triplanar mapping projects colour, normal "
        << "and height maps (Plain, NormalMapping, BumpMapping) only. Turn Triplanar off.";
  }
  else if (act->GetProperty()->GetInterpolation() == VTK_FLAT)
  {
    err << name << " needs smooth shading; the actor's property has flat interpolation. "
        << "Use SetInterpolationToGouraud() or SetInterpolationToPhong().";
  }
  else if (!pd->GetNormals())
  {
    err << name << " needs point normals; the input has none. Generate them first "
        << "(vtkPolyDataNormals, or the source's GenerateNormals).";
  }
  else if (!triplanar && (!tcoords || tcoords->GetNumberOfComponents() != 2))
  {
    err << name << " needs 2-component texture coordinates; the input has "
        << (tcoords ? "texture coordinates with another number of components" : "none")
        << ". Generate them first (e.g. vtkParametricSurfaceSource).";
  }
  else if (usesTangents && (!tangents || !tangents->GetName()))
  {
    err << name << " needs point tangents (a named TANGENTS attribute); the input has "
        << (tangents ? "tangents without a name" : "none")
        << ". Generate tangents first (vtkParametricSurfaceSource with "
        << "GenerateTangents, or vtkMikkTSpaceTangents)"
        << (technique == BumpMapping ? ", or turn TangentFree on." : ".");
  }
  else if (usesNormalMap && !this->Detail->GetNormalMap())
  {
    err << name << " needs a normal map: call SetNormalMap().";
  }
  else if (usesNormalMap &&
    (!normalImage || !normalImage->GetPointData()->GetScalars() ||
      normalImage->GetPointData()->GetScalars()->GetNumberOfComponents() < 3))
  {
    err << "The normal map must be an image with 3 or 4 components (RGB = 0.5*n + 0.5); "
        << "this one has "
        << (normalImage && normalImage->GetPointData()->GetScalars()
               ? normalImage->GetPointData()->GetScalars()->GetNumberOfComponents()
               : 0)
        << ".";
  }
  else if (usesNormalMap &&
    !NormalMapTypeReadable(normalImage->GetPointData()->GetScalars(), this->Detail->GetNormalMap()))
  {
    err << "The normal map's scalars are "
        << normalImage->GetPointData()->GetScalars()->GetDataTypeAsString()
        << (this->Detail->GetNormalMap()->GetColorMode() == VTK_COLOR_MODE_DIRECT_SCALARS
               ? ""
               : " without SetColorModeToDirectScalars() on the texture")
        << ", which VTK's texture does not read as 0.5*n + 0.5: use unsigned char, or float "
        << "in [0,1] with SetColorModeToDirectScalars() (vtkImageShiftScale converts).";
  }
  else if (usesReliefMap && (!reliefScalars || reliefScalars->GetNumberOfComponents() != 4))
  {
    err << "The relief map must be an image with 4 components (RGB = 0.5*n + 0.5, A = depth)"
        << "; this one has " << (reliefScalars ? reliefScalars->GetNumberOfComponents() : 0)
        << ". Make it with vtkHeightMapToNormalMap and OutputRelief on.";
  }
  else if (usesReliefMap && !NormalMapTypeReadable(reliefScalars, this->Detail->GetReliefMap()))
  {
    err << "The relief map's scalars are " << reliefScalars->GetDataTypeAsString()
        << (this->Detail->GetReliefMap()->GetColorMode() == VTK_COLOR_MODE_DIRECT_SCALARS
               ? ""
               : " without SetColorModeToDirectScalars() on the texture")
        << ", which VTK's texture does not read as they are: use unsigned char, or float "
        << "in [0,1] with SetColorModeToDirectScalars().";
  }
  else if (usesHeightMap && !this->Detail->GetHeightMap())
  {
    err << name << " needs a height map: call SetHeightMap()"
        << (technique == ReliefMapping ? ", or give it a relief map (SetReliefMap)." : ".");
  }
  else if (usesHeightMap && (!heightImage || !heightImage->GetPointData()->GetScalars()))
  {
    err << "The height map texture has no image scalars: give it an input image.";
  }
  else if (usesHeightMap &&
    !vtkSurfaceDetail::HeightMapScale(
      heightImage->GetPointData()->GetScalars()->GetDataType(), heightScale))
  {
    err << "The height map's scalars are "
        << heightImage->GetPointData()->GetScalars()->GetDataTypeAsString() << ": "
        << vtkSurfaceDetail::HeightMapTypeAdvice() << ".";
  }
  else if (usesHeightMap &&
    this->Detail->GetHeightComponent() >= heightImage->GetPointData()->GetScalars()->GetNumberOfComponents())
  {
    err << "HeightComponent is " << this->Detail->GetHeightComponent() << " but the height map has "
        << heightImage->GetPointData()->GetScalars()->GetNumberOfComponents() << " component(s).";
  }
  else if (needs.ConeMap)
  {
    err << ConeMapProblem(coneImage, coneScalars, this->Detail->GetConeMap(),
      usesReliefMap ? reliefImage : heightImage);
  }
  return err.str();
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::Resolve(
  vtkSurfaceDetailMapper* detail, const std::vector<vtkPolyData*>& blocks, vtkActor* act)
{
  this->Detail = detail;
  this->ActiveTechnique = Plain;
  this->ActiveUsesTangents = false;
  this->ActiveUsesHandedness = false;
  this->ActiveUsesNormalMap = false;
  this->ActiveUsesHeightMap = false;
  this->ActiveUsesReliefMap = false;
  this->ActiveUsesConeMap = false;
  this->ActiveTriplanar = false;
  this->ActiveTriplanarColor = false;

  int technique = detail->GetTechnique();
  // The actor's colour texture is projected where the input has no texture coordinates
  // (where it has, VTK's own texturing applies it by them).
  vtkPolyData* first = blocks.empty() ? nullptr : blocks.front();
  bool triplanarColor = detail->GetTriplanar() && act->GetTexture() && first &&
    !first->GetPointData()->GetTCoords();
  std::string problem;
  for (vtkPolyData* block : blocks)
  {
    if ((technique != Plain || triplanarColor) && block && problem.empty())
    {
      problem = this->Problem(technique, block, act);
    }
  }
  if (!problem.empty())
  {
    problem += " Rendering without surface detail.";
    technique = Plain;
    triplanarColor = false;
  }
  if (problem != this->ReportedProblem)
  {
    this->ReportedProblem = problem;
    if (!problem.empty())
    {
      vtkErrorWithObjectMacro(this->Reporter, << problem);
    }
  }

  // Lighting off means no normal is ever read: nothing to do but draw as VTK does.
  if (!first || !act->GetProperty()->GetLighting())
  {
    technique = Plain;
    triplanarColor = false;
  }
  vtkPointData* pd = technique != Plain ? first->GetPointData() : nullptr;
  this->ActiveTechnique = pd ? technique : Plain;
  this->ActiveTriplanarColor = triplanarColor;
  this->ActiveTriplanar = detail->GetTriplanar() && (pd || triplanarColor);
  const Needs needs = NeedsOf(technique, detail);
  if (pd)
  {
    this->ActiveUsesTangents = needs.Tangents;
    this->ActiveUsesHandedness =
      needs.Tangents && vtkSurfaceDetailTangents::GetHandedness(pd) != nullptr;
    this->ActiveUsesNormalMap = needs.NormalMap;
    this->ActiveUsesHeightMap = needs.HeightMap;
    this->ActiveUsesReliefMap = needs.ReliefMap;
    this->ActiveUsesConeMap = needs.ConeMap;
  }

  const std::string handednessProblem =
    this->ActiveUsesTangents ? vtkSurfaceDetailTangents::GetHandednessProblem(pd) : "";
  if (handednessProblem != this->ReportedHandednessProblem)
  {
    this->ReportedHandednessProblem = handednessProblem;
    if (!handednessProblem.empty())
    {
      vtkWarningWithObjectMacro(this->Reporter, << handednessProblem);
    }
  }

  // The tangent attributes are uploaded only while a technique reads them.
  vtkDataArray* tangents = this->ActiveUsesTangents ? pd->GetTangents() : nullptr;
  this->TangentArray = tangents ? tangents->GetName() : "";
  this->HandednessArray =
    this->ActiveUsesHandedness ? vtkSurfaceDetailTangents::GetHandednessArrayName() : "";
}

//------------------------------------------------------------------------------
bool vtkSurfaceDetailShading::AppliesTo(bool triangles, bool normalsUploaded,
  bool tcoordsUploaded, int lightComplexity, vtkActor* act) const
{
  // Flat shading uploads no point normals (and then no normalMC to build the frame from).
  return (this->ActiveTechnique != Plain || this->ActiveTriplanarColor) && triangles &&
    normalsUploaded && (tcoordsUploaded || this->ActiveTriplanar) && lightComplexity > 0 &&
    act->GetProperty()->GetRepresentation() == VTK_SURFACE;
}

//------------------------------------------------------------------------------
std::string vtkSurfaceDetailShading::ShaderKey() const
{
  std::ostringstream key;
  key << this->ActiveTechnique << this->ActiveUsesTangents << this->ActiveUsesHandedness
      << this->ActiveUsesNormalMap << this->ActiveUsesHeightMap << this->ActiveUsesReliefMap
      << this->ActiveTriplanar << this->ActiveTriplanarColor;
  if (this->ActiveTechnique == ReliefMapping)
  {
    key << this->Detail->GetSelfShadowing() << this->Detail->GetDepthCorrection()
        << this->ActiveUsesConeMap;
  }
  return key.str();
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::BindMaps(vtkRenderer* ren)
{
  // Our maps are not the actor's or the property's textures, so we bind them ourselves
  // for the duration of the piece; SetUniforms reads their units.
  if (this->ActiveUsesNormalMap)
  {
    this->Detail->GetNormalMap()->Render(ren);
  }
  if (this->ActiveUsesReliefMap)
  {
    this->Detail->GetReliefMap()->Render(ren);
  }
  if (this->ActiveUsesHeightMap)
  {
    this->UploadHeightMap(ren);
    this->HeightTexture->Activate();
  }
  if (this->ActiveUsesConeMap)
  {
    this->UploadConeMap(ren);
    this->ConeTexture->Activate();
  }
}

//------------------------------------------------------------------------------
std::vector<double> vtkSurfaceDetailShading::Heights(vtkIdType& nonFinite) const
{
  // Resolve has refused the types and components this does not accept.
  vtkDataArray* scalars = this->Detail->GetHeightMap()->GetInput()->GetPointData()->GetScalars();
  double scale = 1.0;
  vtkSurfaceDetail::HeightMapScale(scalars->GetDataType(), scale);
  const int comp = this->Detail->GetHeightComponent();
  // Non-finite heights would turn whole bumps into NaN normals: they are read as 0.
  std::vector<double> values(static_cast<size_t>(scalars->GetNumberOfTuples()));
  nonFinite = 0;
  for (size_t k = 0; k < values.size(); ++k)
  {
    const double v = scale * scalars->GetComponent(static_cast<vtkIdType>(k), comp);
    nonFinite += std::isfinite(v) ? 0 : 1;
    values[k] = std::isfinite(v) ? v : 0.0;
  }
  return values;
}

//------------------------------------------------------------------------------
std::vector<float> vtkSurfaceDetailShading::ReliefDepths() const
{
  // The depth the relief reads: the relief map's alpha, or one minus the height.
  std::vector<double> depths;
  if (this->ActiveUsesReliefMap)
  {
    vtkDataArray* scalars = this->Detail->GetReliefMap()->GetInput()->GetPointData()->GetScalars();
    const double scale = scalars->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
    depths.resize(static_cast<size_t>(scalars->GetNumberOfTuples()));
    for (size_t k = 0; k < depths.size(); ++k)
    {
      depths[k] = scale * scalars->GetComponent(static_cast<vtkIdType>(k), 3);
    }
  }
  else
  {
    vtkIdType nonFinite = 0; // reported by the height map's own upload
    depths = this->Heights(nonFinite);
    std::transform(depths.begin(), depths.end(), depths.begin(), [](double h) { return 1.0 - h; });
  }
  std::vector<float> clamped(depths.size());
  std::transform(depths.begin(), depths.end(), clamped.begin(), [](double d) {
    return std::isfinite(d) ? static_cast<float>(std::min(std::max(d, 0.0), 1.0)) : 1.f;
  });
  return clamped;
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::UploadConeMap(vtkRenderer* ren)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkTexture* cone = this->Detail->GetConeMap();
  vtkImageData* image = cone->GetInput();
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  vtkTexture* depth =
    this->ActiveUsesReliefMap ? this->Detail->GetReliefMap() : this->Detail->GetHeightMap();
  const vtkMTimeType stamp = std::max({ image->GetMTime(), scalars->GetMTime(), cone->GetMTime(),
    depth->GetMTime(), depth->GetInput()->GetMTime(),
    depth->GetInput()->GetPointData()->GetScalars()->GetMTime() });
  if (!this->ConeTexture)
  {
    this->ConeTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  if (this->ConeTexture->GetContext() == window && stamp == this->ConeUploadStamp &&
    depth == this->ConeUploadDepth)
  {
    return;
  }
  int dims[3];
  image->GetDimensions(dims);
  const int w = dims[0], h = dims[1];
  const int wrap = cone->GetWrap();
  const std::vector<float> depths = this->ReliefDepths();
  // A texel that is not finite guides no step: apex at the top, no cone.
  auto apexAndRatio = [&](int i, int j, double& apex, double& ratio)
  {
    const vtkIdType k = static_cast<vtkIdType>(vtkSurfaceDetail::WrapIndex(j, h, wrap)) * w +
      vtkSurfaceDetail::WrapIndex(i, w, wrap);
    apex = scalars->GetComponent(k, 0);
    ratio = scalars->GetComponent(k, 1);
    const bool valid = std::isfinite(apex) && std::isfinite(ratio);
    apex = valid ? std::min(std::max(apex, 0.0), 1.0) : 0.0;
    ratio = valid ? std::max(ratio, 0.0) : 0.0;
  };
  // Texel (i,j): (depth, apex, square root of the ratio), read with linear filtering so that one
  // read gives the depth where the ray is and a cone for where it stands. The apex and the ratio
  // are the least over the texel and its eight neighbours: any blend of the four texels around
  // a point is then no higher an apex and no wider a cone than that point's own texel's. Eight
  // bits each, as a relief map holds its depth (and as texture units read fastest), the apex
  // and the ratio rounded toward the safe side (the ratio at most 1); the square root keeps
  // narrow cones apart.
  std::vector<unsigned char> bytes(4 * static_cast<size_t>(w) * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      double apex = 1.0, ratio = VTK_DOUBLE_MAX;
      for (int dj = -1; dj <= 1; ++dj)
      {
        for (int di = -1; di <= 1; ++di)
        {
          double a, r;
          apexAndRatio(i + di, j + dj, a, r);
          apex = std::min(apex, a);
          ratio = std::min(ratio, r);
        }
      }
      unsigned char* texel = &bytes[4 * (static_cast<size_t>(j) * w + i)];
      texel[0] = static_cast<unsigned char>(std::lround(255.0 * depths[static_cast<size_t>(j) * w + i]));
      // Half a step more: the rounded depths may lie that much above the exact ones.
      texel[1] = static_cast<unsigned char>(std::max(std::floor(255.0 * apex - 0.5), 0.0));
      texel[2] = static_cast<unsigned char>(std::floor(255.0 * std::sqrt(std::min(ratio, 1.0))));
      texel[3] = 255;
    }
  }
  this->ConeTexture->SetContext(window);
  this->ConeTexture->ResetFormatAndType();
  this->ConeTexture->Create2DFromRaw(w, h, 4, VTK_UNSIGNED_CHAR, bytes.data());
  this->ConeTexture->SetWrapS(wrap);
  this->ConeTexture->SetWrapT(wrap);
  this->ConeTexture->SetMinificationFilter(vtkTextureObject::Linear);
  this->ConeTexture->SetMagnificationFilter(vtkTextureObject::Linear);
  this->ConeUploadStamp = stamp;
  this->ConeUploadDepth = depth;
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::UploadHeightMap(vtkRenderer* ren)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkImageData* image = this->Detail->GetHeightMap()->GetInput();
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const vtkMTimeType stamp =
    std::max({ image->GetMTime(), scalars->GetMTime(), this->Detail->GetHeightMap()->GetMTime() });
  if (!this->HeightTexture)
  {
    this->HeightTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  // Bump mapping reads only the gradient: two channels instead of three is a third less
  // texture traffic per fragment. Parallax reads the height too (and the gradient when it
  // lights the relief without a normal map).
  const int components = this->ActiveTechnique == BumpMapping ? 2 : 3;
  if (this->HeightTexture->GetContext() == window && stamp == this->HeightUploadStamp &&
    this->Detail->GetDifferenceScheme() == this->HeightUploadDifferenceScheme &&
    components == this->HeightUploadComponents &&
    this->Detail->GetHeightComponent() == this->HeightUploadComponent)
  {
    return;
  }
  int dims[3];
  image->GetDimensions(dims);
  const int w = dims[0], h = dims[1];
  const int comp = this->Detail->GetHeightComponent();
  vtkIdType nonFinite = 0;
  const std::vector<double> values = this->Heights(nonFinite);
  if (nonFinite > 0)
  {
    vtkWarningWithObjectMacro(this->Reporter, << "The height map has " << nonFinite
                    << " non-finite values (NaN or infinite); they are read as height 0.");
  }
  // Texel (i,j) holds (h, dh/ds, dh/dt), or (dh/ds, dh/dt) for bump mapping, the derivatives per
  // unit of texture coordinate by forward or central differences with the texture's own wrap mode.
  // Differences of linearly interpolated heights taken one texel apart equal the linear
  // interpolation of these texel differences (both use the same weights), so one lookup gives
  // exactly what the classic three-lookup Cg code computes, at a third of the texture traffic. With
  // ClampToBorder the height outside is the border colour's HeightComponent and its
  // differences are 0 (the sampler's border below): the identity holds there as well.
  const int wrap = this->Detail->GetHeightMap()->GetWrap();
  const bool border = wrap == vtkTexture::ClampToBorder;
  const double borderHeight = this->Detail->GetHeightMap()->GetBorderColor()[comp];
  auto height = [&](int i, int j)
  {
    if (border && (i < 0 || i >= w || j < 0 || j >= h))
    {
      return borderHeight;
    }
    i = vtkSurfaceDetail::WrapIndex(i, w, wrap);
    j = vtkSurfaceDetail::WrapIndex(j, h, wrap);
    return values[static_cast<size_t>(j) * w + i];
  };
  const bool central = this->Detail->GetDifferenceScheme() == Central;
  const int back = central ? 1 : 0;
  const double span = central ? 2.0 : 1.0;
  const int gradient = components - 2; // the channel of dh/ds
  std::vector<float> texels(components * static_cast<size_t>(w) * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      float* texel = &texels[components * (static_cast<size_t>(j) * w + i)];
      if (gradient > 0)
      {
        texel[0] = static_cast<float>(height(i, j));
      }
      texel[gradient] = static_cast<float>((height(i + 1, j) - height(i - back, j)) * w / span);
      texel[gradient + 1] = static_cast<float>((height(i, j + 1) - height(i, j - back)) * h / span);
    }
  }
  this->HeightTexture->SetContext(window);
  this->HeightTexture->SetRequireTextureFloat(true);
  // The texture object keeps the internal format of its last upload unless told to forget
  // it, which would read a 3-channel upload as 2 channels after a switch from bump mapping.
  this->HeightTexture->ResetFormatAndType();
  this->HeightTexture->Create2DFromRaw(w, h, components, VTK_FLOAT, texels.data());
  // vtkTexture and vtkTextureObject number their wrap modes alike.
  this->HeightTexture->SetWrapS(this->Detail->GetHeightMap()->GetWrap());
  this->HeightTexture->SetWrapT(this->Detail->GetHeightMap()->GetWrap());
  const float borderFirst = components == 3 ? static_cast<float>(borderHeight) : 0.f;
  this->HeightTexture->SetBorderColor(borderFirst, 0.f, 0.f, 0.f);
  const int filter =
    this->Detail->GetHeightMap()->GetInterpolate() ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
  this->HeightTexture->SetMinificationFilter(filter);
  this->HeightTexture->SetMagnificationFilter(filter);
  this->HeightUploadStamp = stamp;
  this->HeightUploadDifferenceScheme = this->Detail->GetDifferenceScheme();
  this->HeightUploadComponents = components;
  this->HeightUploadComponent = comp;
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::UnbindMaps(vtkRenderer* ren)
{
  if (this->ActiveUsesHeightMap)
  {
    this->HeightTexture->Deactivate();
  }
  if (this->ActiveUsesConeMap)
  {
    this->ConeTexture->Deactivate();
  }
  if (this->ActiveUsesNormalMap)
  {
    this->Detail->GetNormalMap()->PostRender(ren);
  }
  if (this->ActiveUsesReliefMap)
  {
    this->Detail->GetReliefMap()->PostRender(ren);
  }
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::ReleaseGraphicsResources(vtkWindow* win)
{
  // The maps are the settings' own textures, which their mapper releases.
  if (this->HeightTexture)
  {
    this->HeightTexture->ReleaseGraphicsResources(win);
  }
  if (this->ConeTexture)
  {
    this->ConeTexture->ReleaseGraphicsResources(win);
  }
  this->ConeUploadStamp = 0;
  this->HeightUploadStamp = 0;
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::AddTags(std::map<vtkShader::Type, vtkShader*>& shaders) const
{
  {
    std::string vs = shaders[vtkShader::Vertex]->GetSource();
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    vtkShaderProgram::Substitute(
      vs, "//VTK::Normal::Dec", std::string(DecTag) + "\n//VTK::Normal::Dec");
    vtkShaderProgram::Substitute(
      vs, "//VTK::Normal::Impl", std::string(VSImplTag) + "\n  //VTK::Normal::Impl");
    vtkShaderProgram::Substitute(
      fs, "//VTK::Normal::Dec", std::string(DecTag) + "\n//VTK::Normal::Dec");
    // The texture coordinate (parallax) is settled before anything samples a texture, and
    // the normal after VTK has interpolated it but before its lighting code reads it.
    vtkShaderProgram::Substitute(
      fs, "//VTK::Color::Impl", std::string(TCoordImplTag) + "\n  //VTK::Color::Impl");
    vtkShaderProgram::Substitute(
      fs, "//VTK::Light::Impl", std::string(NormalImplTag) + "\n  //VTK::Light::Impl");
    // A projected colour texture modulates the lit colour where VTK's own texturing would.
    vtkShaderProgram::Substitute(
      fs, "//VTK::TCoord::Impl", std::string(TriplanarColorTag) + "\n  //VTK::TCoord::Impl");
    shaders[vtkShader::Vertex]->SetSource(vs);
    shaders[vtkShader::Fragment]->SetSource(fs);
  }
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::ReplaceNormal(std::map<vtkShader::Type, vtkShader*>& shaders) const
{
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();

  // The frame is built per vertex in the mesh's coordinates and sent as normalMatrix*T and
  // normalMatrix*B (see vtkSurfaceDetailTangentFrameFS.glsl for why not MCVCMatrix*T).
  std::string vsDec;
  std::string vsImpl;
  std::string fsDec;
  if (this->ActiveUsesTangents)
  {
    // Without a handedness array, w = +1 as VTK takes it.
    vsDec += this->ActiveUsesHandedness ? "in float sdHandednessMC;\n"
                                        : "const float sdHandednessMC = 1.0;\n";
    vsDec +=
      "in vec3 sdTangentMC;\nout vec3 sdTangentVCVSOutput;\nout vec3 sdBitangentVCVSOutput;\n";
    vsImpl += "{\n"
              "    vec3 sdN = normalize(normalMC);\n"
              "    vec3 sdT = sdTangentMC - sdN * dot(sdN, sdTangentMC);\n"
              "    float sdLen = length(sdT);\n"
              "    sdT = sdLen > 0.0 ? sdT / sdLen : vec3(0.0);\n"
              "    vec3 sdB = (sdHandednessMC < 0.0 ? -1.0 : 1.0) * cross(sdN, sdT);\n"
              "    float sdNLen = length(normalMatrix * sdN);\n"
              "    sdTangentVCVSOutput = (normalMatrix * sdT) / sdNLen;\n"
              "    sdBitangentVCVSOutput = (normalMatrix * sdB) / sdNLen;\n"
              "  }\n";
    fsDec += "in vec3 sdTangentVCVSOutput;\nin vec3 sdBitangentVCVSOutput;\n";
  }
  if (this->ActiveTriplanar)
  {
    // Position and normal in the triplanar space (the object's or the world's), and the map
    // from that space's normals to view coordinates: normalMatrix after the way back to the
    // object's normals.
    vsDec += "uniform mat4 sdTriplanarMatrix;\nuniform mat3 sdTriplanarNormalMatrix;\n"
             "uniform mat3 sdTriplanarToObjectNormal;\n"
             "out vec3 sdTriplanarPositionVSOutput;\nout vec3 sdTriplanarNormalVSOutput;\n"
             "out mat3 sdTriplanarToViewVSOutput;\n";
    vsImpl += "sdTriplanarPositionVSOutput = (sdTriplanarMatrix * vertexMC).xyz;\n"
              "  sdTriplanarNormalVSOutput = sdTriplanarNormalMatrix * normalMC;\n"
              "  sdTriplanarToViewVSOutput = normalMatrix * sdTriplanarToObjectNormal;\n";
    fsDec += "in mat3 sdTriplanarToViewVSOutput;\n";
    fsDec += this->ActiveTriplanarColor ? "#define SD_TRIPLANAR_COLOR\n" : "";
    fsDec += this->ActiveUsesNormalMap ? "#define SD_TRIPLANAR_NORMAL_MAP\n" : "";
    fsDec += this->ActiveTechnique == BumpMapping ? "#define SD_TRIPLANAR_BUMP\n" : "";
  }
  const bool marches =
    this->ActiveTechnique == ParallaxMapping || this->ActiveTechnique == ReliefMapping;
  if (marches)
  {
    // A depth D along the unit object normal n is the view vector D*M*n (M the 3x3 of
    // MCVCMatrix); its part along the unit view normal N = normalMatrix*n/|normalMatrix*n|,
    // with normalMatrix = M^-T, is D*(M n).(M^-T n)/|M^-T n| = D/|normalMatrix*n|. That,
    // not |M n|, is the depth below the surface that the ray test needs.
    vsDec += "out float sdDepthUnitVCVSOutput;\n";
    vsImpl += "sdDepthUnitVCVSOutput = 1.0 / length(normalMatrix * normalize(normalMC));\n";
    fsDec += "in float sdDepthUnitVCVSOutput;\n";
  }
  if (this->ActiveUsesTangents)
  {
    fsDec += vtkSurfaceDetailTangentFrameFS;
  }
  if (this->ActiveUsesNormalMap || this->ActiveUsesReliefMap)
  {
    // A relief map is read as a normal map (its RGB) through the same sampler.
    fsDec += vtkSurfaceDetailNormalCoding;
    fsDec += vtkSurfaceDetailNormalMapFS;
  }
  if (this->ActiveUsesHeightMap)
  {
    // Where UploadHeightMap put the gradient (dh/ds, dh/dt).
    fsDec += this->ActiveTechnique == BumpMapping ? "#define SD_GRADIENT rg\n"
                                                  : "#define SD_GRADIENT gb\n";
    fsDec += vtkSurfaceDetailBumpFS;
  }
  if (this->ActiveTriplanar)
  {
    fsDec += vtkSurfaceDetailTriplanarFS;
  }
  if (this->ActiveTechnique == ParallaxMapping)
  {
    fsDec += vtkSurfaceDetailParallaxFS;
  }
  if (this->ActiveTechnique == ReliefMapping)
  {
    // Where the depth is read: the relief map's alpha, or one minus the height.
    fsDec += this->ActiveUsesReliefMap
      ? "#define SD_RELIEF_SAMPLER sdNormalMap\n"
        "#define SD_RELIEF_DEPTH(tc) textureLod(sdNormalMap, tc, sdReliefLod).a\n"
      : "#define SD_RELIEF_SAMPLER sdHeightMap\n"
        "#define SD_RELIEF_DEPTH(tc) (1.0 - textureLod(sdHeightMap, tc, sdReliefLod).r)\n";
    fsDec += vtkSurfaceDetailReliefFS;
    fsDec += this->ActiveUsesConeMap ? vtkSurfaceDetailReliefConeFS : vtkSurfaceDetailReliefLinearFS;
    if (this->Detail->GetSelfShadowing())
    {
      fsDec += vtkSurfaceDetailReliefShadowFS;
    }
    if (this->Detail->GetDepthCorrection())
    {
      fsDec += vtkSurfaceDetailReliefDepthFS;
    }
  }
  vtkShaderProgram::Substitute(vs, DecTag, vsDec + DecTag);
  vtkShaderProgram::Substitute(vs, VSImplTag, vsImpl + VSImplTag);
  vtkShaderProgram::Substitute(fs, DecTag, fsDec + DecTag);
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::ReplaceLight(std::map<vtkShader::Type, vtkShader*>& shaders) const
{
  // VTK's lighting (headlight, light kit, positional and spot lights) reads
  // normalVCVSOutput: replacing it there is all the lighting needs.
  std::string nTS;
  if (this->ActiveTriplanar)
  {
    // nTS stays empty: the triplanar branch below builds the normal.
  }
  else if (this->ActiveUsesNormalMap || this->ActiveUsesReliefMap)
  {
    nTS = "sdNormalMapTS(tcoordVCVSOutput)";
  }
  else if (this->ActiveUsesTangents)
  {
    nTS = "sdBumpTS(tcoordVCVSOutput)";
  }
  // VTK has flipped the normal on back faces; the frame is built for the front face and
  // the result flipped back.
  std::string impl = "// SurfaceDetail: the detail normal, in view coordinates\n  ";
  if (this->ActiveTriplanar && this->ActiveTechnique == Plain)
  {
    impl.clear(); // a projected colour texture only
  }
  else if (this->ActiveTriplanar)
  {
    // The triplanar normal of the front face, taken to view coordinates.
    // The colour is read here too, once, and applied where VTK applies textures.
    impl += "{\n"
            "    vec3 sdN = normalize(sdTriplanarNormalVSOutput);\n"
            "    sdTriplanarSample(sdTriplanarPositionVSOutput, sdN);\n"
            "    vec3 sdD = sdTriplanarToViewVSOutput * sdTriplanarDetail;\n"
            "    float sdLen2 = dot(sdD, sdD);\n"
            "    normalVCVSOutput = sdLen2 > 0.0 ? sdD * inversesqrt(sdLen2)\n"
            "      : (gl_FrontFacing ? normalVCVSOutput : -normalVCVSOutput);\n"
            "    if (!gl_FrontFacing) { normalVCVSOutput = -normalVCVSOutput; }\n"
            "  }\n";
  }
  else if (!nTS.empty())
  {
    impl += "normalVCVSOutput = sdTangentToView(" + nTS +
      ", gl_FrontFacing ? normalVCVSOutput : -normalVCVSOutput, sdTangentVCVSOutput, "
      "sdBitangentVCVSOutput);\n"
      "  if (!gl_FrontFacing) { normalVCVSOutput = -normalVCVSOutput; }\n";
  }
  else if (this->ActiveTechnique == ReliefMapping)
  {
    // The relief's own normal, at the hit, for the front face the march used.
    impl += "normalVCVSOutput = sdReliefHeightNormal(tcoordVCVSOutput, "
            "textureLod(sdHeightMap, tcoordVCVSOutput, sdReliefLod).gb);\n"
            "  if (!gl_FrontFacing) { normalVCVSOutput = -normalVCVSOutput; }\n";
  }
  else
  {
    // The surface gradient is that of the front face, whichever face is drawn.
    impl += "normalVCVSOutput = sdBumpSurfaceGradient(gl_FrontFacing ? normalVCVSOutput : "
            "-normalVCVSOutput, vertexVC.xyz, tcoordVCVSOutput, "
            "sdHeightGradient(tcoordVCVSOutput));\n"
            "  if (!gl_FrontFacing) { normalVCVSOutput = -normalVCVSOutput; }\n";
  }
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(fs, NormalImplTag, impl);
  if (this->ActiveTechnique == ReliefMapping && this->Detail->GetSelfShadowing())
  {
    this->AddReliefShadows(fs);
  }
  shaders[vtkShader::Fragment]->SetSource(fs);
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::AddReliefShadows(std::string& fs) const
{
  // VTK 9.1 writes one diffuse factor df per light: the headlight's from normal.z, a light
  // kit's from lightDirectionVC<i>, positional and spot lights' from vertLightDirectionVC,
  // each followed by a specular factor sf = sign(df)*... (or pow(df, ...) for the
  // headlight). Each df is passed through sdShadowed with the direction toward its light,
  // and each sign(df) specular factor gets the same visibility.
  const std::regex sceneLight(
    "(\\bdf = max\\(0\\.0, ?(?:attenuation\\*)?dot\\(normalVCVSOutput, -(\\w+)\\)\\);)");
  const std::string headlight = "float df = max(0.0,normalVCVSOutput.z);";
  auto lights = std::distance(std::sregex_iterator(fs.begin(), fs.end(), sceneLight), {});
  fs = std::regex_replace(fs, sceneLight, "$1\n  df = sdShadowed(df, -$2);");
  if (vtkShaderProgram::Substitute(
        fs, headlight, headlight + "\n  df = sdShadowed(df, vec3(0.0, 0.0, 1.0));"))
  {
    ++lights;
  }
  vtkShaderProgram::Substitute(fs, "sf = sign(df)*", "sf = sdLightVisibility*sign(df)*", true);
  if (lights == 0)
  {
    // Only a VTK whose lighting code differs from 9.1's gets here.
    vtkErrorWithObjectMacro(this->Reporter, "No light of VTK's fragment shader was recognised: the relief is drawn "
                  "without self-shadowing.");
  }
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::ReplaceTCoord(std::map<vtkShader::Type, vtkShader*>& shaders) const
{
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  if (this->ActiveTriplanar)
  {
    // No texture coordinate is read or moved; the projected colour modulates the lit colour
    // as VTK's texturing does (gl_FragData[0] * tcolor).
    vtkShaderProgram::Substitute(vs, DecTag, "");
    vtkShaderProgram::Substitute(vs, VSImplTag, "");
    vtkShaderProgram::Substitute(fs, DecTag, "");
    vtkShaderProgram::Substitute(fs, TCoordImplTag, "");
    // With a normal technique, the lighting code has sampled the colour already.
    std::string color;
    if (this->ActiveTriplanarColor && this->ActiveTechnique == Plain)
    {
      color = "sdTriplanarSample(sdTriplanarPositionVSOutput, "
              "normalize(sdTriplanarNormalVSOutput));\n  ";
    }
    if (this->ActiveTriplanarColor)
    {
      color += "gl_FragData[0] = gl_FragData[0] * sdTriplanarColor;";
    }
    vtkShaderProgram::Substitute(fs, TriplanarColorTag, color);
    shaders[vtkShader::Vertex]->SetSource(vs);
    shaders[vtkShader::Fragment]->SetSource(fs);
    return;
  }
  vtkShaderProgram::Substitute(fs, TriplanarColorTag, "");

  // Every texture lookup, VTK's colour texture included, reads tcoordVCVSOutput. We make it
  // a plain variable fed from our own varying, so that parallax can move it for all of them.
  // With an actor texture VTK has declared the varying already (and applied any texture
  // transform); without one we pass the "tcoord" attribute through ourselves.
  const std::string fsDecl = "in vec2 sdTCoordVCVSOutput;\nvec2 tcoordVCVSOutput;\n";
  if (vs.find("tcoordVCVSOutput") != std::string::npos)
  {
    // Whole identifiers only: VTK's seamless-texture varyings (tcoordVCVSOutputU1, ...) keep
    // their names.
    vs = std::regex_replace(vs, std::regex("\\btcoordVCVSOutput\\b"), "sdTCoordVCVSOutput");
    if (!vtkShaderProgram::Substitute(fs, "in vec2 tcoordVCVSOutput;\n", fsDecl))
    {
      // Only a VTK whose shader text differs from 9.1's gets here; say so rather than
      // leave a shader that does not compile without explanation.
      vtkErrorWithObjectMacro(this->Reporter, "VTK's fragment shader does not declare \"in vec2 tcoordVCVSOutput;\" "
                    "as VTK 9.1 does; the surface-detail shader will not compile.");
    }
    vtkShaderProgram::Substitute(vs, DecTag, "");
    vtkShaderProgram::Substitute(vs, VSImplTag, "");
    vtkShaderProgram::Substitute(fs, DecTag, "");
  }
  else
  {
    vtkShaderProgram::Substitute(vs, DecTag, "in vec2 tcoord;\nout vec2 sdTCoordVCVSOutput;\n");
    vtkShaderProgram::Substitute(vs, VSImplTag, "sdTCoordVCVSOutput = tcoord;\n");
    vtkShaderProgram::Substitute(fs, DecTag, fsDecl);
  }

  std::string impl = "tcoordVCVSOutput = sdTCoordVCVSOutput;\n";
  if (this->ActiveTechnique == ReliefMapping)
  {
    impl += "  tcoordVCVSOutput = sdReliefTCoord(sdTCoordVCVSOutput, vertexVC.xyz,\n"
            "    normalize(gl_FrontFacing ? normalVCVSOutput : -normalVCVSOutput),\n"
            "    sdDepthUnitVCVSOutput);\n";
    if (this->Detail->GetDepthCorrection())
    {
      impl += "  gl_FragDepth = sdReliefFragDepth(vertexVC.xyz);\n";
    }
  }
  if (this->ActiveTechnique == ParallaxMapping)
  {
    // VTK has not yet redeclared normalVCVSOutput (normalised, flipped on back faces).
    impl += "  tcoordVCVSOutput = sdParallaxTCoord(sdTCoordVCVSOutput, vertexVC.xyz,\n"
            "    normalize(gl_FrontFacing ? normalVCVSOutput : -normalVCVSOutput),\n"
            "    sdDepthUnitVCVSOutput);\n";
  }
  vtkShaderProgram::Substitute(fs, TCoordImplTag, impl);
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::SetUniforms(vtkShaderProgram* program, vtkRenderer* ren,
  vtkActor* act, vtkOpenGLVertexBufferObjectGroup* vbos) const
{
  if (this->ActiveTriplanar)
  {
    this->SetTriplanarUniforms(program, act, vbos);
  }
  if (this->ActiveUsesNormalMap)
  {
    program->SetUniformi("sdNormalMap", TextureUnit(this->Detail->GetNormalMap()));
    const float strength = static_cast<float>(this->Detail->GetNormalScale());
    const float scaleXY[2] = { strength, this->Detail->GetGreenUp() ? strength : -strength };
    program->SetUniform2f("sdNormalScaleXY", scaleXY);
  }
  if (this->ActiveUsesHeightMap)
  {
    program->SetUniformi("sdHeightMap", this->HeightTexture->GetTextureUnit());
    program->SetUniformf("sdBumpScale", static_cast<float>(this->Detail->GetBumpScale()));
  }
  if (this->ActiveTechnique == ParallaxMapping || this->ActiveTechnique == ReliefMapping)
  {
    program->SetUniformf("sdDepthScale", static_cast<float>(this->Detail->GetDepthScale()));
    program->SetUniformi(
      "sdCameraParallel", ren->GetActiveCamera()->GetParallelProjection() ? 1 : 0);
  }
  if (this->ActiveUsesReliefMap)
  {
    program->SetUniformi("sdNormalMap", TextureUnit(this->Detail->GetReliefMap()));
    const float scaleXY[2] = { 1.f, this->Detail->GetGreenUp() ? 1.f : -1.f };
    program->SetUniform2f("sdNormalScaleXY", scaleXY);
  }
  if (this->ActiveTechnique == ReliefMapping)
  {
    program->SetUniformi("sdLinearSearchSteps", this->Detail->GetLinearSearchSteps());
    program->SetUniformi("sdBinarySearchSteps", this->Detail->GetBinarySearchSteps());
    program->SetUniformi("sdAdaptiveSteps", this->Detail->GetAdaptiveSteps() ? 1 : 0);
    if (this->ActiveUsesConeMap)
    {
      program->SetUniformi("sdConeMap", this->ConeTexture->GetTextureUnit());

    }
    if (this->Detail->GetDepthCorrection())
    {
      vtkMatrix4x4* wcvc;
      vtkMatrix3x3* normalMatrix;
      vtkMatrix4x4* vcdc;
      vtkMatrix4x4* wcdc;
      vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera())
        ->GetKeyMatrices(ren, wcvc, normalMatrix, vcdc, wcdc);
      program->SetUniformMatrix("sdVCDCMatrix", vcdc);
    }
  }
}

//------------------------------------------------------------------------------
void vtkSurfaceDetailShading::SetTriplanarUniforms(
  vtkShaderProgram* program, vtkActor* act, vtkOpenGLVertexBufferObjectGroup* vbos) const
{
  // vertexMC is the point shifted and scaled by VTK (vtkOpenGLVertexBufferObject): the
  // matrix first undoes that, then, in world space, applies the actor's matrix.
  vtkNew<vtkMatrix4x4> toSpace;
  vtkOpenGLVertexBufferObject* points = vbos ? vbos->GetVBO("vertexMC") : nullptr;
  if (points && points->GetCoordShiftAndScaleEnabled())
  {
    const std::vector<double>& shift = points->GetShift();
    const std::vector<double>& scale = points->GetScale();
    for (int i = 0; i < 3; ++i)
    {
      toSpace->SetElement(i, i, 1.0 / scale[i]);
      toSpace->SetElement(i, 3, shift[i]);
    }
  }
  vtkNew<vtkMatrix3x3> normalToSpace;
  vtkNew<vtkMatrix3x3> spaceToObjectNormal;
  if (this->Detail->GetTriplanarSpace() == vtkSurfaceDetailMapper::WorldSpace)
  {
    vtkMatrix4x4* model = act->GetMatrix();
    vtkMatrix4x4::Multiply4x4(model, toSpace, toSpace);
    // Normals go to the world with the inverse transpose of the model matrix's 3x3 part, and
    // come back with its transpose.
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        spaceToObjectNormal->SetElement(i, j, model->GetElement(j, i));
        normalToSpace->SetElement(i, j, model->GetElement(i, j));
      }
    }
    normalToSpace->Invert();
    normalToSpace->Transpose();
  }
  // GLSL reads matrices column by column.
  float matrix[16];
  float normals[9];
  float back[9];
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      matrix[4 * j + i] = static_cast<float>(toSpace->GetElement(i, j));
      if (i < 3 && j < 3)
      {
        normals[3 * j + i] = static_cast<float>(normalToSpace->GetElement(i, j));
        back[3 * j + i] = static_cast<float>(spaceToObjectNormal->GetElement(i, j));
      }
    }
  }
  program->SetUniformMatrix4x4("sdTriplanarMatrix", matrix);
  program->SetUniformMatrix3x3("sdTriplanarNormalMatrix", normals);
  program->SetUniformMatrix3x3("sdTriplanarToObjectNormal", back);
  program->SetUniformf("sdTriplanarScale", static_cast<float>(this->Detail->GetTriplanarScale()));
  program->SetUniformf(
    "sdTriplanarSharpness", static_cast<float>(this->Detail->GetTriplanarSharpness()));
  if (this->ActiveTriplanarColor)
  {
    program->SetUniformi("sdTriplanarColorTexture", TextureUnit(act->GetTexture()));
  }
}
