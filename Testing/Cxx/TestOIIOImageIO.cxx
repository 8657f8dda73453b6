// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkOIIOImageReader / vtkOIIOImageWriter: exact round trips for the lossless formats,
// orientation checked against independent programs (VTK's own PNG reader and writer,
// libjpeg-turbo's cjpeg), the factory registration, vtkImageReader2's contract (the caller's
// spacing and origin kept, the inputs this reader cannot read refused), and every bad input.

#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkImageReader2Collection.h>
#include <vtkImageReader2Factory.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>

#include <vtksys/SystemTools.hxx>

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace
{
/// Counts the ErrorEvents and WarningEvents an algorithm fires and keeps the last message.
class ErrorObserver : public vtkCommand
{
public:
  static ErrorObserver* New() { return new ErrorObserver; }
  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    this->Errors += event == vtkCommand::ErrorEvent;
    this->Warnings += event == vtkCommand::WarningEvent;
    this->Message = callData ? static_cast<const char*>(callData) : "";
  }
  int Errors = 0;
  int Warnings = 0;
  std::string Message;
};

std::string TempDir()
{
  const std::string dir = std::string(SURFACEDETAIL_TEMP_DIR) + "/TestOIIOImageIO";
  vtksys::SystemTools::MakeDirectory(dir);
  return dir;
}

std::string TempPath(const std::string& name)
{
  return TempDir() + "/" + name;
}

/// A W x H image of random values covering the whole range of the type (float: [-2, 6)).
vtkSmartPointer<vtkImageData> RandomImage(int type, int components, int w, int h, unsigned seed)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(type, components);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  std::mt19937 random(seed);
  const double low = type == VTK_FLOAT ? -2.0 : scalars->GetDataTypeMin();
  const double high = type == VTK_FLOAT ? 6.0 : scalars->GetDataTypeMax();
  std::uniform_real_distribution<double> value(low, high);
  for (vtkIdType i = 0; i < scalars->GetNumberOfValues(); ++i)
  {
    const double v = value(random);
    scalars->SetVariantValue(
      i, type == VTK_FLOAT ? vtkVariant(static_cast<float>(v)) : vtkVariant(std::floor(v + 0.5)));
  }
  return image;
}

bool Write(vtkImageData* image, const std::string& path, bool half = false)
{
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  if (half)
  {
    writer->SetFloatPrecisionToHalf();
  }
  writer->Write();
  return writer->GetErrorCode() == vtkErrorCode::NoError;
}

vtkSmartPointer<vtkImageData> Read(const std::string& path)
{
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError) << path;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  return image;
}

/// Every value of @a b equals @a a's, with the same type, layout, spacing and origin.
void ExpectIdentical(vtkImageData* a, vtkImageData* b)
{
  ASSERT_NE(b->GetPointData()->GetScalars(), nullptr);
  EXPECT_EQ(a->GetScalarType(), b->GetScalarType());
  EXPECT_EQ(a->GetNumberOfScalarComponents(), b->GetNumberOfScalarComponents());
  int ea[6], eb[6];
  a->GetExtent(ea);
  b->GetExtent(eb);
  for (int i = 0; i < 6; ++i)
  {
    ASSERT_EQ(ea[i], eb[i]) << "extent " << i;
  }
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(b->GetSpacing()[i], 1.0);
    EXPECT_EQ(b->GetOrigin()[i], 0.0);
  }
  vtkDataArray* va = a->GetPointData()->GetScalars();
  vtkDataArray* vb = b->GetPointData()->GetScalars();
  ASSERT_EQ(va->GetNumberOfValues(), vb->GetNumberOfValues());
  vtkIdType mismatches = 0;
  for (vtkIdType i = 0; i < va->GetNumberOfValues(); ++i)
  {
    mismatches += va->GetVariantValue(i).ToDouble() != vb->GetVariantValue(i).ToDouble();
  }
  EXPECT_EQ(mismatches, 0);
}

