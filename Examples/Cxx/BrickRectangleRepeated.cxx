// Seed 004: texture coordinates beyond [0,1] repeat the picture. The rectangle
// -2 <= x <= 2, 0 <= y <= 1.5 gets u from 0 to 4 and v from 0 to 1.5: four copies across
// and one and a half up, each brick keeping the picture's proportions.

#include "BrickRectangle.h"

int main(int argc, char* argv[])
{
  const double corners[4][3] = { { -2, 1.5, 0 }, { -2, 0, 0 }, { 2, 0, 0 }, { 2, 1.5, 0 } };
  const double tcoords[4][2] = { { 0, 1.5 }, { 0, 0 }, { 4, 0 }, { 4, 1.5 } };
  return RenderBrickRectangle(argc, argv, "BrickRectangleRepeated", corners, tcoords);
}
