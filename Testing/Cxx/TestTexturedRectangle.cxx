// The first image test: a screen-filling rectangle textured with a quadrant card whose
// colours say where row 0 of the image landed (bottom-left red, bottom-right green,
// top-left blue, top-right white). With --flip the texture is turned upside down, which
// the harness must catch (TestTexturedRectangleFlippedIsCaught).

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

#include <cstring>

int main(int argc, char* argv[])
{
  bool flip = false;
  for (int i = 1; i < argc; ++i)
  {
    flip = flip || std::strcmp(argv[i], "--flip") == 0;
  }

  constexpr int size = 64;
  vtkNew<vtkImageData> card;
  card->SetDimensions(size, size, 1);
  card->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* rgb = static_cast<unsigned char*>(card->GetScalarPointer());
  const unsigned char quadrant[2][2][3] = { { { 230, 20, 20 }, { 20, 230, 20 } },
    { { 20, 20, 230 }, { 230, 230, 230 } } };
  for (int j = 0; j < size; ++j)
  {
    const int row = flip ? size - 1 - j : j;
    for (int i = 0; i < size; ++i)
    {
      const int top = row >= size / 2 ? 1 : 0;
      const int right = i >= size / 2 ? 1 : 0;
      std::memcpy(rgb + 3 * (j * size + i), quadrant[top][right], 3);
      // A one-texel diagonal from the bottom-left corner, so that a mirror shows too.
      if (i == row && i < size / 2)
      {
        std::memset(rgb + 3 * (j * size + i), 0, 3);
      }
    }
  }

  vtkNew<vtkPlaneSource> plane; // (0,0) bottom-left, texture coordinates 0..1
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);

  vtkNew<vtkTexture> texture;
  texture->SetInputData(card);
  texture->InterpolateOff();

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(texture);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.1);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(1.0);

  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(256, 256);
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();

  const int result = vtkRegressionTestImageThreshold(window, 0.05);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return !result;
}
