// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSurfaceDetailRepresentation.h"

#include "vtkCompositeSurfaceDetailMapper.h"
#include "vtkObjectFactory.h"
#include "vtkSurfaceDetailMapper.h"
#include "vtkTexture.h"

vtkStandardNewMacro(vtkSurfaceDetailRepresentation);

//------------------------------------------------------------------------------
vtkSurfaceDetailRepresentation::vtkSurfaceDetailRepresentation()
{
  // The superclass made plain composite mappers and wired them; ours replace them, sharing
  // one set of settings, and are wired the same way.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  auto* mapper = vtkCompositeSurfaceDetailMapper::New();
  auto* lodMapper = vtkCompositeSurfaceDetailMapper::New();
  lodMapper->SetDetail(mapper->GetDetail());
  this->Mapper = mapper;
  this->LODMapper = lodMapper;
  this->SetupDefaults();
}

//------------------------------------------------------------------------------
vtkSurfaceDetailMapper* vtkSurfaceDetailRepresentation::GetDetail()
{
  return static_cast<vtkCompositeSurfaceDetailMapper*>(this->Mapper)->GetDetail();
}

// Each setter changes the shared settings and marks the representation modified, so that the
// view renders again.
#define vtkSurfaceDetailForward(name, type)                                                      \
  void vtkSurfaceDetailRepresentation::Set##name(type value)                                     \
  {                                                                                              \
    this->GetDetail()->Set##name(value);                                                         \
    this->Modified();                                                                            \
  }

vtkSurfaceDetailForward(Technique, int);
vtkSurfaceDetailForward(NormalMap, vtkTexture*);
vtkSurfaceDetailForward(HeightMap, vtkTexture*);
vtkSurfaceDetailForward(ReliefMap, vtkTexture*);
vtkSurfaceDetailForward(ConeMap, vtkTexture*);
vtkSurfaceDetailForward(HeightComponent, int);
vtkSurfaceDetailForward(NormalScale, double);
vtkSurfaceDetailForward(GreenUp, bool);
vtkSurfaceDetailForward(BumpScale, double);
vtkSurfaceDetailForward(DifferenceScheme, int);
vtkSurfaceDetailForward(TangentFree, bool);
vtkSurfaceDetailForward(Triplanar, bool);
vtkSurfaceDetailForward(TriplanarSpace, int);
vtkSurfaceDetailForward(TriplanarScale, double);
vtkSurfaceDetailForward(TriplanarSharpness, double);
vtkSurfaceDetailForward(DepthScale, double);
vtkSurfaceDetailForward(LinearSearchSteps, int);
vtkSurfaceDetailForward(BinarySearchSteps, int);
vtkSurfaceDetailForward(AdaptiveSteps, bool);
vtkSurfaceDetailForward(SelfShadowing, bool);
vtkSurfaceDetailForward(DepthCorrection, bool);
#undef vtkSurfaceDetailForward

//------------------------------------------------------------------------------
void vtkSurfaceDetailRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Detail:\n";
  this->GetDetail()->PrintSelf(os, indent.GetNextIndent());
}
