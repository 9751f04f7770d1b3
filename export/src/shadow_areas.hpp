// Shadows as surface detail of a drawing (hlr draw --sun): the lit and shadow polygons of
// cast_shadows (hidden_line/shadows.hpp), exact in model space, projected exactly into the view and
// clipped to the visible polygons of their sources there; what remains is rounded into the
// drawing's view coordinates. After Weiler and Atherton: "a normal hidden surface removed view
// can be taken from any viewpoint to create a correctly shadowed scene". Exact kernel only.
#pragma once

#include <hlr/export/lines.hpp>
#include <hlr/hidden_line/shadows.hpp>

#include <vector>

namespace hlr::exporter::detail {

// Appends the projected shadow polygons' support lines to `sources` (auxiliary lines, which no
// later stage reads).
std::vector<DrawingArea> shadow_areas(const Scene& scene, const ViewFrame<ExactKernel>& frame,
                                      hidden_line::Sources<ExactKernel>& sources,
                                      const hidden_line::VisibilityMap<ExactKernel>& map,
                                      const std::vector<hidden_line::Light>& lights);

}  // namespace hlr::exporter::detail
