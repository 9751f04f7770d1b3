// The clipper instantiated for EpickKernel; one translation unit per kernel keeps rebuilds parallel.
#include "clip_impl.hpp"
#include "normalize_impl.hpp"

namespace hlr::clip {
HLR_CLIPPER_DECLARE(hlr::EpickKernel, )
}  // namespace hlr::clip
