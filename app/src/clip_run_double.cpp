#include "clip_run_impl.hpp"

namespace hlr::app {

int run_clip_double(const ClipJob& job) { return clip_detail::ClipRun<DoubleKernel>(job, "double").run(); }

}  // namespace hlr::app
