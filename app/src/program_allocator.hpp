// hlr app, the program's allocator: tcmalloc where hlr links it (app/CMakeLists.txt), else the C
// library's malloc, on which these do nothing.
#pragma once

namespace hlr::app {

// For the run: freed pages are kept for the next stage to reuse. Pages handed back sooner are
// faulted in and zeroed again by the next stage that grows (0.7 s of a 1M-face draw's output
// stage, docs/BENCHMARKS.md).
void keep_freed_pages();

// The pages free now are handed back to the operating system; those freed later are kept. Before
// a large drawing's lines stage, when the penetration search ran beside the polygons: 1M faces on
// 2 threads, about 70 MB less peak and no slower (docs/BENCHMARKS.md, "Nineteenth run").
void release_free_pages();

// From here to the end of the run: free pages are handed back to the operating system, those free
// now and those freed later. For the output stage of a large drawing, which frees more than it
// then allocates: its allocations come from pages handed back instead of adding to the peak the
// lines stage left (1M faces: 125 MB less at about 0.3 s, docs/BENCHMARKS.md "Sixteenth run").
void return_freed_pages();

}  // namespace hlr::app