void RoundTrip(const char* extension, int type, int components)
{
  auto image = RandomImage(type, components, 37, 23, 1000u * type + components);
  const std::string path =
    TempPath("roundtrip_" + std::to_string(type) + "_" + std::to_string(components) + extension);
  ASSERT_TRUE(Write(image, path)) << path;
  ExpectIdentical(image, Read(path));
}

/// The error checks every bad input must pass: an ErrorEvent naming the file, an error
/// code, and an empty output.
void ExpectReadFails(
  const std::string& path, const char* reasonPart = nullptr, bool headerIsValid = false)
{
  vtkNew<vtkOIIOImageReader> reader;
  vtkNew<ErrorObserver> observer;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->SetFileName(path.c_str());
  reader->Update();
  EXPECT_GE(observer->Errors, 1) << path;
  EXPECT_NE(observer->Message.find(path), std::string::npos) << observer->Message;
  if (reasonPart)
  {
    EXPECT_NE(observer->Message.find(reasonPart), std::string::npos) << observer->Message;
  }
  EXPECT_NE(reader->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(reader->GetOutput()->GetPointData()->GetScalars(), nullptr);
  // Like VTK's readers, CanReadFile() looks at the header only.
  if (!headerIsValid)
  {
    EXPECT_EQ(reader->CanReadFile(path.c_str()), 0);
  }
}

/// What a reader given an input it cannot read must do when updated: an error naming the
/// setter that gave it, NoFileNameError, and an empty output.
void ExpectRefused(vtkOIIOImageReader* reader, const char* setter)
{
  vtkNew<ErrorObserver> observer;
  const unsigned long tag = reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->Update();
  reader->RemoveObserver(tag);
  EXPECT_EQ(observer->Errors, 1) << setter;
  EXPECT_NE(observer->Message.find(setter), std::string::npos) << observer->Message;
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoFileNameError) << setter;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << setter;
  EXPECT_EQ(reader->GetOutput()->GetPointData()->GetScalars(), nullptr) << setter;
}

void ExpectWriteFails(vtkImageData* image, const std::string& path, const char* reasonPart)
{
  vtkNew<vtkOIIOImageWriter> writer;
  vtkNew<ErrorObserver> observer;
  writer->AddObserver(vtkCommand::ErrorEvent, observer);
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  EXPECT_GE(observer->Errors, 1) << path;
  EXPECT_NE(observer->Message.find(path), std::string::npos) << observer->Message;
  EXPECT_NE(observer->Message.find(reasonPart), std::string::npos) << observer->Message;
  EXPECT_NE(writer->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_FALSE(vtksys::SystemTools::FileExists(path)) << "partial file left behind: " << path;
}
}

TEST(TestOIIOImageIO, RoundTripPNG8)
{
  for (int components = 1; components <= 4; ++components)
  {
    RoundTrip(".png", VTK_UNSIGNED_CHAR, components);
  }
}

TEST(TestOIIOImageIO, RoundTripPNG16)
{
  for (int components = 1; components <= 4; ++components)
  {
    RoundTrip(".png", VTK_UNSIGNED_SHORT, components);
  }
}

TEST(TestOIIOImageIO, RoundTripEXRFloat)
{
  for (int components = 1; components <= 4; ++components)
  {
    RoundTrip(".exr", VTK_FLOAT, components);
  }
}

TEST(TestOIIOImageIO, RoundTripTIFF)
{
  for (int type : { VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT, VTK_FLOAT })
  {
    for (int components : { 1, 3, 4 })
    {
      RoundTrip(".tif", type, components);
    }
  }
}

