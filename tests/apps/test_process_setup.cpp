// The process set-up of apps/process_setup.hpp: the heap's huge-page advice reaches the kernel
// and covers what malloc hands out afterwards.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "apps/process_setup.hpp"

namespace inpact::app {
namespace {

/// The VmFlags of the mapping of this process that holds `address` ("" when none does).
std::string vm_flags_at(const void* address) {
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> lo >> dash >> hi && dash == '-' && line.find(' ') > line.find('-')) {
      inside = lo <= a && a < hi;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line.substr(8);
    }
  }
  return "";
}

TEST(ProcessSetup, HeapIsAdvisedForHugePagesAndLaterBlocksLieInTheAdvisedRange) {
  unsetenv("INPACT_HUGE_PAGES");
  const std::size_t reserve = std::size_t{64} << 20;
  std::ifstream thp("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(thp, modes);
  if (modes.find("[always]") == std::string::npos && modes.find("[madvise]") == std::string::npos)
    GTEST_SKIP() << "this kernel gives no transparent huge pages ('" << modes << "')";
  const AdvisedHeap heap = set_up_heap(reserve);
  ASSERT_GE(heap.bytes, reserve) << "the heap was not advised";
  // A block from the heap after the advice (below the 32 MiB that set_up_heap keeps in the heap).
  void* block = std::malloc(std::size_t{4} << 20);
  ASSERT_NE(block, nullptr);
  const auto* b = static_cast<const char*>(block);
  const auto* begin = static_cast<const char*>(heap.begin);
  EXPECT_TRUE(begin <= b && b < begin + heap.bytes) << "the block is outside the advised heap range";
  EXPECT_NE((" " + vm_flags_at(block) + " ").find(" hg "), std::string::npos)
      << "no hg (MADV_HUGEPAGE) flag on the heap mapping: " << vm_flags_at(block);
  std::free(block);
}

TEST(ProcessSetup, InpactHugePagesZeroLeavesTheHeapAlone) {
  setenv("INPACT_HUGE_PAGES", "0", 1);
  const AdvisedHeap heap = set_up_heap(std::size_t{64} << 20);
  unsetenv("INPACT_HUGE_PAGES");
  EXPECT_EQ(heap.bytes, 0u);
  EXPECT_EQ(heap.begin, nullptr);
}

}  // namespace
}  // namespace inpact::app
