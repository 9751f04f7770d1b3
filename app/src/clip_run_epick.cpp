#include "clip_run_impl.hpp"

namespace hlr::app {

int run_clip_epick(const ClipJob& job) { return clip_detail::ClipRun<EpickKernel>(job, "epick").run(); }

}  // namespace hlr::app
