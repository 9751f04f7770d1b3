// The kernel-dependent writers (surfaces, and the rounding of line drawings) instantiated for ExactKernel.
#include "lines_impl.hpp"
#include "surfaces_impl.hpp"

namespace hlr::exporter {
HLR_EXPORT_SURFACES_DECLARE(hlr::ExactKernel, )
HLR_EXPORT_LINES_DECLARE(hlr::ExactKernel, )
}  // namespace hlr::exporter
