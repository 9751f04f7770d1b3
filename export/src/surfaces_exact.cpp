// The surfaces writers instantiated for ExactKernel.
#include "surfaces_impl.hpp"

namespace hlr::exporter {
HLR_EXPORT_SURFACES_DECLARE(hlr::ExactKernel, )
}  // namespace hlr::exporter
