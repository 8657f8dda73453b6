// The private huge-page allocation gives ordinary VTK arrays (right size, writable, grown
// and copied by VTK, freed by VTK without help), and its cache of freed blocks reuses
// memory, respects its limit, can be turned off, and gives memory back to the system.
#include "vtkSurfaceDetailMemory.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkParametricSurfaceSource.h"
#include "vtkParametricTorus.h"
#include "vtkPolyData.h"
#include "vtkTypeInt32Array.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <unistd.h>
#endif

namespace
{
constexpr std::size_t MiB = std::size_t(1) << 20;
constexpr std::size_t DefaultLimit = std::size_t(1024) * MiB;

// Every test starts from an empty cache with the default settings.
void ResetCache()
{
  vtkSurfaceDetailMemory::SetCacheLimit(0);
  vtkSurfaceDetailMemory::SetCacheLimit(DefaultLimit);
  vtkSurfaceDetailMemory::SetCacheIdleTime(5.0);
}

template <typename ArrayT>
void CheckArray(vtkIdType tuples, int components)
{
  vtkNew<ArrayT> array;
  array->SetNumberOfComponents(components);
  ASSERT_TRUE(vtkSurfaceDetailMemory::AllocateTuples(array.Get(), tuples));
  EXPECT_EQ(array->GetNumberOfTuples(), tuples);
  EXPECT_EQ(array->GetNumberOfComponents(), components);
  const vtkIdType values = tuples * components;
  if (values == 0)
  {
    return;
  }
  auto* p = array->GetPointer(0);
  if (static_cast<std::size_t>(values) * sizeof(*p) >= vtkSurfaceDetailMemory::HugePageBytes)
  {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % vtkSurfaceDetailMemory::HugePageBytes, 0u);
#endif
  }
  for (vtkIdType i = 0; i < values; ++i)
  {
    p[i] = static_cast<typename ArrayT::ValueType>(i % 1000);
  }
  // VTK grows the array through its own reallocation; values must survive.
  array->InsertNextTuple(array->GetTuple(0));
  EXPECT_EQ(array->GetNumberOfTuples(), tuples + 1);
  for (vtkIdType i = 0; i < values; i += 997)
  {
    ASSERT_EQ(array->GetValue(i), static_cast<typename ArrayT::ValueType>(i % 1000));
  }
  vtkNew<ArrayT> copy;
  copy->DeepCopy(array);
  EXPECT_EQ(copy->GetValue(values - 1), array->GetValue(values - 1));
}

// Resident memory of this process in bytes (0 where /proc is not available).
std::size_t ResidentBytes()
{
  std::ifstream statm("/proc/self/statm");
  std::size_t size = 0, resident = 0;
  if (!(statm >> size >> resident))
  {
    return 0;
  }
#if defined(__linux__)
  return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
#else
  return 0;
#endif
}

// A big float array from the allocator, every value written.
vtkSmartPointer<vtkFloatArray> BigArray(std::size_t bytes)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  const vtkIdType values = static_cast<vtkIdType>(bytes / sizeof(float));
  EXPECT_TRUE(vtkSurfaceDetailMemory::AllocateTuples(array.Get(), values));
  std::memset(array->GetPointer(0), 0x5a, bytes);
  return array;
}
} // namespace

TEST(TestSurfaceDetailMemory, SmallArrayIsOrdinary)
{
  ResetCache();
  CheckArray<vtkFloatArray>(10, 3);
  CheckArray<vtkFloatArray>(0, 4);
}

TEST(TestSurfaceDetailMemory, BigArrayIsHugePageAlignedAndBehavesAsVTKArray)
{
  ResetCache();
  CheckArray<vtkFloatArray>(1000000, 3);
  CheckArray<vtkTypeInt32Array>(3000001, 1);
}

#if defined(__linux__)
TEST(TestSurfaceDetailMemory, ReleasedBlockIsReusedWarm)
{
  ResetCache();
  const auto before = vtkSurfaceDetailMemory::GetCacheStatistics();
  EXPECT_EQ(before.CachedBytes, 0u);
  void* first = nullptr;
  {
    auto array = BigArray(8 * MiB);
    first = array->GetPointer(0);
  }
  // The array's release kept its block.
  auto after = vtkSurfaceDetailMemory::GetCacheStatistics();
  EXPECT_EQ(after.CachedBytes, 8 * MiB);
  EXPECT_EQ(after.CachedBlocks, 1u);
  // A request that fits gets the same block back, with what was written still there
  // (proof that no fresh, zeroed page was faulted in).
  void* p = vtkSurfaceDetailMemory::Allocate(7 * MiB + 5);
  EXPECT_EQ(p, first);
  EXPECT_EQ(static_cast<unsigned char*>(p)[12345], 0x5a);
  after = vtkSurfaceDetailMemory::GetCacheStatistics();
  EXPECT_EQ(after.Hits, before.Hits + 1);
  EXPECT_EQ(after.CachedBytes, 0u);
  vtkSurfaceDetailMemory::Release(p);
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 8 * MiB);
}

