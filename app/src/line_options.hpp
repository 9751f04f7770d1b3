// What the line-drawing subcommands (draw, sheet, check) share: the options of the line job
// (exporter::draw_lines, hlr/export/jobs.hpp).
#pragma once

#include "scene_options.hpp"

#include <hlr/export/jobs.hpp>

namespace hlr::app {

// --crease DEG, --smooth-edges [off|thin|full] and --no-intersections, into `options`.
void add_line_options(CLI::App& cmd, exporter::DrawOptions& options);


}  // namespace hlr::app
