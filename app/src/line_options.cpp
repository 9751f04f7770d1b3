#include "line_options.hpp"

#include <map>
#include <string>

namespace hlr::app {

void add_line_options(CLI::App& cmd, exporter::DrawOptions& options) {
  cmd.add_option("--crease", options.crease, "an edge is a crease when its faces meet at more than DEG degrees")
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str()
      ->type_name("DEG");
  // A value is optional: bare --smooth-edges is `full`, as the flag it was. A word after it that
  // is not a mode (a mesh) is refused by name, so that the mistake is plain.
  const std::map<std::string, SmoothEdges> modes{{"off", SmoothEdges::off}, {"thin", SmoothEdges::thin}, {"full", SmoothEdges::full}};
  cmd.add_option_function<std::string>(
         "--smooth-edges", [&options, modes](const std::string& mode) { options.smooth_edges = modes.at(mode); },
         "smooth edges, where surfaces meet tangentially (a fillet's boundaries: CAD models' tangent B-rep edges, "
         "meshes' edges between a flat face and a tessellated fillet, docs/FORMATS.md): off (not drawn), thin (thin "
         "continuous lines, kind smooth; hidden ones left off the sheet) or full (ordinary lines, kind crease); "
         "bare --smooth-edges is full. CAD models' other B-rep edges are drawn whatever --crease says")
      ->expected(0, 1)
      ->default_str("full")
      ->check(CLI::Validator(
          [modes](std::string& mode) -> std::string {
            if (modes.count(mode)) return {};
            return "'" + mode + "' is not off, thin or full (put meshes before a bare --smooth-edges)";
          },
          "MODE"))
      ->option_text("[off|thin|full]");
  cmd.add_flag_callback(
      "--no-intersections", [&options] { options.intersections = false; }, "leave out the lines where faces penetrate");
}

}  // namespace hlr::app
