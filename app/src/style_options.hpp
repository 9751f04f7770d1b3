// What `hlr draw` and `hlr sheet` share about the sheet: its size, scale and units, the line
// group, hidden and centre lines, the drawing's resolution (merge distance) and contact lines,
// and the output formats they write a sheet in.
#pragma once

#include <hlr/export/lines.hpp>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace hlr::app {

struct StyleOptions {
  std::string sheet = "A4";
  std::string scale;
  std::string units = "mm";
  std::string line_group = "0.5";
  std::string hidden = "dashed";
  double merge_distance = 0.01;  // mm on the sheet
  double contact_degrees = 10;
  bool centre_lines = true;
};

// --sheet, --scale, --units, --line-group, --hidden, --no-centre-lines, --merge-distance,
// --contact-angle, into `options` (whose values are the defaults shown).
void add_style_options(CLI::App& cmd, StyleOptions& options);

// The style the options name, or nothing after a one-line usage error on stderr.
std::optional<exporter::DrawingStyle> resolve_style(const StyleOptions& options);

// "1:2" (drawing : part), "2:1", or a plain factor "0.5"; nothing for anything else.
std::optional<double> parse_scale(const std::string& text);

}  // namespace hlr::app
