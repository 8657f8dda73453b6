// Small helpers shared by the parametric-surface examples (issue 3): textures from Data/ and
// rendering of one actor into <folder>/<name>.png.
#ifndef ParametricExampleHelpers_h
#define ParametricExampleHelpers_h

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtkWindowToImageFilter.h>

#include <iostream>
#include <string>

/// A texture from Data/ (see Data/README.md), mipmapped, linearly filtered, repeating.
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

/**
 * Renders @a actor with a key light from the upper right (in camera space) into
 * <folder>/<name>.png. The camera looks from @a eye at @a focus with +y up.
 */
inline int RenderExample(vtkActor* actor, const std::string& folder, const std::string& name,
  const double eye[3], const double focus[3], double viewAngle = 30.0)
{
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.12, 0.13, 0.16);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> key;
  key->SetLightTypeToCameraLight();
  key->SetPosition(1.0, 0.7, 1.0); // upper right, in front of the camera
  key->SetFocalPoint(0, 0, 0);
  key->SetIntensity(1.0);
  renderer->AddLight(key);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(eye[0], eye[1], eye[2]);
  camera->SetFocalPoint(focus[0], focus[1], focus[2]);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(viewAngle);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(8);
  window->SetSize(800, 600);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  const std::string path = folder + "/" + name + ".png";
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  std::cout << "wrote " << path << "\n";
  return writer->GetErrorCode() == 0 ? 0 : 1;
}

#endif