// Half keeps 11 significant bits: values of the form k/1024 in [-2, 2) survive exactly,
// and any other float comes back within half a unit in the last place (2^-11 relative).
TEST(TestOIIOImageIO, RoundTripEXRHalf)
{
  auto exact = RandomImage(VTK_FLOAT, 3, 31, 17, 7u);
  vtkDataArray* values = exact->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    values->SetComponent(
      i / 3, i % 3, std::floor(values->GetComponent(i / 3, i % 3) / 3.0 * 1024) / 1024);
  }
  const std::string exactPath = TempPath("half_exact.exr");
  ASSERT_TRUE(Write(exact, exactPath, true));
  ExpectIdentical(exact, Read(exactPath));

  auto any = RandomImage(VTK_FLOAT, 4, 31, 17, 8u);
  const std::string halfPath = TempPath("half_any.exr");
  const std::string singlePath = TempPath("single_any.exr");
  ASSERT_TRUE(Write(any, halfPath, true));
  ASSERT_TRUE(Write(any, singlePath, false));
  auto back = Read(halfPath);
  ASSERT_EQ(back->GetScalarType(), VTK_FLOAT);
  vtkDataArray* a = any->GetPointData()->GetScalars();
  vtkDataArray* b = back->GetPointData()->GetScalars();
  ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues());
  double worst = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    const double x = a->GetVariantValue(i).ToDouble();
    const double y = b->GetVariantValue(i).ToDouble();
    worst = std::max(worst, std::abs(x - y) / std::max(std::abs(x), std::ldexp(1.0, -14)));
  }
  EXPECT_LE(worst, std::ldexp(1.0, -11));
  EXPECT_GT(worst, 0.0) << "half precision should round some random floats";
  EXPECT_LT(vtksys::SystemTools::FileLength(halfPath), vtksys::SystemTools::FileLength(singlePath));
}

// VTK's own PNG reader and writer are the independent truth for orientation and values.
TEST(TestOIIOImageIO, AgreesWithVTKPNGReaderAndWriter)
{
  auto image = RandomImage(VTK_UNSIGNED_CHAR, 3, 29, 19, 11u);
  const std::string ours = TempPath("ours.png");
  ASSERT_TRUE(Write(image, ours));
  vtkNew<vtkPNGReader> vtkReader;
  vtkReader->SetFileName(ours.c_str());
  vtkReader->Update();
  ExpectIdentical(image, vtkReader->GetOutput());

  const std::string theirs = TempPath("theirs.png");
  vtkNew<vtkPNGWriter> vtkWriter;
  vtkWriter->SetInputData(image);
  vtkWriter->SetFileName(theirs.c_str());
  vtkWriter->Write();
  ExpectIdentical(image, Read(theirs));
}

// A JPEG made by libjpeg-turbo's cjpeg from a hand-written PPM (whose first row is the top
// of the picture): top-left red, top-right green, bottom-left blue, bottom-right white.
TEST(TestOIIOImageIO, ReadsJPEGFromCjpegUpright)
{
  constexpr int size = 32;
  const std::string ppm = TempPath("quadrants.ppm");
  const std::string jpg = TempPath("quadrants.jpg");
  {
    std::ofstream file(ppm, std::ios::binary);
    file << "P6\n" << size << " " << size << "\n255\n";
    for (int row = 0; row < size; ++row) // row 0 = top
    {
      for (int column = 0; column < size; ++column)
      {
        const bool top = row < size / 2;
        const bool left = column < size / 2;
        const unsigned char red[3] = { 255, 0, 0 }, green[3] = { 0, 255, 0 },
                            blue[3] = { 0, 0, 255 }, white[3] = { 255, 255, 255 };
        const unsigned char* c = top ? (left ? red : green) : (left ? blue : white);
        file.write(reinterpret_cast<const char*>(c), 3);
      }
    }
  }
  vtksys::SystemTools::RemoveFile(jpg);
  // A hard failure, not a skip: ctest counts a skipped gtest as passed, and the JPEG path
  // would then go unchecked without anyone noticing.
  const std::string cjpeg = vtksys::SystemTools::FindProgram("cjpeg");
  ASSERT_FALSE(cjpeg.empty())
    << "cjpeg (Debian package libjpeg-turbo-progs) is not on the PATH: run "
       "scripts/install-deps.sh";
  const std::string command = "'" + cjpeg + "' -quality 95 -outfile '" + jpg + "' '" + ppm + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;

  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(jpg.c_str());
  EXPECT_EQ(reader->CanReadFile(jpg.c_str()), 3);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  ASSERT_EQ(image->GetScalarType(), VTK_UNSIGNED_CHAR);
  ASSERT_EQ(image->GetNumberOfScalarComponents(), 3);
  EXPECT_TRUE(reader->GetIsSRGB()) << reader->GetColorSpace();
  // Sample the middle of each quadrant, away from JPEG's ringing at the edges.
  auto expectColour = [image](int i, int j, double r, double g, double b)
  {
    const double expected[3] = { r, g, b };
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(image->GetScalarComponentAsDouble(i, j, 0, c), expected[c], 24.0)
        << "pixel (" << i << ", " << j << ") component " << c;
    }
  };
  const int low = size / 4, high = 3 * size / 4;
  expectColour(low, high, 255, 0, 0);  // top-left: high row index
  expectColour(high, high, 0, 255, 0); // top-right
  expectColour(low, low, 0, 0, 255);   // bottom-left: row 0 side
  expectColour(high, low, 255, 255, 255);
}

