#include "program_allocator.hpp"

#ifdef HLR_TCMALLOC
#include <gperftools/malloc_extension.h>
#endif

namespace hlr::app {

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
