// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The first image test: a screen-filling rectangle textured with a quadrant card whose
// colours say where row 0 of the image landed (bottom-left red, bottom-right green,
// top-left blue, top-right white). With --flip the texture is turned upside down, which
// the harness must catch (TestTexturedRectangleFlippedIsCaught).

#include "TexturedSquareTestHelpers.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkTexture.h>

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

  vtkNew<vtkTexture> texture;
  texture->SetInputData(card);
  texture->InterpolateOff();
  return RenderTexturedSquareAndCompare(argc, argv, texture);
}
