// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// SurfaceDetailMakeData: makes every texture in Data/ from nothing but formulas, so the
// data can be checked, changed and re-made, never just trusted.
//
//   SurfaceDetailMakeData <output-folder> [--compare <folder>]
//
// writes the PNGs into <output-folder> with vtkOIIOImageWriter. With --compare it then
// reads each written file and the file of the same name in <folder> (the committed Data/)
// and fails unless they hold the same pixels: Data/ cannot drift from this program.
//
// Every texture tiles (its right edge continues into its left, its top into its bottom),
// so it can be repeated on a surface without seams. All randomness is an integer hash of
// the lattice position, so the output is the same on every run.

#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

using Image = vtkSmartPointer<vtkImageData>;

Image NewImage(int size, int type, int components)
{
  auto image = Image::New();
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(type, components);
  return image;
}

//------------------------------------------------------------------------------
// Noise

/// A well-mixed 32-bit hash of a lattice point and a seed (multiply-xorshift rounds).
std::uint32_t Hash(std::uint32_t x, std::uint32_t y, std::uint32_t seed)
{
  std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}

/// Uniform in [0, 1) at a lattice point.
double Random01(int x, int y, std::uint32_t seed)
{
  return Hash(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), seed) / 4294967296.0;
}

int Modulo(int a, int n)
{
  return ((a % n) + n) % n;
}

/// Value noise with @a period lattice cells across [0,1)^2, periodic in u and v: lattice
/// values hashed at (i mod period, j mod period), blended with the quintic fade so that
/// the surface has continuous slope (a height map's normals stay smooth).
double ValueNoise(double u, double v, int period, std::uint32_t seed)
{
  const double x = u * period, y = v * period;
  const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
  const double fx = x - i, fy = y - j;
  auto fade = [](double t) { return t * t * t * (t * (t * 6 - 15) + 10); };
  const double sx = fade(fx), sy = fade(fy);
  const int i0 = Modulo(i, period), i1 = Modulo(i + 1, period);
  const int j0 = Modulo(j, period), j1 = Modulo(j + 1, period);
  const double a = Random01(i0, j0, seed), b = Random01(i1, j0, seed);
  const double c = Random01(i0, j1, seed), d = Random01(i1, j1, seed);
  return (a + (b - a) * sx) * (1 - sy) + (c + (d - c) * sx) * sy;
}

/// Fractal sum of @a octaves of value noise, each twice the frequency and half the
/// amplitude of the one before; in [0, 1), periodic over [0,1)^2.
double Fbm(double u, double v, int period, int octaves, std::uint32_t seed)
{
  double sum = 0, amplitude = 0.5, total = 0;
  for (int o = 0; o < octaves; ++o)
  {
    sum += amplitude * ValueNoise(u, v, period << o, seed + 101u * o);
    total += amplitude;
    amplitude *= 0.5;
  }
  return sum / total;
}

unsigned char ToByte(double x)
{
  return static_cast<unsigned char>(std::lround(std::clamp(x, 0.0, 255.0)));
}

unsigned short ToUShort(double unit)
{
  return static_cast<unsigned short>(std::lround(std::clamp(unit, 0.0, 1.0) * 65535.0));
}

/// Calls @a f(i, j, u, v) for every texel, (u, v) its centre in [0,1)^2 (row 0 = v near 0).
void ForEachTexel(int size, const std::function<void(int, int, double, double)>& f)
{
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      f(i, j, (i + 0.5) / size, (j + 0.5) / size);
    }
  }
}

//------------------------------------------------------------------------------
// Bricks: running bond, 4 bricks across and 8 courses up the 512 px tile (128 x 64 px
// each, mortar joints 8 px wide), odd courses shifted by half a brick.

constexpr int BrickSize = 512;
constexpr int BrickWidth = 128;
constexpr int BrickHeight = 64;
constexpr double MortarHalfWidth = 4.0;
constexpr double Bevel = 6.0;

struct BrickSample
{
  int Brick;     ///< Which brick (a stable id), or -1 in the mortar.
  double Inside; ///< Distance in texels from the mortar edge into the brick (0 in mortar).
};

BrickSample SampleBrick(double x, double y)
{
  const int course = static_cast<int>(std::floor(y / BrickHeight));
  const double shift = (course % 2) * BrickWidth * 0.5;
  const int column = static_cast<int>(std::floor((x + shift) / BrickWidth));
  const double bx = x + shift - column * BrickWidth; // Position within the brick cell.
  const double by = y - course * BrickHeight;
  const double toEdge = std::min({ bx, BrickWidth - bx, by, BrickHeight - by });
  const double inside = toEdge - MortarHalfWidth;
  if (inside <= 0)
  {
    return { -1, 0.0 };
  }
  const int columns = BrickSize / BrickWidth;
  return { course * columns + Modulo(column, columns), inside };
}

