// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOIIOImageReader.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkImageReader2Collection.h"
#include "vtkImageReader2Factory.h"
#include "vtkOIIOUtilities.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <vtksys/SystemTools.hxx>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkOIIOImageReader);

namespace
{
using vtkOIIOUtilities::OIIOError;
using vtkOIIOUtilities::OIIOTypeOf;
using vtkOIIOUtilities::VTKTypeOf;

/// Why a vtkImageData cannot hold @a spec's image, or empty if it can.
std::string LayoutProblem(const OIIO::ImageSpec& spec)
{
  std::ostringstream why;
  if (spec.deep)
  {
    why << "it holds deep (multi-sample) pixels; flatten it first (e.g. oiiotool --flatten)";
  }
  else if (spec.depth > 1)
  {
    why << "it is a 3-D image (" << spec.width << "x" << spec.height << "x" << spec.depth
        << "); this reader reads 2-D images only";
  }
  else if (spec.nchannels < 1 || spec.nchannels > 4)
  {
    why << "it has " << spec.nchannels
        << " channels; a texture has 1 to 4 (extract channels first, e.g. oiiotool --ch R,G,B)";
  }
  else if (VTKTypeOf(spec.format) < 0)
  {
    why << "its pixel type " << spec.format.c_str() << " has no VTK equivalent";
  }
  else if (spec.width < 1 || spec.height < 1)
  {
    why << "it has no pixels (" << spec.width << "x" << spec.height << ")";
  }
  return why.str();
}

/// Opens @a path keeping alpha unassociated (straight), as vtkTexture blends it, instead
/// of OIIO's default premultiplication, which would change the colour of translucent pixels.
std::unique_ptr<OIIO::ImageInput> OpenInput(const std::string& path)
{
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  return OIIO::ImageInput::open(path, &config);
}
}

//------------------------------------------------------------------------------
vtkOIIOImageReader::vtkOIIOImageReader()
{
  this->FileLowerLeft = 1;
  this->FileDimensionality = 2;
  this->DataScalarType = VTK_UNSIGNED_CHAR;
  // vtkImageReader2 starts with the pattern "%s.%d"; without it, a pattern is one the caller
  // set, and can be refused.
  this->SetFilePattern(nullptr);
}

//------------------------------------------------------------------------------
void vtkOIIOImageReader::RegisterWithImageReader2Factory()
{
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  vtkNew<vtkImageReader2Collection> registered;
  vtkImageReader2Factory::GetRegisteredReaders(registered);
  registered->InitTraversal();
  while (vtkImageReader2* reader = registered->GetNextItem())
  {
    if (vtkOIIOImageReader::SafeDownCast(reader))
    {
      return;
    }
  }
  vtkNew<vtkOIIOImageReader> reader;
  vtkImageReader2Factory::RegisterReader(reader);
}

//------------------------------------------------------------------------------
bool vtkOIIOImageReader::GetIsSRGB() const
{
  return vtksys::SystemTools::LowerCase(this->ColorSpace) == "srgb";
}

//------------------------------------------------------------------------------
int vtkOIIOImageReader::CanReadFile(const char* fname)
{
  if (!fname || vtksys::SystemTools::FileIsDirectory(fname))
  {
    return 0;
  }
  try
  {
    auto in = OpenInput(fname);
    if (!in)
    {
      OIIOError();
      return 0;
    }
    const bool fits = LayoutProblem(in->spec()).empty();
    in->close();
    return fits ? 3 : 0;
  }
  catch (const std::exception&)
  {
    return 0;
  }
}

//------------------------------------------------------------------------------
const char* vtkOIIOImageReader::GetFileExtensions()
{
  if (this->FileExtensions.empty())
  {
    std::vector<std::string> extensions;
    for (const auto& format : OIIO::get_extension_map())
    {
      for (const auto& extension : format.second)
      {
        extensions.push_back("." + extension);
      }
    }
    std::sort(extensions.begin(), extensions.end());
    extensions.erase(std::unique(extensions.begin(), extensions.end()), extensions.end());
    for (const auto& extension : extensions)
    {
      this->FileExtensions += (this->FileExtensions.empty() ? "" : " ") + extension;
    }
  }
  return this->FileExtensions.c_str();
}

//------------------------------------------------------------------------------
void vtkOIIOImageReader::Fail(unsigned long errorCode, const std::string& message)
{
  vtkErrorMacro(<< message);
  this->SetErrorCode(errorCode);
  if (vtkDataObject* output = this->GetOutputDataObject(0))
  {
    output->Initialize();
  }
}

