// The hidden-surface solution and line classification instantiated for ExactKernel.
#include "area_sort_impl.hpp"
#include "lines_impl.hpp"
#include "sources_impl.hpp"

namespace hlr::hidden_line {
HLR_HIDDEN_LINE_DECLARE(hlr::ExactKernel, )
HLR_HIDDEN_LINE_LINES_DECLARE(hlr::ExactKernel, )
}  // namespace hlr::hidden_line
