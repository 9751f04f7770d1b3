// hlr app, the program's code pages.
#pragma once

namespace hlr::app {

// Maps the program's own machine code into the process at once (MADV_POPULATE_READ), as a part
// of its loading, rather than by a page fault at the first call into each 64 KB of it. A fault
// costs 20-40 us on the benchmark machine (a virtual machine), and a fresh run of fandisk took 30
// of them in its timed stages (docs/BENCHMARKS.md, "Thirty-second run"). The process takes as
// long as before; the faults are no longer inside the first stage that calls the code. The
// libraries are left to fault: a run uses a few of their pages. Where the kernel refuses (before
// Linux 5.14), the pages fault in as before.
void map_program_code();

}  // namespace hlr::app