//------------------------------------------------------------------------------
void vtkOIIOImageReader::ExecuteInformation()
{
  this->ColorSpace.clear();
  // vtkImageReader2 also offers file lists, file series and memory buffers. Reading the one
  // FileName instead would read something other than what was asked for, so they are refused.
  // Its setters make the last of SetFileName, SetFileNames, SetFilePrefix and SetFilePattern
  // win, so a pattern matters only without a FileName; a buffer matters always.
  const char* refused = nullptr;
  if (this->MemoryBuffer || this->MemoryBufferLength > 0)
  {
    refused = "reads files, not memory buffers: use SetFileName(), not "
              "SetMemoryBuffer()/SetMemoryBufferLength()";
  }
  else if (this->FileNames)
  {
    refused = "reads one file: use SetFileName(), not SetFileNames()";
  }
  else if (this->FilePrefix || (this->FilePattern && !this->FileName))
  {
    refused = "reads one file: use SetFileName(), not SetFilePrefix()/SetFilePattern() (file "
              "series are not supported)";
  }
  if (refused)
  {
    this->Fail(vtkErrorCode::NoFileNameError, std::string("vtkOIIOImageReader ") + refused + ".");
    return;
  }
  if (!this->FileName || !*this->FileName)
  {
    this->Fail(vtkErrorCode::NoFileNameError, "No file name: call SetFileName() first.");
    return;
  }
  const std::string path = this->FileName;
  if (vtksys::SystemTools::FileIsDirectory(path))
  {
    this->Fail(vtkErrorCode::CannotOpenFileError,
      "Cannot read '" + path + "': it is a directory, not an image file.");
    return;
  }

  try
  {
    // Not every OIIO input is a file (e.g. "x.null?RES=8x8"), so OIIO is asked first and
    // the file system only explains a failure.
    auto in = OpenInput(path);
    if (!in)
    {
      const std::string reason = OIIOError();
      if (!vtksys::SystemTools::FileExists(path))
      {
        this->Fail(vtkErrorCode::FileNotFoundError, "Cannot read '" + path + "': no such file.");
      }
      else
      {
        this->Fail(vtkErrorCode::UnrecognizedFileTypeError,
          "Cannot read '" + path + "': OpenImageIO could not open it: " + reason);
      }
      return;
    }
    const OIIO::ImageSpec& spec = in->spec();
    const std::string problem = LayoutProblem(spec);
    if (!problem.empty())
    {
      in->close();
      this->Fail(vtkErrorCode::FileFormatError, "Cannot read '" + path + "': " + problem + ".");
      return;
    }

    // The file's size is the extent, whatever was set. Spacing and origin stay the caller's
    // (vtkImageReader2's 1 and 0 by default): they place the texture in the scene, which the
    // file knows nothing about, and a resolution the file records is print metadata.
    this->DataExtent[0] = 0;
    this->DataExtent[1] = spec.width - 1;
    this->DataExtent[2] = 0;
    this->DataExtent[3] = spec.height - 1;
    this->DataExtent[4] = 0;
    this->DataExtent[5] = 0;
    this->SetDataScalarType(VTKTypeOf(spec.format));
    this->SetNumberOfScalarComponents(spec.nchannels);
    this->ColorSpace = spec.get_string_attribute("oiio:ColorSpace");
    in->close();
  }
  catch (const std::exception& e)
  {
    this->Fail(
      vtkErrorCode::UnknownError, "Cannot read '" + path + "': OpenImageIO failed: " + e.what());
  }
}

