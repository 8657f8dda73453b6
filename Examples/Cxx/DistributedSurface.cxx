// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Generates, displaces and writes a large surface under MPI, one piece per rank:
//
//   mpirun -np 4 DistributedSurface [--resolution N] [--threads T] [--output surface.pvtp]
//
// The surface has 2N x N quads (default N = 1024: 2.1 million points). Each rank also runs
// vtkSMPTools threads: T per rank (default: what vtkSMPTools chooses, all cores), so that
// ranks x threads can be matched to the cores.
//
// Every rank asks the pipeline for its own piece only (UPDATE_PIECE_NUMBER = rank of
// UPDATE_NUMBER_OF_PIECES = ranks): vtkParametricSurfaceSource makes only that piece's rows,
// plus one row of ghost cells on each side because vtkDisplacementMapFilter asks for one
// ghost level to merge seams and read neighbours; the filter removes the ghosts again before
// the writer. vtkXMLPPolyDataWriter writes one .vtp per rank and rank 0 the .pvtp that
// lists them (ParaView opens it as one surface). Each rank prints how long its piece took.

#include "DistributedSurfacePipeline.h"

#include <vtkMPIController.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkTimerLog.h>
#include <vtkXMLPPolyDataWriter.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();

  int resolution = 1024;
  int threads = 0;
  std::string output = "DistributedSurface.pvtp";
  // Any argument it does not know, or --help, answers with the usage and writes nothing: a
  // mistyped option must not start a run that writes hundreds of megabytes.
  bool help = false;
  bool understood = true;
  for (int a = 1; a < argc && understood && !help; ++a)
  {
    const bool hasValue = a + 1 < argc;
    if (!std::strcmp(argv[a], "--help") || !std::strcmp(argv[a], "-h"))
    {
      help = true;
    }
    else if (!std::strcmp(argv[a], "--resolution") && hasValue)
    {
      resolution = std::atoi(argv[++a]);
    }
    else if (!std::strcmp(argv[a], "--threads") && hasValue)
    {
      threads = std::atoi(argv[++a]);
    }
    else if (!std::strcmp(argv[a], "--output") && hasValue)
    {
      output = argv[++a];
    }
    else
    {
      understood = false;
    }
  }
  if (help || !understood)
  {
    if (rank == 0)
    {
      std::fprintf(help ? stdout : stderr,
        "Usage: mpirun -np P DistributedSurface [--resolution N] [--threads T] [--output F]\n\n"
        "Generates and displaces a surface of 2N x N quads (default N = 1024), one piece per\n"
        "rank, T vtkSMPTools threads per rank (default: all cores), and writes it to F\n"
        "(default DistributedSurface.pvtp, with one .vtp per rank beside it).\n");
    }
    controller->Finalize();
    return help ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  if (resolution < 1)
  {
    if (rank == 0)
    {
      std::fprintf(stderr, "--resolution must be a positive number of rows\n");
    }
    controller->Finalize();
    return EXIT_FAILURE;
  }

  vtkSMPTools::Initialize(threads);
  DistributedSurface::Pipeline pipeline(resolution);

  // Timed apart from the writing, which measures the disk rather than the module.
  vtkNew<vtkTimerLog> timer;
  controller->Barrier();
  // Wall-clock time, and processor time (all threads), which other jobs on a shared machine
  // do not inflate.
  const std::clock_t cpu0 = std::clock();
  timer->StartTimer();
  pipeline.Displace->UpdatePiece(rank, ranks, 0);
  timer->StopTimer();
  const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  vtkPolyData* piece = pipeline.Displace->GetOutput();
  const double seconds = timer->GetElapsedTime();
  const double points = static_cast<double>(piece->GetNumberOfPoints());
  std::printf("rank %d of %d, %d threads: %.0f points, %lld triangles in %.3f s, %.3f s of "
              "processor time (%.3g points/s, %.3g points per processor second)\n",
    rank, ranks, vtkSMPTools::GetEstimatedNumberOfThreads(), points,
    static_cast<long long>(piece->GetNumberOfCells()), seconds, cpu, points / seconds,
    points / cpu);

  // The writer asks for the same piece, which is up to date: nothing runs again.
  vtkNew<vtkXMLPPolyDataWriter> writer;
  writer->SetInputConnection(pipeline.Displace->GetOutputPort());
  writer->SetFileName(output.c_str());
  writer->SetNumberOfPieces(ranks);
  writer->SetStartPiece(rank);
  writer->SetEndPiece(rank);
  writer->SetController(controller);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  // LZ4: several times faster than the default zlib for a few percent more bytes.
  writer->SetCompressorTypeToLZ4();
  timer->StartTimer();
  const int written = writer->Write();
  timer->StopTimer();
  std::printf("rank %d of %d: wrote its piece in %.3f s\n", rank, ranks, timer->GetElapsedTime());

  int ok = written == 1 ? 1 : 0, allOk = 0;
  controller->AllReduce(&ok, &allOk, 1, vtkCommunicator::MIN_OP);
  if (rank == 0)
  {
    std::printf(
      allOk ? "wrote %s (%d pieces)\n" : "writing %s (%d pieces) failed\n", output.c_str(), ranks);
  }
  controller->Finalize();
  return allOk ? EXIT_SUCCESS : EXIT_FAILURE;
}
