// The kernel-dependent writers (surfaces, and the rounding of line drawings) instantiated for EpickKernel.
#include "lines_impl.hpp"
#include "surfaces_impl.hpp"

namespace hlr::exporter {
HLR_EXPORT_SURFACES_DECLARE(hlr::EpickKernel, )
HLR_EXPORT_LINES_DECLARE(hlr::EpickKernel, )
}  // namespace hlr::exporter
