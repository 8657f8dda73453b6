// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// What the gallery's examples share: textures from Data/, the key light, panel labels, and the
// picture written to <folder>/<name>.png. Every window has a fixed size and no multisampling,
// so that a picture is the same on every run and each example can be an image test
// (Testing/Examples). Examples/Python/example_scene.py is the same for the Python scripts.
#ifndef ExampleScene_h
#define ExampleScene_h

#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkProp.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkWindowToImageFilter.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <string>

namespace ExampleScene
{
/// True when the arguments ask for help (--help or -h): the program then prints its usage
/// and stops without rendering or writing anything.
inline bool AskedForHelp(int argc, char* argv[])
{
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
    {
      return true;
    }
  }
  return false;
}

/// Answers --help for an example that takes only an output folder: prints what the example
/// draws and where the picture goes, and returns true (the program should then return 0).
inline bool PrintedUsage(int argc, char* argv[], const char* name, const char* what)
{
  if (!AskedForHelp(argc, argv))
  {
    return false;
  }
  std::cout << "Usage: " << name << " [output folder]\n\n"
            << what << "\n\nWrites <output folder>/" << name
            << ".png (default: the current folder).\n";
  return true;
}

/// The folder to write into: the first argument, or the current folder.
inline std::string OutputFolder(int argc, char* argv[])
{
  return argc > 1 ? argv[1] : ".";
}

/// A texture from Data/ (see Data/README.md): linear, mipmapped, repeating.
inline vtkSmartPointer<vtkTexture> LoadTexture(const std::string& name)
{
  const std::string path = std::string(SURFACEDETAIL_DATA_DIR) + "/" + name;
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    std::cerr << "cannot read " << path << "\n";
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputConnection(reader->GetOutputPort());
  texture->InterpolateOn();
  texture->MipmapOn();
  texture->SetWrap(vtkTexture::Repeat);
  return texture;
}

/// The key light: from the upper right and in front, wherever the camera looks from.
inline void AddKeyLight(vtkRenderer* renderer)
{
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> key;
  key->SetLightTypeToCameraLight();
  key->SetPosition(1.0, 0.7, 1.0);
  key->SetFocalPoint(0, 0, 0);
  renderer->AddLight(key);
}

/// A caption in the lower left corner of @a renderer's viewport, on a dark box so that it
/// reads on any picture.
inline void AddLabel(vtkRenderer* renderer, const std::string& text)
{
  vtkNew<vtkTextActor> label;
  label->SetInput(text.c_str());
  label->GetTextProperty()->SetFontSize(20);
  label->GetTextProperty()->SetColor(0.92, 0.92, 0.92);
  label->GetTextProperty()->SetBackgroundColor(0.05, 0.05, 0.05);
  label->GetTextProperty()->SetBackgroundOpacity(0.7);
  label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  label->GetPositionCoordinate()->SetValue(0.03, 0.03);
  renderer->AddViewProp(label);
}

/**
 * A height map (8-bit, one channel, read as 0..1) of round bumps, @a across by @a up of them
 * over the texture square: h = (sin(pi across s) sin(pi up t))^2. It tiles.
 */
inline vtkSmartPointer<vtkImageData> QuiltHeights(int width, int height, int across, int up)
{
  constexpr double pi = 3.14159265358979323846;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* h = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const double s = (i + 0.5) / width, t = (j + 0.5) / height;
      const double b = std::sin(pi * across * s) * std::sin(pi * up * t);
      h[j * width + i] = static_cast<unsigned char>(std::lround(255.0 * b * b));
    }
  }
  return image;
}

inline vtkSmartPointer<vtkRenderWindow> MakeWindow(int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  return window;
}

/// An 800 x 600 window showing @a actor, lit by the key light, seen from @a eye, +y up.
inline vtkSmartPointer<vtkRenderWindow> ViewActor(
  vtkProp* actor, const double eye[3], const double focus[3], double viewAngle = 30.0)
{
  vtkNew<vtkRenderer> renderer;
  renderer->AddViewProp(actor);
  renderer->SetBackground(0.12, 0.13, 0.16);
  AddKeyLight(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(eye[0], eye[1], eye[2]);
  camera->SetFocalPoint(focus[0], focus[1], focus[2]);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(viewAngle);
  renderer->ResetCameraClippingRange();
  auto window = MakeWindow(800, 600);
  window->AddRenderer(renderer);
  return window;
}

/// Renders @a window and writes <folder>/<name>.png; returns the program's exit status.
inline int WritePicture(vtkRenderWindow* window, const std::string& folder, const std::string& name)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  const std::string path = folder + "/" + name + ".png";
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::cerr << "cannot write " << path << "\n";
    return 1;
  }
  std::cout << "wrote " << path << "\n";
  return 0;
}
} // namespace ExampleScene

#endif
