// The surfaces writers instantiated for EpickKernel.
#include "surfaces_impl.hpp"

namespace hlr::exporter {
HLR_EXPORT_SURFACES_DECLARE(hlr::EpickKernel, )
}  // namespace hlr::exporter