TEST(TestOIIOImageIO, ReportsColorSpace)
{
  vtkNew<vtkOIIOImageReader> reader;
  const std::string exr = TempPath("colorspace.exr");
  ASSERT_TRUE(Write(RandomImage(VTK_FLOAT, 3, 4, 4, 1u), exr));
  reader->SetFileName(exr.c_str());
  reader->UpdateInformation();
  EXPECT_FALSE(reader->GetIsSRGB()) << reader->GetColorSpace();
  EXPECT_STRCASEEQ(reader->GetColorSpace(), "linear");
}

// VTK 9.1 has no OpenEXR reader, so the factory must hand out ours; it has vtkHDRReader,
// which it asks before registered readers, so for .hdr it is enough that a reader is found
// and that ours reads the file too.
TEST(TestOIIOImageIO, FactoryFindsReaderForEXRAndHDR)
{
  auto image = RandomImage(VTK_FLOAT, 3, 8, 8, 3u);
  vtkDataArray* values = image->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    values->SetVariantValue(i, std::abs(values->GetVariantValue(i).ToDouble()));
  }
  for (const char* name : { "factory.exr", "factory.hdr" })
  {
    const std::string path = TempPath(name);
    ASSERT_TRUE(Write(image, path));
    vtkSmartPointer<vtkImageReader2> reader;
    reader.TakeReference(vtkImageReader2Factory::CreateImageReader2(path.c_str()));
    ASSERT_NE(reader, nullptr) << path;
    if (vtksys::SystemTools::GetFilenameLastExtension(path) == ".exr")
    {
      EXPECT_TRUE(vtkOIIOImageReader::SafeDownCast(reader)) << reader->GetClassName();
    }
    reader->SetFileName(path.c_str());
    reader->Update();
    EXPECT_EQ(reader->GetOutput()->GetScalarType(), VTK_FLOAT);
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 64);
    auto ours = Read(path);
    EXPECT_EQ(ours->GetScalarType(), VTK_FLOAT);
    EXPECT_EQ(ours->GetNumberOfScalarComponents(), 3);
  }
  vtkNew<vtkOIIOImageReader> reader;
  const std::string extensions = reader->GetFileExtensions();
  EXPECT_NE(extensions.find(".exr"), std::string::npos) << extensions;
  EXPECT_NE(extensions.find(".hdr"), std::string::npos) << extensions;
  EXPECT_STREQ(reader->GetDescriptiveName(), "OpenImageIO image");
  // Registering again must not add a second instance.
  vtkOIIOImageReader::RegisterWithImageReader2Factory();
  vtkNew<vtkImageReader2Collection> registered;
  vtkImageReader2Factory::GetRegisteredReaders(registered);
  int ours = 0;
  registered->InitTraversal();
  while (vtkImageReader2* r = registered->GetNextItem())
  {
    ours += vtkOIIOImageReader::SafeDownCast(r) != nullptr;
  }
  EXPECT_EQ(ours, 1);
}

