// Small helpers shared by the parametric-surface examples (issue 3): a procedural test card
// that shows at a glance whether a texture is upright, mirrored or seamed, and rendering of
// one actor into <folder>/<name>.png.
#ifndef ParametricExampleHelpers_h
#define ParametricExampleHelpers_h

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

/**
 * A W x H RGB card: a checkerboard of `cells` x `cells` squares whose colour runs from
 * red (s = 0) to blue (s = 1) on the light squares, a white band at the top (t near 1), a
 * black band at the bottom, and a large upright "F" in the lower-left quarter, so that a
 * flip shows as the bands swapping and a mirror as the F facing left.
 */
inline vtkSmartPointer<vtkImageData> MakeTestCard(int width, int height, int cells)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int j = 0; j < height; ++j)
  {
    const double t = (j + 0.5) / height;
    for (int i = 0; i < width; ++i)
    {
      const double s = (i + 0.5) / width;
      unsigned char* p = rgb + 3 * (static_cast<size_t>(j) * width + i);
      const bool light = ((static_cast<int>(s * cells) + static_cast<int>(t * cells)) % 2) == 0;
      double r = light ? 230 * (1 - s) + 40 * s : 60;
      double g = light ? 90 : 60;
      double b = light ? 40 * (1 - s) + 230 * s : 70;
      // The F: a vertical bar with two arms pointing right, in the lower-left quarter.
      const double fx = s / 0.5, fy = t / 0.5;
      const bool bar = fx > 0.2 && fx < 0.32 && fy > 0.15 && fy < 0.85;
      const bool top = fx > 0.2 && fx < 0.75 && fy > 0.73 && fy < 0.85;
      const bool mid = fx > 0.2 && fx < 0.6 && fy > 0.47 && fy < 0.57;
      if (bar || top || mid)
      {
        r = 250;
        g = 250;
        b = 250;
      }
      if (t > 0.94)
      {
        r = g = b = 255;
      }
      else if (t < 0.06)
      {
        r = g = b = 0;
      }
      p[0] = static_cast<unsigned char>(r);
      p[1] = static_cast<unsigned char>(g);
      p[2] = static_cast<unsigned char>(b);
    }
  }
  return image;
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
