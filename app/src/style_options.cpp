#include "style_options.hpp"

#include <charconv>
#include <cmath>
#include <iostream>

namespace hlr::app {

void add_style_options(CLI::App& cmd, StyleOptions& options) {
  cmd.add_option("--sheet", options.sheet, "sheet, landscape: A0, A1, A2, A3 or A4")->capture_default_str()->type_name("SIZE");
  cmd.add_option("--scale", options.scale,
                 "drawing scale such as 1:2 or 5:1 (default: the largest ISO 5455 scale that fits the sheet); "
                 "a scale at which the drawing does not fit is an error")
      ->type_name("SCALE");
  cmd.add_option("--units", options.units, "what one model unit is: mm, cm, m or in (the scale is of sheet to part)")
      ->check(CLI::IsMember({"mm", "cm", "m", "in"}))
      ->capture_default_str()
      ->type_name("UNIT");
  cmd.add_option("--line-group", options.line_group,
                 "ISO 128 line group: the width of visible lines in mm, 0.35, 0.5 or 0.7 (narrow lines half as wide)")
      ->check(CLI::IsMember({"0.35", "0.5", "0.7"}))
      ->capture_default_str()
      ->type_name("MM");
  cmd.add_option("--hidden", options.hidden, "hidden lines on the sheet: dashed or none (JSON keeps them)")
      ->check(CLI::IsMember({"dashed", "none"}))
      ->capture_default_str()
      ->type_name("STYLE");
  cmd.add_flag_callback(
      "--no-centre-lines", [&options] { options.centre_lines = false; },
      "leave out the centre marks of circles and the centre lines of cylinders");
  cmd.add_option("--merge-distance", options.merge_distance,
                 "the drawing's resolution on the sheet: lines closer than MM are drawn once, visible over hidden, "
                 "and runs of segments whose vertices lie within MM of a circle are drawn as circles and arcs (0: "
                 "neither; the JSON keeps every piece; a CAD model's own circles are drawn as circles, arcs and ellipses "
                 "at any distance)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str()
      ->type_name("MM");
  cmd.add_option("--contact-angle", options.contact_degrees,
                 "on the sheet, leave out intersection lines where surfaces meet at less than DEG degrees (the "
                 "contact of nearly tangent surfaces, such as a shaft in a bore; 0: draw all; the JSON keeps them)")
      ->check(CLI::Range(0.0, 90.0))
      ->capture_default_str()
      ->type_name("DEG");
}

std::optional<double> parse_scale(const std::string& text) {
  auto number = [](std::string_view s) -> std::optional<double> {
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !(v > 0) || !std::isfinite(v)) return std::nullopt;
    return v;
  };
  const auto colon = text.find(':');
  if (colon == std::string::npos) return number(text);
  const auto drawing = number(std::string_view(text).substr(0, colon));
  const auto model = number(std::string_view(text).substr(colon + 1));
  if (!drawing || !model) return std::nullopt;
  const double scale = *drawing / *model;
  if (!(scale > 0) || !std::isfinite(scale)) return std::nullopt;
  return scale;
}

std::optional<exporter::DrawingStyle> resolve_style(const StyleOptions& options) {
  exporter::DrawingStyle style;
  if (const auto sheet = exporter::sheet_by_name(options.sheet)) {
    style.sheet = *sheet;
  } else {
    std::cerr << "hlr: --sheet: unknown sheet \"" << options.sheet << "\" (use A0, A1, A2, A3 or A4)" << std::endl;
    return std::nullopt;
  }
  style.units = options.units;
  style.unit_mm = options.units == "cm" ? 10 : options.units == "m" ? 1000 : options.units == "in" ? 25.4 : 1;
  if (!options.scale.empty()) {
    const auto ratio = parse_scale(options.scale);
    if (!ratio) {
      std::cerr << "hlr: --scale: \"" << options.scale << "\" is not a scale (write 1:2, 5:1 or a factor such as 0.5)"
                << std::endl;
      return std::nullopt;
    }
    style.scale = *ratio * style.unit_mm;  // sheet mm per model unit
  }
  style.line_group = parse_scale(options.line_group).value_or(0.5);  // one of IsMember's: a plain number
  style.hidden = options.hidden == "dashed";
  style.centre_lines = options.centre_lines;
  style.merge_distance = options.merge_distance;
  style.contact_degrees = options.contact_degrees;
  return style;
}

}  // namespace hlr::app
