#include "clip_run_impl.hpp"

namespace hlr::app {

int run_clip_exact(const ClipJob& job) { return clip_detail::ClipRun<ExactKernel>(job, "exact").run(); }

}  // namespace hlr::app
