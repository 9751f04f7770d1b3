#include "clip_job_impl.hpp"

namespace hlr::exporter {

ClipOutcome clip_polygons_double(const std::vector<RawPolygon>& subjects, const std::vector<RawPolygon>& clips,
                                 const ClipOptions& options) {
  return clip_detail::ClipRun<DoubleKernel>(subjects, clips, options).run();
}

}  // namespace hlr::exporter
