// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOIIOImageReader
 * @brief   Reads any 2-D image OpenImageIO can read (PNG, JPEG, TIFF, OpenEXR, HDR, TGA, ...).
 *
 * Textures come in many formats VTK cannot read (OpenEXR, Radiance HDR) and in pixel types
 * VTK's readers narrow (half floats). This reader hands the file to OpenImageIO and keeps
 * what the file holds:
 *
 * - the pixel type: 8-bit stays unsigned char, 16-bit stays unsigned short, float stays
 *   float; half becomes float (VTK has no half type); other integer types and double keep
 *   their VTK equivalent;
 * - the channel count, 1 to 4 (grey, grey+alpha, RGB, RGBA);
 * - VTK's orientation: row 0 of the output is the bottom row of the picture, so that
 *   texture coordinate t = 0 samples the bottom (as OpenGL and vtkTexture do);
 * - the colour space the file declares (OpenImageIO's "oiio:ColorSpace"), through
 *   GetColorSpace() and GetIsSRGB(), so a caller can set vtkTexture::UseSRGBColorSpace.
 *
 * The extent is the file's size, (0, width - 1, 0, height - 1, 0, 0): a DataExtent set on
 * the reader is replaced. DataSpacing and DataOrigin are the caller's (vtkImageReader2's 1
 * and 0 unless set) and never come from the file, as with vtkPNGReader and vtkJPEGReader:
 * they place the texture in the scene, and a resolution the file records (dots per inch)
 * is print metadata.
 *
 * Only the first subimage at full resolution is read. Files OpenImageIO cannot open, and
 * layouts VTK cannot hold (more than 4 channels, volumes, deep data), are errors: the
 * reader reports the path and OpenImageIO's reason with vtkErrorMacro, sets its ErrorCode
 * and leaves the output empty.
 *
 * The reader reads the one file named by SetFileName(). The other inputs vtkImageReader2
 * offers are refused when the pipeline asks for information, in the same way (an error
 * naming the setter, ErrorCode vtkErrorCode::NoFileNameError, an empty output): file lists
 * (SetFileNames()), file series (SetFilePrefix(), SetFilePattern(); GetFilePattern() is
 * null until one is set) and memory buffers (SetMemoryBuffer(), SetMemoryBufferLength()).
 * The setters keep vtkImageReader2's rule that the last of SetFileName(), SetFileNames(),
 * SetFilePrefix() and SetFilePattern() wins; a memory buffer is refused even beside a file
 * name, so clear it with SetMemoryBuffer(nullptr) and SetMemoryBufferLength(0).
 *
 * The reader is registered with vtkImageReader2Factory through VTK's autoinit:
 * SurfaceDetail::IO implements VTK::IOImage, so a program built with
 * `vtk_module_autoinit(TARGETS app MODULES SurfaceDetail::IO)`, and the Python package
 * (importing surfacedetail), register it at start-up (in C++, from each source file that
 * includes a VTK::IOImage header such as vtkImageReader2Factory.h), and
 * vtkImageReader2Factory::CreateImageReader2() finds it for the formats VTK's own readers
 * lack (EXR, ...). Merely linking the library registers nothing; a program built without
 * that autoinit calls RegisterWithImageReader2Factory(), which may be called any number of
 * times. VTK's readers are asked first, so PNG, JPEG or HDR still go to vtkPNGReader,
 * vtkJPEGReader or vtkHDRReader from the factory; instantiate this class to use OpenImageIO
 * for them too.
 *
 * @sa vtkOIIOImageWriter vtkImageReader2Factory vtkPNGReader
 */

#ifndef vtkOIIOImageReader_h
#define vtkOIIOImageReader_h

#include "SurfaceDetailIOModule.h" // For export macro
#include "vtkImageReader2.h"

#include <string> // For the colour space and extension strings

class SURFACEDETAILIO_EXPORT vtkOIIOImageReader : public vtkImageReader2
{
public:
  static vtkOIIOImageReader* New();
  vtkTypeMacro(vtkOIIOImageReader, vtkImageReader2);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * 3 if OpenImageIO opens the file and its layout fits a vtkImageData (1-4 channels, 2-D),
   * 0 otherwise. Does not read the pixels.
   */
  int CanReadFile(const char* fname) override;

  /**
   * The extensions of every format this OpenImageIO build reads, e.g. ".exr .hdr .png".
   */
  const char* GetFileExtensions() override;

  const char* GetDescriptiveName() override { return "OpenImageIO image"; }

  /**
   * The colour space the file declares (OpenImageIO's "oiio:ColorSpace", e.g. "sRGB" or
   * "Linear"), empty if it declares none. Valid after UpdateInformation().
   */
  const char* GetColorSpace() const { return this->ColorSpace.c_str(); }

  /**
   * Whether the file's pixels are sRGB-encoded (true for most 8-bit PNG/JPEG) rather than
   * linear (OpenEXR, HDR). Valid after UpdateInformation().
   */
  bool GetIsSRGB() const;

  /**
   * Adds an instance to vtkImageReader2Factory's list unless one is there already.
   * Called at start-up in programs whose vtk_module_autoinit names SurfaceDetail::IO, and
   * by the Python package; safe to call again.
   */
  static void RegisterWithImageReader2Factory();

protected:
  vtkOIIOImageReader();
  ~vtkOIIOImageReader() override = default;

  void ExecuteInformation() override;
  void ExecuteDataWithInformation(vtkDataObject* output, vtkInformation* outInfo) override;

private:
  vtkOIIOImageReader(const vtkOIIOImageReader&) = delete;
  void operator=(const vtkOIIOImageReader&) = delete;

  /// Reports the failure, sets the error code and empties the output.
  void Fail(unsigned long errorCode, const std::string& message);

  std::string ColorSpace;
  std::string FileExtensions;
};

#endif
