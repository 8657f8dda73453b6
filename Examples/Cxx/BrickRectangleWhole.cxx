// Seed 004: the whole brick picture on the rectangle -2 <= x <= 2, 0 <= y <= 3.5,
// corner to corner: 0 <= u <= 1 -> -2 <= x <= 2, 0 <= v <= 1 -> 0 <= y <= 3.5.

#include "BrickRectangle.h"

int main(int argc, char* argv[])
{
  const double corners[4][3] = { { -2, 3.5, 0 }, { -2, 0, 0 }, { 2, 0, 0 }, { 2, 3.5, 0 } };
  const double tcoords[4][2] = { { 0, 1 }, { 0, 0 }, { 1, 0 }, { 1, 1 } };
  return RenderBrickRectangle(argc, argv, "BrickRectangleWhole", corners, tcoords);
}
