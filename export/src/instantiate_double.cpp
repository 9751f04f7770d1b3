// The kernel-dependent writers (surfaces, and the rounding of line drawings) instantiated for DoubleKernel.
#include "lines_impl.hpp"
#include "surfaces_impl.hpp"

namespace hlr::exporter {
HLR_EXPORT_SURFACES_DECLARE(hlr::DoubleKernel, )
HLR_EXPORT_LINES_DECLARE(hlr::DoubleKernel, )
}  // namespace hlr::exporter
