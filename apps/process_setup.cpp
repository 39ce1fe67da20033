#include "process_setup.hpp"

#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include "solver/blas_info.hpp"

namespace inpact::app {

namespace {

/// The heap's address space reserved at start (virtual: memory comes only as pages are touched).
constexpr std::size_t kHeapReserve = std::size_t{1} << 30;
/// glibc's largest mmap threshold (HEAP_MAX_SIZE / 2 on 64-bit): blocks up to it come from the heap.
constexpr int kLargestHeapBlock = 32 << 20;
/// glibc's default M_TOP_PAD (mallopt(3)).
constexpr int kDefaultTopPad = 128 * 1024;

}  // namespace

AdvisedHeap set_up_heap(std::size_t reserve) {
  // Every Newton iteration allocates and frees the same vectors, matrices and factors. glibc
  // hands blocks above its mmap threshold (128 KiB at start) back to the kernel when they are
  // freed and trims the heap's free top beyond 128 KiB, so the next iteration page-faults the
  // same memory in again, page by page. Keeping blocks up to 32 MiB (glibc's largest threshold)
  // and the free top in the process: 7,600 -> 4,500 page faults and a ~10 % shorter solve for
  // the 3,240-element plane deck; a study worker also reuses its heap from case to case.
  // Larger blocks (big factors) are still mapped and unmapped one by one.
  mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
  // A fresh process still faults every heap page in on first touch, 4 KiB at a time: 2 MiB
  // pages took a lone run of the 3,000-element C3D8 deck from 20,400 to 1,700 page faults and
  // 1.15 to 0.99 s (the 3,240-element plane deck 0.44 to 0.39 s, a one-element deck 51 to
  // 47 ms). glibc's glibc.malloc.hugetlb=1 also advises the blocks over 32 MiB (0.87 s for the
  // C3D8 deck), but only from the environment a process starts with.
  if (const char* v = std::getenv("INPACT_HUGE_PAGES"); v && std::string_view(v) == "0") return {};
  // Every later growth of the heap reserves `reserve` more, and the heap keeps that much free
  // top (glibc trims only beyond M_TOP_PAD): the advised range stays the heap's.
  mallopt(M_TOP_PAD, static_cast<int>(reserve));
  // Make the heap grow now: a block larger than its free top (and served by the heap).
  AdvisedHeap advised;
  const std::size_t probe_bytes = mallinfo2().keepcost + (std::size_t{1} << 20);
  if (void* probe = probe_bytes < static_cast<std::size_t>(kLargestHeapBlock) ? std::malloc(probe_bytes) : nullptr) {
    const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    auto* begin = reinterpret_cast<char*>(reinterpret_cast<std::uintptr_t>(probe) & ~(page - 1));
    auto* end = static_cast<char*>(sbrk(0));
    // The probe came from the grown heap (brk) when the break lies `reserve` beyond it.
    if (end > begin && static_cast<std::size_t>(end - begin) >= reserve &&
        madvise(begin, static_cast<std::size_t>(end - begin), MADV_HUGEPAGE) == 0)
      advised = {begin, static_cast<std::size_t>(end - begin)};
    std::free(probe);
  }
  // No advice (no THP, strict overcommit refusing the reserve, a malloc of its own as under
  // a sanitizer): the heap grows as glibc's default would, not by `reserve` at a time.
  if (advised.bytes == 0) mallopt(M_TOP_PAD, kDefaultTopPad);
  return advised;
}

void set_up_process() {
  set_up_heap(kHeapReserve);
  // One thread until a command asks for more (run --threads, study --threads).
  solver::set_blas_threads(1);
}

}  // namespace inpact::app
