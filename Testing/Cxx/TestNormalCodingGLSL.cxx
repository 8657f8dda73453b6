// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The GLSL twin of the normal coding (Module/Rendering/glsl/vtkSurfaceDetailNormalCoding.glsl)
// agrees with the C++ one (vtkSurfaceDetailConventions.h EncodeNormal/DecodeNormal): a
// fragment shader decodes a pattern of colours as green-down normals and re-encodes them
// green-up; the window's pixels must equal what the C++ functions give for the same colours,
// to within the framebuffer's 8-bit rounding. Numbers are compared, not pictures.

#include "vtkSurfaceDetailConventions.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOpenGLShaderProperty.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace
{
// The colour the shader below gives pixel (x, y): components in [0,1], not unit length.
void PatternColour(int x, int y, double rgb[3])
{
  rgb[0] = (x % 8) / 7.0;
  rgb[1] = (y % 8) / 7.0;
  rgb[2] = ((x + y) % 5 + 1) / 5.0;
}
} // namespace

TEST(TestNormalCodingGLSL, ShaderMatchesTheConventionsHeader)
{
  std::ifstream file(SURFACEDETAIL_GLSL_DIR "/vtkSurfaceDetailNormalCoding.glsl");
  ASSERT_TRUE(file.good());
  std::stringstream glsl;
  glsl << file.rdbuf();

  constexpr int size = 40;
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  auto* shaders = vtkOpenGLShaderProperty::SafeDownCast(actor->GetShaderProperty());
  ASSERT_NE(shaders, nullptr);
  shaders->AddFragmentShaderReplacement(
    "//VTK::Normal::Dec", true, "//VTK::Normal::Dec\n" + glsl.str(), false);
  shaders->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
    "  vec2 p = floor(gl_FragCoord.xy);\n"
    "  vec3 rgb = vec3(mod(p.x, 8.0) / 7.0, mod(p.y, 8.0) / 7.0,\n"
    "    (mod(p.x + p.y, 5.0) + 1.0) / 5.0);\n"
    "  gl_FragData[0] = vec4(sdEncodeNormal(sdDecodeNormal(rgb, false), true), 1.0);\n",
    false);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(1.0);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(size, size);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->SetInputBufferTypeToRGB();
  capture->ReadFrontBufferOff();
  capture->Update();
  auto* pixels =
    vtkUnsignedCharArray::SafeDownCast(capture->GetOutput()->GetPointData()->GetScalars());
  ASSERT_NE(pixels, nullptr);
  ASSERT_EQ(pixels->GetNumberOfTuples(), size * size);

  int checked = 0;
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      double rgb[3], n[3], back[3];
      PatternColour(x, y, rgb);
      vtkSurfaceDetail::DecodeNormal(rgb, false, n);
      vtkSurfaceDetail::EncodeNormal(n, true, back);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(pixels->GetTypedComponent(y * size + x, c), 255.0 * back[c], 1.0)
          << "pixel " << x << "," << y << " component " << c;
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, size * size);
}
