// hlr app, the program's code pages.
#pragma once

namespace hlr::app {

// Maps the program's own machine code into the process at once (MADV_POPULATE_READ), as a part
// of its loading, rather than by a page fault at the first call into each 64 KB of it. A fault
// costs 20-40 us on the benchmark machine (a virtual machine), and a fresh run of a small part
// took about 30 of them after its clock started (docs/BENCHMARKS.md, "Thirty-second run"). The
// libraries are left to fault: a run uses a few of their pages. Where the kernel refuses
// (before Linux 5.14), the pages fault in as before.
void map_program_code();

}  // namespace hlr::app