TEST(TestOIIOImageIO, ReadsRequestedSubExtent)
{
  auto image = RandomImage(VTK_UNSIGNED_SHORT, 2, 20, 16, 5u);
  const std::string path = TempPath("subextent.png");
  ASSERT_TRUE(Write(image, path));
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(path.c_str());
  int extent[6] = { 3, 11, 5, 14, 0, 0 };
  reader->UpdateExtent(extent);
  vtkImageData* part = reader->GetOutput();
  for (int j = extent[2]; j <= extent[3]; ++j)
  {
    for (int i = extent[0]; i <= extent[1]; ++i)
    {
      for (int c = 0; c < 2; ++c)
      {
        ASSERT_EQ(part->GetScalarComponentAsDouble(i, j, 0, c),
          image->GetScalarComponentAsDouble(i, j, 0, c));
      }
    }
  }
}

TEST(TestOIIOImageIO, PrintSelf)
{
  vtkNew<vtkOIIOImageReader> reader;
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetFloatPrecisionToHalf();
  std::ostringstream text;
  reader->Print(text);
  writer->Print(text);
  EXPECT_NE(text.str().find("ColorSpace"), std::string::npos);
  EXPECT_NE(text.str().find("FloatPrecision: Half"), std::string::npos);
  EXPECT_NE(text.str().find("CompressionLevel: 5"), std::string::npos);
}

// As with VTK's own readers, spacing and origin are the caller's: they place the texture in
// the scene. The extent is the file's, whatever the caller set.
TEST(TestOIIOImageIO, ReaderKeepsUserSpacingAndOrigin)
{
  const std::string path = TempPath("spacing.png");
  ASSERT_TRUE(Write(RandomImage(VTK_UNSIGNED_CHAR, 1, 37, 23, 12u), path));
  const double spacing[3] = { 0.5, 2.0, 3.0 };
  const double origin[3] = { -1.0, 4.0, 7.0 };
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetDataSpacing(spacing);
  reader->SetDataOrigin(origin);
  reader->SetDataExtent(0, 3, 0, 3, 0, 0);
  reader->Update();
  ASSERT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  vtkImageData* image = reader->GetOutput();
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(image->GetSpacing()[i], spacing[i]) << "spacing " << i;
    EXPECT_EQ(image->GetOrigin()[i], origin[i]) << "origin " << i;
    EXPECT_EQ(reader->GetDataSpacing()[i], spacing[i]) << "DataSpacing " << i;
    EXPECT_EQ(reader->GetDataOrigin()[i], origin[i]) << "DataOrigin " << i;
  }
  const int fileExtent[6] = { 0, 36, 0, 22, 0, 0 };
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(image->GetExtent()[i], fileExtent[i]) << "extent " << i;
    EXPECT_EQ(reader->GetDataExtent()[i], fileExtent[i]) << "DataExtent " << i;
  }
}

// A list of files would be a volume; this reader reads one picture. After the refusal, a
// single file name makes the reader work again.
TEST(TestOIIOImageIO, ReaderRefusesFileNames)
{
  const std::string good = TempPath("one_of_many.png");
  ASSERT_TRUE(Write(RandomImage(VTK_UNSIGNED_CHAR, 1, 8, 8, 2u), good));
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(good.c_str());
  reader->Update();
  ASSERT_EQ(reader->GetOutput()->GetNumberOfPoints(), 64);

  vtkNew<vtkStringArray> names;
  names->InsertNextValue(good);
  names->InsertNextValue(good);
  reader->SetFileNames(names);
  ExpectRefused(reader, "SetFileNames");

  reader->SetFileName(good.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 64);
}

TEST(TestOIIOImageIO, ReaderRefusesFileSeries)
{
  vtkNew<vtkOIIOImageReader> patterned;
  patterned->SetFilePattern(TempPath("series_%d.png").c_str());
  ExpectRefused(patterned, "SetFilePattern");

  vtkNew<vtkOIIOImageReader> prefixed;
  prefixed->SetFilePrefix(TempPath("series").c_str());
  ExpectRefused(prefixed, "SetFilePrefix");
}