TEST(TestSurfaceDetailMemory, BlocksAreSplitAndJoined)
{
  ResetCache();
  char* whole = static_cast<char*>(vtkSurfaceDetailMemory::Allocate(8 * MiB));
  ASSERT_NE(whole, nullptr);
  vtkSurfaceDetailMemory::Release(whole);
  // Two halves come out of the one cached block...
  char* a = static_cast<char*>(vtkSurfaceDetailMemory::Allocate(4 * MiB));
  char* b = static_cast<char*>(vtkSurfaceDetailMemory::Allocate(4 * MiB));
  EXPECT_EQ(a, whole);
  EXPECT_EQ(b, whole + 4 * MiB);
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 0u);
  // ...and go back as one, so that a request for the whole is served warm again.
  vtkSurfaceDetailMemory::Release(b);
  vtkSurfaceDetailMemory::Release(a);
  auto statistics = vtkSurfaceDetailMemory::GetCacheStatistics();
  EXPECT_EQ(statistics.CachedBlocks, 1u);
  EXPECT_EQ(statistics.CachedBytes, 8 * MiB);
  void* p = vtkSurfaceDetailMemory::Allocate(8 * MiB);
  EXPECT_EQ(p, whole);
  vtkSurfaceDetailMemory::Release(p);
}

TEST(TestSurfaceDetailMemory, ReexecutingSourceWritesIntoWarmMemory)
{
  ResetCache();
  vtkNew<vtkParametricTorus> torus;
  vtkNew<vtkParametricSurfaceSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(511);
  source->SetVResolution(511);
  source->GenerateTangentsOn();
  source->Update();
  vtkNew<vtkPolyData> first;
  first->DeepCopy(source->GetOutput());
  const auto before = vtkSurfaceDetailMemory::GetCacheStatistics();
  source->Modified();
  source->Update();
  const auto after = vtkSurfaceDetailMemory::GetCacheStatistics();
  // Every big array of the new output came from the previous output's blocks.
  EXPECT_GT(after.Hits, before.Hits);
  EXPECT_EQ(after.Misses, before.Misses);
  // And the output is the same.
  auto* p0 = vtkFloatArray::SafeDownCast(first->GetPoints()->GetData());
  auto* p1 = vtkFloatArray::SafeDownCast(source->GetOutput()->GetPoints()->GetData());
  ASSERT_NE(p0, nullptr);
  ASSERT_NE(p1, nullptr);
  ASSERT_EQ(p0->GetNumberOfValues(), p1->GetNumberOfValues());
  EXPECT_EQ(
    std::memcmp(p0->GetPointer(0), p1->GetPointer(0), sizeof(float) * p0->GetNumberOfValues()), 0);
}

TEST(TestSurfaceDetailMemory, CacheRespectsItsLimit)
{
  ResetCache();
  vtkSurfaceDetailMemory::SetCacheLimit(10 * MiB);
  std::vector<void*> blocks;
  for (int i = 0; i < 4; ++i)
  {
    blocks.push_back(vtkSurfaceDetailMemory::Allocate(4 * MiB));
  }
  for (void* p : blocks)
  {
    vtkSurfaceDetailMemory::Release(p);
    EXPECT_LE(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 10 * MiB);
  }
  EXPECT_GE(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 8 * MiB);
  // A block bigger than the limit is never kept.
  vtkSurfaceDetailMemory::SetCacheLimit(0);
  vtkSurfaceDetailMemory::SetCacheLimit(10 * MiB);
  vtkSurfaceDetailMemory::Release(vtkSurfaceDetailMemory::Allocate(12 * MiB));
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 0u);
  // Lowering the limit gives back the excess at once (the tail of a block; the rest is
  // still warm).
  vtkSurfaceDetailMemory::Release(vtkSurfaceDetailMemory::Allocate(8 * MiB));
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 8 * MiB);
  vtkSurfaceDetailMemory::SetCacheLimit(4 * MiB);
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 4 * MiB);
  vtkSurfaceDetailMemory::SetCacheLimit(3 * MiB);
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 2 * MiB);
  vtkSurfaceDetailMemory::SetCacheLimit(0);
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 0u);
}

