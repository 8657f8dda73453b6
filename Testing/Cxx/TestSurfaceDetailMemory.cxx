// The private huge-page allocation gives ordinary VTK arrays: right size, writable,
// resizable by VTK (realloc of the same memory), copyable, freed by VTK without help.
#include "vtkSurfaceDetailMemory.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkTypeInt32Array.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace
{
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
} // namespace

TEST(TestSurfaceDetailMemory, SmallArrayIsOrdinary)
{
  CheckArray<vtkFloatArray>(10, 3);
  CheckArray<vtkFloatArray>(0, 4);
}

TEST(TestSurfaceDetailMemory, BigArrayIsHugePageAlignedAndBehavesAsVTKArray)
{
  CheckArray<vtkFloatArray>(1000000, 3);
  CheckArray<vtkTypeInt32Array>(3000001, 1);
}