// A memory buffer beside a file name must not be silently passed over for the file.
TEST(TestOIIOImageIO, ReaderRefusesMemoryBuffer)
{
  const std::string path = TempPath("buffer.png");
  ASSERT_TRUE(Write(RandomImage(VTK_UNSIGNED_CHAR, 3, 8, 8, 4u), path));
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetMemoryBuffer(bytes.data());
  reader->SetMemoryBufferLength(static_cast<vtkIdType>(bytes.size()));
  ExpectRefused(reader, "SetMemoryBuffer");

  vtkNew<vtkOIIOImageReader> lengthOnly;
  lengthOnly->SetFileName(path.c_str());
  lengthOnly->SetMemoryBufferLength(static_cast<vtkIdType>(bytes.size()));
  ExpectRefused(lengthOnly, "SetMemoryBufferLength");
}

TEST(TestOIIOImageIO, ReaderRejectsMissingFile)
{
  ExpectReadFails(TempPath("no_such_file.png"), "no such file");
}

TEST(TestOIIOImageIO, ReaderRejectsEmptyFile)
{
  const std::string path = TempPath("empty.png");
  std::ofstream(path, std::ios::binary | std::ios::trunc).close();
  ExpectReadFails(path, "OpenImageIO");
}

TEST(TestOIIOImageIO, ReaderRejectsNonImageFile)
{
  const std::string path = TempPath("text.png");
  std::ofstream(path) << "this is not a picture\n";
  ExpectReadFails(path, "OpenImageIO");
}

TEST(TestOIIOImageIO, ReaderRejectsTruncatedFile)
{
  for (const char* name : { "truncated.png", "truncated.exr", "truncated.tif" })
  {
    const std::string path = TempPath(name);
    ASSERT_TRUE(Write(RandomImage(VTK_UNSIGNED_CHAR, 3, 64, 64, 9u), path));
    std::string bytes;
    {
      std::ifstream in(path, std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), bytes.size() / 2);
    ExpectReadFails(path, "truncated", true);
  }
}

// A header that claims more pixels than memory holds (found by FuzzOIIOImageReader): an error,
// not a read into memory that was never allocated.
TEST(TestOIIOImageIO, ReaderRejectsHeaderBeyondMemory)
{
  const std::string path = TempPath("huge.pnm");
  std::ofstream(path, std::ios::binary | std::ios::trunc) << "P5\n2000000000 2000000000\n255\n"
                                                          << std::string(64, 'x');
  ExpectReadFails(path, "do not fit in memory", true);
}

TEST(TestOIIOImageIO, ReaderRejectsDirectory)
{
  ExpectReadFails(TempDir(), "directory");
}

TEST(TestOIIOImageIO, ReaderRejectsFiveChannels)
{
  const std::string path = TempPath("five_channels.tif");
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(4, 4, 5, OIIO::TypeDesc::UINT8);
  ASSERT_TRUE(out->open(path, spec));
  const std::vector<unsigned char> pixels(4 * 4 * 5, 7);
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
  out->close();
  ExpectReadFails(path, "5 channels");
}

// OIIO's "null" plugin makes an image from its name alone: here a 3-D one. (OIIO 2.4's TIFF
// writer cannot write volumes, and no other bundled format writes them.)
TEST(TestOIIOImageIO, ReaderRejectsVolume)
{
  ExpectReadFails("volume.null?RES=8x8x3&CHANNELS=1&TYPE=uint8", "3-D");
}

TEST(TestOIIOImageIO, ReaderWithoutFileName)
{
  vtkNew<vtkOIIOImageReader> reader;
  vtkNew<ErrorObserver> observer;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->Update();
  EXPECT_GE(observer->Errors, 1);
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoFileNameError);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}

