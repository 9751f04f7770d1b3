#include "clip_job_impl.hpp"

namespace hlr::exporter {

ClipOutcome clip_polygons_exact(const std::vector<RawPolygon>& subjects, const std::vector<RawPolygon>& clips,
                                const ClipOptions& options) {
  return clip_detail::ClipRun<ExactKernel>(subjects, clips, options).run();
}

}  // namespace hlr::exporter
