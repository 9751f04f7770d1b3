#include "program_allocator.hpp"

#ifdef HLR_TCMALLOC
#include <gperftools/malloc_extension.h>
#include <sys/mman.h>
#endif

namespace hlr::app {

#ifdef HLR_TCMALLOC
namespace {

#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23  // Linux 5.14; older kernels refuse it, and pages fault in as before
#endif

// The system allocator tcmalloc found, with large allocations faulted in at once.
class PrefaultingAllocator : public SysAllocator {
 public:
  explicit PrefaultingAllocator(SysAllocator* base) : base_(base) {}
  void* Alloc(size_t size, size_t* actual_size, size_t alignment) override {
    void* memory = base_->Alloc(size, actual_size, alignment);
    const size_t got = actual_size ? *actual_size : size;
    if (memory && got >= kLeast) (void)madvise(memory, got, MADV_POPULATE_WRITE);
    return memory;
  }

 private:
  // Smaller growth is what small runs make, which touch a few of its pages.
  static constexpr size_t kLeast = size_t(2) << 20;
  SysAllocator* base_;
};

}  // namespace
#endif

void prefault_large_allocations() {
#ifdef HLR_TCMALLOC
  // Never freed: tcmalloc may grow its heap until the process ends.
  static auto* prefaulting = new PrefaultingAllocator(MallocExtension::instance()->GetSystemAllocator());
  MallocExtension::instance()->SetSystemAllocator(prefaulting);
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
