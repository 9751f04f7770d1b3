// hlr hidden_line, parallel loops: the kernel's (hlr/kernel/parallel.hpp), where the hidden-line
// stages and the exporters call them.
#pragma once

#include <hlr/kernel/parallel.hpp>

namespace hlr::hidden_line {

using hlr::free_each_in_parallel;
using hlr::free_in_parallel;
using hlr::parallel_chunks;
using hlr::resize_in_parallel;

}  // namespace hlr::hidden_line