/// Height of the brick wall in [0,1]: mortar low (about 0.1), the faces of the bricks high
/// (0.9 to 1), joined by a bevel whose slope eases in and out (a quarter-sine) over
/// Bevel texels, so a bump-mapped wall shows rounded, raised bricks.
double BrickHeightAt(double x, double y)
{
  const BrickSample s = SampleBrick(x, y);
  const double u = x / BrickSize, v = y / BrickSize;
  const double mortar = 0.08 + 0.04 * Fbm(u, v, 32, 2, 7u);
  if (s.Brick < 0)
  {
    return mortar;
  }
  const double face = 0.9 + 0.1 * Fbm(u, v, 16, 4, 11u);
  const double t = std::min(1.0, s.Inside / Bevel);
  return mortar + (face - mortar) * std::sin(0.5 * Pi * t);
}

Image MakeBrickHeight()
{
  Image image = NewImage(BrickSize, VTK_UNSIGNED_SHORT, 1);
  auto* h = static_cast<unsigned short*>(image->GetScalarPointer());
  ForEachTexel(BrickSize,
    [h](int i, int j, double, double)
    { h[j * BrickSize + i] = ToUShort(BrickHeightAt(i + 0.5, j + 0.5)); });
  return image;
}

Image MakeBrickColor()
{
  Image image = NewImage(BrickSize, VTK_UNSIGNED_CHAR, 3);
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer());
  ForEachTexel(BrickSize,
    [rgb](int i, int j, double u, double v)
    {
      const BrickSample s = SampleBrick(i + 0.5, j + 0.5);
      double colour[3];
      if (s.Brick < 0)
      {
        const double grain = 0.9 + 0.1 * Fbm(u, v, 64, 2, 5u);
        const double mortar[3] = { 196, 190, 178 };
        std::transform(mortar, mortar + 3, colour, [grain](double c) { return c * grain; });
      }
      else
      {
        // Each brick its own fired colour, between orange-red and dark brown-red.
        const double tone = Random01(s.Brick, 0, 3u);
        const double base[3] = { 150 + 50 * tone, 58 + 22 * tone, 42 + 14 * tone };
        const double grain = 0.8 + 0.2 * Fbm(u, v, 32, 4, 13u);
        // Edges a little darker (weathered), following the height's bevel.
        const double edge = 0.85 + 0.15 * std::min(1.0, s.Inside / Bevel);
        std::transform(
          base, base + 3, colour, [grain, edge](double c) { return c * grain * edge; });
      }
      for (int c = 0; c < 3; ++c)
      {
        rgb[3 * (j * BrickSize + i) + c] = ToByte(colour[c]);
      }
    });
  return image;
}

//------------------------------------------------------------------------------
// Checkerboard: 256 px, 8 x 8 squares, the bottom-left square dark.

Image MakeCheckerboard()
{
  constexpr int size = 256, squares = 8;
  Image image = NewImage(size, VTK_UNSIGNED_CHAR, 3);
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer());
  ForEachTexel(size,
    [rgb](int i, int j, double, double)
    {
      const bool light = ((i * squares / size) + (j * squares / size)) % 2 == 1;
      std::memset(rgb + 3 * (j * size + i), light ? 224 : 32, 3);
    });
  return image;
}

//------------------------------------------------------------------------------
// Noise height field: 256 px, 5 octaves of value noise, stretched to fill [0,1].

Image MakeNoiseHeight()
{
  constexpr int size = 256;
  std::vector<double> h(size * size);
  ForEachTexel(
    size, [&h](int i, int j, double u, double v) { h[j * size + i] = Fbm(u, v, 4, 5, 17u); });
  const auto range = std::minmax_element(h.begin(), h.end());
  const double low = *range.first, span = *range.second - *range.first;
  Image image = NewImage(size, VTK_UNSIGNED_SHORT, 1);
  auto* out = static_cast<unsigned short*>(image->GetScalarPointer());
  for (int k = 0; k < size * size; ++k)
  {
    out[k] = ToUShort((h[k] - low) / span);
  }
  return image;
}

//------------------------------------------------------------------------------
// Marble: 512 px, veins along sin(2 pi (2u + v + 1.5 turbulence)), turbulence being fBm.
// The integer frequencies keep it periodic.

