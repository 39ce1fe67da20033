#pragma once
/// How an inpact process sets up its memory and its BLAS before any work (main() calls
/// set_up_process first). Every figure below was measured on the study bench's decks
/// (bench/study_overhead_deck.py) on this project's 2-core VMs, where a page fault is dear.
#include <cstddef>

namespace inpact::app {

/// The heap range set_up_heap asked 2 MiB pages for (bytes 0: none).
struct AdvisedHeap {
  void* begin = nullptr;
  std::size_t bytes = 0;
};

/// The heap serves blocks up to 32 MiB and keeps what is freed (M_MMAP_THRESHOLD,
/// M_TRIM_THRESHOLD), and gets 2 MiB pages: it reserves `reserve` bytes of address space (its
/// next growth, untouched, so no memory) and advises transparent huge pages for them (madvise
/// MADV_HUGEPAGE), as glibc's glibc.malloc.hugetlb=1 tunable would, which glibc reads only at
/// process start. The heap then keeps that much free top rather than giving it back. No advice
/// with INPACT_HUGE_PAGES=0 in the environment (profiling with 4 KiB pages).
AdvisedHeap set_up_heap(std::size_t reserve);

/// The process-wide settings of a batch run: glibc keeps freed blocks and the heap's free top,
/// the heap gets 2 MiB pages, OpenBLAS one thread until a command asks for more.
void set_up_process();

}  // namespace inpact::app
