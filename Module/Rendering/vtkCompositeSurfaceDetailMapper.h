// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkCompositeSurfaceDetailMapper
 * @brief   Surface detail on every block of a composite dataset of polydata.
 *
 * vtkCompositeSurfaceDetailMapper is to vtkSurfaceDetailMapper what
 * vtkCompositePolyDataMapper2 is to vtkOpenGLPolyDataMapper: it draws a
 * vtkMultiBlockDataSet, vtkPartitionedDataSetCollection or plain vtkPolyData, batching blocks
 * as vtkCompositePolyDataMapper2 does (block colours, opacities, visibilities and picking
 * included), and shades every block with the same technique, maps and settings. ParaView
 * draws geometry through this kind of mapper, so its "Surface Detail" representation uses it.
 *
 * The technique and its settings are those of a vtkSurfaceDetailMapper, GetDetail(): set
 * them there, with the same methods and meanings; that mapper's own input is not used. One
 * such settings object may be shared by several composite mappers (SetDetail), as ParaView's
 * full-resolution and level-of-detail mappers do.
 *
 * Each block must carry what the technique needs (point normals, 2-component texture
 * coordinates and, where the technique reads them, tangents with the same array names in every
 * block); where one block lacks it, the error names the problem once and the blocks that are
 * drawn together with it are drawn without surface detail, as vtkSurfaceDetailMapper does.
 *
 * @sa vtkSurfaceDetailMapper vtkCompositePolyDataMapper2
 */

#ifndef vtkCompositeSurfaceDetailMapper_h
#define vtkCompositeSurfaceDetailMapper_h

#include "SurfaceDetailRenderingModule.h" // For export macro
#include "vtkCompositePolyDataMapper2.h"

class vtkSurfaceDetailMapper;

class SURFACEDETAILRENDERING_EXPORT vtkCompositeSurfaceDetailMapper
  : public vtkCompositePolyDataMapper2
{
public:
  static vtkCompositeSurfaceDetailMapper* New();
  vtkTypeMacro(vtkCompositeSurfaceDetailMapper, vtkCompositePolyDataMapper2);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The technique, maps and settings drawn on every block. Never null: a new mapper has its
   * own, with vtkSurfaceDetailMapper's defaults; setting nullptr gives it a new one.
   */
  void SetDetail(vtkSurfaceDetailMapper* detail);
  vtkGetObjectMacro(Detail, vtkSurfaceDetailMapper);
  ///@}

  /**
   * Releases the maps' textures as well as the blocks' buffers and shaders.
   */
  void ReleaseGraphicsResources(vtkWindow* win) override;

protected:
  vtkCompositeSurfaceDetailMapper();
  ~vtkCompositeSurfaceDetailMapper() override;

  vtkCompositeMapperHelper2* CreateHelper() override;

  vtkSurfaceDetailMapper* Detail = nullptr;

private:
  vtkCompositeSurfaceDetailMapper(const vtkCompositeSurfaceDetailMapper&) = delete;
  void operator=(const vtkCompositeSurfaceDetailMapper&) = delete;
};

#endif