Image MakeMarble()
{
  constexpr int size = 512;
  Image image = NewImage(size, VTK_UNSIGNED_CHAR, 3);
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer());
  ForEachTexel(size,
    [rgb](int i, int j, double u, double v)
    {
      const double turbulence = Fbm(u, v, 4, 6, 23u);
      const double wave = std::sin(2 * Pi * (2 * u + v + 1.5 * turbulence));
      const double vein = std::pow(1.0 - std::abs(wave), 6.0); // Thin dark veins.
      const double cloud = 0.94 + 0.06 * Fbm(u, v, 8, 3, 29u);
      const double stone[3] = { 236, 232, 224 }, veinColour[3] = { 84, 90, 104 };
      for (int c = 0; c < 3; ++c)
      {
        rgb[3 * (j * size + i) + c] =
          ToByte((stone[c] + (veinColour[c] - stone[c]) * vein) * cloud);
      }
    });
  return image;
}

//------------------------------------------------------------------------------
// Test card: 512 px. Quadrants coloured as the image-test harness's card (bottom-left
// red, bottom-right green, top-left blue, top-right white), a grid every 64 px, and
// letters that read correctly only when the texture is upright: TOP, BOTTOM, LEFT, RIGHT,
// a large F in the middle and the (s,t) texture coordinates of each corner.

/// A 5 x 7 bitmap font (rows from the top of the glyph), just the characters we need.
const std::array<const char*, 7>* Glyph(char c)
{
  static const std::array<const char*, 7> glyphs[] = {
    { "#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.." }, // T
    { ".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###." }, // O
    { "####.", "#...#", "#...#", "####.", "#....", "#....", "#...." }, // P
    { "####.", "#...#", "#...#", "####.", "#...#", "#...#", "####." }, // B
    { "#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#" }, // M
    { "#....", "#....", "#....", "#....", "#....", "#....", "#####" }, // L
    { "#####", "#....", "#....", "####.", "#....", "#....", "#####" }, // E
    { "#####", "#....", "#....", "####.", "#....", "#....", "#...." }, // F
    { "####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#" }, // R
    { ".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###." }, // I
    { ".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".###." }, // G
    { "#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#" }, // H
    { ".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###." }, // 0
    { "..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###." }, // 1
    { "...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#." }, // (
    { ".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..." }, // )
    { ".....", ".....", ".....", ".....", "..##.", "..#..", ".#..." }, // ,
  };
  static const char names[] = "TOPBMLEFRIGH01(),";
  const char* at = std::strchr(names, c);
  return c && at ? &glyphs[at - names] : nullptr;
}

class Card
{
public:
  explicit Card(vtkImageData* image)
    : Size(image->GetDimensions()[0])
    , Pixels(static_cast<unsigned char*>(image->GetScalarPointer()))
  {
  }

  /// Colours the pixel in column @a x, row @a row counted from the TOP of the picture.
  void Set(int x, int row, const unsigned char colour[3])
  {
    if (x >= 0 && x < this->Size && row >= 0 && row < this->Size)
    {
      std::memcpy(this->Pixels + 3 * ((this->Size - 1 - row) * this->Size + x), colour, 3);
    }
  }

  /// Writes @a text with its top-left corner at (@a x, @a row), each font pixel a
  /// @a scale x @a scale block, glyphs one font pixel apart.
  void Text(int x, int row, int scale, const std::string& text, const unsigned char colour[3])
  {
    for (const char c : text)
    {
      if (const auto* glyph = Glyph(c))
      {
        for (int gy = 0; gy < 7; ++gy)
        {
          for (int gx = 0; gx < 5; ++gx)
          {
            if ((*glyph)[gy][gx] == '#')
            {
              this->Block(x + gx * scale, row + gy * scale, scale, colour);
            }
          }
        }
      }
      x += 6 * scale;
    }
  }

  /// Like Text(), centred horizontally on @a centreX.
  void CentredText(
    int centreX, int row, int scale, const std::string& text, const unsigned char colour[3])
  {
    const int width = (6 * static_cast<int>(text.size()) - 1) * scale;
    this->Text(centreX - width / 2, row, scale, text, colour);
  }

private:
  void Block(int x, int row, int scale, const unsigned char colour[3])
  {
    for (int dy = 0; dy < scale; ++dy)
    {
      for (int dx = 0; dx < scale; ++dx)
      {
        this->Set(x + dx, row + dy, colour);
      }
    }
  }

  int Size;
  unsigned char* Pixels;
};

Image MakeTestCard()
{
  constexpr int size = 512;
  Image image = NewImage(size, VTK_UNSIGNED_CHAR, 3);
  Card card(image);
  const unsigned char topLeft[3] = { 140, 170, 240 }, topRight[3] = { 240, 240, 240 };
  const unsigned char bottomLeft[3] = { 240, 150, 150 }, bottomRight[3] = { 150, 220, 150 };
  const unsigned char grid[3] = { 90, 90, 90 }, ink[3] = { 0, 0, 0 };
  for (int row = 0; row < size; ++row)
  {
    for (int x = 0; x < size; ++x)
    {
      const bool top = row < size / 2, left = x < size / 2;
      const bool line = x % 64 == 0 || x % 64 == 63 || row % 64 == 0 || row % 64 == 63;
      card.Set(x, row,
        line    ? grid
          : top ? (left ? topLeft : topRight)
                : (left ? bottomLeft : bottomRight));
    }
  }
  card.CentredText(size / 2, 24, 6, "TOP", ink);
  card.CentredText(size / 2, size - 24 - 42, 6, "BOTTOM", ink);
  card.Text(16, size / 2 - 21 - 80, 6, "LEFT", ink);
  card.Text(size - 16 - 29 * 6, size / 2 + 80, 6, "RIGHT", ink);
  card.CentredText(size / 2, size / 2 - 56, 16, "F", ink);
  card.Text(8, size - 8 - 21, 3, "(0,0)", ink);
  card.Text(size - 8 - 29 * 3, size - 8 - 21, 3, "(1,0)", ink);
  card.Text(8, 8, 3, "(0,1)", ink);
  card.Text(size - 8 - 29 * 3, 8, 3, "(1,1)", ink);
  return image;
}

//------------------------------------------------------------------------------

bool Write(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

Image Read(const std::string& path)
{
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader->GetErrorCode() != 0)
  {
    return nullptr;
  }
  Image image = Image::New();
  image->ShallowCopy(reader->GetOutput());
  return image;
}

/// Empty if the two files hold the same pixels, else what differs.
std::string Compare(const std::string& made, const std::string& committed)
{
  const Image a = Read(made), b = Read(committed);
  if (!a || !b)
  {
    return "cannot read " + (a ? committed : made);
  }
  if (a->GetScalarType() != b->GetScalarType() ||
    a->GetNumberOfScalarComponents() != b->GetNumberOfScalarComponents() ||
    a->GetNumberOfPoints() != b->GetNumberOfPoints())
  {
    return "different size, type or channel count";
  }
  vtkDataArray* va = a->GetPointData()->GetScalars();
  vtkDataArray* vb = b->GetPointData()->GetScalars();
  vtkIdType differ = 0;
  for (vtkIdType k = 0; k < va->GetNumberOfValues(); ++k)
  {
    differ += va->GetVariantValue(k).ToDouble() != vb->GetVariantValue(k).ToDouble();
  }
  return differ ? std::to_string(differ) + " values differ" : std::string();
}
}