//------------------------------------------------------------------------------
void vtkOIIOImageReader::ExecuteDataWithInformation(vtkDataObject* output, vtkInformation* outInfo)
{
  if (!this->FileName)
  {
    return;
  }
  const std::string path = this->FileName;
  // A header may claim more pixels than memory holds (a damaged or hostile file): VTK then
  // leaves the scalars unallocated, or throws, and nothing may be read into them.
  vtkImageData* data = nullptr;
  try
  {
    data = this->AllocateOutputData(output, outInfo);
  }
  catch (const std::bad_alloc&)
  {
    data = nullptr;
  }
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  if (data)
  {
    data->GetExtent(extent);
    if (extent[0] > extent[1] || extent[2] > extent[3] || extent[4] > extent[5])
    {
      return; // An empty update extent reads nothing.
    }
  }
  const vtkIdType expected = static_cast<vtkIdType>(extent[1] - extent[0] + 1) *
    (extent[3] - extent[2] + 1) * (extent[5] - extent[4] + 1);
  vtkDataArray* scalars = data ? data->GetPointData()->GetScalars() : nullptr;
  if (!scalars || scalars->GetNumberOfTuples() != expected || !data->GetScalarPointer())
  {
    this->Fail(vtkErrorCode::FileFormatError,
      "Cannot read '" + path + "': its " + std::to_string(this->DataExtent[1] + 1) + " x " +
        std::to_string(this->DataExtent[3] + 1) + " pixels do not fit in memory.");
    return;
  }
  scalars->SetName("OIIOImage");

  try
  {
    auto in = OpenInput(path);
    if (!in)
    {
      this->Fail(vtkErrorCode::CannotOpenFileError,
        "Cannot read '" + path + "': OpenImageIO could not open it: " + OIIOError());
      return;
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width != this->DataExtent[1] + 1 || spec.height != this->DataExtent[3] + 1 ||
      spec.nchannels != this->NumberOfScalarComponents ||
      VTKTypeOf(spec.format) != this->DataScalarType)
    {
      this->Fail(vtkErrorCode::FileFormatError,
        "Cannot read '" + path + "': the file changed since its information was read; " +
          "call Modified() on the reader and update again.");
      return;
    }

    // Row 0 of the file is the top of the picture, row 0 of VTK's image the bottom: OIIO
    // writes the file's rows upwards from the last row through a negative row stride.
    const OIIO::TypeDesc format = OIIOTypeOf(this->DataScalarType);
    const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(format.size()) * spec.nchannels;
    const OIIO::stride_t rowBytes = pixelBytes * spec.width;
    const bool whole = extent[0] == 0 && extent[1] == spec.width - 1 && extent[2] == 0 &&
      extent[3] == spec.height - 1;
    // A smaller update extent is cut from the whole picture: read_image() serves scanline
    // and tiled files alike, and textures are small enough to read whole.
    std::vector<unsigned char> buffer;
    unsigned char* destination = static_cast<unsigned char*>(data->GetScalarPointer());
    if (!whole)
    {
      buffer.resize(static_cast<size_t>(rowBytes) * spec.height);
      destination = buffer.data();
    }
    const bool ok = in->read_image(0, 0, 0, spec.nchannels, format,
      destination + rowBytes * (spec.height - 1), pixelBytes, -rowBytes);
    // OIIO 2.4's TIFF reader reports a missing strip yet returns true (with zeros where the
    // strip was), so a pending error counts as a failure too.
    if (!ok || in->has_error())
    {
      const std::string reason = OIIOError(in.get());
      this->Fail(vtkErrorCode::PrematureEndOfFileError,
        "Cannot read the pixels of '" + path + "' (truncated or corrupt?): " + reason);
      return;
    }
    in->close();

    if (!whole)
    {
      const size_t copyBytes = static_cast<size_t>(pixelBytes) * (extent[1] - extent[0] + 1);
      for (int j = extent[2]; j <= extent[3]; ++j)
      {
        std::memcpy(data->GetScalarPointer(extent[0], j, 0),
          buffer.data() + rowBytes * j + pixelBytes * extent[0], copyBytes);
      }
    }
  }
  catch (const std::exception& e)
  {
    this->Fail(
      vtkErrorCode::UnknownError, "Cannot read '" + path + "': OpenImageIO failed: " + e.what());
  }
}

//------------------------------------------------------------------------------
void vtkOIIOImageReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ColorSpace: " << (this->ColorSpace.empty() ? "(none)" : this->ColorSpace)
     << "\n";
  os << indent << "IsSRGB: " << (this->GetIsSRGB() ? "true" : "false") << "\n";
}

//------------------------------------------------------------------------------
// SurfaceDetail::IO implements VTK::IOImage (vtk.module): a program built with
// vtk_module_autoinit naming SurfaceDetail::IO, and the Python module, call this when they
// start, from every translation unit that includes a VTK::IOImage header. Registration is
// the program's choice, as for VTK's own object factories, rather than a side effect of
// loading the library; and a static library's reader is linked in because this is called.
SURFACEDETAILIO_EXPORT void SurfaceDetailIO_AutoInit_Construct()
{
  vtkOIIOImageReader::RegisterWithImageReader2Factory();
}
