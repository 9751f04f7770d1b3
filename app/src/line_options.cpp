#include "line_options.hpp"

#include <iostream>

namespace hlr::app {

void add_line_options(CLI::App& cmd, exporter::DrawOptions& options) {
  cmd.add_option("--crease", options.crease, "an edge is a crease when its faces meet at more than DEG degrees")
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str()
      ->type_name("DEG");
  cmd.add_flag_callback(
      "--no-intersections", [&options] { options.intersections = false; }, "leave out the lines where faces penetrate");
}

exporter::Progress stage_lines(bool shown) {
  exporter::Progress progress;
  // One write per line: stages may run side by side.
  if (shown) progress.stage = [](std::string_view what) { std::cerr << ("hlr: " + std::string(what) + '\n'); };
  return progress;
}

}  // namespace hlr::app