int main(int argc, char* argv[])
{
  const bool help = argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h");
  if (help || (argc != 2 && !(argc == 4 && std::string(argv[2]) == "--compare")))
  {
    (help ? std::cout : std::cerr)
      << "Usage: SurfaceDetailMakeData <output-folder> [--compare <folder>]\n\n"
         "Makes every texture in Data/ from formulas and writes the PNGs into <output-folder>;\n"
         "with --compare, fails unless each holds the same pixels as the file of that name in\n"
         "<folder>.\n";
    return help ? 0 : 2;
  }
  const std::string out = argv[1];
  if (!vtksys::SystemTools::MakeDirectory(out))
  {
    std::cerr << "cannot create " << out << "\n";
    return 1;
  }
  const std::pair<const char*, std::function<Image()>> textures[] = {
    { "brick_color.png", MakeBrickColor },
    { "brick_height.png", MakeBrickHeight },
    { "checkerboard.png", MakeCheckerboard },
    { "noise_height.png", MakeNoiseHeight },
    { "marble.png", MakeMarble },
    { "test_card.png", MakeTestCard },
  };
  int failures = 0;
  for (const auto& texture : textures)
  {
    const std::string path = out + "/" + texture.first;
    if (!Write(texture.second(), path))
    {
      std::cerr << "FAILED to write " << path << "\n";
      ++failures;
      continue;
    }
    std::cout << "wrote " << path << "\n";
    if (argc == 4)
    {
      const std::string committed = std::string(argv[3]) + "/" + texture.first;
      const std::string difference = Compare(path, committed);
      std::cout << (difference.empty() ? "  same pixels as " : "  DIFFERS from ") << committed
                << (difference.empty() ? "" : ": " + difference) << "\n";
      failures += !difference.empty();
    }
  }
  return failures == 0 ? 0 : 1;
}
