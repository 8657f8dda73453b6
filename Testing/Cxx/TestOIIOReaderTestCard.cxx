// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Data/test_card.png read by vtkOIIOImageReader and shown on a screen-filling rectangle
// whose texture coordinates run from (0,0) bottom-left to (1,1) top-right: the words must
// read upright, TOP at the top, LEFT on the left, "(0,0)" in the bottom-left corner. A
// reader that forgot to flip the rows (OIIO's row 0 is the top) puts BOTTOM at the top.

#include "TexturedSquareTestHelpers.h"
#include "vtkOIIOImageReader.h"

#include <vtkNew.h>
#include <vtkTexture.h>

int main(int argc, char* argv[])
{
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(SURFACEDETAIL_DATA_DIR "/test_card.png");
  vtkNew<vtkTexture> texture;
  texture->SetInputConnection(reader->GetOutputPort());
  texture->InterpolateOn();
  return RenderTexturedSquareAndCompare(argc, argv, texture);
}
