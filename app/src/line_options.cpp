#include "line_options.hpp"

namespace hlr::app {

void add_line_options(CLI::App& cmd, exporter::DrawOptions& options) {
  cmd.add_option("--crease", options.crease, "an edge is a crease when its faces meet at more than DEG degrees")
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str()
      ->type_name("DEG");
  cmd.add_flag("--smooth-edges", options.smooth_edges,
               "CAD models: also draw the tangent edges (B-rep edges whose faces meet smoothly, such as a "
               "fillet's boundaries); their other B-rep edges are drawn whatever --crease says");
  cmd.add_flag_callback(
      "--no-intersections", [&options] { options.intersections = false; }, "leave out the lines where faces penetrate");
}

}  // namespace hlr::app
