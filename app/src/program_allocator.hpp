// hlr app, the program's allocator: tcmalloc where hlr links it (app/CMakeLists.txt), else the C
// library's malloc, on which these do nothing.
#pragma once

namespace hlr::app {

// From here (the run's start): the memory tcmalloc takes from the system is what the kernel may
// back with 2 MB pages, faulted in one such page at a time rather than 4 KB at a time. A fault
// costs about 10 us on the benchmark machine (a virtual machine): a fresh run of fandisk spent
// about 40% of its time in them (docs/BENCHMARKS.md, "Thirty-second run"). Growth of 2 MB or more
// is faulted in by one madvise call (MADV_POPULATE_WRITE): the large arrays of a large scene (1M
// faces on 2 threads: 12.9 s against 12.0 s, "Twenty-first run").
void use_huge_pages();

// From here: the heap grows in 4 KB pages. For a large drawing, whose peak memory counts (1M
// faces: 2 MB pages half filled by the stages after the reading added 2% to it) and whose large
// arrays are faulted in at once anyway.
void use_small_pages();

// From here (the run's start, or after return_freed_pages): freed pages are kept for the next stage
// to reuse. Pages handed back sooner are faulted in and zeroed again by the next stage that grows
// (0.7 s of a 1M-face draw's output stage, docs/BENCHMARKS.md; a fault costs about 14 us on the
// benchmark machine, and handing back a small span one madvise call as long).
void keep_freed_pages();

// The pages free now are handed back to the operating system; those freed later are kept. Before
// a large drawing's lines stage, when the penetration search ran beside the polygons: 1M faces on
// 2 threads, about 70 MB less peak and no slower (docs/BENCHMARKS.md, "Nineteenth run").
void release_free_pages();

// From here to keep_freed_pages: free pages are handed back to the operating system, those free
// now and those freed later. For the precedence and rounding of a large drawing, which free more
// than they then allocate: their allocations come from pages handed back instead of adding to the
// peak the lines stage left (1M faces: 125 MB less, docs/BENCHMARKS.md "Sixteenth run"). Each
// freed span then costs a madvise call, and each page a fault when used again (1M faces: the
// solution freed in 0.76 s against 0.18 s, "Twentieth run"), so the solution's own freeing, after
// the rounding, keeps its pages for the outputs (DrawOptions::drawing_rounded).
void return_freed_pages();

}  // namespace hlr::app
