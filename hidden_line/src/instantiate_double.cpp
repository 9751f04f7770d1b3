// The hidden-surface solution and line classification instantiated for DoubleKernel.
#include "area_sort_impl.hpp"
#include "lines_impl.hpp"
#include "sources_impl.hpp"

namespace hlr::hidden_line {
HLR_HIDDEN_LINE_DECLARE(hlr::DoubleKernel, )
HLR_HIDDEN_LINE_LINES_DECLARE(hlr::DoubleKernel, )
}  // namespace hlr::hidden_line