TEST(TestSurfaceDetailMemory, ZeroLimitTurnsTheCacheOff)
{
  ResetCache();
  vtkSurfaceDetailMemory::SetCacheLimit(0);
  const auto before = vtkSurfaceDetailMemory::GetCacheStatistics();
  for (int i = 0; i < 3; ++i)
  {
    BigArray(4 * MiB);
    EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 0u);
  }
  const auto after = vtkSurfaceDetailMemory::GetCacheStatistics();
  EXPECT_EQ(after.Hits, before.Hits);
  EXPECT_EQ(after.Misses, before.Misses + 3);
}

TEST(TestSurfaceDetailMemory, EnvironmentSetsTheLimit)
{
  const char* name = "SURFACEDETAIL_ARRAY_CACHE_MB";
  unsetenv(name);
  EXPECT_EQ(vtkSurfaceDetailMemory::CacheLimitFromEnvironment(), DefaultLimit);
  setenv(name, "0", 1);
  EXPECT_EQ(vtkSurfaceDetailMemory::CacheLimitFromEnvironment(), 0u);
  setenv(name, "64", 1);
  EXPECT_EQ(vtkSurfaceDetailMemory::CacheLimitFromEnvironment(), 64 * MiB);
  for (const char* bad : { "", "abc", "12x", "-3" })
  {
    setenv(name, bad, 1);
    EXPECT_EQ(vtkSurfaceDetailMemory::CacheLimitFromEnvironment(), DefaultLimit) << bad;
  }
  // The cache itself reads the variable when the process first allocates: in a fresh
  // process started with 0, released blocks go straight back to the system.
  setenv(name, "0", 1);
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
    {
      const bool off = vtkSurfaceDetailMemory::GetCacheLimit() == 0;
      BigArray(4 * MiB);
      std::exit(off && vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes == 0 ? 0 : 1);
    },
    testing::ExitedWithCode(0), "");
  unsetenv(name);
}

TEST(TestSurfaceDetailMemory, IdleBlocksGoBackToTheSystem)
{
  ResetCache();
  vtkSurfaceDetailMemory::SetCacheIdleTime(0.05);
  const std::size_t bytes = 64 * MiB;
  BigArray(bytes); // written, then released into the cache
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, bytes);
  const std::size_t cachedResident = ResidentBytes();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  // Any next call gives back what has been idle too long.
  vtkSurfaceDetailMemory::Release(vtkSurfaceDetailMemory::Allocate(16));
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 0u);
  if (cachedResident > 0)
  {
    EXPECT_LE(ResidentBytes() + bytes / 2, cachedResident);
  }
  // TrimCache(0) empties the cache at once, whatever the idle time.
  vtkSurfaceDetailMemory::SetCacheIdleTime(5.0);
  BigArray(bytes);
  EXPECT_EQ(vtkSurfaceDetailMemory::TrimCache(), bytes);
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 0u);
}

TEST(TestSurfaceDetailMemory, ArraysSharingABlockReleaseItOnce)
{
  ResetCache();
  auto array = BigArray(4 * MiB);
  vtkNew<vtkFloatArray> shallow;
  shallow->ShallowCopy(array);
  array = nullptr;
  // The block still belongs to the shallow copy.
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 0u);
  EXPECT_EQ(static_cast<unsigned char*>(shallow->GetVoidPointer(0))[100], 0x5a);
  shallow->Initialize();
  EXPECT_EQ(vtkSurfaceDetailMemory::GetCacheStatistics().CachedBytes, 4 * MiB);
}

TEST(TestSurfaceDetailMemory, ThreadsShareTheCacheSafely)
{
  ResetCache();
  vtkSurfaceDetailMemory::SetCacheLimit(24 * MiB);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
  {
    threads.emplace_back(
      [t]()
      {
        for (int i = 0; i < 40; ++i)
        {
          const std::size_t bytes = (1 + (i * 7 + t) % 5) * MiB + 4096 * t;
          auto* p = static_cast<unsigned char*>(vtkSurfaceDetailMemory::Allocate(bytes));
          ASSERT_NE(p, nullptr);
          std::memset(p, t, bytes);
          EXPECT_EQ(p[bytes - 1], t);
          vtkSurfaceDetailMemory::Release(p);
        }
      });
  }
  for (auto& thread : threads)
  {
    thread.join();
  }
  const auto statistics = vtkSurfaceDetailMemory::GetCacheStatistics();
  EXPECT_LE(statistics.CachedBytes, 24 * MiB);
  EXPECT_GT(statistics.Hits, 0u);
}
#endif