// A reader that read a good file must not keep showing it once pointed at a bad one.
TEST(TestOIIOImageIO, ReaderEmptiesOutputAfterGoodThenBad)
{
  const std::string good = TempPath("good.png");
  ASSERT_TRUE(Write(RandomImage(VTK_UNSIGNED_CHAR, 1, 8, 8, 2u), good));
  vtkNew<vtkOIIOImageReader> reader;
  vtkNew<ErrorObserver> observer;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->SetFileName(good.c_str());
  reader->Update();
  ASSERT_EQ(reader->GetOutput()->GetNumberOfPoints(), 64);
  reader->SetFileName(TempPath("missing_after_good.png").c_str());
  reader->Update();
  EXPECT_GE(observer->Errors, 1);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(TestOIIOImageIO, WriterRejectsUnwritablePath)
{
  ExpectWriteFails(RandomImage(VTK_UNSIGNED_CHAR, 3, 4, 4, 1u),
    TempPath("no_such_directory/image.png"), "Cannot write");
}

TEST(TestOIIOImageIO, WriterRejectsUnknownExtension)
{
  ExpectWriteFails(
    RandomImage(VTK_UNSIGNED_CHAR, 3, 4, 4, 1u), TempPath("image.notaformat"), "extension");
}

TEST(TestOIIOImageIO, WriterRejectsFiveComponents)
{
  ExpectWriteFails(
    RandomImage(VTK_UNSIGNED_CHAR, 5, 4, 4, 1u), TempPath("five.png"), "5 components");
}

TEST(TestOIIOImageIO, WriterRejectsVolume)
{
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(4, 4, 3);
  volume->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  ExpectWriteFails(volume, TempPath("volume.png"), "3 slices");
}

TEST(TestOIIOImageIO, WriterRejectsUnsupportedType)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 1);
  image->AllocateScalars(VTK_LONG_LONG, 1);
  ExpectWriteFails(image, TempPath("longlong.tif"), "scalar type");
}

// A write that fails before the writer has opened the file must leave a file already at
// that path as it was: it is the user's, not a partial file of the writer's.
TEST(TestOIIOImageIO, WriterFailingBeforeOpenKeepsExistingFile)
{
  const std::string original = "the user's file, not an image";
  auto makeExisting = [&original](const std::string& path)
  {
    std::ofstream(path, std::ios::binary) << original;
    return path;
  };
  auto contents = [](const std::string& path)
  {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  };
  auto fiveComponents = RandomImage(VTK_UNSIGNED_CHAR, 5, 4, 4, 1u);
  auto rgb = RandomImage(VTK_UNSIGNED_CHAR, 3, 4, 4, 1u);

  // Layouts rejected before OpenImageIO is asked, and an extension it has no writer for.
  const std::string rejected = makeExisting(TempPath("existing_five.png"));
  const std::string unknown = makeExisting(TempPath("existing.notaformat"));
  for (const auto& job :
    { std::make_pair(fiveComponents.Get(), rejected), std::make_pair(rgb.Get(), unknown) })
  {
    vtkNew<vtkOIIOImageWriter> writer;
    vtkNew<ErrorObserver> observer;
    writer->AddObserver(vtkCommand::ErrorEvent, observer);
    writer->SetInputData(job.first);
    writer->SetFileName(job.second.c_str());
    writer->Write();
    EXPECT_EQ(observer->Errors, 1) << job.second;
    EXPECT_NE(writer->GetErrorCode(), vtkErrorCode::NoError);
    EXPECT_EQ(contents(job.second), original) << job.second;
  }

  // An exception before open() (here from an ErrorEvent observer that throws, as
  // applications that turn VTK errors into exceptions have) must not delete the file either.
  class ThrowingObserver : public vtkCommand
  {
  public:
    static ThrowingObserver* New() { return new ThrowingObserver; }
    void Execute(vtkObject*, unsigned long, void*) override
    {
      throw std::runtime_error("error turned into an exception");
    }
  };
  vtkNew<vtkOIIOImageWriter> writer;
  vtkNew<ThrowingObserver> thrower;
  writer->AddObserver(vtkCommand::ErrorEvent, thrower);
  writer->SetInputData(rgb);
  writer->SetFileName(unknown.c_str());
  EXPECT_THROW(writer->Write(), std::runtime_error);
  EXPECT_EQ(contents(unknown), original);
}

