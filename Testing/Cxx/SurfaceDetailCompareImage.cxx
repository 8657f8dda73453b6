// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The strict image comparison (SurfaceDetailImageComparison.h) for a picture that another
// program wrote: an example, a Python script. VTK's conventions: the candidate is compared
// with -V <baseline.png> and its alternates; on failure the candidate and the difference
// image go into -T <folder>. Prints "Failed Image Test" and returns 1 unless it passes.
//
// Usage: SurfaceDetailCompareImage <candidate.png> -V <baseline.png> -T <folder>
#include "SurfaceDetailImageComparison.h"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  const char* baseline = SurfaceDetailImageComparison::Argument(argc, argv, "-V");
  const char* temporary = SurfaceDetailImageComparison::Argument(argc, argv, "-T");
  const bool help = argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h");
  if (help || argc != 6 || !baseline || !temporary)
  {
    (help ? std::cout : std::cerr)
      << "Usage: SurfaceDetailCompareImage <candidate.png> -V <baseline.png> -T <folder>\n\n"
         "The project's strict image comparison: passes when the candidate matches the baseline\n"
         "or one of its alternates; otherwise writes it and the difference into <folder>, fails.\n";
    return help ? 0 : 2;
  }
  vtkSmartPointer<vtkImageData> candidate = SurfaceDetailImageComparison::ReadPNG(argv[1]);
  if (!candidate)
  {
    std::cout << "Failed Image Test: there is no picture " << argv[1] << "\n";
    return 1;
  }
  return SurfaceDetailImageComparison::CompareWithBaseline(candidate, baseline, temporary) ==
      SurfaceDetailImageComparison::Passed
    ? 0
    : 1;
}
