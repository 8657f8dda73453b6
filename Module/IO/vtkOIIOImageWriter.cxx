// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOIIOImageWriter.h"

#include "vtkCommand.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOIIOUtilities.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <vtksys/SystemTools.hxx>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <exception>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkOIIOImageWriter);

using vtkOIIOUtilities::OIIOError;
using vtkOIIOUtilities::OIIOTypeOf;

//------------------------------------------------------------------------------
vtkOIIOImageWriter::vtkOIIOImageWriter()
{
  this->FileLowerLeft = 1;
  this->FileDimensionality = 2;
}

//------------------------------------------------------------------------------
const char* vtkOIIOImageWriter::GetFloatPrecisionAsString() const
{
  return this->FloatPrecision == Half ? "Half" : "Single";
}

//------------------------------------------------------------------------------
void vtkOIIOImageWriter::Fail(unsigned long errorCode, const char* message)
{
  vtkErrorMacro(<< message);
  this->SetErrorCode(errorCode);
}

//------------------------------------------------------------------------------
void vtkOIIOImageWriter::Write()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->GetInputConnection(0, 0) && !this->GetInput())
  {
    this->Fail(vtkErrorCode::UnknownError,
      "No input: call SetInputData() or SetInputConnection() before Write().");
    return;
  }
  // Always write, even if nothing changed since the last Write().
  this->Modified();
  this->UpdateWholeExtent();
}

//------------------------------------------------------------------------------
int vtkOIIOImageWriter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkImageData* input = vtkImageData::GetData(inInfo);
  if (input && inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    int whole[6];
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    int extent[6];
    input->GetExtent(extent);
    if (!std::equal(extent, extent + 6, whole) && this->GetInputAlgorithm())
    {
      this->GetInputAlgorithm()->UpdateExtent(whole);
      input = vtkImageData::GetData(inInfo);
    }
  }
  this->InvokeEvent(vtkCommand::StartEvent);
  this->UpdateProgress(0.0);
  this->WriteImage(input);
  this->UpdateProgress(1.0);
  this->InvokeEvent(vtkCommand::EndEvent);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOIIOImageWriter::WriteImage(vtkImageData* image)
{
  if (!this->FileName || !*this->FileName)
  {
    this->Fail(vtkErrorCode::NoFileNameError,
      "No file name: call SetFileName() first (file patterns are not supported).");
    return false;
  }
  const std::string path = this->FileName;
  auto fail = [this, &path](unsigned long code, const std::string& why)
  {
    this->Fail(code, ("Cannot write '" + path + "': " + why).c_str());
    return false;
  };

  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars)
  {
    return fail(vtkErrorCode::UnknownError, "the input has no point scalars to write.");
  }
  int extent[6];
  image->GetExtent(extent);
  const int width = extent[1] - extent[0] + 1;
  const int height = extent[3] - extent[2] + 1;
  if (width < 1 || height < 1 || extent[5] < extent[4])
  {
    return fail(vtkErrorCode::UnknownError, "the input image is empty.");
  }
  if (extent[5] != extent[4])
  {
    std::ostringstream why;
    why << "the input has " << extent[5] - extent[4] + 1
        << " slices; this writer writes 2-D images (extract one with vtkExtractVOI).";
    return fail(vtkErrorCode::UnknownError, why.str());
  }
  const int components = image->GetNumberOfScalarComponents();
  if (components < 1 || components > 4)
  {
    std::ostringstream why;
    why << "the input has " << components
        << " components; image files hold 1 to 4 (use vtkImageExtractComponents).";
    return fail(vtkErrorCode::UnknownError, why.str());
  }
  const OIIO::TypeDesc memoryType = OIIOTypeOf(image->GetScalarType());
  if (memoryType == OIIO::TypeDesc::UNKNOWN)
  {
    return fail(vtkErrorCode::UnknownError,
      std::string("image files cannot hold the input's scalar type ") +
        image->GetScalarTypeAsString() + " (use vtkImageCast).");
  }
  const OIIO::TypeDesc fileType =
    memoryType == OIIO::TypeDesc::FLOAT && this->FloatPrecision == Half ? OIIO::TypeDesc::HALF
                                                                        : memoryType;

  // Until open() succeeds, whatever is at path is the user's and must survive a failure;
  // after it, the file is this writer's partial output and is removed.
  bool opened = false;
  try
  {
    auto out = OIIO::ImageOutput::create(path);
    if (!out)
    {
      return fail(vtkErrorCode::UnrecognizedFileTypeError,
        "OpenImageIO has no writer for this file name's extension: " + OIIOError());
    }
    OIIO::ImageSpec spec(width, height, components, fileType);
    // VTK images carry straight (unassociated) alpha: say so, so that OIIO stores the
    // values as they are rather than un-premultiplying them.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    spec.attribute("png:compressionLevel", this->CompressionLevel);
    if (!out->open(path, spec))
    {
      return fail(vtkErrorCode::CannotOpenFileError, OIIOError(out.get()));
    }
    opened = true;
    if (out->spec().format != fileType)
    {
      vtkWarningMacro(<< "'" << path << "' (" << out->format_name() << ") cannot hold "
                      << fileType.c_str() << " values; OpenImageIO stores them as "
                      << out->spec().format.c_str()
                      << ", which loses precision (floats are clamped to 0..1). Use .exr or "
                         ".tif to keep them.");
    }
    // VTK's row 0 is the bottom, the file's the top: hand OIIO the last row and a negative
    // row stride so that it walks the image from top to bottom.
    vtkIdType increments[3];
    image->GetIncrements(increments);
    const OIIO::stride_t typeSize = static_cast<OIIO::stride_t>(memoryType.size());
    const OIIO::stride_t xStride = typeSize * increments[0];
    const OIIO::stride_t yStride = -typeSize * increments[1];
    const void* topRow = image->GetScalarPointer(extent[0], extent[3], extent[4]);
    const bool written = out->write_image(memoryType, topRow, xStride, yStride);
    const std::string writeError = written ? std::string() : OIIOError(out.get());
    const bool closed = out->close();
    if (!written || !closed)
    {
      vtksys::SystemTools::RemoveFile(path);
      return fail(vtkErrorCode::OutOfDiskSpaceError, written ? OIIOError(out.get()) : writeError);
    }
  }
  catch (const std::exception& e)
  {
    if (opened)
    {
      vtksys::SystemTools::RemoveFile(path);
    }
    return fail(vtkErrorCode::UnknownError, std::string("OpenImageIO failed: ") + e.what());
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOIIOImageWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FloatPrecision: " << this->GetFloatPrecisionAsString() << "\n";
  os << indent << "CompressionLevel: " << this->CompressionLevel << "\n";
}
