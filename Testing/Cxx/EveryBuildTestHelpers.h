// Runs a test's own program again once per instruction-set build that
// vtkSurfaceDetailVectorize can pick (SURFACEDETAIL_MAX_ISA), so that a test can compare the
// builds' outputs bit for bit.
#ifndef EveryBuildTestHelpers_h
#define EveryBuildTestHelpers_h

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#ifdef __linux__
#include <unistd.h> // getpid
#endif

namespace EveryBuild
{
/// In the child run: the file to write the outputs to, or nullptr in the test's own run.
inline const char* DumpPath()
{
  return std::getenv("SURFACEDETAIL_TEST_EVERY_BUILD_DUMP");
}

/// Writes @a bytes to the child run's file.
inline void WriteDump(const char* path, const std::string& bytes)
{
  std::ofstream file(path, std::ios::binary);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  ASSERT_TRUE(file.good());
}

/// Runs this program's test @a filter (Suite.Name) once per build, widest, avx2 and baseline
/// (where the processor lacks a build, the next narrower one), and returns what each child
/// wrote, in that order; empty on failure (with a test failure recorded).
inline std::vector<std::string> OutputsOfEveryBuild(const std::string& filter)
{
  std::vector<std::string> results;
#ifdef __linux__
  // The program's own path: a shell that ran /proc/self/exe would run itself.
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  for (const char* isa : { "widest", "avx2", "baseline" })
  {
    // ctest may run a test's -avx2 and -baseline registrations at the same time.
    const std::string path = std::string(SURFACEDETAIL_TEMP_DIR) + "/" + filter + "-" +
      std::to_string(getpid()) + "-" + isa;
    const std::string command = std::string("SURFACEDETAIL_MAX_ISA=") + isa +
      " SURFACEDETAIL_TEST_EVERY_BUILD_DUMP='" + path + "' '" + self +
      "' --gtest_filter=" + filter + " >/dev/null";
    if (std::system(command.c_str()) != 0)
    {
      ADD_FAILURE() << "the " << isa << " run failed";
      return {};
    }
    std::ifstream file(path, std::ios::binary);
    if (!file.good())
    {
      ADD_FAILURE() << "the " << isa << " run wrote nothing";
      return {};
    }
    results.emplace_back(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    file.close();
    std::remove(path.c_str());
  }
#else
  (void)filter;
#endif
  return results;
}
}

#endif
