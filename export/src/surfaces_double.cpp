// The surfaces writers instantiated for DoubleKernel.
#include "surfaces_impl.hpp"

namespace hlr::exporter {
HLR_EXPORT_SURFACES_DECLARE(hlr::DoubleKernel, )
}  // namespace hlr::exporter
