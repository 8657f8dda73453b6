// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkOIIOUtilities.h
 * @brief  Private to SurfaceDetail::IO: the one mapping between VTK and OpenImageIO pixel
 *         types, and how OpenImageIO's errors are fetched, shared by reader and writer.
 *
 * Not installed: OpenImageIO is a private dependency of the module, so no public header
 * may include it.
 */

#ifndef vtkOIIOUtilities_h
#define vtkOIIOUtilities_h

#include "vtkType.h"

#include <OpenImageIO/imageio.h>

#include <string>

namespace vtkOIIOUtilities
{

/// The VTK scalar type that holds a channel of type @a t without loss, or -1 if none does.
inline int VTKTypeOf(OIIO::TypeDesc t)
{
  switch (t.basetype)
  {
    case OIIO::TypeDesc::UINT8:
      return VTK_UNSIGNED_CHAR;
    case OIIO::TypeDesc::INT8:
      return VTK_SIGNED_CHAR;
    case OIIO::TypeDesc::UINT16:
      return VTK_UNSIGNED_SHORT;
    case OIIO::TypeDesc::INT16:
      return VTK_SHORT;
    case OIIO::TypeDesc::UINT32:
      return VTK_UNSIGNED_INT;
    case OIIO::TypeDesc::INT32:
      return VTK_INT;
    case OIIO::TypeDesc::HALF: // VTK has no half type; float holds every half exactly.
    case OIIO::TypeDesc::FLOAT:
      return VTK_FLOAT;
    case OIIO::TypeDesc::DOUBLE:
      return VTK_DOUBLE;
    default:
      return -1;
  }
}

/// The OIIO type of VTK scalar type @a vtkType, or UNKNOWN if OIIO has none.
inline OIIO::TypeDesc OIIOTypeOf(int vtkType)
{
  switch (vtkType)
  {
    case VTK_UNSIGNED_CHAR:
      return OIIO::TypeDesc::UINT8;
    case VTK_SIGNED_CHAR:
    case VTK_CHAR:
      return OIIO::TypeDesc::INT8;
    case VTK_UNSIGNED_SHORT:
      return OIIO::TypeDesc::UINT16;
    case VTK_SHORT:
      return OIIO::TypeDesc::INT16;
    case VTK_UNSIGNED_INT:
      return OIIO::TypeDesc::UINT32;
    case VTK_INT:
      return OIIO::TypeDesc::INT32;
    case VTK_FLOAT:
      return OIIO::TypeDesc::FLOAT;
    case VTK_DOUBLE:
      return OIIO::TypeDesc::DOUBLE;
    default:
      return OIIO::TypeDesc::UNKNOWN;
  }
}

/**
 * OIIO's pending error text: @a io's (an ImageInput or ImageOutput) if it has one, else
 * OIIO's global one. Both are cleared, so that the next failure does not repeat this one;
 * without @a io, only the global error is read (e.g. after open() or create() failed).
 */
template <typename ImageIO = OIIO::ImageInput>
std::string OIIOError(const ImageIO* io = nullptr)
{
  std::string reason = io ? io->geterror() : std::string();
  const std::string global = OIIO::geterror();
  if (reason.empty())
  {
    reason = global;
  }
  return reason.empty() ? std::string("no reason given") : reason;
}

}

#endif
