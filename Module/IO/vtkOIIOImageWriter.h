// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOIIOImageWriter
 * @brief   Writes a 2-D vtkImageData to any format OpenImageIO writes (PNG, TIFF, OpenEXR, ...).
 *
 * The inverse of vtkOIIOImageReader: row 0 of the image (the bottom, VTK's convention) is
 * written as the last row of the file, so the picture is upright in any viewer and
 * reading the file back with vtkOIIOImageReader gives the same image, value for value, for
 * lossless formats (PNG, TIFF, OpenEXR at the input's precision).
 *
 * The format comes from the file name's extension. The pixel type is the input's:
 * unsigned char for 8-bit PNG/TIFF/JPEG, unsigned short for 16-bit PNG/TIFF, float for
 * TIFF and OpenEXR. FloatPrecision chooses how float images are stored in formats that
 * offer a choice (OpenEXR): Single (32-bit, the default, exact) or Half (16-bit, half the
 * size, about 3 decimal digits). A format that cannot hold the input's type gets the type
 * OpenImageIO chooses for it (e.g. 8-bit for a float image written as PNG), with a warning.
 *
 * The input must have 1 to 4 components (grey, grey+alpha, RGB, RGBA) and one slice.
 * Errors (no input, no file name, a layout the writer cannot store, a path that cannot be
 * written) are reported with vtkErrorMacro naming the file and OpenImageIO's reason, set
 * ErrorCode and leave no partial file behind.
 *
 * @sa vtkOIIOImageReader vtkPNGWriter
 */

#ifndef vtkOIIOImageWriter_h
#define vtkOIIOImageWriter_h

#include "SurfaceDetailIOModule.h" // For export macro
#include "vtkImageWriter.h"

class SURFACEDETAILIO_EXPORT vtkOIIOImageWriter : public vtkImageWriter
{
public:
  static vtkOIIOImageWriter* New();
  vtkTypeMacro(vtkOIIOImageWriter, vtkImageWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FloatPrecisionType
  {
    Half = 0,
    Single = 1
  };

  ///@{
  /**
   * How float images are stored by formats that can store either precision (OpenEXR):
   * Half (16-bit) or Single (32-bit, the default, a lossless round trip). Other input
   * types are stored at their own precision.
   */
  vtkSetClampMacro(FloatPrecision, int, Half, Single);
  vtkGetMacro(FloatPrecision, int);
  void SetFloatPrecisionToHalf() { this->SetFloatPrecision(Half); }
  void SetFloatPrecisionToSingle() { this->SetFloatPrecision(Single); }
  const char* GetFloatPrecisionAsString() const;
  ///@}

  ///@{
  /**
   * zlib compression level for PNG files, 0 (none, fastest) to 9 (smallest, slowest);
   * default 5, as vtkPNGWriter. Other formats ignore it.
   */
  vtkSetClampMacro(CompressionLevel, int, 0, 9);
  vtkGetMacro(CompressionLevel, int);
  ///@}

  /**
   * Writes the input's whole extent to FileName.
   */
  void Write() override;

protected:
  vtkOIIOImageWriter();
  ~vtkOIIOImageWriter() override = default;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int FloatPrecision = Single;
  int CompressionLevel = 5;

private:
  vtkOIIOImageWriter(const vtkOIIOImageWriter&) = delete;
  void operator=(const vtkOIIOImageWriter&) = delete;

  /// Writes @a image to FileName; false (after reporting why) if it could not.
  bool WriteImage(vtkImageData* image);
  void Fail(unsigned long errorCode, const char* message);
};

#endif