TEST(TestOIIOImageIO, WriterWithoutInputOrFileName)
{
  vtkNew<vtkOIIOImageWriter> writer;
  vtkNew<ErrorObserver> observer;
  writer->AddObserver(vtkCommand::ErrorEvent, observer);
  writer->SetFileName(TempPath("no_input.png").c_str());
  writer->Write();
  EXPECT_EQ(observer->Errors, 1);
  EXPECT_NE(writer->GetErrorCode(), vtkErrorCode::NoError);

  writer->SetFileName(nullptr);
  writer->SetInputData(RandomImage(VTK_UNSIGNED_CHAR, 1, 2, 2, 1u));
  writer->Write();
  EXPECT_EQ(observer->Errors, 2);
  EXPECT_EQ(writer->GetErrorCode(), vtkErrorCode::NoFileNameError);
}

// Through a pipeline connection (not SetInputData) and with Update() instead of Write(),
// the writer still asks for and writes the whole image.
TEST(TestOIIOImageIO, WriterInPipeline)
{
  auto image = RandomImage(VTK_UNSIGNED_SHORT, 3, 23, 13, 4u);
  const std::string source = TempPath("pipeline_source.png");
  ASSERT_TRUE(Write(image, source));
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(source.c_str());
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputConnection(reader->GetOutputPort());
  const std::string viaWrite = TempPath("pipeline_write.tif");
  writer->SetFileName(viaWrite.c_str());
  writer->Write();
  ExpectIdentical(image, Read(viaWrite));
  const std::string viaUpdate = TempPath("pipeline_update.tif");
  writer->SetFileName(viaUpdate.c_str());
  writer->Update();
  ExpectIdentical(image, Read(viaUpdate));
}

// PNG holds integers only: a float image written as PNG is converted, and the writer warns.
TEST(TestOIIOImageIO, WriterWarnsWhenFormatCannotHoldType)
{
  vtkNew<vtkOIIOImageWriter> writer;
  vtkNew<ErrorObserver> observer;
  writer->AddObserver(vtkCommand::WarningEvent, observer);
  writer->AddObserver(vtkCommand::ErrorEvent, observer);
  writer->SetInputData(RandomImage(VTK_FLOAT, 3, 4, 4, 1u));
  const std::string path = TempPath("float.png");
  writer->SetFileName(path.c_str());
  writer->Write();
  EXPECT_EQ(observer->Errors, 0);
  EXPECT_EQ(observer->Warnings, 1);
  EXPECT_NE(observer->Message.find("float"), std::string::npos) << observer->Message;
  EXPECT_EQ(Read(path)->GetScalarType(), VTK_UNSIGNED_CHAR);

  observer->Warnings = 0;
  writer->SetFileName(TempPath("float.exr").c_str());
  writer->Write();
  EXPECT_EQ(observer->Warnings, 0) << observer->Message;
}

// The level reaches zlib: no compression makes a larger file than the strongest, and both
// hold the same pixels.
TEST(TestOIIOImageIO, WriterCompressionLevel)
{
  auto image = RandomImage(VTK_UNSIGNED_CHAR, 3, 64, 64, 6u);
  vtkDataArray* values = image->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    values->SetVariantValue(i, (i / 97) % 256); // Compressible.
  }
  std::vector<unsigned long> sizes;
  for (int level : { 0, 9 })
  {
    vtkNew<vtkOIIOImageWriter> writer;
    writer->SetInputData(image);
    writer->SetCompressionLevel(level);
    const std::string path = TempPath("level" + std::to_string(level) + ".png");
    writer->SetFileName(path.c_str());
    writer->Write();
    ExpectIdentical(image, Read(path));
    sizes.push_back(vtksys::SystemTools::FileLength(path));
  }
  EXPECT_GT(sizes[0], 2 * sizes[1]);
}
