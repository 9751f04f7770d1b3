// `hlr draw MESH... --view V -o OUT.svg|OUT.dxf|OUT.json [--hidden dashed|none] [--crease DEG]
//            [--sheet A4] [--scale 1:2] [--kernel exact|epick|double]`
#include "atomic_file.hpp"
#include "errors.hpp"
#include "scene_options.hpp"
#include "subcommand.hpp"

#include <hlr/export/lines.hpp>

#include <charconv>
#include <cmath>
#include <iostream>
#include <memory>

namespace hlr::app {
namespace {

struct DrawOptions {
  SceneOptions scene;
  std::vector<std::string> outputs;
  std::string hidden = "dashed";
  double crease = 30;
  std::string sheet = "A4";
  std::string scale;
  bool no_intersections = false;
};

enum class Format { json, svg, dxf };

Format format_of(const std::string& path) {
  if (has_extension(path, ".json")) return Format::json;
  if (has_extension(path, ".svg")) return Format::svg;
  if (has_extension(path, ".dxf")) return Format::dxf;
  throw UserError(path, "unknown output format (the name must end in .svg, .dxf or .json)");
}

// "1:2" (drawing : model), "2:1", or a plain factor "0.5".
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

// Stage lines on stderr once a run is long enough for a person to wonder.
struct Progress {
  bool on;
  void stage(const std::string& what) const {
    if (on) std::cerr << "hlr draw: " << what << '\n';
  }
};

template <class K>
int solve(const DrawOptions& options, const View& view, KernelKind kind, const exporter::DrawingStyle& style) {
  const auto start = std::chrono::steady_clock::now();
  // Every output is checked and opened before the work starts, and all are committed together at
  // the end: a bad path fails fast, and a failed run leaves no output at all.
  std::vector<Format> formats;
  for (const auto& out : options.outputs) formats.push_back(format_of(out));
  std::vector<std::unique_ptr<AtomicFile>> files;
  for (const auto& out : options.outputs) files.push_back(std::make_unique<AtomicFile>(out));

  const auto [meshes, input] = load_scene(options.scene.meshes);
  exporter::StageTimes times;
  times.read = seconds_since(start);
  const Progress progress{input.faces >= 10000};
  progress.stage(std::to_string(input.faces) + " faces read; building polygons");

  const ViewFrame<K> frame(view);
  auto mark = std::chrono::steady_clock::now();
  hidden_line::LineSet<K> lines;
  std::vector<hidden_line::DrawnSegment<K>> segments;
  hidden_line::AreaSortStats sort_stats;
  try {
    hidden_line::Sources<K> sources = hidden_line::build_sources<K>(meshes, frame);
    times.sources = seconds_since(mark);
    progress.stage("sorting " + std::to_string(sources.polygons.size()) + " polygons");
    mark = std::chrono::steady_clock::now();
    const hidden_line::VisibilityMap<K> map = hidden_line::area_sort<K>(sources);
    sort_stats = map.stats;
    times.sort = seconds_since(mark);
    progress.stage("classifying feature lines");
    mark = std::chrono::steady_clock::now();
    hidden_line::LineOptions line_options;
    line_options.features.crease_degrees = options.crease;
    line_options.intersections = !options.no_intersections;
    const auto intersections = line_options.intersections ? hidden_line::intersection_lines(meshes)
                                                          : std::vector<hidden_line::IntersectionSegment>{};
    times.intersections = seconds_since(mark);
    mark = std::chrono::steady_clock::now();
    lines = hidden_line::classify_lines<K>(meshes, frame, sources, map, intersections, line_options);
    times.lines = seconds_since(mark);
    mark = std::chrono::steady_clock::now();
    segments = hidden_line::drawing_segments<K>(lines);
    times.precedence = seconds_since(mark);
  } catch (const clip::ClipError& e) {
    throw inexact_kernel_failure(options.scene, kind, e);
  }
  times.total = seconds_since(start);

  exporter::LineDrawing drawing = exporter::make_drawing<K>(input, frame, kind, lines, segments);
  drawing.crease_degrees = options.crease;
  drawing.times = times;
  for (std::size_t i = 0; i < files.size(); ++i) {
    switch (formats[i]) {
      case Format::json: files[i]->write(exporter::lines_json(drawing)); break;
      case Format::svg: files[i]->write(exporter::lines_svg(drawing, style)); break;
      case Format::dxf: files[i]->write(exporter::lines_dxf(drawing, style)); break;
    }
  }
  for (auto& file : files) file->commit();

  const auto& st = lines.stats;
  auto kind_count = [&](FeatureKind k) { return st.by_kind[static_cast<int>(k)]; };
  std::cout << "hlr draw: " << input.faces << " faces, view " << view.name << ", kernel " << kernel_name(kind) << '\n'
            << "  " << st.lines << " feature lines (" << kind_count(FeatureKind::silhouette) << " silhouette, "
            << kind_count(FeatureKind::crease) << " crease, " << kind_count(FeatureKind::boundary) << " boundary, "
            << kind_count(FeatureKind::group) << " group, " << kind_count(FeatureKind::intersection)
            << " intersection)\n"
            << "  " << st.visible_pieces << " visible and " << st.hidden_pieces << " hidden pieces in " << times.total
            << " s\n";
  for (const auto& out : options.outputs) std::cout << "wrote " << out << '\n';
  return kExitOk;
}

int run(const DrawOptions& options) {
  const std::optional<View> view = resolve_view(options.scene);
  if (!view) return kExitUsage;
  exporter::DrawingStyle style;
  if (const auto sheet = exporter::sheet_by_name(options.sheet)) {
    style.sheet = *sheet;
  } else {
    std::cerr << "hlr: --sheet: unknown sheet \"" << options.sheet << "\" (use A0, A1, A2, A3 or A4)" << std::endl;
    return kExitUsage;
  }
  if (!options.scale.empty()) {
    style.scale = parse_scale(options.scale);
    if (!style.scale) {
      std::cerr << "hlr: --scale: \"" << options.scale << "\" is not a scale (write 1:2, 5:1 or a factor such as 0.5)"
                << std::endl;
      return kExitUsage;
    }
  }
  style.hidden = options.hidden == "dashed";
  return with_kernel(options.scene, [&]<class K>(KernelKind kind) { return solve<K>(options, *view, kind, style); });
}

}  // namespace

Subcommand add_draw_command(CLI::App& parent) {
  auto options = std::make_shared<DrawOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "draw", "Draw a mesh as an engineering line drawing: visible lines solid, hidden lines dashed, exactly.");
  add_scene_options(*cmd, options->scene);
  cmd->add_option("-o,--output", options->outputs,
                  "file to write, by extension: .svg (a sheet, in mm), .dxf (R2000, model units) or .json "
                  "(hlr-lines/1); may be given several times")
      ->required()
      ->type_name("OUT");
  cmd->add_option("--hidden", options->hidden, "hidden lines in SVG and DXF: dashed or none (JSON keeps them)")
      ->check(CLI::IsMember({"dashed", "none"}))
      ->capture_default_str()
      ->type_name("STYLE");
  cmd->add_option("--crease", options->crease, "an edge is a crease when its faces meet at more than DEG degrees")
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str()
      ->type_name("DEG");
  cmd->add_option("--sheet", options->sheet, "sheet for the SVG, landscape: A0, A1, A2, A3 or A4")
      ->capture_default_str()
      ->type_name("SIZE");
  cmd->add_option("--scale", options->scale,
                  "drawing scale such as 1:2 or 5:1 (default: the largest ISO 5455 scale that fits the sheet)")
      ->type_name("SCALE");
  cmd->add_flag("--no-intersections", options->no_intersections, "do not draw lines where faces penetrate");
  cmd->footer(
      "Example:\n"
      "  hlr draw fixtures/scenes/l_bracket.off --view iso -o out/bracket.svg -o out/bracket.dxf\n"
      "\n"
      "Feature lines are boundary, crease, silhouette, group and intersection lines; each is split into\n"
      "visible and hidden pieces exactly. Model units are taken as millimetres. Formats: docs/FORMATS.md.");
  return {cmd, [options] { return run(*options); }};
}

}  // namespace hlr::app
