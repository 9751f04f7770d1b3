#include "program_allocator.hpp"

#ifdef HLR_TCMALLOC
#include <gperftools/malloc_extension.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#endif

namespace hlr::app {

#ifdef HLR_TCMALLOC
namespace {

#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23  // Linux 5.14; older kernels refuse it, and pages fault in as before
#endif

constexpr size_t kSmallPage = 4096, kHugePage = size_t(2) << 20;

// tcmalloc's page heap grows by the program break, as tcmalloc's own allocator grows it, but in
// steps that end on 2 MB boundaries and marked MADV_HUGEPAGE, as glibc's malloc does with its
// hugetlb tunable: the kernel may then back each 2 MB of new heap with one page (transparent huge
// pages, in their "madvise" and "always" modes). The first write to a fresh 4 KB page costs a
// fault, about 10 us on the benchmark machine (a virtual machine); a 2 MB page costs one fault and
// its clearing, about 0.3 us per 4 KB (docs/BENCHMARKS.md, "Thirty-second run"). Where the kernel
// has no 2 MB page to give, pages fault in 4 KB at a time as before. The heap stays where
// tcmalloc's page map already covers it: memory far from it (a fresh mmap) costs a new 2 MB leaf
// of that map.
class HugePageAllocator : public SysAllocator {
 public:
  explicit HugePageAllocator(SysAllocator* fallback) : fallback_(fallback) {}
  void mark_growth(bool huge) { huge_ = huge; }
  void* Alloc(size_t size, size_t* actual_size, size_t alignment) override {
    const std::lock_guard<std::mutex> lock(mutex_);
    alignment = std::max(alignment, kSmallPage);
    uintptr_t start = align_up(next_, alignment);
    if (start + size > end_) {  // always at the first call, where end_ is 0
      if (!grow(size + alignment)) return fallback_->Alloc(size, actual_size, alignment);
      start = align_up(next_, alignment);
    }
    next_ = start + size;
    if (actual_size) *actual_size = size;
    void* memory = reinterpret_cast<void*>(start);
    // Large arrays are written whole: their pages are faulted in by one call, not one at a time.
    if (size >= kHugePage) (void)madvise(memory, size, MADV_POPULATE_WRITE);
    return memory;
  }

 private:
  static uintptr_t align_up(uintptr_t v, size_t a) { return (v + a - 1) / a * a; }

  // Moves the break to the first 2 MB boundary at least `least` bytes on. Growth that does not
  // continue the last (the first, or after someone else moved the break) starts at a 2 MB
  // boundary: a 2 MB range that holds pages written before cannot become one page. What is left
  // before it stays unused, and costs no memory.
  bool grow(size_t least) {
    void* current = sbrk(0);
    if (current == reinterpret_cast<void*>(-1)) return false;
    const uintptr_t from = align_up(reinterpret_cast<uintptr_t>(current), kSmallPage);
    if (from != end_) next_ = huge_ ? align_up(from, kHugePage) : from;
    const uintptr_t to = align_up(next_ + least, kHugePage);
    if (sbrk(static_cast<intptr_t>(to - reinterpret_cast<uintptr_t>(current))) == reinterpret_cast<void*>(-1))
      return false;
    if (huge_) (void)madvise(reinterpret_cast<void*>(next_), to - next_, MADV_HUGEPAGE);
    end_ = to;
    return true;
  }

  SysAllocator* fallback_;
  std::mutex mutex_;
  uintptr_t next_ = 0, end_ = 0;
  std::atomic<bool> huge_{true};  // whether growth from here is marked for 2 MB pages
};

// Never freed: tcmalloc may grow its heap until the process ends.
HugePageAllocator* huge_page_allocator = nullptr;

// The free pages tcmalloc's heap holds from before (its first growth, in 4 KB pages, most of it
// not yet written) are taken once and never used, so that the run's allocations come from the
// 2 MB pages: a fresh small run wrote about 100 of those 4 KB pages inside its clock. They cost
// address space only.
void* volatile set_aside = nullptr;  // never freed (volatile: a store the compiler must keep)
void set_aside_free_pages() {
  size_t free_bytes = 0;
  // Below 2 MB, so that it is never faulted in at once (HugePageAllocator::Alloc) where the free
  // pages are in more than one piece and it comes from fresh growth instead.
  if (MallocExtension::instance()->GetNumericProperty("tcmalloc.pageheap_free_bytes", &free_bytes) &&
      free_bytes > 0 && free_bytes < kHugePage)
    set_aside = std::malloc(free_bytes);
}

}  // namespace
#endif

void use_huge_pages() {
#ifdef HLR_TCMALLOC
  if (huge_page_allocator) return;  // once, at the start
  huge_page_allocator = new HugePageAllocator(MallocExtension::instance()->GetSystemAllocator());
  MallocExtension::instance()->SetSystemAllocator(huge_page_allocator);
  set_aside_free_pages();
#endif
}

void use_small_pages() {
#ifdef HLR_TCMALLOC
  if (huge_page_allocator) huge_page_allocator->mark_growth(false);
#endif
}

void keep_freed_pages() {
#ifdef HLR_TCMALLOC
  MallocExtension::instance()->SetMemoryReleaseRate(0);
  MallocExtension::instance()->SetNumericProperty("tcmalloc.aggressive_memory_decommit", 0);
#endif
}

void release_free_pages() {
#ifdef HLR_TCMALLOC
  MallocExtension::instance()->ReleaseFreeMemory();
#endif
}

void return_freed_pages() {
#ifdef HLR_TCMALLOC
  MallocExtension::instance()->ReleaseFreeMemory();
  MallocExtension::instance()->SetNumericProperty("tcmalloc.aggressive_memory_decommit", 1);
#endif
}

}  // namespace hlr::app
