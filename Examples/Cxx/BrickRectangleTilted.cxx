// Seed 004: the seed's photograph had tilted bricks and straightened them by mapping only
// a slanted part of the picture, (.029,1) (0,0) (.992,.032) (.929,1), onto the rectangle.
// Our bricks are straight, so the same texture coordinates tilt and shear them instead:
// the courses slope down to the right and the joints lean right towards the top, showing
// what the quick fix does. (The slanted part is not a parallelogram, so the two triangles
// of the quad map it with slightly different shears: OpenGL interpolates per triangle.)

#include "BrickRectangle.h"

int main(int argc, char* argv[])
{
  const double corners[4][3] = { { -2, 3.5, 0 }, { -2, 0, 0 }, { 2, 0, 0 }, { 2, 3.5, 0 } };
  const double tcoords[4][2] = { { .029, 1 }, { 0, 0 }, { .992, .032 }, { .929, 1 } };
  return RenderBrickRectangle(argc, argv, "BrickRectangleTilted", corners, tcoords);
}
